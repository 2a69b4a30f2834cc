/* Camera conversion: UYVY 4:2:2 (the SRV-1 camera's byte order) to 8-bit grey and to RGB24.
 *
 * Source layout: each pair of pixels (2k, 2k+1) of a row is four bytes U Y0 V Y1, so a row of
 * `width` pixels is 2 * width bytes starting at src + y * src_stride. U and V belong to both
 * pixels of the pair. width must be even (>= 2), height >= 1; strides are in bytes, src_stride
 * >= 2 * width. No alignment is required of src, dst or the strides.
 *
 * uyvy_to_grey: dst[x] = Y of pixel x (the Y bytes, unchanged). dst_stride >= width.
 * scratch: BVB_UYVY_TO_GREY_SCRATCH_BYTES(width) bytes, 4-byte aligned: with the frames in
 * SDRAM and the scratch in L1 the assembly streams row bands through it (bvb/stream.h); the C
 * reference does not use it.
 *
 * uyvy_to_rgb24: dst holds R, G, B per pixel (3 * width bytes a row, dst_stride >= 3 * width).
 * BT.601 studio range (Y 16..235, U and V 16..240 around 128), the inverse of the 8-bit integer
 * form the scene generator uses for RGB -> YUV (harness/scene/render.h):
 *   C = Y - 16, D = U - 128, E = V - 128
 *   R = clamp((298 C         + 409 E + 128) >> 8)
 *   G = clamp((298 C - 100 D - 208 E + 128) >> 8)
 *   B = clamp((298 C + 516 D         + 128) >> 8)
 * (298 = 256 * 255/219, 409 = 256 * 1.596, 100 = 256 * 0.391, 208 = 256 * 0.813,
 * 516 = 256 * 2.018, each rounded), >> an arithmetic (flooring) shift, so +128 rounds half up;
 * clamp to 0..255. Chroma is not interpolated: both pixels of a pair use the pair's U and V.
 * A colour that went through the scene's RGB -> YUV comes back within a few levels (the forward
 * conversion floors, and 4:2:2 averages the chroma of the pair). */
#ifndef BVB_YUV_H
#define BVB_YUV_H

#include <stdint.h>

#include "bvb/stream.h"

/* 2 width bytes a row in, width out: 9.4 KB at width 320 (bands of 6 rows), 9.8 KB at 160. */
#define BVB_UYVY_TO_GREY_SCRATCH_BYTES(width) BVB_STREAM_SCRATCH_BYTES(2 * (width), 0, (width))

#ifdef __cplusplus
extern "C" {
#endif

void bvb_uyvy_to_grey_c(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height,
                        int32_t src_stride, int32_t dst_stride, void *scratch);
void bvb_uyvy_to_grey_asm(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height,
                          int32_t src_stride, int32_t dst_stride, void *scratch);

void bvb_uyvy_to_rgb24_c(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height,
                         int32_t src_stride, int32_t dst_stride);

#ifdef __cplusplus
}
#endif

#endif
