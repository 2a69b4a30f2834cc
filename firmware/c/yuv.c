#include "bvb/yuv.h"

void bvb_uyvy_to_grey_c(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height,
                        int32_t src_stride, int32_t dst_stride, void *scratch) {
  (void)scratch;
  for (int32_t y = 0; y < height; ++y) {
    for (int32_t x = 0; x < width; ++x) dst[x] = src[2 * x + 1];
    src += src_stride;
    dst += dst_stride;
  }
}

static uint8_t clamp_u8(int32_t v) { return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v); }

void bvb_uyvy_to_rgb24_c(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height,
                         int32_t src_stride, int32_t dst_stride) {
  for (int32_t y = 0; y < height; ++y) {
    const uint8_t *s = src;
    uint8_t *d = dst;
    for (int32_t x = 0; x < width; x += 2) {
      const int32_t dd = s[0] - 128, e = s[2] - 128;
      const int32_t r = 409 * e + 128, g = -100 * dd - 208 * e + 128, b = 516 * dd + 128;
      const int32_t c0 = 298 * (s[1] - 16), c1 = 298 * (s[3] - 16);
      d[0] = clamp_u8((c0 + r) >> 8);
      d[1] = clamp_u8((c0 + g) >> 8);
      d[2] = clamp_u8((c0 + b) >> 8);
      d[3] = clamp_u8((c1 + r) >> 8);
      d[4] = clamp_u8((c1 + g) >> 8);
      d[5] = clamp_u8((c1 + b) >> 8);
      s += 4;
      d += 6;
    }
    src += src_stride;
    dst += dst_stride;
  }
}
