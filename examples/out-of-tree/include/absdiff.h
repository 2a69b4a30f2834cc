/* Absolute difference of two 8-bit frames: dst = |a - b|, per pixel (frame differencing, the
 * SRV-1 firmware's motion detector).
 *
 * a, b: width x height, src_stride bytes between rows. dst: dst_stride bytes between rows.
 * width, height >= 1; strides >= width. No alignment required. */
#ifndef ABSDIFF_H
#define ABSDIFF_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

void absdiff_u8_c(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t width, int32_t height,
                  int32_t src_stride, int32_t dst_stride);
void absdiff_u8_asm(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t width, int32_t height,
                    int32_t src_stride, int32_t dst_stride);

#ifdef __cplusplus
}
#endif

#endif
