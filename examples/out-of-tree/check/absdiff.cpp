// The harness side of absdiff.h: how bfbench checks absdiff_u8 against its C reference, which
// call it benchmarks, and how it runs on files (bfbench-absdiff run absdiff_u8 --in A --in B
// --out D). The Family is registered with BVB_FAMILY, as the tree's own families are.
#include "absdiff.h"

#include "family.h"
#include "io.h"
#include "patterns.h"

namespace {

using namespace bvb;

CheckCall absdiff_call(int w, int h, int sstride, int dstride, std::vector<uint8_t> a, std::vector<uint8_t> b,
                       const std::string &case_name) {
  CheckCall c;
  c.kernel = "absdiff_u8";
  c.case_name = case_name;
  c.pixels = double(w) * h;
  const View src{1, false, w, h, sstride}, dst{1, false, w, h, dstride};
  const int ia = c.in("a", std::move(a), src);
  const int ib = c.in("b", std::move(b), src);
  const int id = c.out("dst", size_t(dstride) * (h - 1) + w, dst);
  c.buf(ia).buf(ib).buf(id).word(w).word(h).word(sstride).word(dstride);
  c.host = [=](HostBuffers &m) { absdiff_u8_c(m.u8(ia), m.u8(ib), m.u8(id), w, h, sstride, dstride); };
  return c;
}

// Every size check_sizes gives, every pattern against a random other (equal frames, a 0 against
// a 255, ramps crossing each other), padded strides, rows at every byte alignment, buffers
// anywhere in L1 or SDRAM.
void check(Checker &ck) {
  Rng &rng = ck.rng();
  for (Size s : check_sizes(1, 1, rng, ck.options().campaign)) {
    for (Pattern pa : ck.patterns()) {
      const Pattern pb = ck.patterns()[rng.uniform(0, int(ck.patterns().size()) - 1)];
      const int ss = pick_stride(s.w, rng), ds = pick_stride(s.w, rng);
      const std::string name = std::to_string(s.w) + "x" + std::to_string(s.h) + " strides " + std::to_string(ss) +
                               "/" + std::to_string(ds) + " " + pattern_name(pa) + "-" + pattern_name(pb);
      CheckCall c = absdiff_call(s.w, s.h, ss, ds, make_plane(pa, s.w, s.h, ss, rng, ck.options().frames_real),
                                 make_plane(pb, s.w, s.h, ss, rng, ck.options().frames_real), name);
      for (auto &b : c.bufs) b.skew = uint32_t(rng.uniform(0, 3));
      ck.place_randomly(c);
      ck.add(std::move(c));
    }
  }
}

// Two noise frames in SDRAM, as a camera's frames would be.
CheckCall bench_call(const std::string &, int w, int h, Rng &rng) {
  return absdiff_call(w, h, w, w, make_plane(Pattern::Noise, w, h, w, rng, ""),
                      make_plane(Pattern::Noise, w, h, w, rng, ""), std::to_string(w) + "x" + std::to_string(h));
}

// The bus: 2 bytes in and 1 out per pixel at 0.5 byte per core cycle (bvb/dma.h).
double lower_bound(const std::string &, int w, int h) { return 6.0 * w * h; }

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 2) throw InputError("absdiff_u8 takes two --in frames");
  Image a = read_input(req, 0), b = read_input(req, 1);
  if (a.width != b.width || a.height != b.height) throw InputError("absdiff_u8: the two frames differ in size");
  req.params.check_all_used();
  const int w = a.width, h = a.height;
  RunPlan p;
  p.call = absdiff_call(w, h, w, w, a.data, b.data, "run");
  p.write = [w, h](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    Image out(w, h);
    out.data = bufs[2];
    write_image(path, out);
  };
  p.summary = std::to_string(w) + "x" + std::to_string(h);
  return p;
}

const Family kAbsdiff{"absdiff", {"absdiff_u8"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kAbsdiff);

}  // namespace
