/* The C reference of absdiff.h: compiled for the host (the checks' reference) and for the
 * Blackfin (absdiff_u8's C implementation). */
#include "absdiff.h"

void absdiff_u8_c(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t width, int32_t height,
                  int32_t src_stride, int32_t dst_stride) {
  for (int32_t y = 0; y < height; ++y) {
    const uint8_t *ra = a + y * src_stride, *rb = b + y * src_stride;
    uint8_t *rd = dst + y * dst_stride;
    for (int32_t x = 0; x < width; ++x) rd[x] = (uint8_t)(ra[x] > rb[x] ? ra[x] - rb[x] : rb[x] - ra[x]);
  }
}
