// Check, bench and run for bvb/hornschunck.h: hs_prepare (derivatives and coefficients),
// hs_iterate (one Jacobi iteration), hs_iterate_n (N iterations, fused) and hornschunck
// (prepare plus N iterations).
//
// Bench cases: hs_prepare and hs_iterate are one call on a w x h frame (c/px per frame pixel;
// hs_iterate is one iteration). hs_iterate_n runs N = 10 iterations in one call, and its c/px is
// per frame pixel per iteration (the call's cycles over 10 w h), as the case name
// "WxH N=10, per iteration" says. hornschunck runs N = 10 iterations, and its c/px is per frame
// pixel for the whole call (prepare + 10 iterations), as the case name "WxH N=10" says.
#include "bvb/hornschunck.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "formats.h"
#include "names.h"

namespace bvb {
namespace {

// The C reference at 640x480 with 10 iterations takes about 1.1e9 cycles (prepare ~330 c/px,
// each iteration ~300 c/px), past the default watchdog.
constexpr uint32_t kLongCallLimit = 2000000000u;
constexpr int kBenchIterations = 10;

struct FramePair {
  std::vector<uint8_t> f1, f2;  // stride * (h - 1) + w bytes each
  std::string name;
};

// Bilinear sample of a w x h image at (x, y), coordinates clamped to the frame.
double sample(const Image &img, double x, double y) {
  x = std::min(std::max(x, 0.0), double(img.width - 1));
  y = std::min(std::max(y, 0.0), double(img.height - 1));
  const int x0 = int(x), y0 = int(y);
  const int x1 = std::min(x0 + 1, img.width - 1), y1 = std::min(y0 + 1, img.height - 1);
  const double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * img.at(x0, y0) + fx * img.at(x1, y0)) +
         fy * ((1 - fx) * img.at(x0, y1) + fx * img.at(x1, y1));
}

// A crop of a real frame (the caller has made sure the frames are there).
Image real_texture(int w, int h, Rng &rng, const std::string &frames_real) {
  Image img = real_crop(frames_real, w, h, rng);
  if (img.data.empty()) throw std::logic_error("hornschunck: a real-frame pair without the frames");
  return img;
}

// Frame 2 of a warp of the integer texture (hermetic_texture_at): the texture sampled along a
// translation (tx, ty in 1/256 px), rotation (mrad) and zoom (permille) about the centre, in
// integers only, so the pair (and the bench's cycles on it) is the same on every host. cos and
// sin of the small angle are their Taylor polynomials in Q16.
Image warped_texture(int w, int h, uint64_t seed, int64_t tx, int64_t ty, int64_t rot, int64_t zoom) {
  const int64_t c = 65536 - rot * rot * 65536 / 2000000, s = rot * 65536 / 1000 - rot * rot * rot * 65536 / 6000000000LL;
  const int64_t cx = int64_t(w - 1) * 128, cy = int64_t(h - 1) * 128;  // the centre in 1/256 px
  Image b(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // I2(x) = I1(x - d(x)): the content moves by about (tx, ty) plus the rotation and zoom.
      const int64_t dx = int64_t(x) * 256 - cx, dy = int64_t(y) * 256 - cy;
      const int64_t rx = (dx * c + dy * s) / 65536 * 1000 / zoom, ry = (-dx * s + dy * c) / 65536 * 1000 / zoom;
      b.at(x, y) = hermetic_texture_at(cx + rx - tx, cy + ry - ty, seed);
    }
  return b;
}

std::vector<uint8_t> to_plane(const Image &img, int stride, Rng &rng) {
  std::vector<uint8_t> d(size_t(stride) * (img.height - 1) + img.width);
  for (auto &v : d) v = uint8_t(rng.u32());  // row padding is noise: a kernel reading it shows
  for (int y = 0; y < img.height; ++y)
    std::memcpy(&d[size_t(y) * stride], &img.data[size_t(y) * img.width], size_t(img.width));
  return d;
}

// Frame pairs: frame 2 is frame 1 moved (so the flow means something), unrelated noise, crafted
// patterns, or opposite extremes that drive every derivative to its limit. Warp and Shift move
// the integer texture; RealWarp moves a crop of a real frame and needs the frames.
enum class PairKind { Warp, Shift, Noise, Patterns, Saturate, RealWarp, Count };

// ck: the check's (for its patterns and frames), or null for the bench's hermetic pairs.
FramePair make_pair(PairKind kind, int w, int h, int stride, Rng &rng, Checker *ck) {
  FramePair p;
  const std::string frames_real = ck ? ck->options().frames_real : "";
  switch (kind) {
    case PairKind::Warp: {
      const uint64_t seed = rng.next();
      const int tx = rng.uniform(-768, 768), ty = rng.uniform(-768, 768);
      const int rot = rng.uniform(-30, 30), zoom = 1000 + rng.uniform(-30, 30);
      p.f1 = to_plane(hermetic_texture(w, h, seed), stride, rng);
      p.f2 = to_plane(warped_texture(w, h, seed, tx, ty, rot, zoom), stride, rng);
      p.name = "warp";
      break;
    }
    case PairKind::RealWarp: {
      // Frame 2 samples frame 1 along a smooth motion: translation, rotation and zoom.
      const Image a = real_texture(w, h, rng, frames_real);
      const double tx = rng.uniform(-300, 300) / 100.0, ty = rng.uniform(-300, 300) / 100.0;
      const double rot = rng.uniform(-30, 30) / 1000.0, zoom = 1 + rng.uniform(-30, 30) / 1000.0;
      Image b(w, h);
      const double cx = (w - 1) / 2.0, cy = (h - 1) / 2.0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          // I2(x) = I1(x - d(x)): the content moves by about (tx, ty) plus the rotation/zoom.
          const double dx = x - cx, dy = y - cy;
          const double sx = cx + (dx * std::cos(rot) + dy * std::sin(rot)) / zoom - tx;
          const double sy = cy + (-dx * std::sin(rot) + dy * std::cos(rot)) / zoom - ty;
          b.at(x, y) = uint8_t(std::lround(sample(a, sx, sy)));
        }
      p.f1 = to_plane(a, stride, rng);
      p.f2 = to_plane(b, stride, rng);
      p.name = "real warp";
      break;
    }
    case PairKind::Shift: {
      // Two windows of one larger texture, an integer number of pixels apart.
      const int dx = rng.uniform(-4, 4), dy = rng.uniform(-4, 4);
      const Image big = hermetic_texture(w + 8, h + 8, rng.next());
      Image a(w, h), b(w, h);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          a.at(x, y) = big.at(x + 4, y + 4);
          b.at(x, y) = big.at(x + 4 - dx, y + 4 - dy);
        }
      p.f1 = to_plane(a, stride, rng);
      p.f2 = to_plane(b, stride, rng);
      p.name = "shift " + std::to_string(dx) + "," + std::to_string(dy);
      break;
    }
    case PairKind::Noise:
      p.f1 = make_plane(Pattern::Noise, w, h, stride, rng, frames_real);
      p.f2 = make_plane(Pattern::Noise, w, h, stride, rng, frames_real);
      p.name = "noise";
      break;
    case PairKind::Patterns: {
      if (!ck) throw std::logic_error("hornschunck: pattern pairs are for checks");
      const auto &all = ck->patterns();
      const Pattern pa = all[rng.uniform(0, int(all.size()) - 1)];
      const Pattern pb = all[rng.uniform(0, int(all.size()) - 1)];
      p.f1 = make_plane(pa, w, h, stride, rng, frames_real);
      p.f2 = make_plane(pb, w, h, stride, rng, frames_real);
      p.name = std::string(pattern_name(pa)) + "+" + pattern_name(pb);
      break;
    }
    default: {
      // 0 -> 255 everywhere (gt at its limit), or a checkerboard against its inverse (gt = 0
      // but the largest |gx|, |gy| pattern), or a checkerboard against flat extremes.
      const int v = rng.uniform(0, 2);
      p.f1 = make_plane(v == 0 ? Pattern::Zero : Pattern::Checker, w, h, stride, rng, frames_real);
      p.f2 = make_plane(v == 0 ? Pattern::Max : v == 1 ? Pattern::Checker : Pattern::Max, w, h, stride,
                        rng, frames_real);
      if (v == 1)
        for (auto &b : p.f2) b = uint8_t(255 - b);
      p.name = v == 0 ? "0->255" : v == 1 ? "checker->inverse" : "checker->255";
      break;
    }
  }
  return p;
}

// alpha2_q4 values: the legal range's ends, the project's default (alpha 8), random legal values,
// and out-of-range values the kernels clamp.
int32_t pick_alpha2(Rng &rng) {
  switch (rng.uniform(0, 6)) {
    case 0: return BVB_HS_ALPHA2_Q4_MIN;
    case 1: return BVB_HS_ALPHA2_Q4_MAX;
    case 2: return 16 * 16 * 16;  // alpha 16
    case 3: {
      static const int32_t outside[] = {0, -5, 1, 1023, 1048577, 0x7fffffff, int32_t(0x80000000)};
      return outside[rng.uniform(0, 6)];
    }
    default: return rng.uniform(BVB_HS_ALPHA2_Q4_MIN, BVB_HS_ALPHA2_Q4_MAX);
  }
}


// Coefficients for the iterate checks: the C prepare on a frame pair (what the kernel really
// sees), or any int16 values (the iteration's arithmetic is defined for all of them).
std::vector<int16_t> make_coef(int w, int h, Rng &rng, Checker &ck, std::string *name) {
  std::vector<int16_t> coef(BVB_HS_COEF_BYTES(w, h) / 2);
  const int kind = rng.uniform(0, 3);
  if (kind == 0) {
    for (auto &c : coef) c = int16_t(rng.u32());
    *name = "coef random";
  } else if (kind == 1) {
    const int16_t ext[] = {-32768, 32767, -32767, 0, 1, -1, 16384, -16384};
    for (auto &c : coef) c = ext[rng.uniform(0, 7)];
    *name = "coef extremes";
  } else {
    const int stride = pick_stride(w, rng);
    // Any pair kind; a real frame's only when the frames are there (the name says which).
    const int kinds = int(PairKind::Count) - (ck.have_frames() ? 0 : 1);
    FramePair p = make_pair(PairKind(rng.uniform(0, kinds - 1)), w, h, stride, rng, &ck);
    bvb_hs_prepare_c(p.f1.data(), p.f2.data(), w, h, stride, pick_alpha2(rng), coef.data(), nullptr);
    *name = "coef " + p.name;
  }
  return coef;
}

// A flow field with `stride` bytes per row (padding is noise).
std::vector<int16_t> make_flow(int w, int h, int stride, Rng &rng, std::string *name) {
  std::vector<int16_t> uv(size_t(stride / 2) * h);
  for (auto &v : uv) v = int16_t(rng.u32());
  const int kind = rng.uniform(0, 3);
  int32_t lim = 0;
  switch (kind) {
    case 0: *name = "flow random"; return uv;  // the whole int16 range
    case 1: lim = 20 * 512; *name = "flow +-20px"; break;
    case 2: lim = 2 * 512; *name = "flow +-2px"; break;
    default: *name = "flow extremes"; break;
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < 2 * w; ++x) {
      int16_t &v = uv[size_t(y) * (stride / 2) + x];
      if (kind == 3) {
        const int16_t ext[] = {-32768, 32767, 0};
        v = ext[rng.uniform(0, 2)];
      } else {
        v = int16_t(rng.uniform(-lim, lim));
      }
    }
  return uv;
}

CheckCall prepare_call(int w, int h, int stride, const FramePair &p, int32_t alpha2, const std::string &name) {
  CheckCall c;
  c.kernel = "hs_prepare";
  c.case_name = name;
  c.pixels = double(w) * h;
  c.cycle_limit = kLongCallLimit;
  const View fv{1, false, w, h, stride};
  const int pitch = BVB_HS_COEF_PITCH(w);
  const View cv{2, true, pitch, h, pitch};
  int i1 = c.in("i1", p.f1, fv);
  int i2 = c.in("i2", p.f2, fv);
  int ic = c.out("coef", BVB_HS_COEF_BYTES(w, h), cv);
  int is = c.scratch("scratch", BVB_HS_PREPARE_SCRATCH_BYTES(w));
  c.buf(i1).buf(i2).word(w).word(h).word(stride).word(alpha2).buf(ic).buf(is);
  c.host = [=](HostBuffers &m) {
    bvb_hs_prepare_c(m.u8(i1), m.u8(i2), w, h, stride, alpha2, m.s16(ic), m.u8(is));
  };
  return c;
}

constexpr int kIterFlowScratch = 3, kIterCoefScratch = 4;

// hs_iterate: with `scratches`, buffers 3 and 4 are the streamed path's (as hs_iterate_n's);
// without, both arguments are NULL.
CheckCall iterate_call(int w, int h, const std::vector<int16_t> &coef, const std::vector<int16_t> &uv,
                       int in_stride, int out_stride, bool scratches, const std::string &name) {
  CheckCall c;
  c.kernel = "hs_iterate";
  c.case_name = name;
  c.pixels = double(w) * h;
  c.cycle_limit = kLongCallLimit;
  const int pitch = BVB_HS_COEF_PITCH(w);
  int ic = c.in("coef", as_bytes(coef), {2, true, pitch, h, pitch});
  int iu = c.in("uv_in", as_bytes(uv), {2, true, 2 * w, h, in_stride / 2});
  int io = c.out("uv_out", size_t(out_stride) * (h - 1) + 4 * size_t(w), {2, true, 2 * w, h, out_stride / 2, 2});
  c.buf(ic).buf(iu).word(in_stride).buf(io).word(out_stride).word(w).word(h);
  if (scratches) {
    int fs = c.scratch("flow_scratch", BVB_HS_ITER_FLOW_SCRATCH_BYTES(w));
    int cs = c.scratch("coef_scratch", BVB_HS_ITER_COEF_SCRATCH_BYTES(w));
    c.buf(fs).buf(cs);
    c.host = [=](HostBuffers &m) {
      bvb_hs_iterate_c(m.s16(ic), m.s16(iu), in_stride, m.s16(io), out_stride, w, h, m.u8(fs), m.u8(cs));
    };
  } else {
    c.word(0).word(0);
    c.host = [=](HostBuffers &m) {
      bvb_hs_iterate_c(m.s16(ic), m.s16(iu), in_stride, m.s16(io), out_stride, w, h, nullptr, nullptr);
    };
  }
  return c;
}

// hs_iterate_n: the flow rows' and the coefficient rows' scratches are buffers 3 and 4. With
// in_stride 0 uv holds one row and the word after it, every row of the field.
CheckCall iterate_n_call(int w, int h, const std::vector<int16_t> &coef, const std::vector<int16_t> &uv,
                         int in_stride, int out_stride, int iterations, const std::string &name) {
  CheckCall c;
  c.kernel = "hs_iterate_n";
  c.case_name = name;
  c.pixels = double(w) * h * iterations;  // cycles per pixel per iteration
  c.cycle_limit = kLongCallLimit;
  const int pitch = BVB_HS_COEF_PITCH(w);
  int ic = c.in("coef", as_bytes(coef), {2, true, pitch, h, pitch});
  const View uv_view = in_stride ? View{2, true, 2 * w, h, in_stride / 2} : View{2, true, 2 * w, 1, 2 * w + 2};
  int iu = c.in("uv_in", as_bytes(uv), uv_view);
  int io = c.out("uv_out", size_t(out_stride) * (h - 1) + 4 * size_t(w), {2, true, 2 * w, h, out_stride / 2, 2});
  int fs = c.scratch("flow_scratch", BVB_HS_ITER_FLOW_SCRATCH_BYTES(w));
  int cs = c.scratch("coef_scratch", BVB_HS_ITER_COEF_SCRATCH_BYTES(w));
  c.buf(ic).buf(iu).word(in_stride).buf(io).word(out_stride).word(w).word(h).word(iterations);
  c.buf(fs).buf(cs);
  c.host = [=](HostBuffers &m) {
    bvb_hs_iterate_n_c(m.s16(ic), m.s16(iu), in_stride, m.s16(io), out_stride, w, h, iterations, m.u8(fs),
                       m.u8(cs));
  };
  return c;
}

CheckCall full_call(int w, int h, int stride, const FramePair &p, int32_t alpha2, int iterations,
                    int out_stride, const std::string &name) {
  CheckCall c;
  c.kernel = "hornschunck";
  c.case_name = name;
  c.pixels = double(w) * h;
  c.cycle_limit = kLongCallLimit;
  const View fv{1, false, w, h, stride};
  int i1 = c.in("i1", p.f1, fv);
  int i2 = c.in("i2", p.f2, fv);
  int io = c.out("uv_out", size_t(out_stride) * (h - 1) + 4 * size_t(w), {2, true, 2 * w, h, out_stride / 2, 2});
  int is = c.scratch("scratch", BVB_HS_SCRATCH_BYTES(w, h));
  int fs = c.scratch("flow_scratch", BVB_HS_FLOW_SCRATCH_BYTES(w));
  int cs = c.scratch("coef_scratch", BVB_HS_ITER_COEF_SCRATCH_BYTES(w));
  c.buf(i1).buf(i2).word(w).word(h).word(stride).word(alpha2).word(iterations).buf(io).word(out_stride).buf(is);
  c.buf(fs).buf(cs);
  c.host = [=](HostBuffers &m) {
    bvb_hornschunck_c(m.u8(i1), m.u8(i2), w, h, stride, alpha2, iterations, m.s16(io), out_stride, m.u8(is),
                      m.u8(fs), m.u8(cs));
  };
  return c;
}
// hornschunck as the robot runs it: frames, flow and coefficients in SDRAM, the flow rows'
// scratch in L1 bank B, the coefficient rows' in bank A (prepare's stream and the fused
// iterations' DMA).
constexpr int kFullFlowScratch = 4, kFullCoefScratch = 5;
void place_full_robot(CheckCall &c) {
  c.bufs[kFullFlowScratch].place = BVB_PLACE_L1B;
  c.bufs[kFullCoefScratch].place = BVB_PLACE_L1A;
}

// Frames have no alignment contract; flow, coefficients and scratch are word-aligned.
void place(Checker &ck, CheckCall &c, Rng &rng) {
  for (auto &b : c.bufs) b.skew = b.role == Role::In && b.view.elem == 1 ? uint32_t(rng.uniform(0, 3)) : 0;
  ck.place_randomly(c);
}

// hs_prepare: half the calls as the robot runs it (frames and coefficients in SDRAM, the row
// bands through the scratch in L1), half placed at random (the direct path wherever the stream
// refuses: a scratch in SDRAM or the scratchpad, everything in L1).
constexpr int kPrepareScratch = 3;
void place_prepare(Checker &ck, CheckCall &c, Rng &rng) {
  for (auto &b : c.bufs) b.skew = b.role == Role::In && b.view.elem == 1 ? uint32_t(rng.uniform(0, 3)) : 0;
  ck.place_streaming(c, kPrepareScratch, rng);
}

// hs_iterate (with its scratches) and hs_iterate_n as the robot runs them: frames in SDRAM,
// the flow rows' scratch in L1 bank B and the coefficient rows' in bank A (the DMA path).
void place_iter_robot(CheckCall &c) {
  for (auto &b : c.bufs) b.skew = 0;
  c.bufs[kIterFlowScratch].place = BVB_PLACE_L1B;
  c.bufs[kIterCoefScratch].place = BVB_PLACE_L1A;
  c.case_name += " frames SDRAM";
}

int flow_stride(int w, Rng &rng) { return pick_stride(4 * w, rng, 4); }

void check(Checker &ck) {
  Rng &rng = ck.rng();
  const bool campaign = ck.options().campaign;
  const std::vector<Size> sizes = check_sizes(BVB_HS_MIN_DIM, BVB_HS_MIN_DIM, rng, campaign);
  std::vector<Size> small = sizes;
  // Every width from 2 to 25 on small heights: each way the assembly splits a row (iteration:
  // width - 2 mod 3; prepare: 0 to 5 groups of 4 columns, odd/even group counts, 0-3 columns
  // left over, odd/even width).
  for (int w = 2; w <= 25; ++w) small.push_back({w, rng.uniform(2, 6)});

  // Every kernel's cases are generated whatever -k says (Checker::add filters).
  auto skip = [&](int k) {
    if (PairKind(k) != PairKind::RealWarp || ck.have_frames()) return false;
    ck.skip_real();
    return true;
  };
  {
    for (Size s : small)
      for (int k = 0; k < int(PairKind::Count); ++k) {
        if (skip(k)) continue;
        const int stride = pick_stride(s.w, rng);
        FramePair p = make_pair(PairKind(k), s.w, s.h, stride, rng, &ck);
        const int32_t a2 = pick_alpha2(rng);
        CheckCall c = prepare_call(s.w, s.h, stride, p, a2,
                                   size_name(s.w, s.h) + " stride " + std::to_string(stride) + " " + p.name +
                                       " alpha2_q4 " + std::to_string(a2));
        place_prepare(ck, c, rng);
        ck.add(std::move(c));
      }
    // The streamed path's band shapes (bvb/stream.h: BVB_STREAM_BAND_ROWS of 8 bytes a pixel,
    // the stream carrying rows 1..h-1): one band; full bands and a last band of one row (16,
    // 15, 2 rows a band); bands of 3 and of 1 row (width 385 and up); odd widths, whose rows
    // start misaligned in L1. Always streamed: the scratch in L1, the rest in SDRAM.
    static const Size bands[] = {{2, 2},  {3, 2},  {2, 3},  {5, 4},   {48, 18}, {49, 17},
                                 {2, 40}, {3, 34}, {200, 7}, {257, 6}, {385, 4}, {400, 3},
                                 {640, 2}};
    for (Size s : bands) {
      const int k = rng.uniform(0, int(PairKind::Count) - 2);  // not RealWarp: always runs
      const int stride = pick_stride(s.w, rng);
      FramePair p = make_pair(PairKind(k), s.w, s.h, stride, rng, &ck);
      const int32_t a2 = pick_alpha2(rng);
      CheckCall c = prepare_call(s.w, s.h, stride, p, a2,
                                 size_name(s.w, s.h) + " stride " + std::to_string(stride) + " " + p.name +
                                     " alpha2_q4 " + std::to_string(a2) + " bands");
      for (auto &b : c.bufs) b.skew = b.role == Role::In ? uint32_t(rng.uniform(0, 3)) : 0;
      c.bufs[kPrepareScratch].place = BVB_PLACE_L1B;
      ck.add(std::move(c));
    }
  }
  {
    for (Size s : small)
      for (int k = 0; k < 4; ++k) {
        std::string cn, fn;
        const std::vector<int16_t> coef = make_coef(s.w, s.h, rng, ck, &cn);
        const int is = flow_stride(s.w, rng), os = flow_stride(s.w, rng);
        const std::vector<int16_t> uv = make_flow(s.w, s.h, is, rng, &fn);
        // A third without the scratches (the direct path), a third streamed as the robot
        // would (frames in SDRAM, the scratches in L1 banks B and A), a third placed at random.
        const int how = rng.uniform(0, 2);
        CheckCall c = iterate_call(s.w, s.h, coef, uv, is, os, how != 0,
                                   size_name(s.w, s.h) + " strides " + std::to_string(is) + "/" +
                                       std::to_string(os) + " " + cn + " " + fn);
        if (how == 1)
          place_iter_robot(c);
        else
          place(ck, c, rng);
        ck.add(std::move(c));
      }
  }
  {
    // hs_iterate_n: iteration counts below, at and above the levels of one pass (1 to 8 by
    // width: BVB_HS_ITER_LEVELS), so that passes of every length and heights smaller than a
    // pass's levels occur; half the calls as the robot runs it (frames in SDRAM, the flow rows'
    // scratch in L1 bank B and the coefficient rows' in bank A: the DMA path), half placed at
    // random (the core's copies wherever DMA does not reach).
    std::vector<Size> nsizes = small;
    for (Size s : sizes) nsizes.push_back(s);
    static const Size extra[] = {{2, 2}, {3, 9}, {160, 7}, {161, 13}, {320, 5}, {319, 11}, {640, 4}, {341, 3}};
    for (Size s : extra) nsizes.push_back(s);
    for (Size s : nsizes) {
      std::string cn, fn;
      const std::vector<int16_t> coef = make_coef(s.w, s.h, rng, ck, &cn);
      // A quarter with in_stride 0 (one row for every row: hornschunck's zero start field).
      const int is = rng.uniform(0, 3) == 0 ? 0 : flow_stride(s.w, rng), os = flow_stride(s.w, rng);
      const std::vector<int16_t> uv = is ? make_flow(s.w, s.h, is, rng, &fn) : make_flow(s.w, 1, 4 * s.w + 4, rng, &fn);
      static const int counts[] = {1, 2, 3, 4, 5, 7, 8, 9, 10, 17};
      int n = counts[rng.uniform(0, 9)];
      if (double(s.w) * s.h > 40000) n = std::min(n, 3);
      CheckCall c = iterate_n_call(s.w, s.h, coef, uv, is, os, n,
                                   size_name(s.w, s.h) + " strides " + std::to_string(is) + "/" +
                                       std::to_string(os) + " " + cn + " " + fn + " N=" + std::to_string(n));
      if (rng.uniform(0, 1) == 0)
        place_iter_robot(c);
      else
        place(ck, c, rng);
      ck.add(std::move(c));
    }
  }
  {
    for (Size s : sizes)
      for (int k = 0; k < int(PairKind::Count); ++k) {
        if (skip(k)) continue;
        const int stride = pick_stride(s.w, rng), os = flow_stride(s.w, rng);
        FramePair p = make_pair(PairKind(k), s.w, s.h, stride, rng, &ck);
        const int32_t a2 = pick_alpha2(rng);
        // Up to 10 iterations on small frames; large ones keep the simulator time reasonable.
        static const int counts[] = {0, 1, 2, 3, 10};
        int n = counts[rng.uniform(0, 4)];
        if (double(s.w) * s.h > 40000) n = std::min(n, 2);
        CheckCall c = full_call(s.w, s.h, stride, p, a2, n, os,
                                size_name(s.w, s.h) + " stride " + std::to_string(stride) + "/" +
                                    std::to_string(os) + " " + p.name + " alpha2_q4 " + std::to_string(a2) +
                                    " N=" + std::to_string(n));
        // Half as the robot runs it (the DMA paths of prepare and the iterations), half placed
        // at random (the direct paths wherever a scratch is out of DMA's reach or not in L1).
        if (rng.uniform(0, 1) == 0) {
          for (auto &b : c.bufs) b.skew = b.role == Role::In ? uint32_t(rng.uniform(0, 3)) : 0;
          place_full_robot(c);
          c.case_name += " frames SDRAM";
        } else {
          place(ck, c, rng);
        }
        ck.add(std::move(c));
      }
  }
}

CheckCall bench_call(const std::string &kernel, int w, int h, Rng &rng) {
  // The integer texture warped: the same bytes, and so the same cycles, on every host.
  FramePair p = make_pair(PairKind::Warp, w, h, w, rng, nullptr);
  if (kernel == "hs_prepare") {
    CheckCall c = prepare_call(w, h, w, p, 1024, size_name(w, h));
    c.bufs[kPrepareScratch].place = BVB_PLACE_L1B;  // frames and coefficients in SDRAM
    return c;
  }
  if (kernel == "hs_iterate") {
    std::vector<int16_t> coef(BVB_HS_COEF_BYTES(w, h) / 2);
    bvb_hs_prepare_c(p.f1.data(), p.f2.data(), w, h, w, 1024, coef.data(), nullptr);
    std::vector<int16_t> uv(size_t(2) * w * h);
    for (auto &v : uv) v = int16_t(rng.uniform(-1024, 1024));
    CheckCall c = iterate_call(w, h, coef, uv, 4 * w, 4 * w, true, size_name(w, h));
    c.bufs[kIterFlowScratch].place = BVB_PLACE_L1B;  // coefficients and flow in SDRAM, streamed
    c.bufs[kIterCoefScratch].place = BVB_PLACE_L1A;
    return c;
  }
  if (kernel == "hs_iterate_n") {
    std::vector<int16_t> coef(BVB_HS_COEF_BYTES(w, h) / 2);
    bvb_hs_prepare_c(p.f1.data(), p.f2.data(), w, h, w, 1024, coef.data(), nullptr);
    std::vector<int16_t> uv(size_t(2) * w * h);
    for (auto &v : uv) v = int16_t(rng.uniform(-1024, 1024));
    CheckCall c = iterate_n_call(w, h, coef, uv, 4 * w, 4 * w, kBenchIterations,
                                 size_name(w, h) + " N=" + std::to_string(kBenchIterations) + ", per iteration");
    c.bufs[kIterFlowScratch].place = BVB_PLACE_L1B;  // coefficients and flow in SDRAM
    c.bufs[kIterCoefScratch].place = BVB_PLACE_L1A;
    return c;
  }
  CheckCall c = full_call(w, h, w, p, 1024, kBenchIterations, 4 * w,
                          size_name(w, h) + " N=" + std::to_string(kBenchIterations));
  place_full_robot(c);  // frames, flow and coefficients in SDRAM
  return c;
}

// Issues per pixel of the assembly's instruction mapping, one issue per cycle being one 32-bit
// ALU/MAC instruction with up to two loads or a load and a store, or one 16-bit instruction
// (firmware/asm/hornschunck.S derives them):
//   iteration 10 (ALU/MAC; its 6 loads and 1 store ride along);
//   prepare 17 = 1 (per-row sums: 4 stores per 4 columns) + 2 (column sums: 8 ALU per 4
//     columns) + 14 (coefficients: 10 ALU/MAC + 4 pointer moves per pixel);
//   hornschunck = prepare + 10 per iteration (its zero start field is one row, read with
//     stride 0).
// prepare's bus bound with the frames and coefficients in SDRAM is lower: 2 bytes in and 6 out
// per pixel at 0.5 byte per core cycle (bvb/dma.h) is 16.
// hs_iterate streamed (the bench: frames in SDRAM, scratches in L1) is hs_iterate_n's one pass
// of one level: the larger of 10 and 28, the bus's.
// hs_iterate_n (frames in SDRAM): per pass of L fused levels (bvb/hornschunck.h: FUSED
// ITERATIONS; N = 10 at 160 and 320 wide is two passes of 5, at 640 five of 2) the larger of
// the compute, 10 L, and the bus, 14 bytes a pixel (6 coefficients and 4 flow in, 4 flow out)
// at 0.5 byte a cycle, 28: 100 per pixel for the 10 iterations at 160 and 320, 140 at 640
// (bus-bound); the bench's c/px divides it by the 10 iterations (10.0, 10.0, 14.0).
double iterate_n_bound(int w, int iterations) {
  const int lmax = BVB_HS_ITER_LEVELS(w);
  double c = 0;
  for (int left = iterations; left > 0;) {
    const int passes = (left + lmax - 1) / lmax, l = (left + passes - 1) / passes;
    c += std::max(10.0 * l, 28.0);
    left -= l;
  }
  return c;
}

double lower_bound(const std::string &kernel, int w, int h) {
  const double px = double(w) * h;
  if (kernel == "hs_iterate") return iterate_n_bound(w, 1) * px;  // streamed: the bus's 28
  if (kernel == "hs_iterate_n") return iterate_n_bound(w, kBenchIterations) * px;
  if (kernel == "hs_prepare") return 17 * px;
  if (kernel == "hornschunck") return (17 + 10.0 * kBenchIterations) * px;
  return 0;
}

RunPlan plan_run(RunRequest &req) {
  if (req.kernel != "hornschunck")
    throw InputError(req.kernel + " is a stage of Horn-Schunck; run 'hornschunck' on a frame pair");
  if (req.inputs.size() != 2) throw InputError("hornschunck takes two --in frames (frame 1, frame 2)");
  const int alpha = req.params.get_int("alpha", 8, 8, 256);
  const int iterations = req.params.get_int("iterations", 10, 0, 100000);
  req.params.check_all_used();
  Image a = read_input(req, 0);
  Image b = read_input(req, 1);
  if (a.width != b.width || a.height != b.height) throw InputError("hornschunck: the two frames differ in size");
  if (a.width < BVB_HS_MIN_DIM || a.height < BVB_HS_MIN_DIM)
    throw InputError("hornschunck: frames must be at least 2x2");
  const int w = a.width, h = a.height;
  FramePair p{a.data, b.data, "run"};
  RunPlan plan;
  plan.call = full_call(w, h, w, p, 16 * alpha * alpha, iterations, 4 * w, "run");
  place_full_robot(plan.call);
  plan.write = [w, h](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    // Q9 to pixels: value / 512 is exact in float.
    const int16_t *uv = reinterpret_cast<const int16_t *>(bufs[2].data());
    FlowField f(w, h);
    for (size_t i = 0; i < size_t(w) * h; ++i) {
      f.u[i] = float(uv[2 * i]) / (1 << BVB_HS_UV_FRAC_BITS);
      f.v[i] = float(uv[2 * i + 1]) / (1 << BVB_HS_UV_FRAC_BITS);
    }
    write_flow(path, f);
  };
  plan.kind = OutputKind::Flow;
  plan.summary = size_name(w, h) + ", alpha " + std::to_string(alpha) + ", " + std::to_string(iterations) +
                 " iterations";
  return plan;
}

const Family kHornSchunck{"hornschunck", {"hs_prepare", "hs_iterate", "hs_iterate_n", "hornschunck"}, check, bench_call,
                          lower_bound, plan_run};
BVB_FAMILY(kHornSchunck);

}  // namespace
}  // namespace bvb
