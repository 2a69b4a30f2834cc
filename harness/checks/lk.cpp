// Check, bench and run for bvb/lk.h: lk_pyramid and lk_track (C and assembly).
//
// lk_track's bench: 32 Harris corners of a real frame (Grove2 frame10, cropped; a synthetic
// texture if the frames are missing) tracked into the next frame (frame11, real motion up to
// 5 px) with 3 levels, 7x7 windows and BVB_LK_FIXED_ITER at 10 iterations. Its "pixels" are the
// work count features x window pixels x iterations x levels (32 x 49 x 10 x 3 = 47040), so the
// c/px columns are cycles per window pixel per iteration; the count is nominal (a level skipped
// or a feature lost does less).
#include "bvb/lk.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

#include "bvb/harris.h"
#include "family.h"
#include "io.h"
#include "patterns.h"
#include "formats.h"
#include "names.h"

namespace bvb {
namespace {

int max_levels(int w, int h) {
  int l = 1;
  while (l < BVB_LK_MAX_LEVELS && (w >> l) >= 1 && (h >> l) >= 1) ++l;
  return l;
}

// ---- lk_pyramid ----

CheckCall pyramid_call(int w, int h, int stride, int levels, std::vector<uint8_t> src, const std::string &name) {
  CheckCall c;
  c.kernel = "lk_pyramid";
  c.case_name = name;
  const size_t bytes = bvb_lk_pyramid_bytes(w, h, levels);
  c.pixels = std::max<double>(1, double(bytes));
  int is = c.in("src", std::move(src), View{1, false, w, h, stride});
  int ip = c.out("pyr", std::max<size_t>(bytes, 4), View{1, false});
  int ic = c.scratch("scratch", BVB_LK_PYRAMID_SCRATCH_BYTES(w));
  c.buf(is).word(w).word(h).word(stride).word(levels).buf(ip).buf(ic);
  c.host = [=](HostBuffers &m) {
    bvb_lk_pyramid_streamed_c(m.u8(is), w, h, stride, levels, m.u8(ip), m.u8(ic));
  };
  return c;
}

std::vector<uint8_t> host_pyramid(const std::vector<uint8_t> &img, int w, int h, int stride, int levels) {
  std::vector<uint8_t> p(std::max<size_t>(bvb_lk_pyramid_bytes(w, h, levels), 4));
  bvb_lk_pyramid_c(img.data(), w, h, stride, levels, p.data());
  return p;
}

// ---- lk_track ----

struct TrackSetup {
  int w, h, stride;
  std::vector<uint8_t> prev, next;
  bvb_lk_params params;
  std::vector<int32_t> features;  // x, y pairs, Q16
};

CheckCall track_call(const TrackSetup &t, const std::string &name) {
  CheckCall c;
  c.kernel = "lk_track";
  c.case_name = name;
  const bvb_lk_params &p = t.params;
  c.pixels = double(p.count) * p.win_w * p.win_h * p.max_iter * p.levels;
  const int w = t.w, h = t.h, stride = t.stride;
  const View frame{1, false, w, h, stride};
  int ia = c.in("prev", t.prev, frame);
  int ipa = c.in("prev_pyr", host_pyramid(t.prev, w, h, stride, p.levels));
  int ib = c.in("next", t.next, frame);
  int ipb = c.in("next_pyr", host_pyramid(t.next, w, h, stride, p.levels));
  std::vector<int32_t> pw = {p.levels, p.win_w, p.win_h, p.max_iter, p.eps_q16, p.min_det, p.flags, p.count};
  int ip = c.in("params", as_bytes(pw), View{4, true});
  std::vector<int32_t> feats = t.features;
  if (feats.empty()) feats.assign(2, 0);
  int ii = c.in("in", as_bytes(feats), View{4, true, 2, std::max(1, p.count), 2});
  int io = c.out("out", size_t(std::max(1, p.count)) * BVB_LK_OUT_WORDS * 4,
                 View{4, true, BVB_LK_OUT_WORDS, std::max(1, p.count), BVB_LK_OUT_WORDS});
  int is = c.scratch("scratch", BVB_LK_SCRATCH_BYTES);
  c.buf(ia).buf(ipa).buf(ib).buf(ipb).word(w).word(h).word(stride).buf(ip).buf(ii).buf(io).buf(is);
  c.host = [=](HostBuffers &m) {
    bvb_lk_track_c(m.u8(ia), m.u8(ipa), m.u8(ib), m.u8(ipb), w, h, stride, m.as<bvb_lk_params>(ip), m.s32(ii),
                   m.s32(io), m.u8(is));
  };
  return c;
}

// The frame moved by (dx, dy) pixels, bilinear (borders clamped): a pair with known motion.
std::vector<uint8_t> shifted(const std::vector<uint8_t> &src, int w, int h, int stride, double dx, double dy) {
  std::vector<uint8_t> out = src;
  auto at = [&](int x, int y) {
    x = std::min(std::max(x, 0), w - 1);
    y = std::min(std::max(y, 0), h - 1);
    return double(src[size_t(y) * stride + x]);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double sx = x - dx, sy = y - dy;
      const int ix = int(std::floor(sx)), iy = int(std::floor(sy));
      const double fx = sx - ix, fy = sy - iy;
      const double v = (1 - fy) * ((1 - fx) * at(ix, iy) + fx * at(ix + 1, iy)) +
                       fy * ((1 - fx) * at(ix, iy + 1) + fx * at(ix + 1, iy + 1));
      out[size_t(y) * stride + x] = uint8_t(std::lround(v));
    }
  return out;
}

int odd_window(Rng &rng) { return 2 * rng.uniform(1, BVB_LK_MAX_HALF) + 1; }

void check(Checker &ck) {
  Rng &rng = ck.rng();
  const std::string &frames = ck.options().frames_real;
  {
    for (Size s : check_sizes(1, 1, rng, ck.options().campaign)) {
      for (Pattern p : ck.patterns()) {
        const int stride = pick_stride(s.w, rng);
        const int levels = rng.uniform(1, max_levels(s.w, s.h));
        CheckCall c = pyramid_call(s.w, s.h, stride, levels, make_plane(p, s.w, s.h, stride, rng, frames),
                                   size_name(s.w, s.h) + " stride " +
                                       std::to_string(stride) + " levels " + std::to_string(levels) + " " +
                                       pattern_name(p));
        // Half the calls as the robot runs it: the frame and the levels in SDRAM, the bands
        // through the scratch in L1.
        ck.place_streaming(c, 2, rng);
        c.bufs[0].skew = uint32_t(rng.uniform(0, 3));  // the frame has no alignment contract
        ck.add(std::move(c));
      }
    }
  }
  {
    for (Size s : check_sizes(1, 1, rng, ck.options().campaign)) {
      for (int variant = 0; variant < 6; ++variant) {
        if (variant < 2 && !ck.have_frames()) {  // the real-frame variants
          ck.skip_real();
          continue;
        }
        TrackSetup t;
        t.w = s.w;
        t.h = s.h;
        t.stride = pick_stride(s.w, rng);
        // Textures that track (real, noise, runs), and ones that do not (zero, ramps, edges).
        static const Pattern kinds[] = {Pattern::Real, Pattern::Real, Pattern::Noise,
                                        Pattern::Runs, Pattern::RampX, Pattern::Edges};
        const Pattern kind = kinds[variant];
        t.prev = make_plane(kind, s.w, s.h, t.stride, rng, frames);
        const double dx = rng.uniform(-4000, 4000) / 1000.0, dy = rng.uniform(-4000, 4000) / 1000.0;
        t.next = variant == 1 ? make_plane(Pattern::Noise, s.w, s.h, t.stride, rng, frames)  // no relation
                              : shifted(t.prev, s.w, s.h, t.stride, dx, dy);
        bvb_lk_params &p = t.params;
        p.levels = rng.uniform(1, std::min(4, max_levels(s.w, s.h)));
        p.win_w = odd_window(rng);
        p.win_h = rng.uniform(0, 2) == 0 ? p.win_w : odd_window(rng);
        p.max_iter = rng.uniform(1, 12);
        p.eps_q16 = rng.uniform(0, 3) == 0 ? 0 : rng.uniform(100, 3000);
        p.min_det = rng.uniform(0, 2) == 0 ? 0 : rng.uniform(1, 400);
        p.flags = rng.uniform(0, 2) == 0 ? BVB_LK_FIXED_ITER : 0;
        p.count = rng.uniform(0, 5) == 0 ? rng.uniform(0, 2) : rng.uniform(3, 12);
        for (int f = 0; f < p.count; ++f) {
          // Mostly inside, some near and beyond the borders; any sub-pixel phase.
          const int margin = rng.uniform(0, 3) == 0 ? -3 : 2;
          const int x0 = margin, x1 = std::max(x0, s.w - 1 - margin), y0 = margin, y1 = std::max(y0, s.h - 1 - margin);
          t.features.push_back(rng.uniform(x0 * 65536, x1 * 65536));
          t.features.push_back(rng.uniform(y0 * 65536, y1 * 65536));
        }
        char name[200];
        std::snprintf(name, sizeof name, "%dx%d stride %d %s%s shift %.3f,%.3f levels %d win %dx%d iter %d%s eps %d det %d, %d features",
                      s.w, s.h, t.stride, pattern_name(kind), variant == 1 ? "/noise" : "", dx, dy, p.levels, p.win_w,
                      p.win_h, p.max_iter, p.flags ? " fixed" : "", p.eps_q16, p.min_det, p.count);
        CheckCall c = track_call(t, name);
        if (rng.uniform(0, 1) == 0) {
          // As the robot runs it: frames and levels in SDRAM, the scratch in L1 at any word of a
          // 4 KB sub-bank, so that the level copies (by DMA) and the windows that leave them
          // are taken.
          c.bufs[7].place = BVB_PLACE_L1B;
          c.bufs[7].align = 4096;
          c.bufs[7].skew = uint32_t(4 * rng.uniform(0, 1023));
          c.case_name += " frames SDRAM";
        } else {
          ck.place_randomly(c);
        }
        for (int b : {0, 2}) c.bufs[b].skew = uint32_t(rng.uniform(0, 3));
        ck.add(std::move(c));
      }
    }
  }
}

// ---- bench ----

// The bench pair: the integer texture (patterns.h) and the same texture moved by (2.3, -1.4)
// pixels, sampled exactly (not interpolated): the same bytes on every host, so that the budgets
// depend on nothing outside the repository.
void bench_pair(int w, int h, std::vector<uint8_t> &a, std::vector<uint8_t> &b) {
  const uint64_t seed = 0x4C4B545241434B01ull;
  a = hermetic_texture(w, h, seed).data;
  b = hermetic_texture(w, h, seed, 589, -358).data;  // 2.3 and -1.4 px in 1/256 px
}

// The n strongest Harris corners at least 8 pixels apart (the C references of bvb/harris.h).
std::vector<int32_t> corners(const std::vector<uint8_t> &img, int w, int h, int n) {
  std::vector<int32_t> resp(size_t(w) * h);
  std::vector<uint8_t> scr(BVB_HARRIS_SCRATCH_BYTES(w));
  bvb_harris_response_c(img.data(), resp.data(), w, h, w, w, scr.data());
  int32_t maxv = 0;
  for (int32_t v : resp) maxv = std::max(maxv, v);
  std::vector<int32_t> cand(size_t(BVB_HARRIS_NMS_CAPACITY(w, h) + 1) * 2), out(size_t(n) * 3);
  int32_t count = 0;
  bvb_harris_nms_c(resp.data(), w, h, w, maxv / 100, cand.data(), &count, nullptr);
  const int taken = bvb_harris_select_c(cand.data(), count, n, 8, out.data());
  std::vector<int32_t> f;
  for (int k = 0; k < taken; ++k) {
    f.push_back(out[3 * k] << 16);
    f.push_back(out[3 * k + 1] << 16);
  }
  return f;
}

CheckCall bench_call(const std::string &kernel, int w, int h, Rng &) {
  const std::string size = size_name(w, h);
  TrackSetup t;
  t.w = w;
  t.h = h;
  t.stride = w;
  bench_pair(w, h, t.prev, t.next);
  if (kernel == "lk_pyramid") {
    CheckCall c = pyramid_call(w, h, w, 3, t.prev, size);
    c.bufs[2].place = BVB_PLACE_L1B;  // the frame and the levels in SDRAM, the bands in L1
    return c;
  }
  t.features = corners(t.prev, w, h, 32);
  bvb_lk_params &p = t.params;
  p.levels = 3;
  p.win_w = p.win_h = 7;
  p.max_iter = 10;
  p.eps_q16 = 655;
  p.min_det = 1;
  p.flags = BVB_LK_FIXED_ITER;
  p.count = int32_t(t.features.size() / 2);
  CheckCall c = track_call(t, size);
  c.pixels = 32.0 * 49 * 10 * 3;
  // Frames and levels in SDRAM, the scratch in L1 across a 4 KB sub-bank boundary, where a
  // caller with room puts it (bvb_lk_scratch_place; the odometry does): the iteration's two
  // groups of arrays on either side, the level copies beside the template.
  c.bufs[7].place = BVB_PLACE_L1B;
  c.bufs[7].align = 4096;
  c.bufs[7].skew = 2048;
  return c;
}

// lk_pyramid: per output pixel four input bytes; BYTEOP2P averages two outputs' 2x2 blocks per
// issue and BYTEPACK packs four outputs: 0.75 issues per output pixel. With the frame and the
// levels in SDRAM the bus is the bound: the frame's 2 (h >> 1) w bytes in and the levels' bytes
// out at 0.5 byte per core cycle (bvb/dma.h): 8.4 cycles per level byte at 3 levels.
// lk_track: per window pixel per iteration the bilinear sample (4 products: 2 dual-MAC issues),
// the difference (half a vector subtract) and b (2 products: 1 issue): 3.5 issues per work unit,
// not counting the per-level template work.
double lower_bound(const std::string &kernel, int w, int h) {
  if (kernel == "lk_pyramid") {
    double out = 0;
    for (int l = 1; l < 3; ++l) out += double(w >> l) * (h >> l);
    return std::max(0.75 * double(bvb_lk_pyramid_bytes(w, h, 3)), 2.0 * (2.0 * (h >> 1) * w + out));
  }
  return 3.5 * 32 * 49 * 10 * 3;
}

RunPlan plan_run(RunRequest &req) {
  RunPlan p;
  if (req.kernel == "lk_pyramid") {
    if (req.inputs.size() != 1) throw InputError("lk_pyramid takes one --in frame");
    Image a = read_input(req, 0);
    const int levels = req.params.get_int("levels", 3, 1, BVB_LK_MAX_LEVELS);
    req.params.check_all_used();
    if (levels > max_levels(a.width, a.height)) throw InputError("lk_pyramid: the frame is too small for that many levels");
    const int w = a.width, h = a.height;
    p.call = pyramid_call(w, h, w, levels, a.data, "run");
    // The top level as a PGM.
    p.write = [w, h, levels](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
      const int l = levels - 1, lw = w >> l, lh = h >> l;
      Image out(lw, lh);
      const uint8_t *src = bufs[1].data() + bvb_lk_level_offset(w, h, l);
      const int s = l == 0 ? w : BVB_LK_LEVEL_STRIDE(lw);
      for (int y = 0; y < lh; ++y)
        for (int x = 0; x < lw; ++x) out.at(x, y) = l == 0 ? bufs[0][size_t(y) * w + x] : src[size_t(y) * s + x];
      write_image(path, out);
    };
    p.summary = size_name(w, h) + ", level " + std::to_string(levels - 1) + " written";
    return p;
  }
  if (req.inputs.size() != 2) throw InputError("lk_track takes two --in frames (previous, next)");
  Image a = read_input(req, 0);
  Image b = read_input(req, 1);
  if (a.width != b.width || a.height != b.height) throw InputError("lk_track: the two frames differ in size");
  TrackSetup t;
  t.w = a.width;
  t.h = a.height;
  t.stride = a.width;
  t.prev = a.data;
  t.next = b.data;
  bvb_lk_params &pr = t.params;
  pr.levels = req.params.get_int("levels", 3, 1, BVB_LK_MAX_LEVELS);
  pr.win_w = pr.win_h = req.params.get_int("window", 7, 3, 2 * BVB_LK_MAX_HALF + 1) | 1;
  pr.max_iter = req.params.get_int("iterations", 10, 1, 100);
  pr.eps_q16 = req.params.get_int("eps_q16", 655, 0, 1 << 20);
  pr.min_det = req.params.get_int("min_det", 1, 0, 1 << 20);
  pr.flags = 0;
  const int n = req.params.get_int("features", 32, 1, 1000);
  req.params.check_all_used();
  if (pr.levels > max_levels(t.w, t.h)) throw InputError("lk_track: the frames are too small for that many levels");
  if (t.w < 5 || t.h < 5) throw InputError("lk_track: the frames must be at least 5x5");
  t.features = corners(t.prev, t.w, t.h, n);
  pr.count = int32_t(t.features.size() / 2);
  p.call = track_call(t, "run");
  const std::vector<int32_t> feats = t.features;
  // One line per feature: where it was, where it went, status, iterations.
  p.write = [feats](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    const int32_t *o = reinterpret_cast<const int32_t *>(bufs[6].data());
    static const char *names[] = {"tracked", "left", "flat", "not-converged"};
    std::string text = "# x0 y0 x1 y1 status iterations\n";
    for (size_t k = 0; k < feats.size() / 2; ++k) {
      const int32_t *r = o + k * BVB_LK_OUT_WORDS;
      char line[160];
      std::snprintf(line, sizeof line, "%.4f %.4f %.4f %.4f %s %d\n", feats[2 * k] / 65536.0, feats[2 * k + 1] / 65536.0,
                    r[0] / 65536.0, r[1] / 65536.0, r[2] >= 0 && r[2] <= 3 ? names[r[2]] : "?", r[3]);
      text += line;
    }
    write_text_output(path, text);
  };
  p.kind = OutputKind::Text;
  p.summary = size_name(t.w, t.h) + ", " + std::to_string(pr.count) + " Harris corners tracked";
  return p;
}

const Family kLk{"lk", {"lk_pyramid", "lk_track"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kLk);

}  // namespace
}  // namespace bvb
