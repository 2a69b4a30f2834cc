/* Saturating 8-bit image add: dst = min(255, a + b), per pixel.
 *
 * The smallest kernel family; it exists to exercise every path of the harness (checks, guard
 * bands, ABI checks, faults, budgets) with a kernel whose correctness is obvious.
 *
 * a, b: width x height, src_stride bytes between rows. dst: dst_stride bytes between rows.
 * width, height >= 1; strides >= width. No alignment required. */
#ifndef BVB_ADD_SAT_H
#define BVB_ADD_SAT_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

void bvb_add_sat_u8_c(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t width,
                      int32_t height, int32_t src_stride, int32_t dst_stride);
void bvb_add_sat_u8_asm(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t width,
                        int32_t height, int32_t src_stride, int32_t dst_stride);

#ifdef __cplusplus
}
#endif

#endif
