#include "bvb/add_sat.h"

void bvb_add_sat_u8_c(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t width,
                      int32_t height, int32_t src_stride, int32_t dst_stride, void *scratch) {
  (void)scratch;
  for (int32_t y = 0; y < height; ++y) {
    for (int32_t x = 0; x < width; ++x) {
      int32_t s = a[x] + b[x];
      dst[x] = (uint8_t)(s > 255 ? 255 : s);
    }
    a += src_stride;
    b += src_stride;
    dst += dst_stride;
  }
}
