// The Sobel C references against hand-worked images and against a plain 3x3 correlation with
// the two masks written out as tables.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include "bvb/sobel.h"

namespace {

struct Frame {
  int w, h, stride;
  std::vector<uint8_t> px;
  Frame(int w_, int h_, int stride_ = 0) : w(w_), h(h_), stride(stride_ ? stride_ : w_), px(size_t(stride) * h, 0) {}
  uint8_t &at(int x, int y) { return px[size_t(y) * stride + x]; }
};

struct Out {
  int w, h;
  std::vector<uint8_t> mag;
  std::vector<int16_t> gx, gy;
  std::vector<uint8_t> mag_s16;  // the s16 kernel's own magnitude output
};

// Runs both kernels; the u8 kernel's output rows and the s16 kernel's outputs have padding
// (filled with a marker) so writes past the row end show.
Out run(Frame &f) {
  Out o{f.w, f.h, {}, {}, {}, {}};
  const int ds = f.w + 3, gs = f.w + 2, ms = f.w + 5;
  std::vector<uint8_t> scratch(BVB_SOBEL3X3_SCRATCH_SIZE(f.w));
  std::vector<uint8_t> dst(size_t(ds) * f.h, 0xAB), mag(size_t(ms) * f.h, 0xCD);
  std::vector<int16_t> gx(size_t(gs) * f.h, 0x1234), gy(size_t(gs) * f.h, 0x1234);
  bvb_sobel3x3_u8_c(f.px.data(), f.stride, dst.data(), ds, f.w, f.h, scratch.data());
  bvb_sobel3x3_s16_c(f.px.data(), f.stride, gx.data(), gy.data(), gs, mag.data(), ms, f.w, f.h,
                     scratch.data());
  for (int y = 0; y < f.h; ++y) {
    for (int x = 0; x < f.w; ++x) {
      o.mag.push_back(dst[size_t(y) * ds + x]);
      o.gx.push_back(gx[size_t(y) * gs + x]);
      o.gy.push_back(gy[size_t(y) * gs + x]);
      o.mag_s16.push_back(mag[size_t(y) * ms + x]);
    }
    for (int x = f.w; x < ds; ++x) EXPECT_EQ(dst[size_t(y) * ds + x], 0xAB) << "u8 padding written";
    for (int x = f.w; x < gs; ++x) EXPECT_EQ(gx[size_t(y) * gs + x], 0x1234) << "gx padding written";
    for (int x = f.w; x < ms; ++x) EXPECT_EQ(mag[size_t(y) * ms + x], 0xCD) << "mag padding written";
  }
  return o;
}

int idx(const Out &o, int x, int y) { return y * o.w + x; }

void expect_ring_zero(const Out &o) {
  for (int y = 0; y < o.h; ++y)
    for (int x = 0; x < o.w; ++x)
      if (x == 0 || y == 0 || x == o.w - 1 || y == o.h - 1) {
        EXPECT_EQ(o.mag[idx(o, x, y)], 0) << x << "," << y;
        EXPECT_EQ(o.gx[idx(o, x, y)], 0) << x << "," << y;
        EXPECT_EQ(o.gy[idx(o, x, y)], 0) << x << "," << y;
      }
}

TEST(Sobel, FlatFrameIsZero) {
  Frame f(9, 7);
  for (auto &v : f.px) v = 173;
  Out o = run(f);
  for (size_t i = 0; i < o.mag.size(); ++i) {
    EXPECT_EQ(o.mag[i], 0);
    EXPECT_EQ(o.gx[i], 0);
    EXPECT_EQ(o.gy[i], 0);
  }
}

// A vertical step from a to b between columns e-1 and e: the two columns touching it see the
// full step in each of the mask's three rows, weighted 1 + 2 + 1, so |Gx| = 4 |b - a|.
TEST(Sobel, VerticalStepEdge) {
  const int e = 5, a = 20, b = 50;
  Frame f(10, 6);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) f.at(x, y) = x < e ? a : b;
  Out o = run(f);
  expect_ring_zero(o);
  for (int y = 1; y < f.h - 1; ++y)
    for (int x = 1; x < f.w - 1; ++x) {
      const int want = (x == e - 1 || x == e) ? 4 * (b - a) : 0;
      EXPECT_EQ(o.gx[idx(o, x, y)], want) << x << "," << y;
      EXPECT_EQ(o.gy[idx(o, x, y)], 0) << x << "," << y;
      EXPECT_EQ(o.mag[idx(o, x, y)], want) << x << "," << y;
    }
}

// The same step, falling and large: Gx = -4 * 100 = -400, the magnitude saturates at 255.
TEST(Sobel, StepSaturates) {
  Frame f(8, 5);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) f.at(x, y) = x < 4 ? 200 : 100;
  Out o = run(f);
  for (int y = 1; y < f.h - 1; ++y) {
    EXPECT_EQ(o.gx[idx(o, 3, y)], -400);
    EXPECT_EQ(o.gx[idx(o, 4, y)], -400);
    EXPECT_EQ(o.mag[idx(o, 3, y)], 255);
    EXPECT_EQ(o.mag[idx(o, 2, y)], 0);
  }
}

// A horizontal step: Gy = 4 * step on the two rows touching it, Gx = 0.
TEST(Sobel, HorizontalStepEdge) {
  Frame f(7, 9);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) f.at(x, y) = y < 4 ? 7 : 40;
  Out o = run(f);
  expect_ring_zero(o);
  for (int y = 1; y < f.h - 1; ++y)
    for (int x = 1; x < f.w - 1; ++x) {
      const int want = (y == 3 || y == 4) ? 4 * 33 : 0;
      EXPECT_EQ(o.gy[idx(o, x, y)], want);
      EXPECT_EQ(o.gx[idx(o, x, y)], 0);
      EXPECT_EQ(o.mag[idx(o, x, y)], want);
    }
}

// p = c*x + d*y: each mask row sees a difference of 2c, weighted 1 + 2 + 1: Gx = 8c, Gy = 8d.
TEST(Sobel, Ramps) {
  for (int c : {0, 1, 3}) {
    for (int d : {0, 2, 5}) {
      Frame f(12, 8);
      for (int y = 0; y < f.h; ++y)
        for (int x = 0; x < f.w; ++x) f.at(x, y) = uint8_t(c * x + d * y + 10);
      Out o = run(f);
      expect_ring_zero(o);
      for (int y = 1; y < f.h - 1; ++y)
        for (int x = 1; x < f.w - 1; ++x) {
          EXPECT_EQ(o.gx[idx(o, x, y)], 8 * c);
          EXPECT_EQ(o.gy[idx(o, x, y)], 8 * d);
          EXPECT_EQ(o.mag[idx(o, x, y)], std::min(255, 8 * c + 8 * d));
        }
    }
  }
}

// A single bright pixel v: its four direct neighbours see it through a weight of 2, the
// diagonal ones through 1 in each mask.
TEST(Sobel, Impulse) {
  Frame f(7, 7);
  const int v = 30;
  f.at(3, 3) = v;
  Out o = run(f);
  EXPECT_EQ(o.gx[idx(o, 2, 3)], 2 * v);   // the pixel is right of (2,3), middle row
  EXPECT_EQ(o.gx[idx(o, 4, 3)], -2 * v);
  EXPECT_EQ(o.gy[idx(o, 3, 2)], 2 * v);   // below (3,2)
  EXPECT_EQ(o.gy[idx(o, 3, 4)], -2 * v);
  EXPECT_EQ(o.gx[idx(o, 2, 2)], v);
  EXPECT_EQ(o.gy[idx(o, 2, 2)], v);
  EXPECT_EQ(o.gx[idx(o, 4, 4)], -v);
  EXPECT_EQ(o.gy[idx(o, 4, 4)], -v);
  EXPECT_EQ(o.mag[idx(o, 4, 2)], 2 * v);  // gx = -v, gy = +v
  EXPECT_EQ(o.mag[idx(o, 3, 3)], 0);
  EXPECT_EQ(o.mag[idx(o, 1, 1)], 0);
}

// The smallest frame has one interior pixel.
TEST(Sobel, Smallest) {
  Frame f(3, 3);
  const uint8_t p[9] = {1, 2, 3, 40, 50, 60, 200, 100, 0};
  for (int i = 0; i < 9; ++i) f.at(i % 3, i / 3) = p[i];
  Out o = run(f);
  // Gx = (3-1) + 2(60-40) + (0-200) = -158; Gy = (200+200+0) - (1+4+3) = 392.
  EXPECT_EQ(o.gx[idx(o, 1, 1)], -158);
  EXPECT_EQ(o.gy[idx(o, 1, 1)], 392);
  EXPECT_EQ(o.mag[idx(o, 1, 1)], 255);
  expect_ring_zero(o);
}

// The extremes the header promises: a full-scale edge through all three mask rows gives
// exactly +1020 (gx) and -1020 (gy).
TEST(Sobel, ExtremeGradients) {
  Frame f(5, 5);
  for (int y = 0; y < 5; ++y) f.at(4, y) = 255, f.at(3, y) = 255;
  for (int y = 0; y < 5; ++y) f.at(0, y) = 0;
  Out o = run(f);
  EXPECT_EQ(o.gx[idx(o, 2, 2)], 1020);
  Frame g(5, 5);
  for (int x = 0; x < 5; ++x) g.at(x, 0) = 255;
  Out q = run(g);
  EXPECT_EQ(q.gy[idx(q, 2, 1)], -1020);
}

// Both kernels against the masks as tables, on random frames with row padding.
TEST(Sobel, MatchesTableCorrelation) {
  static const int kx[3][3] = {{-1, 0, 1}, {-2, 0, 2}, {-1, 0, 1}};
  static const int ky[3][3] = {{-1, -2, -1}, {0, 0, 0}, {1, 2, 1}};
  std::mt19937 gen(12345);
  for (int t = 0; t < 40; ++t) {
    const int w = 3 + int(gen() % 20), h = 3 + int(gen() % 15);
    Frame f(w, h, w + int(gen() % 4));
    for (auto &v : f.px) {
      const unsigned r = gen() % 4;
      v = r == 0 ? 0 : r == 1 ? 255 : uint8_t(gen());
    }
    Out o = run(f);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        int sx = 0, sy = 0;
        if (x > 0 && y > 0 && x < w - 1 && y < h - 1)
          for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
              sx += kx[j][i] * f.at(x + i - 1, y + j - 1);
              sy += ky[j][i] * f.at(x + i - 1, y + j - 1);
            }
        const int m = std::min(255, std::abs(sx) + std::abs(sy));
        ASSERT_EQ(o.gx[idx(o, x, y)], sx) << w << "x" << h << " at " << x << "," << y;
        ASSERT_EQ(o.gy[idx(o, x, y)], sy) << w << "x" << h << " at " << x << "," << y;
        ASSERT_EQ(o.mag[idx(o, x, y)], m) << w << "x" << h << " at " << x << "," << y;
        ASSERT_EQ(o.mag_s16[idx(o, x, y)], m) << w << "x" << h << " at " << x << "," << y;
      }
  }
}

TEST(Sobel, S16WithoutMagnitude) {
  Frame f(6, 4);
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 4; ++y) f.at(x, y) = uint8_t(x * 9);
  std::vector<uint8_t> scratch(BVB_SOBEL3X3_SCRATCH_SIZE(6));
  std::vector<int16_t> gx(24, 7), gy(24, 7);
  bvb_sobel3x3_s16_c(f.px.data(), 6, gx.data(), gy.data(), 6, nullptr, 0, 6, 4, scratch.data());
  EXPECT_EQ(gx[6 + 2], 72);
  EXPECT_EQ(gy[6 + 2], 0);
  EXPECT_EQ(gx[0], 0);
}

}  // namespace
