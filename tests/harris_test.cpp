// Host tests of the Harris C references (bvb/harris.h): the response against a direct evaluation
// of the documented formulas, its behaviour on a hand-made square (corners, edges, flat areas),
// the candidates against a brute-force reading of the tie rule, and the greedy selection.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "bvb/harris.h"

namespace {

// The documented formulas, evaluated per output pixel in 64-bit with no row buffers.
std::vector<int64_t> direct_response(const std::vector<uint8_t> &img, int w, int h) {
  auto I = [&](int x, int y) { return int64_t(img[size_t(y) * w + x]); };
  auto gx = [&](int x, int y) { return I(x + 1, y) - I(x - 1, y); };
  auto gy = [&](int x, int y) { return I(x, y + 1) - I(x, y - 1); };
  auto floordiv32 = [](int64_t v) { return v >= 0 ? v / 32 : -((-v + 31) / 32); };
  std::vector<int64_t> r(size_t(w) * h, 0);
  for (int y = 2; y <= h - 3; ++y)
    for (int x = 2; x <= w - 3; ++x) {
      int64_t a = 0, b = 0, c = 0;
      for (int dx = -1; dx <= 1; ++dx) {
        int64_t sxx = 0, syy = 0, sxy = 0;
        for (int dy = -1; dy <= 1; ++dy) {
          sxx += gx(x + dx, y + dy) * gx(x + dx, y + dy);
          syy += gy(x + dx, y + dy) * gy(x + dx, y + dy);
          sxy += gx(x + dx, y + dy) * gy(x + dx, y + dy);
        }
        a += floordiv32(sxx);
        b += floordiv32(syy);
        c += floordiv32(sxy);
      }
      const int64_t hh = (a + b) / 2, kh = hh * BVB_HARRIS_K4_Q15 / 32768;
      r[size_t(y) * w + x] = a * b - c * c - kh * hh;
    }
  return r;
}

std::vector<int32_t> response(const std::vector<uint8_t> &img, int w, int h) {
  std::vector<int32_t> r(size_t(w) * h, 12345);
  std::vector<uint8_t> scratch(BVB_HARRIS_SCRATCH_BYTES(w));
  bvb_harris_response_c(img.data(), r.data(), w, h, w, w, scratch.data());
  return r;
}

// A dark frame with a bright square: corners at (x0, y0), (x1, y0), (x0, y1), (x1, y1).
std::vector<uint8_t> square(int w, int h, int x0, int y0, int x1, int y1) {
  std::vector<uint8_t> img(size_t(w) * h, 30);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) img[size_t(y) * w + x] = 210;
  return img;
}

TEST(HarrisResponse, MatchesDirectEvaluation) {
  std::mt19937 gen(7);
  for (auto [w, h] : std::vector<std::pair<int, int>>{{5, 5}, {9, 7}, {16, 11}, {23, 19}}) {
    for (int kind = 0; kind < 4; ++kind) {
      std::vector<uint8_t> img(size_t(w) * h);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          uint8_t v = uint8_t(gen());
          if (kind == 1) v = ((x & 3) < 2) != ((y & 3) < 2) ? 255 : 0;  // |gx| = |gy| = 255 everywhere
          if (kind == 2) v = ((x - y) & 3) < 2 ? 255 : 0;                // the most negative c
          if (kind == 3) v = uint8_t(x * 40 + y * 3);
          img[size_t(y) * w + x] = v;
        }
      auto got = response(img, w, h);
      auto want = direct_response(img, w, h);
      for (size_t i = 0; i < got.size(); ++i) ASSERT_EQ(int64_t(got[i]), want[i]) << w << "x" << h << " kind " << kind << " at " << i;
    }
  }
}

TEST(HarrisResponse, CornerIsStrongestAndEdgesAreNegative) {
  const int w = 28, h = 24;
  auto img = square(w, h, 9, 7, 18, 16);
  auto r = response(img, w, h);
  auto at = [&](int x, int y) { return r[size_t(y) * w + x]; };
  // The strongest response of the frame is at (or next to) one of the four corners.
  const int best = int(std::max_element(r.begin(), r.end()) - r.begin());
  const int bx = best % w, by = best / w;
  bool near_corner = false;
  for (int cx : {9, 18})
    for (int cy : {7, 16}) near_corner |= std::abs(bx - cx) <= 1 && std::abs(by - cy) <= 1;
  EXPECT_TRUE(near_corner) << "strongest at " << bx << "," << by;
  // Every corner has a positive response peak within one pixel.
  for (int cx : {9, 18})
    for (int cy : {7, 16}) {
      int32_t peak = INT32_MIN;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) peak = std::max(peak, at(cx + dx, cy + dy));
      EXPECT_GT(peak, 0) << "corner " << cx << "," << cy;
      // The middle of the edges next to it: negative (one strong direction only), far below.
      EXPECT_LT(at(13, cy), 0) << "horizontal edge at y " << cy;
      EXPECT_LT(at(cx, 11), 0) << "vertical edge at x " << cx;
    }
  // Flat areas: nothing.
  EXPECT_EQ(at(3, 3), 0);
  EXPECT_EQ(at(13, 11), 0);
  // The border is 0 by definition.
  EXPECT_EQ(at(1, 10), 0);
  EXPECT_EQ(at(10, h - 2), 0);
}

// The tie rule read literally: greater than the four neighbours before, >= the four after.
std::vector<int32_t> brute_nms(const std::vector<int32_t> &r, int w, int h, int32_t thr) {
  std::vector<int32_t> out;
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const int32_t v = r[size_t(y) * w + x];
      bool ok = v > thr;
      for (int dy = -1; dy <= 1 && ok; ++dy)
        for (int dx = -1; dx <= 1 && ok; ++dx) {
          if (!dx && !dy) continue;
          const int32_t n = r[size_t(y + dy) * w + x + dx];
          const bool before = dy < 0 || (dy == 0 && dx < 0);
          ok = before ? v > n : v >= n;
        }
      if (ok) {
        out.push_back(y << 16 | x);
        out.push_back(v);
      }
    }
  return out;
}

TEST(HarrisNms, MatchesBruteForceAndKeepsTheFirstOfATie) {
  std::mt19937 gen(3);
  for (int trial = 0; trial < 20; ++trial) {
    const int w = 3 + int(gen() % 20), h = 3 + int(gen() % 15);
    std::vector<int32_t> r(size_t(w) * h);
    for (auto &v : r) v = int32_t(gen() % (trial < 10 ? 4 : 1000)) - 1;  // plateaus when few values
    std::vector<int32_t> cand(size_t(BVB_HARRIS_NMS_CAPACITY(w, h)) * 2 + 2, -7);
    int32_t n = -1;
    const int32_t ret = bvb_harris_nms_c(r.data(), w, h, w, 0, cand.data(), &n, nullptr);
    ASSERT_EQ(ret, n);
    auto want = brute_nms(r, w, h, 0);
    ASSERT_EQ(size_t(n) * 2, want.size()) << "trial " << trial;
    for (size_t i = 0; i < want.size(); ++i) EXPECT_EQ(cand[i], want[i]);
    EXPECT_EQ(cand[want.size()], -7);  // nothing written past the count
  }
  // Two equal neighbours: only the first in raster order.
  const int w = 5, h = 4;
  std::vector<int32_t> r(size_t(w) * h, 0);
  r[1 * w + 2] = 9;
  r[2 * w + 3] = 9;
  std::vector<int32_t> cand(16);
  int32_t n = 0;
  bvb_harris_nms_c(r.data(), w, h, w, 0, cand.data(), &n, nullptr);
  ASSERT_EQ(n, 1);
  EXPECT_EQ(cand[0], 1 << 16 | 2);
}

TEST(HarrisSelect, StrongestFirstWithSpacing) {
  // Candidates (key, R): two strong ones close together, weaker ones apart, a tie.
  std::vector<int32_t> cand = {
      5 << 16 | 5, 100,   // taken first
      5 << 16 | 7, 90,    // 2 px from it: dropped at distance 3
      20 << 16 | 20, 50,  // taken
      2 << 16 | 30, 50,   // same R, larger key than (20, 20)? no: smaller key, so before it
      9 << 16 | 9, 10,    // taken last
      0, 0};              // room for the sentinel
  std::vector<int32_t> corners(12, -1);
  const int32_t n = bvb_harris_select_c(cand.data(), 5, 4, 3, corners.data());
  ASSERT_EQ(n, 4);
  const std::vector<int32_t> want = {5, 5, 100, 30, 2, 50, 20, 20, 50, 9, 9, 10};
  EXPECT_EQ(corners, want);
}

TEST(HarrisCorners, SquareCornersAreFound) {
  const int w = 40, h = 32;
  auto img = square(w, h, 10, 8, 29, 23);
  auto r = response(img, w, h);
  const int32_t maxv = *std::max_element(r.begin(), r.end());
  std::vector<int32_t> cand(size_t(BVB_HARRIS_NMS_CAPACITY(w, h) + 1) * 2);
  int32_t n = 0;
  bvb_harris_nms_c(r.data(), w, h, w, maxv / 10, cand.data(), &n, nullptr);
  std::vector<int32_t> corners(4 * 3);
  const int32_t taken = bvb_harris_select_c(cand.data(), n, 4, 5, corners.data());
  ASSERT_EQ(taken, 4);
  for (int cx : {10, 29})
    for (int cy : {8, 23}) {
      bool found = false;
      for (int k = 0; k < 4; ++k) found |= std::abs(corners[3 * k] - cx) <= 1 && std::abs(corners[3 * k + 1] - cy) <= 1;
      EXPECT_TRUE(found) << "corner " << cx << "," << cy;
    }
}

}  // namespace
