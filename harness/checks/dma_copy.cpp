// Check, bench and run for bvb/dma_copy.h: the memory DMA helper (bvb/dma.h) byte for byte on
// the transfers the streaming kernels give it.
#include "bvb/dma_copy.h"

#include "bvb/sobel.h"
#include "family.h"
#include "io.h"
#include "patterns.h"
#include "names.h"

namespace bvb {
namespace {

CheckCall copy_call(int w, int h, int ss, int ds, int band, std::vector<uint8_t> src, const std::string &name) {
  CheckCall c;
  c.kernel = "dma_copy_u8";
  c.case_name = name;
  c.pixels = double(w) * h;
  int is = c.in("src", std::move(src), View{1, false, w, h, ss});
  int id = c.out("dst", size_t(ds) * (h - 1) + w, View{1, false, w, h, ds});
  int it = c.scratch("scratch", BVB_DMA_COPY_SCRATCH_SIZE(w, band));
  c.buf(is).word(ss).buf(id).word(ds).word(w).word(h).word(band).buf(it);
  c.host = [=](HostBuffers &m) { bvb_dma_copy_u8_c(m.u8(is), ss, m.u8(id), ds, w, h, band, m.u8(it)); };
  return c;
}

std::string case_name(int w, int h, int ss, int ds, int band, uint32_t ks, uint32_t kd, const char *where) {
  return size_name(w, h) + " strides " + std::to_string(ss) + "/" +
         std::to_string(ds) + " band " + std::to_string(band) + " skews " + std::to_string(ks) + "/" +
         std::to_string(kd) + " " + where;
}

void check(Checker &ck) {
  if (!ck.wants("dma_copy_u8")) return;
  Rng &rng = ck.rng();
  std::vector<Size> sizes = check_sizes(1, 1, rng, ck.options().campaign);
  // Odd and even widths (byte or 16-bit elements), widths that are and are not multiples of 4
  // (padded band rows), one-row and one-column blocks, and the SRV-1's frames.
  for (Size s : std::vector<Size>{{1, 1}, {2, 3}, {3, 2}, {4, 9}, {5, 7}, {6, 17}, {7, 1}, {64, 6},
                                   {161, 5}, {320, 24}, {322, 9}, {640, 12}})
    sizes.push_back(s);
  for (Size s : sizes) {
    // The band sizes the kernels use at this width, and others: one row, two, odd, more
    // rows than the frame has.
    std::vector<int> bands = {BVB_SOBEL3X3_BAND_ROWS(s.w), 1, 2, rng.uniform(3, 9), s.h + rng.uniform(0, 3)};
    for (int band : bands) {
      if (band < 1) continue;
      const bool packed = rng.uniform(0, 2) == 0;
      const int ss = packed ? s.w : pick_stride(s.w, rng);
      const int ds = packed ? s.w : pick_stride(s.w, rng);
      const uint32_t ks = rng.uniform(0, 1) ? 0u : uint32_t(rng.uniform(1, 3));
      const uint32_t kd = rng.uniform(0, 1) ? 0u : uint32_t(rng.uniform(1, 3));
      const std::vector<Pattern> &pats = ck.patterns();  // real frames only when present
      const Pattern p = pats[rng.uniform(0, int(pats.size()) - 1)];
      std::vector<uint8_t> src = make_plane(p, s.w, s.h, ss, rng, ck.options().frames_real);
      // Where the kernels run: frames in SDRAM, band buffers in L1 bank A or B (when they fit).
      const size_t need = BVB_DMA_COPY_SCRATCH_SIZE(s.w, band) + 256;
      const uint32_t l1 = rng.uniform(0, 1) ? BVB_PLACE_L1A : BVB_PLACE_L1B;
      if (need <= ck.target().arena_bytes(l1)) {
        CheckCall c = copy_call(s.w, s.h, ss, ds, band, src, case_name(s.w, s.h, ss, ds, band, ks, kd, "frames SDRAM"));
        c.bufs[0].skew = ks;
        c.bufs[1].skew = kd;
        c.bufs[2].place = l1;
        ck.add(std::move(c));
      }
      // Anywhere: L1 to L1, the scratchpad (no DMA there: the core copies), all SDRAM.
      CheckCall c = copy_call(s.w, s.h, ss, ds, band, std::move(src), case_name(s.w, s.h, ss, ds, band, ks, kd, "random"));
      c.bufs[0].skew = ks;
      c.bufs[1].skew = kd;
      ck.place_randomly(c);
      ck.add(std::move(c));
    }
  }
}

CheckCall bench_call(const std::string &, int w, int h, Rng &rng) {
  const int band = BVB_SOBEL3X3_BAND_ROWS(w);
  CheckCall c = copy_call(w, h, w, w, band, make_plane(Pattern::Noise, w, h, w, rng, ""),
                          size_name(w, h));
  c.bufs[2].place = BVB_PLACE_L1A;
  return c;
}

// The bus: every pixel crosses the SDRAM bus in and out, 2 bytes per SCLK = 0.5 byte per core
// cycle at the SRV-1's CCLK:SCLK of 4 (bvb/dma.h): 4 cycles per pixel.
double lower_bound(const std::string &, int w, int h) { return 4.0 * w * h; }

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError(req.kernel + " takes one --in frame");
  Image in = read_input(req, 0);
  const int band = req.params.get_int("band", BVB_SOBEL3X3_BAND_ROWS(in.width), 1, 4096);
  req.params.check_all_used();
  const int w = in.width, h = in.height;
  RunPlan p;
  p.call = copy_call(w, h, w, w, band, in.data, "run");
  p.write = [w, h](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    Image out(w, h);
    out.data = bufs[1];
    write_image(path, out);
  };
  p.summary = size_name(w, h) + ", bands of " + std::to_string(band) + " rows";
  return p;
}

const Family kDmaCopy{"dma_copy", {"dma_copy_u8"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kDmaCopy);

}  // namespace
}  // namespace bvb
