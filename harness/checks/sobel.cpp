// Check, bench and run for bvb/sobel.h.
#include "bvb/sobel.h"

#include <algorithm>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "names.h"

namespace bvb {
namespace {

CheckCall u8_call(int w, int h, int ss, int ds, std::vector<uint8_t> src, const std::string &name) {
  CheckCall c;
  c.kernel = "sobel3x3_u8";
  c.case_name = name;
  c.pixels = double(w) * h;
  int is = c.in("src", std::move(src), View{1, false, w, h, ss});
  int id = c.out("dst", size_t(ds) * (h - 1) + w, View{1, false, w, h, ds});
  int it = c.scratch("scratch", BVB_SOBEL3X3_SCRATCH_SIZE(w));
  c.buf(is).word(ss).buf(id).word(ds).word(w).word(h).buf(it);
  c.host = [=](HostBuffers &m) { bvb_sobel3x3_u8_c(m.u8(is), ss, m.u8(id), ds, w, h, m.u8(it)); };
  return c;
}

// gs: gx/gy row stride in elements; ms: magnitude stride, or 0 for no magnitude output.
CheckCall s16_call(int w, int h, int ss, int gs, int ms, std::vector<uint8_t> src, const std::string &name) {
  CheckCall c;
  c.kernel = "sobel3x3_s16";
  c.case_name = name;
  c.pixels = double(w) * h;
  int is = c.in("src", std::move(src), View{1, false, w, h, ss});
  const size_t gbytes = 2 * (size_t(gs) * (h - 1) + w);
  int igx = c.out("gx", gbytes, View{2, true, w, h, gs});
  int igy = c.out("gy", gbytes, View{2, true, w, h, gs});
  int im = ms ? c.out("mag", size_t(ms) * (h - 1) + w, View{1, false, w, h, ms}) : -1;
  int it = c.scratch("scratch", BVB_SOBEL3X3_S16_SCRATCH_SIZE(w));
  c.buf(is).word(ss).buf(igx).buf(igy).word(gs);
  if (ms) c.buf(im); else c.word(0);
  c.word(ms).word(w).word(h).buf(it);
  c.host = [=](HostBuffers &m) {
    bvb_sobel3x3_s16_c(m.u8(is), ss, m.s16(igx), m.s16(igy), gs, ms ? m.u8(im) : nullptr, ms, w, h, m.u8(it));
  };
  return c;
}

void check(Checker &ck) {
  Rng &rng = ck.rng();
  // Both kernels' cases are generated whatever -k says (Checker::add filters).
  const bool u8 = true, s16 = true;
  const std::string &real = ck.options().frames_real;
  std::vector<Size> sizes = check_sizes(3, 3, rng, ck.options().campaign);
  // Widths around the multiples of four the assembly's groups of four pixels fall on, and the
  // contiguous layouts of the SRV-1's frames.
  for (Size s : std::vector<Size>{{4, 3}, {5, 4}, {6, 3}, {8, 3}, {8, 8}, {9, 5}, {12, 4}, {13, 6},
                                   {20, 11}, {64, 6}, {80, 60}})
    sizes.push_back(s);
  for (Size s : sizes) {
    for (Pattern p : ck.patterns()) {
      // Contiguous frames half the time (the common case and the assembly's fast path),
      // padded rows otherwise; output rows at every alignment.
      const bool packed = rng.uniform(0, 1) == 0;
      const int ss = packed ? s.w : pick_stride(s.w, rng);
      std::vector<uint8_t> src = make_plane(p, s.w, s.h, ss, rng, real);
      const uint32_t src_skew = uint32_t(rng.uniform(0, 3));
      const uint32_t out_skew = rng.uniform(0, 1) ? 0u : uint32_t(rng.uniform(1, 3));
      if (u8) {
        const int ds = packed ? s.w : pick_stride(s.w, rng);
        CheckCall c = u8_call(s.w, s.h, ss, ds, src,
                              size_name(s.w, s.h) + " strides " + std::to_string(ss) + "/" +
                                  std::to_string(ds) + " " + pattern_name(p));
        c.bufs[0].skew = src_skew;
        c.bufs[1].skew = out_skew;
        // Half the calls where the robot runs it (the DMA path, bvb/sobel.h).
        ck.place_streaming(c, 2, rng);
        ck.add(std::move(c));
      }
      if (s16) {
        const int gs = packed ? s.w : pick_stride(s.w, rng);
        const int ms = rng.uniform(0, 3) == 0 ? 0 : (packed ? s.w : pick_stride(s.w, rng));
        CheckCall c = s16_call(s.w, s.h, ss, gs, ms, src,
                               size_name(s.w, s.h) + " strides " + std::to_string(ss) + "/" +
                                   std::to_string(gs) + "/" + (ms ? std::to_string(ms) : "nomag") +
                                   " " + pattern_name(p));
        c.bufs[0].skew = src_skew;
        // int16 rows: 2-byte aligned, 4-byte aligned or not.
        c.bufs[1].skew = c.bufs[2].skew = out_skew & 2u;
        if (ms) c.bufs[3].skew = out_skew;
        // As for u8 (the scratch is the buffer after the outputs).
        ck.place_streaming(c, ms ? 4 : 3, rng);
        ck.add(std::move(c));
      }
    }
  }
}

CheckCall bench_call(const std::string &kernel, int w, int h, Rng &rng) {
  std::vector<uint8_t> src = make_plane(Pattern::Noise, w, h, w, rng, "");
  if (kernel == "sobel3x3_u8") {
    // Frames in SDRAM, the scratch (ring and band buffers, 23.1 KB at 320) in L1 bank B.
    CheckCall c = u8_call(w, h, w, w, std::move(src), size_name(w, h));
    c.bufs[2].place = BVB_PLACE_L1B;
    return c;
  }
  // Frames in SDRAM, the scratch (ring, band buffers and two DMA jobs, 21.5 KB at 320) in L1 bank B.
  CheckCall c = s16_call(w, h, w, w, w, std::move(src), size_name(w, h));
  c.bufs[4].place = BVB_PLACE_L1B;
  return c;
}

// The operation counts of the assembly's method (bvb/sobel.h, firmware/asm/sobel.S) over the
// interior pixels, one ALU/MAC instruction per cycle:
//   u8:  per 4 pixels, 1 BYTEOP16P + 2 box-sum adds + 4 subtractions + 4 ABS + 2 MAX + 2 MIN
//        + 1 BYTEPACK = 16 instructions: 4 cycles per pixel.
//   s16 (benched with the magnitude): the same up to the subtractions (7), + 2 quad
//        add/subtract for gx and gy, and for the magnitude 4 ABS + 2 adds + 2 MIN + 1 BYTEPACK:
//        18 instructions per 4 pixels; its 26 loads and stores fit the 36 slots of 18 issues,
//        so 4.5 cycles per pixel.
// The larger of the compute bound (4 and 4.5 cycles per interior pixel: firmware/asm/sobel.S)
// and the bus's: with the frames in SDRAM every pixel's bytes cross the 16-bit bus by memory
// DMA at 0.5 byte per core cycle (bvb/dma.h), 1 in and 1 out for u8, 1 in and 5 out (gx, gy,
// mag: the bench's case) for s16: 4 and 12 cycles per frame pixel.
double lower_bound(const std::string &kernel, int w, int h) {
  const double interior = double(w - 2) * (h - 2), pixels = double(w) * h;
  return kernel == "sobel3x3_u8" ? std::max(4.0 * interior, 4.0 * pixels)
                                 : std::max(4.5 * interior, 12.0 * pixels);
}

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError(req.kernel + " takes one --in frame");
  Image in = read_input(req, 0);
  if (in.width < 3 || in.height < 3) throw InputError(req.kernel + ": the frame must be 3x3 or larger");
  const int w = in.width, h = in.height;
  RunPlan p;
  if (req.kernel == "sobel3x3_u8") {
    req.params.check_all_used();
    p.call = u8_call(w, h, w, w, in.data, "run");
    p.write = [w, h](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
      Image out(w, h);
      out.data = bufs[1];
      write_image(path, out);
    };
    p.summary = size_name(w, h) + ", magnitude";
    return p;
  }
  // s16: which output to write as a PGM: the magnitude, or gx / gy as 128 + g/8 (so the full
  // range -1020..1020 fits a byte).
  const std::string show = req.params.get_str("show", "mag");
  if (show != "mag" && show != "gx" && show != "gy") throw InputError("show= wants mag, gx or gy");
  req.params.check_all_used();
  p.call = s16_call(w, h, w, w, w, in.data, "run");
  p.write = [w, h, show](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    Image out(w, h);
    if (show == "mag") {
      out.data = bufs[3];
    } else {
      const std::vector<uint8_t> &g = bufs[show == "gx" ? 1 : 2];
      for (size_t i = 0; i < out.data.size(); ++i) {
        const int16_t v = int16_t(g[2 * i] | (g[2 * i + 1] << 8));
        out.data[i] = uint8_t(std::clamp(128 + v / 8, 0, 255));
      }
    }
    write_image(path, out);
  };
  p.summary = size_name(w, h) + ", " + show;
  return p;
}

const Family kSobel{"sobel", {"sobel3x3_u8", "sobel3x3_s16"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kSobel);

}  // namespace
}  // namespace bvb
