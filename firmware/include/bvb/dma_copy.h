/* A frame copy through L1 row bands by memory DMA: the band scheme of the streaming kernels
 * with nothing computed in between, so that the DMA helper (bvb/dma.h) is checked byte for byte
 * on every shape the kernels give it, and its throughput measured.
 *
 *   dst(x, y) = src(x, y) for 0 <= x < width, 0 <= y < height.
 *
 * Arguments
 *   src, src_stride       width x height bytes, src_stride bytes from row to row.
 *   dst, dst_stride       the same for the copy. Strides >= width; no alignment required.
 *   band                  rows per band, 1 or more.
 *   scratch               BVB_DMA_COPY_SCRATCH_SIZE(width, band) bytes, 4-byte aligned; the C
 *                         reference does not use it.
 *
 * How the assembly does it: rows go in bands of `band` rows from src into one of two L1 band
 * buffers in scratch, rows padded to a multiple of 4 bytes (as the kernels keep them), and from
 * there to dst. Job j (bvb_dma_start) sends band j-1 out and brings band j+1 in, one after the
 * other on MDMA stream 0: the order a kernel uses while it computes band j. The first job brings
 * band 0 alone, the last sends the last band alone. When DMA cannot reach a buffer (the L1
 * scratchpad, the window) the core copies instead.
 *
 * Working set: the two band buffers, 2 x band x (width rounded up to 4) bytes, and a job. */
#ifndef BVB_DMA_COPY_H
#define BVB_DMA_COPY_H

#include <stdint.h>

#include "bvb/dma.h"

#define BVB_DMA_COPY_SCRATCH_SIZE(width, band) \
  (BVB_DMA_JOB_BYTES + 2 * (band) * ((((width) + 3) / 4) * 4))

#ifdef __cplusplus
extern "C" {
#endif

void bvb_dma_copy_u8_c(const uint8_t *src, int32_t src_stride, uint8_t *dst, int32_t dst_stride,
                       int32_t width, int32_t height, int32_t band, void *scratch);
void bvb_dma_copy_u8_asm(const uint8_t *src, int32_t src_stride, uint8_t *dst, int32_t dst_stride,
                         int32_t width, int32_t height, int32_t band, void *scratch);

#ifdef __cplusplus
}
#endif

#endif
