// Check, bench and run for bvb/add_sat.h.
#include "bvb/add_sat.h"

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "names.h"

namespace bvb {
namespace {

CheckCall add_sat_call(int w, int h, int sstride, int dstride, std::vector<uint8_t> a,
                       std::vector<uint8_t> b, const std::string &case_name) {
  CheckCall c;
  c.kernel = "add_sat_u8";
  c.case_name = case_name;
  c.pixels = double(w) * h;
  const View src{1, false, w, h, sstride}, dst{1, false, w, h, dstride};
  int ia = c.in("a", std::move(a), src);
  int ib = c.in("b", std::move(b), src);
  int id = c.out("dst", size_t(dstride) * (h - 1) + w, dst);
  int is = c.scratch("scratch", BVB_ADD_SAT_U8_SCRATCH_BYTES(w));
  c.buf(ia).buf(ib).buf(id).word(w).word(h).word(sstride).word(dstride).buf(is);
  c.host = [=](HostBuffers &m) {
    bvb_add_sat_u8_c(m.u8(ia), m.u8(ib), m.u8(id), w, h, sstride, dstride, m.u8(is));
  };
  return c;
}

void check(Checker &ck) {
  Rng &rng = ck.rng();
  for (Size s : check_sizes(1, 1, rng, ck.options().campaign)) {
    for (Pattern pa : ck.patterns()) {
      const Pattern pb = ck.patterns()[rng.uniform(0, int(ck.patterns().size()) - 1)];
      const int ss = pick_stride(s.w, rng), ds = pick_stride(s.w, rng);
      std::string name = size_name(s.w, s.h) + " strides " +
                         std::to_string(ss) + "/" + std::to_string(ds) + " " + pattern_name(pa) + "+" +
                         pattern_name(pb);
      CheckCall c = add_sat_call(s.w, s.h, ss, ds, make_plane(pa, s.w, s.h, ss, rng, ck.options().frames_real),
                                 make_plane(pb, s.w, s.h, ss, rng, ck.options().frames_real), name);
      // Unaligned rows: the kernel has no alignment contract (the scratch is 4-byte aligned).
      for (auto &b : c.bufs)
        if (b.role != Role::Scratch) b.skew = uint32_t(rng.uniform(0, 3));
      // Half the calls as the robot runs it: frames in SDRAM, row bands through the scratch.
      ck.place_streaming(c, 3, rng);
      ck.add(std::move(c));
    }
  }
}

CheckCall bench_call(const std::string &, int w, int h, Rng &rng) {
  CheckCall c = add_sat_call(w, h, w, w, make_plane(Pattern::Noise, w, h, w, rng, ""),
                             make_plane(Pattern::Noise, w, h, w, rng, ""), size_name(w, h));
  c.bufs[3].place = BVB_PLACE_L1B;  // frames in SDRAM, the band buffers in L1
  return c;
}

// The larger of the compute (two byte loads and a byte store per pixel, one issue does two loads
// or a load and a store: 1.5 cycles) and the bus (1 + 1 bytes in, 1 out per pixel at 0.5 byte
// per core cycle, bvb/dma.h: 6 cycles): the bus.
double lower_bound(const std::string &, int w, int h) { return 6.0 * w * h; }

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 2) throw InputError("add_sat_u8 takes two --in frames");
  Image a = read_input(req, 0);
  Image b = read_input(req, 1);
  if (a.width != b.width || a.height != b.height) throw InputError("add_sat_u8: the two frames differ in size");
  req.params.check_all_used();
  RunPlan p;
  p.call = add_sat_call(a.width, a.height, a.width, a.width, a.data, b.data, "run");
  const int w = a.width, h = a.height;
  p.write = [w, h](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    Image out(w, h);
    out.data = bufs[2];
    write_image(path, out);
  };
  p.summary = size_name(w, h);
  return p;
}

const Family kAddSat{"add_sat", {"add_sat_u8"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kAddSat);

}  // namespace
}  // namespace bvb
