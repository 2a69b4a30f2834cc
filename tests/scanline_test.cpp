// Scan-line profiles and their shift (C reference) on hand-made bands and profiles, against
// direct computations (exact rationals for f(t)).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "bvb/scanline.h"
#include "check.h"
#include "scene/scene_io.h"

namespace {

TEST(ScanlineProfile, RoundedColumnMeans) {
  // 3 columns, 2 rows, stride 4: means 1.5 (rounds up to 2), 0, 254.5 (255).
  const std::vector<uint8_t> band = {1, 0, 254, 0xFF, 2, 0, 255};
  std::vector<uint8_t> prof(3);
  bvb_scanline_profile_u8_c(band.data(), 3, 2, 4, prof.data(), nullptr);
  EXPECT_EQ(prof, (std::vector<uint8_t>{2, 0, 255}));
  // 3 rows: 10 + 11 + 11 = 32, 32 / 3 = 10.67 -> 11; 1 + 0 + 0 -> 0.33 -> 0.
  const std::vector<uint8_t> band3 = {10, 1, 11, 0, 11, 0};
  std::vector<uint8_t> prof3(2);
  bvb_scanline_profile_u8_c(band3.data(), 2, 3, 2, prof3.data(), nullptr);
  EXPECT_EQ(prof3, (std::vector<uint8_t>{11, 0}));
}

TEST(ScanlineProfile, ReciprocalEqualsDivisionForEveryBand) {
  // The assembly divides (S + rows / 2) by rows as a multiplication by ceil(2^24 / rows) and
  // a shift by 24: the same for every sum a band of up to 256 rows of bytes can have.
  for (uint32_t rows = 1; rows <= BVB_SCANLINE_MAX_ROWS; ++rows) {
    const uint64_t r = ((uint64_t(1) << 24) + rows - 1) / rows;
    for (uint32_t s = 0; s <= 255 * rows; ++s) {
      const uint32_t n = s + rows / 2;
      ASSERT_EQ((uint64_t(n) * r) >> 24, n / rows) << "rows " << rows << " sum " << s;
    }
  }
}

struct Shift {
  int32_t t, s, n;
};

Shift shift_of(const std::vector<uint8_t> &p1, const std::vector<uint8_t> &p2, int rho,
               std::vector<uint32_t> *curve = nullptr) {
  const int w = int(p1.size());
  int32_t res[3] = {-999, -999, -999};
  if (curve) curve->assign(size_t(2 * (w - rho) + 1), 0xDEADBEEF);
  bvb_scanline_shift_u8_c(p1.data(), p2.data(), w, rho, res, curve ? curve->data() : nullptr);
  return {res[0], res[1], res[2]};
}

// p1 moved right by d: p2[x] = p1[x - d], the edge repeated where nothing moved in.
std::vector<uint8_t> moved(const std::vector<uint8_t> &p, int d) {
  const int w = int(p.size());
  std::vector<uint8_t> q(w);
  for (int x = 0; x < w; ++x) q[x] = p[std::min(std::max(x - d, 0), w - 1)];
  return q;
}

TEST(ScanlineShift, FindsAKnownShift) {
  bvb::Rng rng(3);
  std::vector<uint8_t> p(88);
  int v = 128;
  for (auto &x : p) x = uint8_t(v = std::min(255, std::max(0, v + rng.uniform(-20, 20))));
  for (int d : {0, 1, -1, 7, -12, 30, -48, 48}) {
    const Shift r = shift_of(p, moved(p, d), 40);
    EXPECT_EQ(r.t, d);
    EXPECT_EQ(r.s, 0);
    EXPECT_EQ(r.n, 88 - (d < 0 ? -d : d));
  }
}

TEST(ScanlineShift, TheHeadersWorkedExample) {
  // bvb/scanline.h: w = 6, rho = 4, p2 = p1 moved right by one pixel.
  std::vector<uint32_t> curve;
  const Shift r = shift_of({10, 20, 30, 40, 50, 60}, {10, 10, 20, 30, 40, 50}, 4, &curve);
  EXPECT_EQ(curve, (std::vector<uint32_t>{110, 90, 50, 0, 40}));
  EXPECT_EQ(r.t, 1);
  EXPECT_EQ(r.s, 0);
  EXPECT_EQ(r.n, 5);
}

TEST(ScanlineShift, TiesGoToTheSmallestShiftThenTheNegativeOne) {
  // Period 2: t = 0 and every even shift match perfectly; 0 is the smallest.
  std::vector<uint8_t> a = {0, 9, 0, 9, 0, 9, 0, 9};
  EXPECT_EQ(shift_of(a, a, 3).t, 0);
  // Out of phase: -1 and +1 both match perfectly, t = 0 does not; -1 wins the tie.
  std::vector<uint8_t> b = {9, 0, 9, 0, 9, 0, 9, 0};
  const Shift r = shift_of(a, b, 3);
  EXPECT_EQ(r.t, -1);
  EXPECT_EQ(r.s, 0);
  // Equal means from unequal sums: S(-2) = 4 over 4, S(1) = 5 over 5 (f = 1 for both; the
  // others 6/5, 7/6, 5/4): the smaller |t| wins although its sum is larger.
  const std::vector<uint8_t> c = {0, 0, 0, 0, 0, 0}, d = {2, 0, 1, 1, 2, 1};
  std::vector<uint32_t> curve;
  const Shift q = shift_of(c, d, 4, &curve);
  EXPECT_EQ(curve, (std::vector<uint32_t>{4, 6, 7, 5, 5}));  // t = -2..2 by hand
  EXPECT_EQ(q.t, 1);
  EXPECT_EQ(q.s, 5);
  EXPECT_EQ(q.n, 5);
}

TEST(ScanlineShift, CurveAndMinimumMatchDirectComputation) {
  bvb::Rng rng(11);
  for (int iter = 0; iter < 200; ++iter) {
    const int w = rng.uniform(1, 40), rho = rng.uniform(1, w), T = w - rho;
    std::vector<uint8_t> p1(w), p2(w);
    for (auto &x : p1) x = uint8_t(rng.uniform(0, 3) * 60);  // few levels: many ties
    for (auto &x : p2) x = uint8_t(rng.uniform(0, 3) * 60);
    std::vector<uint32_t> curve;
    const Shift r = shift_of(p1, p2, rho, &curve);
    // Best by exact rationals: f(t) = S / n, ties by |t| then negative first.
    int bt = 0;
    uint64_t bs = 0, bn = 1;
    bool first = true;
    for (int t = -T; t <= T; ++t) {
      uint64_t s = 0;
      const uint64_t n = uint64_t(w - (t < 0 ? -t : t));
      for (int i = 0; i < w; ++i)
        if (i + t >= 0 && i + t < w) s += uint64_t(p1[i] > p2[i + t] ? p1[i] - p2[i + t] : p2[i + t] - p1[i]);
      ASSERT_EQ(curve[size_t(t + T)], s) << "t " << t;
      const int at = t < 0 ? -t : t, abt = bt < 0 ? -bt : bt;
      const bool better = first || s * bn < bs * n || (s * bn == bs * n && (at < abt || (at == abt && t < bt)));
      if (better) bt = t, bs = s, bn = n, first = false;
    }
    ASSERT_EQ(r.t, bt) << "w " << w << " rho " << rho;
    ASSERT_EQ(uint64_t(r.s), bs);
    ASSERT_EQ(uint64_t(r.n), bn);
  }
}

TEST(ScanlineShift, FollowsTheRobotTurningInARenderedScene) {
  // frames/scenes/boxes_turn: the robot turns 3 degrees right per frame. A yaw by a moves the
  // image centre sideways by fx * tan(a) * cos(tilt) pixels; the seed's setting (88-pixel
  // windows, overlap 40) on a band of the middle rows should find that to the nearest pixel.
  const bvb::SceneData d = bvb::read_scene(std::string(BVB_SOURCE_DIR) + "/frames/scenes/boxes_turn");
  const int w = d.camera.width, h = d.camera.height, rows = h / 2, y0 = (h - rows) / 2;
  const int win = 88, x0 = (w - win) / 2;
  auto profile = [&](int k) {
    const bvb::Image img = d.grey(k);
    std::vector<uint8_t> p(w);
    bvb_scanline_profile_u8_c(&img.data[size_t(y0) * w], w, rows, w, p.data(), nullptr);
    return p;
  };
  const double kPi = 3.14159265358979323846;
  int turns = 0;
  std::vector<uint8_t> prev = profile(0);
  for (int k = 1; k < d.frames; ++k) {
    std::vector<uint8_t> cur = profile(k);
    const double turn = d.truth[k].step.turn_deg;
    if (turn != 0) {
      const double want = d.camera.fx * std::tan(turn * kPi / 180) * std::cos(d.camera.tilt_deg * kPi / 180);
      int32_t res[3];
      bvb_scanline_shift_u8_c(&prev[x0], &cur[x0], win, 40, res, nullptr);
      EXPECT_LE(std::fabs(res[0] - want), 1.0) << "frames " << k - 1 << " -> " << k << ": want " << want;
      ++turns;
    }
    prev = cur;
  }
  EXPECT_GT(turns, 10);
}

}  // namespace
