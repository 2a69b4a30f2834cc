// Check, bench and run for bvb/morph.h (3x3 erosion and dilation).
#include "bvb/morph.h"

#include <algorithm>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "names.h"

namespace bvb {
namespace {

CheckCall morph_call(const std::string &kernel, int w, int h, int sstride, int dstride, std::vector<uint8_t> src,
                     const std::string &case_name) {
  CheckCall c;
  c.kernel = kernel;
  c.case_name = case_name;
  c.pixels = double(w) * h;
  const View sv{1, false, w, h, sstride}, dv{1, false, w, h, dstride};
  int is = c.in("src", std::move(src), sv);
  int id = c.out("dst", size_t(dstride) * (h - 1) + w, dv);
  int iscr = c.scratch("scratch", BVB_MORPH3X3_SCRATCH_BYTES(w));
  c.buf(is).buf(id).word(w).word(h).word(sstride).word(dstride).buf(iscr);
  const bool dilate = kernel == "dilate3x3_u8";
  c.host = [=](HostBuffers &m) {
    if (dilate)
      bvb_dilate3x3_u8_c(m.u8(is), m.u8(id), w, h, sstride, dstride, m.u8(iscr));
    else
      bvb_erode3x3_u8_c(m.u8(is), m.u8(id), w, h, sstride, dstride, m.u8(iscr));
  };
  return c;
}

// A 0/255 mask: noise thresholded at a random density, so blobs, holes and single pixels occur.
std::vector<uint8_t> random_mask(int w, int h, int stride, Rng &rng) {
  std::vector<uint8_t> d(size_t(stride) * (h - 1) + w);
  const uint32_t density = uint32_t(rng.uniform(10, 90));
  for (auto &v : d) v = rng.u32() % 100 < density ? 255 : 0;
  return d;
}

void check(Checker &ck) {
  for (const char *kernel : {"erode3x3_u8", "dilate3x3_u8"}) {
    Rng &rng = ck.rng();
    std::vector<Size> sizes = check_sizes(1, 1, rng, ck.options().campaign);
    // Widths 2..17 (and 1 above) meet each phase of the 8-pixel loop and of the right-edge fix-up.
    for (int w = 2; w <= 17; ++w) sizes.push_back({w, w % 4 + 1});
    for (Size s : sizes) {
      struct Input {
        std::string label;
        int stride;
        std::vector<uint8_t> data;
      };
      std::vector<Input> inputs;
      for (Pattern p : ck.patterns()) {
        const int ss = pick_stride(s.w, rng);
        inputs.push_back({pattern_name(p), ss, make_plane(p, s.w, s.h, ss, rng, ck.options().frames_real)});
      }
      const int ms = pick_stride(s.w, rng);
      inputs.push_back({"mask", ms, random_mask(s.w, s.h, ms, rng)});
      for (auto &in : inputs) {
        const int ds = pick_stride(s.w, rng);
        std::string name = size_name(s.w, s.h) + " " + in.label + " strides " +
                           std::to_string(in.stride) + "/" + std::to_string(ds);
        CheckCall c = morph_call(kernel, s.w, s.h, in.stride, ds, std::move(in.data), name);
        // Source and destination at any alignment; the scratch is documented 4-byte aligned.
        for (auto &b : c.bufs)
          if (b.role != Role::Scratch) b.skew = uint32_t(rng.uniform(0, 3));
        // Half the calls where the robot runs it (the DMA path, firmware/asm/morph.S).
        ck.place_streaming(c, 2, rng);
        ck.add(std::move(c));
      }
    }
  }
}

CheckCall bench_call(const std::string &kernel, int w, int h, Rng &rng) {
  // Frames in SDRAM, the scratch (H rows, band buffers and DMA jobs: 17.2 KB at 320) in L1 bank B.
  CheckCall c = morph_call(kernel, w, h, w, w, make_plane(Pattern::Noise, w, h, w, rng, ""),
                           size_name(w, h));
  c.bufs[2].place = BVB_PLACE_L1B;
  return c;
}

// Per pixel: 7/4 ops in the horizontal pass and 5/4 in the vertical one (firmware/asm/morph.S).
// The larger of the compute bound (3.0 cycles per pixel: firmware/asm/morph.S) and the bus's:
// with the frames in SDRAM each pixel is a byte in and a byte out by memory DMA at 0.5 byte per
// core cycle (bvb/dma.h), 4.0 cycles per pixel.
constexpr double kComputePerPixel = 3.0, kBusPerPixel = 4.0;
double lower_bound(const std::string &, int w, int h) { return std::max(kComputePerPixel, kBusPerPixel) * w * h; }

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError(req.kernel + " takes one --in frame");
  Image a = read_input(req, 0);
  req.params.check_all_used();
  RunPlan p;
  p.call = morph_call(req.kernel, a.width, a.height, a.width, a.width, a.data, "run");
  const int w = a.width, h = a.height;
  p.write = [w, h](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    Image out(w, h);
    out.data = bufs[1];
    write_image(path, out);
  };
  p.summary = size_name(w, h);
  return p;
}

const Family kMorph{"morph", {"erode3x3_u8", "dilate3x3_u8"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kMorph);

}  // namespace
}  // namespace bvb
