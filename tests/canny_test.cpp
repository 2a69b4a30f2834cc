// The Canny C reference (bvb/canny.h) on hand-made images, and against an independent
// floating-point implementation of the same definition.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <vector>

#include "bvb/canny.h"

namespace {

struct Grad {
  int w, h;
  std::vector<int16_t> gx, gy;
};

// Raw 3x3 Sobel, outer ring 0 (the Sobel kernel's contract).
Grad sobel(const std::vector<uint8_t> &img, int w, int h) {
  Grad g{w, h, std::vector<int16_t>(size_t(w) * h), std::vector<int16_t>(size_t(w) * h)};
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      auto p = [&](int dx, int dy) { return int(img[size_t(y + dy) * w + x + dx]); };
      g.gx[size_t(y) * w + x] = int16_t(p(1, -1) + 2 * p(1, 0) + p(1, 1) - p(-1, -1) - 2 * p(-1, 0) - p(-1, 1));
      g.gy[size_t(y) * w + x] = int16_t(p(-1, 1) + 2 * p(0, 1) + p(1, 1) - p(-1, -1) - 2 * p(0, -1) - p(1, -1));
    }
  return g;
}

// The kernel with a stack of `cap` entries (-1: one that never fills).
std::vector<uint8_t> canny(const Grad &g, int low, int high, int cap = -1, int32_t *passes = nullptr) {
  const int w = g.w, h = g.h;
  std::vector<uint8_t> e(size_t(w) * h, 0x5A);
  std::vector<uint16_t> mag(size_t(BVB_CANNY_MAG_ROWS(w)));
  if (cap < 0) cap = BVB_CANNY_STACK_ENTRIES(w, h);
  std::vector<int32_t> stack(size_t(cap) + 1);
  int32_t r = bvb_canny_c(g.gx.data(), g.gy.data(), w, e.data(), w, w, h, low, high, mag.data(), stack.data(), cap);
  if (passes) *passes = r;
  return e;
}

// Canny as the textbook states it, written independently: the direction sector from atan2 in
// degrees, then the neighbour comparisons, then hysteresis as a flood fill over a std::deque.
std::vector<uint8_t> canny_reference(const Grad &g, int low, int high) {
  const int w = g.w, h = g.h;
  std::vector<int> mag(size_t(w) * h);
  for (size_t i = 0; i < mag.size(); ++i) mag[i] = std::abs(g.gx[i]) + std::abs(g.gy[i]);
  auto M = [&](int x, int y) { return mag[size_t(y) * w + x]; };
  std::vector<int> state(size_t(w) * h, 0);  // 0 none, 1 weak, 2 strong
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const int gx = g.gx[size_t(y) * w + x], gy = g.gy[size_t(y) * w + x];
      const int m = M(x, y);
      if (m < low) continue;
      const double deg = std::atan2(std::abs(gy), std::abs(gx)) * 180.0 / M_PI;  // 0..90
      int ax, ay, bx, by;  // a before b in raster order
      if (deg < 22.5) {
        ax = x - 1, ay = y, bx = x + 1, by = y;
      } else if (deg > 67.5) {
        ax = x, ay = y - 1, bx = x, by = y + 1;
      } else if ((gx > 0) == (gy > 0)) {  // gradient towards (+1, +1) or (-1, -1)
        ax = x - 1, ay = y - 1, bx = x + 1, by = y + 1;
      } else {
        ax = x + 1, ay = y - 1, bx = x - 1, by = y + 1;
      }
      if (m > M(ax, ay) && m >= M(bx, by)) state[size_t(y) * w + x] = m >= high ? 2 : 1;
    }
  std::vector<uint8_t> out(size_t(w) * h, 0);
  std::deque<std::pair<int, int>> q;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (state[size_t(y) * w + x] == 2) {
        out[size_t(y) * w + x] = 255;
        q.push_back({x, y});
      }
  while (!q.empty()) {
    auto [x, y] = q.front();
    q.pop_front();
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const size_t i = size_t(ny) * w + nx;
        if (state[i] == 1 && !out[i]) {
          out[i] = 255;
          q.push_back({nx, ny});
        }
      }
  }
  return out;
}

int edge_neighbours(const std::vector<uint8_t> &e, int w, int h, int x, int y) {
  int n = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if ((dx || dy) && nx >= 0 && ny >= 0 && nx < w && ny < h && e[size_t(ny) * w + nx]) ++n;
    }
  return n;
}

TEST(Canny, SquareGivesItsOutlineOnePixelThick) {
  // A bright 10x10 square (x, y in 8..17, value 200) on black. Along each straight side the two
  // pixels either side of the step see the same magnitude (4 x 200 = 800); the tie rule keeps
  // the one first in raster order: the column left of the left side (x = 7), the square's own
  // right column (x = 17), the row above the top (y = 7), the square's own bottom row (y = 17).
  // Corners, worked out by hand from the Sobel sums: the corner pixels of the square itself have
  // magnitude 1200 with a diagonal gradient and win over their diagonal neighbours (400 outside,
  // 0 inside); the outside pixels next to a corner (800, gradient 3:1 towards the corner) lose
  // to them. So the top-left corner is cut diagonally by (8, 8), the top-right corner is
  // (17, 8) at the top of the right column, the bottom row runs x = 8..17, and the bottom-right
  // corner (17, 17) closes an L with (17, 16) and (16, 17).
  const int w = 26, h = 26, x0 = 8, x1 = 17, y0 = 8, y1 = 17;
  std::vector<uint8_t> img(size_t(w) * h, 0);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) img[size_t(y) * w + x] = 200;
  const auto e = canny(sobel(img, w, h), 100, 300);
  std::vector<uint8_t> want(size_t(w) * h, 0);
  auto set = [&](int x, int y) { want[size_t(y) * w + x] = 255; };
  for (int x = x0 + 1; x <= x1 - 1; ++x) set(x, y0 - 1);  // top: the row above
  for (int y = y0 + 1; y <= y1 - 1; ++y) set(x0 - 1, y);  // left: the column left of it
  set(x0, y0);                                          // top-left corner, diagonal
  for (int y = y0; y <= y1 - 1; ++y) set(x1, y);        // right: the square's own column
  for (int x = x0; x <= x1; ++x) set(x, y1);            // bottom: the square's own row
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) EXPECT_EQ(e[size_t(y) * w + x], want[size_t(y) * w + x]) << "at " << x << "," << y;
  // What makes it an outline: one 8-connected closed curve (no end points) without a 2x2 block.
  int count = 0, first = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!e[size_t(y) * w + x]) continue;
      ++count;
      if (first < 0) first = y * w + x;
      EXPECT_GE(edge_neighbours(e, w, h, x, y), 2) << "an end point at " << x << "," << y;
      if (x + 1 < w && y + 1 < h) {
        EXPECT_FALSE(e[size_t(y) * w + x + 1] && e[size_t(y + 1) * w + x] && e[size_t(y + 1) * w + x + 1])
            << "a 2x2 block at " << x << "," << y;
      }
    }
  std::vector<uint8_t> seen(e.size(), 0);
  std::deque<int> q{first};
  seen[size_t(first)] = 1;
  int reached = 0;
  while (!q.empty()) {
    const int p = q.front();
    q.pop_front();
    ++reached;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int n = p + dy * w + dx;
        if (e[size_t(n)] && !seen[size_t(n)]) seen[size_t(n)] = 1, q.push_back(n);
      }
  }
  EXPECT_EQ(reached, count);
  EXPECT_EQ(count, 36);
}

// Gradients drawn by hand: the kernel's input is the Sobel output, so hysteresis can be tested
// with exact magnitudes.
Grad blank(int w, int h) { return Grad{w, h, std::vector<int16_t>(size_t(w) * h), std::vector<int16_t>(size_t(w) * h)}; }
void put(Grad &g, int x, int y, int gx, int gy) {
  g.gx[size_t(y) * g.w + x] = int16_t(gx);
  g.gy[size_t(y) * g.w + x] = int16_t(gy);
}

TEST(Canny, WeakEdgeSurvivesOnlyWhenLinkedToAStrongOne) {
  // Two vertical ridges of horizontal gradient (a vertical edge line each), magnitude 100: weak
  // for low 50, high 200. The first has one strong pixel (300) at its top; the second has none.
  Grad g = blank(24, 16);
  for (int y = 2; y <= 12; ++y) put(g, 5, y, y == 2 ? 300 : 100, 0);
  for (int y = 2; y <= 12; ++y) put(g, 15, y, 100, 0);
  const auto e = canny(g, 50, 200);
  for (int y = 0; y < 16; ++y) {
    EXPECT_EQ(e[size_t(y) * 24 + 5], (y >= 2 && y <= 12) ? 255 : 0) << "linked ridge, row " << y;
    EXPECT_EQ(e[size_t(y) * 24 + 15], 0) << "isolated ridge, row " << y;
  }
  // Raised to strong, the second ridge appears whole.
  put(g, 15, 12, 250, 0);
  const auto e2 = canny(g, 50, 200);
  for (int y = 2; y <= 12; ++y) EXPECT_EQ(e2[size_t(y) * 24 + 15], 255) << "row " << y;
}

TEST(Canny, WeakChainLinksThroughDiagonalSteps) {
  // A staircase of weak pixels running down-right, each pixel's gradient perpendicular to the
  // staircase (Gx = 100, Gy = -100: the 135 deg sector, neighbours (x+1, y-1) and (x-1, y+1),
  // which are off the chain and 0). Only its first pixel is strong; all of it must survive,
  // through 8-connected (diagonal) links only. The same staircase without the strong pixel
  // vanishes.
  for (bool strong : {true, false}) {
    Grad g = blank(20, 20);
    for (int i = 0; i < 14; ++i) put(g, 3 + i, 3 + i, strong && i == 0 ? 300 : 100, -100);
    for (int cap : {-1, 0, 1, 2}) {
      int32_t passes = -1;
      const auto e = canny(g, 50, 250, cap, &passes);
      for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) {
          const bool on = strong && x == y && x >= 3 && x < 17;
          EXPECT_EQ(e[size_t(y) * 20 + x], on ? 255 : 0) << "strong " << strong << " stack " << cap << " at " << x << "," << y;
        }
      // Without a stack every link comes from a raster pass: the staircase runs in raster
      // order, so one pass links it all, and a second finds nothing more.
      if (strong && cap == 0) {
        EXPECT_GE(passes, 1);
      }
      if (cap < 0) {
        EXPECT_EQ(passes, 0);
      }
    }
  }
}

TEST(Canny, StackOverflowFallbackIsExactAgainstTheRasterOrder) {
  // A weak chain that runs up and to the left from its strong end at the bottom right: a raster
  // pass links it one pixel per pass, the hardest case for the fallback.
  Grad g = blank(30, 8);
  for (int x = 2; x <= 27; ++x) put(g, x, 4, 0, x == 27 ? 400 : 120);  // horizontal line, strong at its right end
  for (int cap : {-1, 0, 1, 3}) {
    int32_t passes = 0;
    const auto e = canny(g, 60, 300, cap, &passes);
    for (int x = 0; x < 30; ++x) EXPECT_EQ(e[4 * 30 + x], (x >= 2 && x <= 27) ? 255 : 0) << "stack " << cap << " x " << x;
    if (cap == 0) {
      EXPECT_GE(passes, 25);  // right to left, against the raster order: a pixel a pass
    }
  }
}

TEST(Canny, PlateauAlongTheGradientKeepsTheFirstPixel) {
  // Two columns of equal magnitude side by side along x: the first in raster order is kept.
  Grad g = blank(12, 8);
  for (int y = 1; y <= 6; ++y) put(g, 4, y, 500, 0), put(g, 5, y, 500, 0);
  const auto e = canny(g, 100, 200);
  for (int y = 1; y <= 6; ++y) {
    EXPECT_EQ(e[size_t(y) * 12 + 4], 255);
    EXPECT_EQ(e[size_t(y) * 12 + 5], 0);
  }
}

TEST(Canny, OuterRingAndTinyFramesAreNeverEdges) {
  for (int w = 1; w <= 4; ++w)
    for (int h = 1; h <= 4; ++h) {
      Grad g = blank(w, h);
      for (size_t i = 0; i < g.gx.size(); ++i) g.gx[i] = int16_t(1000 - 37 * int(i)), g.gy[i] = int16_t(11 * int(i));
      const auto e = canny(g, 1, 1);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (x == 0 || y == 0 || x == w - 1 || y == h - 1) {
            EXPECT_EQ(e[size_t(y) * w + x], 0) << w << "x" << h;
          }
    }
}

TEST(Canny, MatchesIndependentImplementation) {
  uint32_t s = 12345;
  auto rnd = [&]() { return s = s * 1664525u + 1013904223u, s >> 8; };
  for (int trial = 0; trial < 60; ++trial) {
    const int w = 3 + int(rnd() % 40), h = 3 + int(rnd() % 30);
    Grad g;
    if (trial % 3 == 2) {
      // Raw gradients over the whole range, every sector and sign; coarse levels make ties.
      g = blank(w, h);
      const int levels = 1 + int(rnd() % 6);
      for (size_t i = 0; i < g.gx.size(); ++i) {
        g.gx[i] = int16_t((int(rnd() % (2 * levels + 1)) - levels) * (1020 / levels));
        g.gy[i] = int16_t((int(rnd() % (2 * levels + 1)) - levels) * (1020 / levels));
      }
    } else {
      // Blocks and noise: steps, corners, texture.
      std::vector<uint8_t> img(size_t(w) * h);
      const int blocks = int(rnd() % 5);
      for (auto &v : img) v = uint8_t(trial % 3 == 0 ? rnd() % 256 : 40 + rnd() % 16);
      for (int b = 0; b < blocks; ++b) {
        const int bx = int(rnd() % w), by = int(rnd() % h), bw = 1 + int(rnd() % 12), bh = 1 + int(rnd() % 12);
        const uint8_t v = uint8_t(rnd() % 256);
        for (int y = by; y < std::min(h, by + bh); ++y)
          for (int x = bx; x < std::min(w, bx + bw); ++x) img[size_t(y) * w + x] = v;
      }
      g = sobel(img, w, h);
    }
    const int low = 1 + int(rnd() % 300), high = low + int(rnd() % 500);
    const auto want = canny_reference(g, low, high);
    for (int cap : {-1, 0, 2, 7}) {
      const auto got = canny(g, low, high, cap);
      ASSERT_EQ(got, want) << "trial " << trial << " " << w << "x" << h << " low " << low << " high " << high
                           << " stack " << cap;
    }
  }
}

TEST(Canny, SectorRuleIsTheExactGeometricOne) {
  // Every (|Gx|, |Gy|) pair a Sobel can give: the kernel's integer rule against atan2.
  // One interior pixel with magnitude m and neighbours chosen so that exactly one sector's
  // pair lets it through.
  for (int ax = 0; ax <= 1020; ax += 3)
    for (int ay = 0; ay <= 1020; ay += 1) {
      if (ax + ay == 0) continue;
      const double deg = std::atan2(ay, ax) * 180.0 / M_PI;
      const int want = deg < 22.5 ? 0 : deg > 67.5 ? 90 : 45;
      // Sector 0 compares left/right, 90 up/down, 45 the main diagonal: make the other
      // neighbours larger, so only the expected sector's pair keeps the pixel.
      Grad g = blank(3, 3);
      put(g, 1, 1, ax, ay);
      const int m = ax + ay, big = std::min(m + 1, 2040);
      auto mag_at = [&](int x, int y, int v) { put(g, x, y, v, 0); };
      for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x)
          if (x != 1 || y != 1) mag_at(x, y, big);
      if (want == 0) mag_at(0, 1, 0), mag_at(2, 1, 0);
      if (want == 90) mag_at(1, 0, 0), mag_at(1, 2, 0);
      if (want == 45) mag_at(0, 0, 0), mag_at(2, 2, 0);
      if (m >= 2040) continue;  // no larger neighbour possible
      const auto e = canny(g, 1, 1);
      ASSERT_EQ(e[4], 255) << "ax " << ax << " ay " << ay << " expected sector " << want;
    }
}

}  // namespace
