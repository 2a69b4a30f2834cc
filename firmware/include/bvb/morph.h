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
 * scratch: working memory for the assembly, at least BVB_MORPH3X3_SCRATCH_BYTES(width) bytes,
 * 4-byte aligned. The C reference does not use it; the assembly overwrites it.
 *
 * Working set and memory. Frames live in SDRAM, where the camera's DMA puts them; the scratch
 * belongs in L1 data SRAM: 7.5 KB at width 160, 17.2 KB at 320, 19.0 KB at 640 (L1 bank B has
 * room). It holds four rows of 16-bit horizontal results (the 3x1 pass) and, for the DMA path,
 * two input and two output band buffers and two DMA jobs. When src or dst is in SDRAM and the
 * scratch is in L1 data SRAM, the assembly never reads or writes a frame through the core:
 * source rows come into L1 in bands by memory DMA (bvb/dma.h) and output rows leave the same
 * way, double-buffered. While the core computes band j+1, MDMA stream 0 sends the output rows
 * made from band j and then brings band j+2 into the buffer band j has left. Bands are up to
 * BVB_MORPH3X3_BAND_ROWS(width) rows (8 at width 160, 10 at 320, 4 at 640): the first ones
 * hold 2, 2, 4, 8 rows, so the compute starts after 2 rows have arrived. In L1 the rows are
 * the width rounded up to 4 apart, whatever the frame's strides. The H row pairs the passes
 * read or write in one issue are placed apart (the band buffers between them), so that most
 * dual accesses fall in different 4 KB sub-banks; the core's time is hidden under the
 * stream's in any case at widths from 320 (firmware/asm/morph.S). Otherwise (both frames in L1, or the scratch in SDRAM or the
 * scratchpad, which DMA cannot reach) the assembly reads each source row once and writes each
 * output row once, in place. */
#ifndef BVB_MORPH_H
#define BVB_MORPH_H

#include <stdint.h>

#include "bvb/dma.h"

/* One H row: 8 * ceil(width / 8) + 8 halfwords. Band rows in L1: the width rounded up to 4
 * apart, up to BVB_MORPH3X3_BAND_ROWS(width) rows per band. */
#define BVB_MORPH3X3_HROW_BYTES(width) (2 * (8 * (((width) + 7) / 8) + 8))
#define BVB_MORPH3X3_ROW_BYTES(width) (4 * (((width) + 3) / 4))
#define BVB_MORPH3X3_BAND_ROWS(width)                   \
  (BVB_MORPH3X3_ROW_BYTES(width) <= 160   ? 8           \
   : BVB_MORPH3X3_ROW_BYTES(width) <= 320 ? 10          \
   : BVB_MORPH3X3_ROW_BYTES(width) <= 640 ? 4 : 2)
/* Four H rows; for the DMA path also two input bands of B rows, two output bands of B + 3
 * rows and two DMA jobs (each with 8 bytes of slot keys). Sized so that the seg_avoid pipeline's work buffer still fits in L1
 * bank B beside its map at 160x120, and alone at 320x240 (bvb/pipeline.h). */
#define BVB_MORPH3X3_SCRATCH_BYTES(width)                                              \
  ((4 * BVB_MORPH3X3_BAND_ROWS(width) + 6) * BVB_MORPH3X3_ROW_BYTES(width) +             \
   4 * BVB_MORPH3X3_HROW_BYTES(width) + 2 * (BVB_DMA_JOB_BYTES + 8))

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
