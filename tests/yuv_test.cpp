// The UYVY conversions' C reference against hand-made frames and an independent floating-point
// BT.601 inverse.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bvb/yuv.h"
#include "scene/render.h"

namespace {

TEST(UyvyToGrey, TakesTheYBytesOfEachPair) {
  // Two rows of 4 pixels, the second row after 3 bytes of padding (stride 11).
  const std::vector<uint8_t> src = {10, 1, 20, 2, 30, 3, 40, 4, 0xEE, 0xEE, 0xEE,
                                    50, 5, 60, 6, 70, 7, 80, 8};
  std::vector<uint8_t> dst(2 * 6, 0xAA);
  bvb_uyvy_to_grey_c(src.data(), dst.data(), 4, 2, 11, 6, nullptr);
  const std::vector<uint8_t> want = {1, 2, 3, 4, 0xAA, 0xAA, 5, 6, 7, 8, 0xAA, 0xAA};
  EXPECT_EQ(dst, want);
}

// One pixel pair of the given Y0, Y1 and chroma, converted.
std::vector<uint8_t> rgb_of(int y0, int y1, int u, int v) {
  const uint8_t src[4] = {uint8_t(u), uint8_t(y0), uint8_t(v), uint8_t(y1)};
  std::vector<uint8_t> dst(6);
  bvb_uyvy_to_rgb24_c(src, dst.data(), 2, 1, 4, 6);
  return dst;
}

TEST(UyvyToRgb, KnownColours) {
  // Studio range: black at Y 16, white at Y 235, grey with neutral chroma.
  EXPECT_EQ(rgb_of(16, 235, 128, 128), (std::vector<uint8_t>{0, 0, 0, 255, 255, 255}));
  // Y 126: 298 * 110 / 256 = 128.05.
  EXPECT_EQ(rgb_of(126, 126, 128, 128), (std::vector<uint8_t>{128, 128, 128, 128, 128, 128}));
  // Below black and above white clamp.
  EXPECT_EQ(rgb_of(0, 255, 128, 128), (std::vector<uint8_t>{0, 0, 0, 255, 255, 255}));
  // Full-scale chroma: V 240 alone saturates red (1.596 * 112 = 178.8 on top of grey 128).
  const auto red = rgb_of(126, 126, 128, 240);
  EXPECT_EQ(red[0], 255);
  EXPECT_EQ(red[2], 128);
  // Both pixels of a pair share the pair's chroma.
  const auto pair = rgb_of(60, 200, 90, 170);
  for (int c = 0; c < 3; ++c) EXPECT_LT(pair[c], pair[3 + c]);
}

TEST(UyvyToRgb, MatchesFloatingPointBt601) {
  // Every Y and a grid of chroma values: within one level of the real-valued inverse.
  std::vector<uint8_t> src, dst;
  for (int y = 16; y <= 235; ++y)
    for (int u = 16; u <= 240; u += 8)
      for (int v = 16; v <= 240; v += 8) src.insert(src.end(), {uint8_t(u), uint8_t(y), uint8_t(v), uint8_t(y)});
  const int w = int(src.size() / 2);
  dst.resize(size_t(w) * 3);
  bvb_uyvy_to_rgb24_c(src.data(), dst.data(), w, 1, 2 * w, 3 * w);
  auto clamp = [](double x) { return x < 0 ? 0.0 : x > 255 ? 255.0 : x; };
  // BT.601: Y' = (Y - 16) / 219, Pb = (U - 128) / 224, Pr = (V - 128) / 224, and
  // R = Y' + 1.402 Pr, G = Y' - 0.344136 Pb - 0.714136 Pr, B = Y' + 1.772 Pb, times 255.
  const double ks = 255.0 / 219, kc = 255.0 / 224;
  for (int i = 0; i < w; i += 2) {
    const double yy = ks * (src[2 * i + 1] - 16), d = kc * (src[2 * i] - 128.0), e = kc * (src[2 * i + 2] - 128.0);
    const double want[3] = {clamp(yy + 1.402 * e), clamp(yy - 0.344136 * d - 0.714136 * e), clamp(yy + 1.772 * d)};
    for (int c = 0; c < 3; ++c)
      ASSERT_LE(std::fabs(dst[3 * i + c] - want[c]), 1.0) << "Y " << int(src[2 * i + 1]) << " U " << int(src[2 * i])
                                                          << " V " << int(src[2 * i + 2]) << " channel " << c;
  }
}

TEST(UyvyToRgb, InvertsTheSceneGeneratorsConversion) {
  // Solid colours through the scene's RGB -> UYVY (harness/scene/render.h) come back within
  // two levels: the forward conversion floors, the inverse rounds.
  const int colours[][3] = {{0, 0, 0},     {255, 255, 255}, {255, 0, 0},   {0, 255, 0},   {0, 0, 255},
                            {255, 255, 0}, {0, 255, 255},   {255, 0, 255}, {128, 64, 32}, {17, 200, 99}};
  for (const auto &c : colours) {
    bvb::Image rgb(2, 1, 3);
    for (int x = 0; x < 2; ++x)
      for (int k = 0; k < 3; ++k) rgb.at(x, 0, k) = uint8_t(c[k]);
    const std::vector<uint8_t> uyvy = bvb::rgb_to_uyvy(rgb);
    std::vector<uint8_t> back(6), grey(2);
    bvb_uyvy_to_rgb24_c(uyvy.data(), back.data(), 2, 1, 4, 6);
    bvb_uyvy_to_grey_c(uyvy.data(), grey.data(), 2, 1, 4, 2, nullptr);
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(back[k], c[k % 3], 2) << c[0] << " " << c[1] << " " << c[2];
    // Grey is the scene generator's own Y.
    EXPECT_EQ(grey[0], bvb::rgb_to_grey(rgb).data[0]);
  }
}

}  // namespace
