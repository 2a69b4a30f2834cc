/* Saturating 8-bit image add: dst = min(255, a + b), per pixel.
 *
 * The smallest kernel family; it exists to exercise every path of the harness (checks, guard
 * bands, ABI checks, faults, budgets) with a kernel whose correctness is obvious.
 *
 * a, b: width x height, src_stride bytes between rows. dst: dst_stride bytes between rows.
 * width, height >= 1; strides >= width. No alignment required.
 * scratch: BVB_ADD_SAT_U8_SCRATCH_BYTES(width) bytes, 4-byte aligned, or NULL: with the frames in
 * SDRAM and the scratch in L1 the assembly streams row bands through it (bvb/stream.h); the C
 * reference does not use it. */
#ifndef BVB_ADD_SAT_H
#define BVB_ADD_SAT_H

#include <stdint.h>

#include "bvb/stream.h"

/* Three planes of width bytes a row: 9.4 KB at width 320 (bands of 6 rows). */
#define BVB_ADD_SAT_U8_SCRATCH_BYTES(width) BVB_STREAM_SCRATCH_BYTES((width), (width), (width))

#ifdef __cplusplus
extern "C" {
#endif

void bvb_add_sat_u8_c(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t width,
                      int32_t height, int32_t src_stride, int32_t dst_stride, void *scratch);
void bvb_add_sat_u8_asm(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t width,
                        int32_t height, int32_t src_stride, int32_t dst_stride, void *scratch);

#ifdef __cplusplus
}
#endif

#endif
