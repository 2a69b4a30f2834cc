#include "bvb/sobel.h"

/* The textbook form: both 3x3 masks at every interior pixel, the ring set to 0. The assembly
 * computes the same integers another way (bvb/sobel.h); nothing here is shaped after it. */

static int32_t gx_at(const uint8_t *r0, const uint8_t *r1, const uint8_t *r2, int32_t x) {
  return (r0[x + 1] - r0[x - 1]) + 2 * (r1[x + 1] - r1[x - 1]) + (r2[x + 1] - r2[x - 1]);
}

static int32_t gy_at(const uint8_t *r0, const uint8_t *r2, int32_t x) {
  return (r2[x - 1] + 2 * r2[x] + r2[x + 1]) - (r0[x - 1] + 2 * r0[x] + r0[x + 1]);
}

static uint8_t magnitude(int32_t gx, int32_t gy) {
  int32_t m = (gx < 0 ? -gx : gx) + (gy < 0 ? -gy : gy);
  return (uint8_t)(m > 255 ? 255 : m);
}

void bvb_sobel3x3_u8_c(const uint8_t *src, int32_t src_stride, uint8_t *dst, int32_t dst_stride,
                       int32_t width, int32_t height, void *scratch) {
  (void)scratch;
  for (int32_t y = 0; y < height; ++y) {
    uint8_t *d = dst + y * dst_stride;
    if (y == 0 || y == height - 1) {
      for (int32_t x = 0; x < width; ++x) d[x] = 0;
      continue;
    }
    const uint8_t *r0 = src + (y - 1) * src_stride, *r1 = r0 + src_stride, *r2 = r1 + src_stride;
    d[0] = 0;
    for (int32_t x = 1; x < width - 1; ++x) d[x] = magnitude(gx_at(r0, r1, r2, x), gy_at(r0, r2, x));
    d[width - 1] = 0;
  }
}

void bvb_sobel3x3_s16_c(const uint8_t *src, int32_t src_stride, int16_t *gx, int16_t *gy,
                        int32_t g_stride, uint8_t *mag, int32_t mag_stride, int32_t width,
                        int32_t height, void *scratch) {
  (void)scratch;
  for (int32_t y = 0; y < height; ++y) {
    int16_t *ox = gx + y * g_stride, *oy = gy + y * g_stride;
    uint8_t *om = mag ? mag + y * mag_stride : 0;
    if (y == 0 || y == height - 1) {
      for (int32_t x = 0; x < width; ++x) {
        ox[x] = 0;
        oy[x] = 0;
        if (om) om[x] = 0;
      }
      continue;
    }
    const uint8_t *r0 = src + (y - 1) * src_stride, *r1 = r0 + src_stride, *r2 = r1 + src_stride;
    ox[0] = oy[0] = ox[width - 1] = oy[width - 1] = 0;
    if (om) om[0] = om[width - 1] = 0;
    for (int32_t x = 1; x < width - 1; ++x) {
      const int32_t a = gx_at(r0, r1, r2, x), b = gy_at(r0, r2, x);
      ox[x] = (int16_t)a;
      oy[x] = (int16_t)b;
      if (om) om[x] = magnitude(a, b);
    }
  }
}
