// Host tests of the Lucas-Kanade C reference (bvb/lk.h) against independent computations: frames
// sampled from a known smooth function and its translate (so the true motion is known exactly),
// a direct 2x2 average for the pyramid, and a floating-point Lucas-Kanade step for one
// iteration.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "bvb/lk.h"

namespace {

// A smooth texture with structure in every direction (several plane waves), 8-bit.
double texture(double x, double y) {
  return 128 + 45 * std::sin(0.31 * x + 0.22 * y) + 35 * std::sin(0.17 * x - 0.35 * y + 1.0) +
         25 * std::cos(0.43 * x + 0.29 * y + 0.5) + 15 * std::sin(0.07 * x + 0.11 * y);
}

// The frame whose content is the texture moved by (dx, dy): J(x, y) = f(x - dx, y - dy).
std::vector<uint8_t> frame(int w, int h, double dx, double dy) {
  std::vector<uint8_t> f(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double v = std::lround(texture(x - dx, y - dy));
      f[size_t(y) * w + x] = uint8_t(v < 0 ? 0 : v > 255 ? 255 : v);
    }
  return f;
}

struct Result {
  double x, y;
  int32_t status, iters;
};

std::vector<Result> track(const std::vector<uint8_t> &a, const std::vector<uint8_t> &b, int w, int h,
                          const std::vector<std::pair<double, double>> &pts, bvb_lk_params p) {
  std::vector<uint8_t> pa(bvb_lk_pyramid_bytes(w, h, p.levels) + 4), pb(pa.size());
  bvb_lk_pyramid_c(a.data(), w, h, w, p.levels, pa.data());
  bvb_lk_pyramid_c(b.data(), w, h, w, p.levels, pb.data());
  std::vector<int32_t> in, out(pts.size() * BVB_LK_OUT_WORDS);
  for (auto &q : pts) {
    in.push_back(int32_t(std::lround(q.first * 65536)));
    in.push_back(int32_t(std::lround(q.second * 65536)));
  }
  p.count = int32_t(pts.size());
  std::vector<uint8_t> scratch(BVB_LK_SCRATCH_BYTES);
  bvb_lk_track_c(a.data(), pa.data(), b.data(), pb.data(), w, h, w, &p, in.data(), out.data(), scratch.data());
  std::vector<Result> r;
  for (size_t i = 0; i < pts.size(); ++i) {
    const int32_t *o = &out[i * BVB_LK_OUT_WORDS];
    r.push_back({o[0] / 65536.0, o[1] / 65536.0, o[2], o[3]});
  }
  return r;
}

bvb_lk_params defaults(int levels) {
  bvb_lk_params p{};
  p.levels = levels;
  p.win_w = p.win_h = 7;
  p.max_iter = 20;
  p.eps_q16 = 655;  // 0.01 px; updates are quantised by the 1/128 px interpolation grid
  p.min_det = 1;
  p.flags = 0;
  return p;
}

std::vector<std::pair<double, double>> grid(int w, int h, int margin, int step) {
  std::vector<std::pair<double, double>> g;
  for (int y = margin; y < h - margin; y += step)
    for (int x = margin; x < w - margin; x += step) g.push_back({x + 0.25 * (x % 3), y + 0.5 * (y % 2)});
  return g;
}

// The motion of a translated texture is recovered: sub-pixel, integer, and large (pyramid). The
// tolerances are those of Lucas-Kanade itself on 8-bit frames (the frames are rounded samples,
// so a 7x7 window sees quantisation noise): every feature within tol_each, the mean error within
// tol_mean; larger windows average it down.
void expect_translation(double dx, double dy, int levels, int win, double tol_each, double tol_mean) {
  const int w = 96, h = 80;
  auto a = frame(w, h, 0, 0), b = frame(w, h, dx, dy);
  auto pts = grid(w, h, 24, 9);
  bvb_lk_params p = defaults(levels);
  p.win_w = p.win_h = win;
  auto r = track(a, b, w, h, pts, p);
  double sum = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    ASSERT_EQ(r[i].status, BVB_LK_TRACKED) << "feature " << i << " at " << pts[i].first << "," << pts[i].second;
    const double ex = r[i].x - pts[i].first - dx, ey = r[i].y - pts[i].second - dy;
    EXPECT_LT(std::hypot(ex, ey), tol_each) << "feature " << i << " error " << ex << ", " << ey;
    sum += std::hypot(ex, ey);
  }
  ASSERT_GT(pts.size(), 10u);
  EXPECT_LT(sum / pts.size(), tol_mean);
}

TEST(LucasKanade, SubPixelTranslation) {
  expect_translation(0.37, -0.62, 1, 7, 0.1, 0.04);
  expect_translation(0.37, -0.62, 1, 11, 0.04, 0.02);
}
TEST(LucasKanade, IntegerTranslation) { expect_translation(2.0, -1.0, 1, 7, 0.1, 0.04); }
TEST(LucasKanade, LargeTranslationNeedsThePyramid) {
  expect_translation(6.3, -4.7, 3, 7, 0.1, 0.04);
  // Without the pyramid the same motion is beyond the window's reach for some features.
  const int w = 96, h = 80;
  auto a = frame(w, h, 0, 0), b = frame(w, h, 6.3, -4.7);
  auto pts = grid(w, h, 24, 9);
  auto r = track(a, b, w, h, pts, defaults(1));
  int wrong = 0;
  for (size_t i = 0; i < pts.size(); ++i)
    wrong += r[i].status != BVB_LK_TRACKED || std::hypot(r[i].x - pts[i].first - 6.3, r[i].y - pts[i].second + 4.7) > 0.1;
  EXPECT_GT(wrong, 0);
}

TEST(LucasKanade, FlatWindowIsFlagged) {
  const int w = 64, h = 48;
  auto a = frame(w, h, 0, 0);
  // A constant patch around (40, 24), and gentle texture elsewhere.
  for (int y = 14; y < 34; ++y)
    for (int x = 30; x < 50; ++x) a[size_t(y) * w + x] = 90;
  auto r = track(a, a, w, h, {{40, 24}, {15, 24}}, defaults(1));
  EXPECT_EQ(r[0].status, BVB_LK_FLAT);
  EXPECT_EQ(r[1].status, BVB_LK_TRACKED);
  // A straight edge has one strong direction only: its determinant is small too.
  std::vector<uint8_t> e(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) e[size_t(y) * w + x] = x < 32 ? 40 : 200;
  auto re = track(e, e, w, h, {{32, 24}}, defaults(1));
  EXPECT_EQ(re[0].status, BVB_LK_FLAT);
}

TEST(LucasKanade, PointLeavingTheImageIsFlagged) {
  const int w = 96, h = 80;
  auto a = frame(w, h, 0, 0), b = frame(w, h, 3.5, 0);
  // The template fits (x + 3 + 2 <= w - 1) but 3.5 pixels to the right the window does not.
  auto r = track(a, b, w, h, {{w - 7.0, 40}, {40, 40}}, defaults(1));
  EXPECT_EQ(r[0].status, BVB_LK_LEFT);
  EXPECT_EQ(r[1].status, BVB_LK_TRACKED);
  // A feature whose own window does not fit in the first frame is lost the same way.
  auto r2 = track(a, a, w, h, {{1.0, 40}}, defaults(1));
  EXPECT_EQ(r2[0].status, BVB_LK_LEFT);
}

TEST(LucasKanade, IterationCapIsFlagged) {
  const int w = 96, h = 80;
  auto a = frame(w, h, 0, 0), b = frame(w, h, 1.7, 1.1);
  bvb_lk_params p = defaults(1);
  p.max_iter = 1;
  p.eps_q16 = 0;
  auto r = track(a, b, w, h, {{48, 40}}, p);
  EXPECT_EQ(r[0].status, BVB_LK_NOT_CONVERGED);
  EXPECT_EQ(r[0].iters, 1);
}

// One iteration against a floating-point Lucas-Kanade step on the same samples: the template
// and gradients come from bvb_lk_patch_c (checked against direct bilinear sampling), the update
// from solving G eta = b in double precision.
TEST(LucasKanade, OneStepMatchesFloatingPointSolve) {
  const int w = 64, h = 48;
  auto a = frame(w, h, 0, 0), b = frame(w, h, 0.8, -0.3);
  const int hx = 3, hy = 3, wy = 7, wxp = 8;  // a 7x7 window, rows padded to 8
  std::vector<int16_t> tmpl(wxp * wy), work(2048);
  std::vector<int32_t> grad(wxp * wy);
  int32_t pa[BVB_LK_PA_WORDS] = {};
  const double px = 30.3, py = 21.6;
  const int32_t q7x = int32_t(std::lround(px * 128)), q7y = int32_t(std::lround(py * 128));
  pa[BVB_LK_PA_STRIDE] = w;
  pa[BVB_LK_PA_IX] = q7x >> 7;
  pa[BVB_LK_PA_IY] = q7y >> 7;
  pa[BVB_LK_PA_FX] = q7x & 127;
  pa[BVB_LK_PA_FY] = q7y & 127;
  pa[BVB_LK_PA_HX] = hx;
  pa[BVB_LK_PA_HY] = hy;
  bvb_lk_patch_c(a.data(), tmpl.data(), grad.data(), work.data(), pa);
  auto bil = [&](const std::vector<uint8_t> &img, double x, double y) {
    const int ix = int(std::floor(x)), iy = int(std::floor(y));
    const double fx = x - ix, fy = y - iy;
    auto at = [&](int u, int v) { return double(img[size_t(v) * w + u]); };
    return (1 - fy) * ((1 - fx) * at(ix, iy) + fx * at(ix + 1, iy)) + fy * ((1 - fx) * at(ix, iy + 1) + fx * at(ix + 1, iy + 1));
  };
  double gxx = 0, gxy = 0, gyy = 0, bx = 0, by = 0;
  for (int j = -hy; j <= hy; ++j)
    for (int i = -hx; i <= hx; ++i) {
      const double x = q7x / 128.0 + i, y = q7y / 128.0 + j;
      const double t = tmpl[(j + hy) * wxp + i + hx] / 32.0;
      EXPECT_NEAR(t, bil(a, x, y), 1.0 / 32 + 1e-9);  // truncated Q5
      const double ix_ = (bil(a, x + 1, y) - bil(a, x - 1, y)) / 2, iy_ = (bil(a, x, y + 1) - bil(a, x, y - 1)) / 2;
      const double d = bil(a, x, y) - bil(b, x, y);
      gxx += ix_ * ix_;
      gxy += ix_ * iy_;
      gyy += iy_ * iy_;
      bx += d * ix_;
      by += d * iy_;
    }
  const double det = gxx * gyy - gxy * gxy;
  const double ex = (gyy * bx - gxy * by) / det, ey = (gxx * by - gxy * bx) / det;
  // The fixed-point step: one iteration, no convergence stop.
  bvb_lk_params p = defaults(1);
  p.max_iter = 1;
  p.eps_q16 = 0;
  p.count = 1;
  std::vector<int32_t> in = {int32_t(q7x) << 9, int32_t(q7y) << 9}, out(BVB_LK_OUT_WORDS);
  std::vector<uint8_t> scratch(BVB_LK_SCRATCH_BYTES);
  bvb_lk_track_c(a.data(), nullptr, b.data(), nullptr, w, h, w, &p, in.data(), out.data(), scratch.data());
  EXPECT_NEAR((out[0] - in[0]) / 65536.0, ex, 0.01);
  EXPECT_NEAR((out[1] - in[1]) / 65536.0, ey, 0.01);
  EXPECT_GT(std::fabs(ex), 0.3);  // the step is not trivially zero
}

TEST(LucasKanadePyramid, TwoByTwoAverageWithRounding) {
  const int w = 7, h = 5, stride = 9;
  std::vector<uint8_t> img(size_t(stride) * h);
  for (size_t i = 0; i < img.size(); ++i) img[i] = uint8_t(i * 37 + (i >> 2) * 11);
  std::vector<uint8_t> pyr(bvb_lk_pyramid_bytes(w, h, 3));
  ASSERT_EQ(pyr.size(), size_t(4 * 2 + 4 * 1));  // 3x2 (rows of 4), then 1x1 (row of 4)
  bvb_lk_pyramid_c(img.data(), w, h, stride, 3, pyr.data());
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      int s = img[2 * y * stride + 2 * x] + img[2 * y * stride + 2 * x + 1] + img[(2 * y + 1) * stride + 2 * x] +
              img[(2 * y + 1) * stride + 2 * x + 1];
      EXPECT_EQ(pyr[y * 4 + x], (s + 2) / 4) << x << "," << y;
    }
  int s = pyr[0] + pyr[1] + pyr[4] + pyr[5];
  EXPECT_EQ(pyr[8], (s + 2) / 4);
  EXPECT_EQ(bvb_lk_level_offset(w, h, 2), 8u);
}

// bvb_lk_scratch_place: wherever the area starts, the 7x7 tracker's scratch (the odometry's)
// lands at the first 4-byte step whose 4 KB sub-bank boundary splits the driver's two groups of
// arrays, Y (template and differences, 4 n + 8 bytes, n = (wx + 1) wy) before it and X
// (gradients and work, 4 n + (2 wy + 5) (4 hx + 8) + 4 bytes) after it; other windows too when
// the slack allows, else the area itself.
TEST(LucasKanadeScratch, PlacedWhereTheSubBankBoundarySplitsTheArrays) {
  const uint32_t slack = 1536, bytes = BVB_LK_SCRATCH_BYTES + slack;
  std::vector<uint8_t> mem(3 * 4096 + bytes);
  const uintptr_t a0 = (reinterpret_cast<uintptr_t>(mem.data()) + 4095) & ~uintptr_t(4095);
  for (int win = 3; win <= 15; win += 2) {
    const uint32_t hx = uint32_t(win / 2), n = (2 * hx + 2) * (2 * hx + 1);
    const uint32_t ysize = 4 * n + 8, xsize = 4 * n + (2 * (2 * hx + 1) + 5) * (4 * hx + 8) + 4;
    auto splits = [&](uintptr_t p) {
      const uint32_t b = 4096 - uint32_t(p & 4095);
      return (p & 4095) != 0 && b >= ysize && b + xsize <= BVB_LK_SCRATCH_BYTES;
    };
    int moved = 0;
    for (uint32_t off = 0; off < 4096; off += 4) {
      const uint8_t *area = reinterpret_cast<const uint8_t *>(a0 + off);
      const uint8_t *got = bvb_lk_scratch_place(area, bytes, win, win);
      uintptr_t want = 0;
      for (uint32_t d = 0; d <= slack && !want; d += 4)
        if (splits(a0 + off + d)) want = a0 + off + d;
      if (!want) want = a0 + off;
      ASSERT_EQ(reinterpret_cast<uintptr_t>(got), want) << win << "x" << win << " at offset " << off;
      moved += got != area;
      if (win == 7) {
        EXPECT_TRUE(splits(reinterpret_cast<uintptr_t>(got))) << "offset " << off;
      }
    }
    if (win == 7) {
      EXPECT_GT(moved, 0);
    }
  }
  // No room to spare: the area itself.
  const uint8_t *area = reinterpret_cast<const uint8_t *>(a0 + 8);
  EXPECT_EQ(bvb_lk_scratch_place(area, BVB_LK_SCRATCH_BYTES, 7, 7), area);
}

}  // namespace

// Real frames with ground truth: Harris corners of RubberWhale frame10 (the references of
// bvb/harris.h) tracked into frame11 with three levels; compared with flow10.flo where it is
// known.
#include <algorithm>
#include <sys/stat.h>

#include "bvb/harris.h"
#include "frames.h"
#include "io.h"

namespace {

TEST(LucasKanadeRealFrames, RubberWhaleAgreesWithGroundTruth) {
  BVB_NEED_REAL_FRAMES(BVB_FRAMES_REAL);
  const std::string dir = std::string(BVB_FRAMES_REAL) + "/RubberWhale/";
  bvb::Image a = bvb::read_pnm(dir + "frame10.pgm"), b = bvb::read_pnm(dir + "frame11.pgm");
  bvb::FlowField gt = bvb::read_flo(dir + "flow10.flo");
  const int w = a.width, h = a.height;
  std::vector<int32_t> resp(size_t(w) * h);
  std::vector<uint8_t> hs(BVB_HARRIS_SCRATCH_BYTES(w));
  bvb_harris_response_c(a.data.data(), resp.data(), w, h, w, w, hs.data());
  const int32_t maxv = *std::max_element(resp.begin(), resp.end());
  std::vector<int32_t> cand(size_t(BVB_HARRIS_NMS_CAPACITY(w, h) + 1) * 2), corners(3 * 100);
  int32_t n = 0;
  bvb_harris_nms_c(resp.data(), w, h, w, maxv / 100, cand.data(), &n, nullptr);
  const int32_t taken = bvb_harris_select_c(cand.data(), n, 100, 10, corners.data());
  ASSERT_EQ(taken, 100);
  std::vector<std::pair<double, double>> pts;
  for (int k = 0; k < taken; ++k) pts.push_back({double(corners[3 * k]), double(corners[3 * k + 1])});
  auto r = track(a.data, b.data, w, h, pts, defaults(3));
  std::vector<double> err;
  for (size_t i = 0; i < pts.size(); ++i) {
    const size_t at = size_t(pts[i].second) * w + size_t(pts[i].first);
    if (bvb::FlowField::unknown(gt.u[at]) || r[i].status != BVB_LK_TRACKED) continue;
    err.push_back(std::hypot(r[i].x - pts[i].first - gt.u[at], r[i].y - pts[i].second - gt.v[at]));
  }
  ASSERT_GT(err.size(), 80u);  // most corners tracked
  std::sort(err.begin(), err.end());
  EXPECT_LT(err[err.size() / 2], 0.1);        // median endpoint error
  EXPECT_LT(err[err.size() * 9 / 10], 0.5);   // 90th percentile (occlusions, motion boundaries)
}

}  // namespace
