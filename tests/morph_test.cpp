// 3x3 erosion and dilation (C reference) on hand-drawn masks, and against a brute-force min/max
// over the in-image neighbourhood.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "bvb/morph.h"
#include "check.h"

namespace {

// A mask from rows of '#' (255) and '.' (0).
std::vector<uint8_t> mask(const std::vector<std::string> &rows) {
  std::vector<uint8_t> m;
  for (const auto &r : rows)
    for (char c : r) m.push_back(c == '#' ? 255 : 0);
  return m;
}

std::vector<uint8_t> run(bool dilate, const std::vector<uint8_t> &src, int w, int h) {
  std::vector<uint8_t> dst(size_t(w) * h, 0x5A);
  std::vector<uint8_t> scratch(BVB_MORPH3X3_SCRATCH_BYTES(w));
  if (dilate)
    bvb_dilate3x3_u8_c(src.data(), dst.data(), w, h, w, w, scratch.data());
  else
    bvb_erode3x3_u8_c(src.data(), dst.data(), w, h, w, w, scratch.data());
  return dst;
}

TEST(Morph, DilationOfOnePixelIsA3x3Square) {
  const auto in = mask({".......",
                        ".......",
                        "....#..",
                        ".......",
                        "......."});
  const auto want = mask({".......",
                          "...###.",
                          "...###.",
                          "...###.",
                          "......."});
  EXPECT_EQ(run(true, in, 7, 5), want);
}

TEST(Morph, DilationAtACornerStaysInside) {
  // The replicated border does not grow the mask from outside: a corner pixel gives 2x2.
  const auto in = mask({"#....",
                        ".....",
                        "....."});
  const auto want = mask({"##...",
                          "##...",
                          "....."});
  EXPECT_EQ(run(true, in, 5, 3), want);
}

TEST(Morph, ErosionOfABlob) {
  // A 5x4 block with a one-pixel spur: the block shrinks by one on every side, the spur goes.
  const auto in = mask({".........",
                        ".#####...",
                        ".#####...",
                        ".######..",
                        ".#####...",
                        "........#"});
  const auto want = mask({".........",
                          ".........",
                          "..###....",
                          "..###....",
                          ".........",
                          "........."});
  EXPECT_EQ(run(false, in, 9, 6), want);
}

TEST(Morph, ErosionDoesNotEatFromTheBorder) {
  // Outside counts as a copy of the edge, so a mask filling the left columns keeps them.
  const auto in = mask({"###..",
                        "###..",
                        "###..",
                        "###.."});
  const auto want = mask({"##...",
                          "##...",
                          "##...",
                          "##..."});
  EXPECT_EQ(run(false, in, 5, 4), want);
  const std::vector<uint8_t> full(12, 255);
  EXPECT_EQ(run(false, full, 4, 3), full);
}

TEST(Morph, GreyMatchesBruteForceMinMax) {
  bvb::Rng rng(7);
  for (int w = 1; w <= 9; ++w)
    for (int h = 1; h <= 5; ++h) {
      std::vector<uint8_t> src(size_t(w) * h);
      for (auto &v : src) v = uint8_t(rng.u32());
      for (bool dilate : {false, true}) {
        const auto got = run(dilate, src, w, h);
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            int lo = 255, hi = 0;
            for (int yy = y - 1; yy <= y + 1; ++yy)
              for (int xx = x - 1; xx <= x + 1; ++xx) {
                if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
                lo = std::min<int>(lo, src[size_t(yy) * w + xx]);
                hi = std::max<int>(hi, src[size_t(yy) * w + xx]);
              }
            ASSERT_EQ(got[size_t(y) * w + x], dilate ? hi : lo) << w << "x" << h << " at " << x << "," << y;
          }
      }
    }
}

}  // namespace
