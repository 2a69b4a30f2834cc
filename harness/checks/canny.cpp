// Check, bench and run for bvb/canny.h. The gradients come from a local 3x3 Sobel (the Sobel
// kernel's contract: raw responses, outer ring 0), or are drawn directly.
#include "bvb/canny.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "robot_view.h"
#include "names.h"

namespace bvb {
namespace {

struct Gradients {
  std::vector<int16_t> gx, gy;  // stride gs elements; padding holds junk
  int gs = 0;
};

// Raw Sobel responses of an 8-bit plane, the outer ring 0.
Gradients sobel(const uint8_t *img, int w, int h, int stride, int gs, Rng &rng) {
  Gradients g;
  g.gs = gs;
  const size_t n = size_t(gs) * (h - 1) + w;
  g.gx.resize(n);
  g.gy.resize(n);
  for (size_t i = 0; i < n; ++i) g.gx[i] = int16_t(rng.u32()), g.gy[i] = int16_t(rng.u32());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int sx = 0, sy = 0;
      if (x > 0 && y > 0 && x < w - 1 && y < h - 1) {
        auto p = [&](int dx, int dy) { return int(img[(y + dy) * stride + x + dx]); };
        sx = p(1, -1) + 2 * p(1, 0) + p(1, 1) - p(-1, -1) - 2 * p(-1, 0) - p(-1, 1);
        sy = p(-1, 1) + 2 * p(0, 1) + p(1, 1) - p(-1, -1) - 2 * p(0, -1) - p(1, -1);
      }
      g.gx[size_t(y) * gs + x] = int16_t(sx);
      g.gy[size_t(y) * gs + x] = int16_t(sy);
    }
  return g;
}

// Gradients drawn at random (the ring too): every sector, sign and tie the kernel can meet.
// `levels` > 0 draws multiples of 1020 / levels, which makes equal magnitudes common.
Gradients random_gradients(int w, int h, int gs, int levels, Rng &rng) {
  Gradients g;
  g.gs = gs;
  const size_t n = size_t(gs) * (h - 1) + w;
  g.gx.resize(n);
  g.gy.resize(n);
  for (size_t i = 0; i < n; ++i) {
    if (levels > 0) {
      g.gx[i] = int16_t(rng.uniform(-levels, levels) * (1020 / levels));
      g.gy[i] = int16_t(rng.uniform(-levels, levels) * (1020 / levels));
    } else {
      g.gx[i] = int16_t(rng.uniform(-1020, 1020));
      g.gy[i] = int16_t(rng.uniform(-1020, 1020));
    }
  }
  return g;
}

// The firmware gets `stack_cap` stack entries; the host reference always gets a stack that
// never fills, so a run that overflowed must still give the same edge map.
CheckCall canny_call(const Gradients &g, int w, int h, int es, int low, int high, int stack_cap,
                     const std::string &case_name) {
  CheckCall c;
  c.kernel = "canny";
  c.case_name = case_name;
  c.pixels = double(w) * h;
  const int gs = g.gs;
  const View gv{2, true, w, h, gs};
  int igx = c.in("gx", as_bytes(g.gx), gv);
  int igy = c.in("gy", as_bytes(g.gy), gv);
  int ie = c.out("edges", size_t(es) * (h - 1) + w, View{1, false, w, h, es});
  int im = c.scratch("mag_rows", size_t(BVB_CANNY_MAG_ROWS(w)) * 2);
  int is = c.scratch("stack", size_t(std::max(stack_cap, 1)) * 4);
  c.buf(igx).buf(igy).word(gs).buf(ie).word(es).word(w).word(h).word(low).word(high).buf(im).buf(is).word(stack_cap);
  c.host = [=](HostBuffers &m) {
    std::vector<uint16_t> mag(size_t(BVB_CANNY_MAG_ROWS(w)));
    std::vector<int32_t> stack(size_t(std::max(BVB_CANNY_STACK_ENTRIES(w, h), 1)));
    bvb_canny_c(m.s16(igx), m.s16(igy), gs, m.u8(ie), es, w, h, low, high, mag.data(), stack.data(),
                BVB_CANNY_STACK_ENTRIES(w, h));
  };
  return c;
}

// Skews each buffer as its element type allows, then places them all together.
void place_buffers(Checker &ck, CheckCall &c, Rng &rng) {
  for (auto &b : c.bufs) {
    // Elements keep their natural alignment; byte planes may start anywhere.
    if (b.name == "edges") b.skew = uint32_t(rng.uniform(0, 3));
    if (b.name == "gx" || b.name == "gy" || b.name == "mag_rows") b.skew = uint32_t(2 * rng.uniform(0, 1));
  }
  ck.place_randomly(c);
}

void check(Checker &ck) {
  Rng &rng = ck.rng();
  const bool campaign = ck.options().campaign;
  for (Size s : check_sizes(1, 1, rng, campaign)) {
    for (Pattern pat : ck.patterns()) {
      const int ss = pick_stride(s.w, rng), gs = pick_stride(s.w, rng), es = pick_stride(s.w, rng);
      Gradients g;
      std::string src;
      const int kind = rng.uniform(0, 5);
      if (kind == 0) {
        const int levels = rng.uniform(0, 1) ? 0 : rng.uniform(1, 4);
        g = random_gradients(s.w, s.h, gs, levels, rng);
        src = "random gradients" + (levels ? " (" + std::to_string(levels) + " levels)" : std::string());
      } else {
        auto plane = make_plane(pat, s.w, s.h, ss, rng, ck.options().frames_real);
        g = sobel(plane.data(), s.w, s.h, ss, gs, rng);
        src = std::string("sobel of ") + pattern_name(pat);
      }
      // Thresholds mostly relative to the frame's largest interior magnitude, so that ramps and
      // real frames have edges too; sometimes absolute, equal, or the lowest legal.
      int top = 1;
      for (int y = 1; y < s.h - 1; ++y)
        for (int x = 1; x < s.w - 1; ++x)
          top = std::max(top, std::abs(g.gx[size_t(y) * gs + x]) + std::abs(g.gy[size_t(y) * gs + x]));
      int low, high;
      if (rng.uniform(0, 3) == 0) {
        low = rng.uniform(1, 300), high = low + rng.uniform(0, 600);
      } else {
        low = rng.uniform(1, std::max(1, top * 3 / 5)), high = low + rng.uniform(0, top);
      }
      if (rng.uniform(0, 7) == 0) low = high = rng.uniform(1, 2040);
      if (rng.uniform(0, 7) == 0) low = 1;
      const int full = BVB_CANNY_STACK_ENTRIES(s.w, s.h);
      // A stack of a few entries, or none at all, makes the raster fallback do the linking; on
      // large frames that takes many passes, so only small frames get it.
      const int r = rng.uniform(0, 3);
      const int cap = r == 0 && s.w * s.h <= 4096 ? rng.uniform(0, 8)
                      : r <= 1                    ? rng.uniform(1, std::max(full / 16, 1))
                                                  : full;
      std::string name = size_name(s.w, s.h) + " strides " + std::to_string(gs) +
                         "/" + std::to_string(es) + " " + src + " low " + std::to_string(low) + " high " +
                         std::to_string(high) + " stack " + std::to_string(cap);
      CheckCall c = canny_call(g, s.w, s.h, es, low, high, cap, name);
      place_buffers(ck, c, rng);
      ck.add(std::move(c));
    }
  }
  // The robot's own view, whole frames at the camera's sizes.
  for (Size s : std::vector<Size>{{160, 120}, {80, 60}, {161, 121}}) {
    for (int pose = 0; pose < 4; ++pose) {
      const Image &grey = robot_view(s.w, s.h, pose).grey;
      Gradients g = sobel(grey.data.data(), s.w, s.h, s.w, s.w, rng);
      const int cap = pose == 3 ? 4 : BVB_CANNY_STACK_ENTRIES(s.w, s.h);
      CheckCall c = canny_call(g, s.w, s.h, s.w, 60, 160, cap,
                               size_name(s.w, s.h) + " robot view " +
                                   std::to_string(pose) + " stack " + std::to_string(cap));
      ck.add(std::move(c));
    }
  }
}

// Thresholds for the benches and for bfbench run's defaults: on the robot's 8-bit frames an L1
// Sobel magnitude of 160 is a clear object edge, 60 the texture of the floor.
constexpr int kLow = 60, kHigh = 160;

CheckCall bench_call(const std::string &, int w, int h, Rng &rng) {
  const Image &grey = robot_view(w, h, 0).grey;
  Gradients g = sobel(grey.data.data(), w, h, w, w, rng);
  return canny_call(g, w, h, w, kLow, kHigh, BVB_CANNY_STACK_ENTRIES(w, h),
                    size_name(w, h));
}

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError("canny takes one --in frame (its Sobel gradients are computed on the host)");
  Image img = read_input(req, 0);
  const int low = req.params.get_int("low", kLow, 1, 2040);
  const int high = req.params.get_int("high", std::max(kHigh, low), low, 65535);
  const int w = img.width, h = img.height;
  const int full = BVB_CANNY_STACK_ENTRIES(w, h);
  const int cap = req.params.get_int("stack", full, 0, std::max(full, 0));
  req.params.check_all_used();
  Rng rng(1);
  Gradients g = sobel(img.data.data(), w, h, w, w, rng);
  RunPlan p;
  p.call = canny_call(g, w, h, w, low, high, cap, "run");
  p.write = [w, h](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    Image out(w, h);
    out.data = bufs[2];
    write_image(path, out);
  };
  p.summary = size_name(w, h) + " low " + std::to_string(low) + " high " +
              std::to_string(high) + " stack " + std::to_string(cap);
  return p;
}

const Family kCanny{"canny", {"canny"}, check, bench_call, nullptr, plan_run};
BVB_FAMILY(kCanny);

}  // namespace
}  // namespace bvb
