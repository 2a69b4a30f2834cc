#include "bvb/morph.h"

/* The neighbourhood is clipped to the image (row and column indices clamped), which is what
 * replicating the edge gives for a min or a max. */
#define MORPH3X3(name, better)                                                                     \
  void name(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height, int32_t src_stride,  \
            int32_t dst_stride, void *scratch) {                                                   \
    (void)scratch;                                                                                 \
    for (int32_t y = 0; y < height; ++y) {                                                         \
      const uint8_t *a = src + (y > 0 ? y - 1 : 0) * src_stride;                                   \
      const uint8_t *b = src + y * src_stride;                                                     \
      const uint8_t *c = src + (y + 1 < height ? y + 1 : y) * src_stride;                          \
      uint8_t *d = dst + y * dst_stride;                                                           \
      for (int32_t x = 0; x < width; ++x) {                                                        \
        const int32_t l = x > 0 ? x - 1 : 0, r = x + 1 < width ? x + 1 : x;                        \
        int32_t m = b[x];                                                                          \
        if (better(a[l], m)) m = a[l];                                                             \
        if (better(a[x], m)) m = a[x];                                                             \
        if (better(a[r], m)) m = a[r];                                                             \
        if (better(b[l], m)) m = b[l];                                                             \
        if (better(b[r], m)) m = b[r];                                                             \
        if (better(c[l], m)) m = c[l];                                                             \
        if (better(c[x], m)) m = c[x];                                                             \
        if (better(c[r], m)) m = c[r];                                                             \
        d[x] = (uint8_t)m;                                                                         \
      }                                                                                            \
    }                                                                                              \
  }

#define LESS(v, m) ((v) < (m))
#define GREATER(v, m) ((v) > (m))

MORPH3X3(bvb_erode3x3_u8_c, LESS)
MORPH3X3(bvb_dilate3x3_u8_c, GREATER)
