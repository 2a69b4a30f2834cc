/* 3x3 erosion and dilation of 8-bit images: grey images and binary masks alike.
 *
 *   erode3x3_u8:  dst(x, y) = min of src over the 3x3 neighbourhood of (x, y)
 *   dilate3x3_u8: dst(x, y) = max of src over the 3x3 neighbourhood of (x, y)
 *
 * Binary masks are 0/255 bytes (0 background, 255 foreground). On them min and max are exactly
 * binary erosion (a pixel stays set only when its whole 3x3 neighbourhood is set) and binary
 * dilation (a pixel becomes set when any neighbour is set), so masks use the same kernels.
 *
 * Borders replicate the edge: a neighbour outside the image takes the value of the nearest
 * pixel inside it. For a 3x3 min or max that is the same as taking the min or max over the
 * part of the neighbourhood that lies inside the image, so the border neither erodes from
 * nor grows into the outside (a mask touching the edge keeps touching it after erosion; a
 * mask does not grow from the edge under dilation).
 *
 * src: width x height bytes, src_stride bytes between rows; dst: dst_stride bytes between rows.
 * width, height >= 1; strides >= width; no alignment required of src, dst or the strides.
 * src and dst must not overlap.
 *
 * scratch: working memory for the assembly (four rows of 16-bit horizontal results), at least
 * BVB_MORPH3X3_SCRATCH_BYTES(width) bytes, 4-byte aligned. The C reference does not use it; the
 * assembly overwrites it. Placing it in L1 (5.2 KB for a 640-pixel row) is what makes the
 * assembly fast on hardware; the simulator's counts do not depend on it. */
#ifndef BVB_MORPH_H
#define BVB_MORPH_H

#include <stdint.h>

#include "bvb/dma.h"

/* One H row: 8 * ceil(width / 8) + 8 halfwords. Band rows in L1: the width rounded up to 4
 * apart, up to BVB_MORPH3X3_BAND_ROWS(width) rows per band. */
#define BVB_MORPH3X3_HROW_BYTES(width) (2 * (8 * (((width) + 7) / 8) + 8))
#define BVB_MORPH3X3_ROW_BYTES(width) (4 * (((width) + 3) / 4))
#define BVB_MORPH3X3_BAND_ROWS(width)                   \
  (BVB_MORPH3X3_ROW_BYTES(width) <= 160   ? 16          \
   : BVB_MORPH3X3_ROW_BYTES(width) <= 320 ? 10          \
   : BVB_MORPH3X3_ROW_BYTES(width) <= 640 ? 4 : 2)
/* Four H rows; for the DMA path also two input bands of B rows, two output bands of B + 3
 * rows, up to 4 KB to put three H rows in a sub-bank of their own, and two DMA jobs. */
#define BVB_MORPH3X3_SCRATCH_BYTES(width)                                              \
  ((4 * BVB_MORPH3X3_BAND_ROWS(width) + 6) * BVB_MORPH3X3_ROW_BYTES(width) +             \
   4 * BVB_MORPH3X3_HROW_BYTES(width) + 4096 + 2 * BVB_DMA_JOB_BYTES)

#ifdef __cplusplus
extern "C" {
#endif

void bvb_erode3x3_u8_c(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height,
                       int32_t src_stride, int32_t dst_stride, void *scratch);
void bvb_erode3x3_u8_asm(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height,
                         int32_t src_stride, int32_t dst_stride, void *scratch);
void bvb_dilate3x3_u8_c(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height,
                        int32_t src_stride, int32_t dst_stride, void *scratch);
void bvb_dilate3x3_u8_asm(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height,
                          int32_t src_stride, int32_t dst_stride, void *scratch);

#ifdef __cplusplus
}
#endif

#endif
