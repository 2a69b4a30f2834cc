#include "bvb/dma_copy.h"

/* The plain row copy the DMA bands must reproduce. */
void bvb_dma_copy_u8_c(const uint8_t *src, int32_t src_stride, uint8_t *dst, int32_t dst_stride,
                       int32_t width, int32_t height, int32_t band, void *scratch) {
  (void)band;
  (void)scratch;
  for (int32_t y = 0; y < height; ++y)
    for (int32_t x = 0; x < width; ++x) dst[y * dst_stride + x] = src[y * src_stride + x];
}
