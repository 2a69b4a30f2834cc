// The NCC reference (bvb/ncc.h) against an independent double-precision NCC on small hand-made
// images: known translations are found with score ~1, every fixed-point score is within its
// stated quantisation of the double one, the exact comparison agrees with doubles, and borders,
// flat templates and ties follow the documented rules.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "bvb/ncc.h"

namespace {

struct Frame {
  int w, h;
  std::vector<uint8_t> px;
  uint8_t at(int x, int y) const { return px[size_t(y) * w + x]; }
};

// A deterministic texture: a few sine gratings plus hashed noise, no two windows alike.
Frame texture(int w, int h, uint32_t seed) {
  Frame f{w, h, std::vector<uint8_t>(size_t(w) * h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint32_t z = (uint32_t(x) * 73856093u) ^ (uint32_t(y) * 19349663u) ^ (seed * 83492791u);
      z = (z ^ (z >> 13)) * 0x5bd1e995u;
      z ^= z >> 15;
      double v = 128 + 50 * std::sin(0.37 * x + 0.11 * y + seed) + 30 * std::cos(0.23 * y - 0.41 * x) +
                 int(z % 61) - 30;
      f.px[size_t(y) * w + x] = uint8_t(std::lround(std::fmin(255, std::fmax(0, v))));
    }
  return f;
}

// Frame 2 sees the scene moved by (dx, dy): frame2(x, y) = frame1(x - dx, y - dy), edge-clamped.
Frame shifted(const Frame &f, int dx, int dy) {
  Frame g = f;
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      int sx = std::min(std::max(x - dx, 0), f.w - 1), sy = std::min(std::max(y - dy, 0), f.h - 1);
      g.px[size_t(y) * f.w + x] = f.at(sx, sy);
    }
  return g;
}

// The textbook definition in doubles; NaN when a window is flat.
double ncc_double(const Frame &a, const Frame &b, int x, int y, int dx, int dy, int r) {
  const int n = (2 * r + 1) * (2 * r + 1);
  double mt = 0, mi = 0;
  for (int i = -r; i <= r; ++i)
    for (int j = -r; j <= r; ++j) {
      mt += a.at(x + j, y + i);
      mi += b.at(x + dx + j, y + dy + i);
    }
  mt /= n;
  mi /= n;
  double c = 0, vt = 0, vi = 0;
  for (int i = -r; i <= r; ++i)
    for (int j = -r; j <= r; ++j) {
      const double t = a.at(x + j, y + i) - mt, v = b.at(x + dx + j, y + dy + i) - mi;
      c += t * v;
      vt += t * t;
      vi += v * v;
    }
  if (vt == 0 || vi == 0) return NAN;
  return c / std::sqrt(vt * vi);
}

struct Match {
  int dx, dy, score, status;
};

std::vector<Match> match(const Frame &a, const Frame &b, const std::vector<int16_t> &pts, int r, int s) {
  std::vector<int16_t> res(pts.size() * 2, -99);
  bvb_ncc_match_c(a.px.data(), b.px.data(), a.w, a.w, a.h, pts.data(), int32_t(pts.size() / 2), r, s,
                  res.data(), nullptr);
  std::vector<Match> m;
  for (size_t i = 0; i < pts.size() / 2; ++i) m.push_back({res[4 * i], res[4 * i + 1], res[4 * i + 2], res[4 * i + 3]});
  return m;
}

TEST(Ncc, FindsKnownTranslationWithScoreOne) {
  const Frame a = texture(64, 48, 1);
  for (auto [tx, ty] : {std::pair{3, -2}, {0, 0}, {-5, 4}, {6, 6}, {-6, -1}}) {
    const Frame b = shifted(a, tx, ty);
    const std::vector<int16_t> pts = {32, 24, 20, 20, 44, 30};
    for (const Match &m : match(a, b, pts, 5, 6)) {
      EXPECT_EQ(m.status, BVB_NCC_OK);
      EXPECT_EQ(m.dx, tx);
      EXPECT_EQ(m.dy, ty);
      EXPECT_GE(m.score, 32767 - 3);  // the double score is exactly 1
    }
  }
}

TEST(Ncc, EveryScoreWithinQuantisationOfDouble) {
  // Frame 2 is frame 1 moved and with noise, so scores spread over (-1, 1].
  const Frame a = texture(48, 40, 2);
  Frame b = shifted(a, 2, 1);
  for (size_t i = 0; i < b.px.size(); ++i) b.px[i] = uint8_t(std::min(255, b.px[i] + int(uint32_t(i * 2654435761u) >> 28)));
  for (int r : {1, 2, 3, 5}) {
    const int s = 4, side = 2 * s + 1;
    for (auto [x, y] : {std::pair{24, 20}, {r + s, r + s}, {47 - r - s, 39 - r - s}}) {
      std::vector<int16_t> map(side * side + 1, -1);
      bvb_ncc_scoremap_c(a.px.data(), b.px.data(), a.w, a.w, a.h, x, y, r, s, map.data(), nullptr);
      ASSERT_EQ(map[side * side], BVB_NCC_OK);
      double best = -2;
      int bdx = 0, bdy = 0;
      for (int dy = -s; dy <= s; ++dy)
        for (int dx = -s; dx <= s; ++dx) {
          const double d = ncc_double(a, b, x, y, dx, dy, r);
          const int q = map[(dy + s) * side + (dx + s)];
          ASSERT_FALSE(std::isnan(d));
          EXPECT_LE(std::fabs(q - 32768 * d), 3.0) << "r " << r << " at " << dx << "," << dy;
          if (d > best + 1e-12) best = d, bdx = dx, bdy = dy;
        }
      const Match m = match(a, b, {int16_t(x), int16_t(y)}, r, s)[0];
      EXPECT_EQ(m.dx, bdx);
      EXPECT_EQ(m.dy, bdy);
      EXPECT_EQ(m.score, map[(bdy + s) * side + (bdx + s)]);
    }
  }
}

TEST(Ncc, ScoreFormulaMatchesDouble) {
  // Scores straight from (num, vt, v), over the whole range of magnitudes.
  uint64_t z = 12345;
  auto next = [&z]() { return (z = z * 6364136223846793005ull + 1442695040888963407ull) >> 33; };
  for (int i = 0; i < 20000; ++i) {
    const uint32_t vt = 1 + uint32_t(next() % ((1u << (1 + next() % 28)) - 1));
    const uint32_t v = 1 + uint32_t(next() % ((1u << (1 + next() % 28)) - 1));
    const double lim = std::sqrt(double(vt) * v);
    const double frac = (double(next() % 2000001) - 1000000) / 1000000;
    const int32_t num = int32_t(std::trunc(frac * lim));
    const double d = num / lim;
    const int q = bvb_ncc_score_q15(num, vt, v);
    ASSERT_LE(std::fabs(q - std::fmin(32767.0, 32768 * d)), 3.0) << num << " " << vt << " " << v;
  }
  EXPECT_EQ(bvb_ncc_score_q15(0, 100, 100), 0);
  EXPECT_EQ(bvb_ncc_score_q15(5, 0, 100), 0);
  EXPECT_EQ(bvb_ncc_score_q15(100, 100, 100), 32767);    // exactly 1
  EXPECT_EQ(bvb_ncc_score_q15(-100, 100, 100), -32767);  // exactly -1
  EXPECT_EQ(bvb_ncc_score_q15(50, 100, 100), 16384);     // exactly 1/2
}

TEST(Ncc, ExactComparisonAgreesWithDoubles) {
  uint64_t z = 99;
  auto next = [&z]() { return (z = z * 6364136223846793005ull + 1442695040888963407ull) >> 33; };
  for (int i = 0; i < 20000; ++i) {
    const uint32_t va = uint32_t(next() % (1u << 28)), vb = uint32_t(next() % (1u << 28));
    const int32_t na = int32_t(next() % (1u << 29)) - (1 << 28), nb = int32_t(next() % (1u << 29)) - (1 << 28);
    const double sa = na / std::sqrt(std::max(1.0, double(va))), sb = nb / std::sqrt(std::max(1.0, double(vb)));
    const int c = bvb_ncc_compare(na, va, nb, vb);
    const double tol = 1e-9 * std::max({1.0, std::fabs(sa), std::fabs(sb)});
    if (sa - sb > tol) {
      EXPECT_EQ(c, 1);
    }
    if (sb - sa > tol) {
      EXPECT_EQ(c, -1);
    }
    EXPECT_EQ(bvb_ncc_compare(nb, vb, na, va), -c);
  }
  // Equal ratios that no float rounding can separate: (k*n)^2 / (k^2*v) = n^2 / v.
  EXPECT_EQ(bvb_ncc_compare(3 * 12345, 9 * 99991, 12345, 99991), 0);
  EXPECT_EQ(bvb_ncc_compare(-2 * 7777, 4 * 1234567, -7777, 1234567), 0);
  // Adjacent values differing far below double precision of the squared products.
  EXPECT_EQ(bvb_ncc_compare(200000001, 199999999, 200000000, 199999998), 1);
  EXPECT_EQ(bvb_ncc_compare(0, 0, 0, 5), 0);
  EXPECT_EQ(bvb_ncc_compare(1, 268435455, 0, 0), 1);
  EXPECT_EQ(bvb_ncc_compare(-1, 268435455, 0, 0), -1);
}

TEST(Ncc, BordersAndParametersAreFlagged) {
  Frame a = texture(40, 30, 3), b = texture(40, 30, 4);
  const int r = 3, s = 4;  // r + s = 7
  const std::vector<int16_t> pts = {7, 7, 6, 7, 7, 6, 32, 22, 33, 22, 32, 23, -5, 10, 100, 10};
  const std::vector<int> expect = {BVB_NCC_OK, BVB_NCC_BORDER, BVB_NCC_BORDER, BVB_NCC_OK,
                                   BVB_NCC_BORDER, BVB_NCC_BORDER, BVB_NCC_BORDER, BVB_NCC_BORDER};
  const std::vector<Match> m = match(a, b, pts, r, s);
  for (size_t i = 0; i < m.size(); ++i) {
    EXPECT_EQ(m[i].status, expect[i]) << "point " << i;
    if (m[i].status != BVB_NCC_OK) {
      EXPECT_EQ(m[i].dx | m[i].dy | m[i].score, 0);
    }
  }
  // A frame of exactly the search area's size: the one legal point is its centre.
  Frame c = texture(2 * (r + s) + 1, 2 * (r + s) + 1, 5);
  EXPECT_EQ(match(c, c, {int16_t(r + s), int16_t(r + s)}, r, s)[0].status, BVB_NCC_OK);
  // Out-of-range parameters.
  EXPECT_EQ(match(a, b, {20, 15}, 0, 4)[0].status, BVB_NCC_BAD_PARAMS);
  EXPECT_EQ(match(a, b, {20, 15}, 6, 4)[0].status, BVB_NCC_BAD_PARAMS);
  EXPECT_EQ(match(a, b, {20, 15}, 3, 0)[0].status, BVB_NCC_BAD_PARAMS);
  EXPECT_EQ(match(a, b, {20, 15}, 3, BVB_NCC_MAX_SEARCH + 1)[0].status, BVB_NCC_BAD_PARAMS);
}

TEST(Ncc, FlatTemplateAndFlatSearchArea) {
  Frame a = texture(40, 40, 6), b = texture(40, 40, 7);
  for (int y = 10; y <= 16; ++y)
    for (int x = 10; x <= 16; ++x) a.px[size_t(y) * a.w + x] = 77;
  EXPECT_EQ(match(a, b, {13, 13}, 3, 3)[0].status, BVB_NCC_FLAT);
  // Frame 2 flat: every window has zero variance, every score is 0, the tie rule picks (0, 0).
  Frame flat{40, 40, std::vector<uint8_t>(1600, 200)};
  const Match m = match(a, flat, {25, 25}, 3, 4)[0];
  EXPECT_EQ(m.status, BVB_NCC_OK);
  EXPECT_EQ(m.dx, 0);
  EXPECT_EQ(m.dy, 0);
  EXPECT_EQ(m.score, 0);
}

TEST(Ncc, TiesGoToTheSmallestMotion) {
  // Columns repeat with period 4 and rows with period 6 (a hashed tile): exact copies of the
  // template sit at dx = 2 + 4i, dy = 3 + 6j when the scene moved by (2, 3).
  Frame a{60, 60, std::vector<uint8_t>(3600)};
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 60; ++x) a.px[size_t(y) * 60 + x] = uint8_t((((x % 4) * 7 + (y % 6) * 13) * 37) % 251);
  const Frame b = shifted(a, 2, 3);
  // Candidates with score 1: dx in {-6, -2, 2, 6}, dy in {-3, 3}; smallest |dx|+|dy| = 5 at
  // (-2, -3), (2, -3), (-2, 3), (2, 3); then smallest dy (-3), then smallest dx (-2).
  Match m = match(a, b, {30, 30}, 2, 6)[0];
  EXPECT_EQ(m.dx, -2);
  EXPECT_EQ(m.dy, -3);
  EXPECT_GE(m.score, 32767 - 3);
  // With no motion the exact copy at (0, 0) wins over its repeats.
  m = match(a, a, {30, 30}, 2, 6)[0];
  EXPECT_EQ(m.dx, 0);
  EXPECT_EQ(m.dy, 0);
  // Rows only: period 5 vertically, constant along x -> every dx ties; dy = 0 and dx = 0 win.
  Frame c{50, 50, std::vector<uint8_t>(2500)};
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 50; ++x) c.px[size_t(y) * 50 + x] = uint8_t(40 * (y % 5) + 10);
  m = match(c, c, {25, 25}, 2, 7)[0];
  EXPECT_EQ(m.dx, 0);
  EXPECT_EQ(m.dy, 0);
  // Shifted by one row: copies at dy = 1 and dy = -4, 6 (period 5); dy = 1, dx = 0 wins.
  m = match(c, shifted(c, 0, 1), {25, 25}, 2, 7)[0];
  EXPECT_EQ(m.dx, 0);
  EXPECT_EQ(m.dy, 1);
}

}  // namespace
