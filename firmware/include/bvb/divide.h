/* Integer division as the firmware's C code gets it: the runtime's ___udivsi3
 * (firmware/runtime/udiv.S), which the compiler calls for '/' and '%' on 32-bit values, directly
 * for unsigned ones and through libgcc's ___divsi3, ___modsi3, ___umodsi3 and ___divdi3 for the
 * others. The check compares the Blackfin build of this C with the host's division, so the
 * helper is checked on edge and random pairs of every bit length; the pipelines' C (the
 * odometry divides some 140 times a frame) is what it speeds up.
 *
 *   for each i < count, with n = num[i], d = den[i] (as uint32_t, and as int32_t for s):
 *     out[6i + 0] = n / d                 out[6i + 1] = n % d
 *     out[6i + 2] = (int32_t)n / (int32_t)d   out[6i + 3] = (int32_t)n % (int32_t)d
 *     out[6i + 4], out[6i + 5] = the low and high words of q = a / (int32_t)d, a 64-bit signed
 *       division of a = (int64_t)(int32_t)n * 65536 + (n >> 7)
 *
 * Arguments: num, den: count words each, den[i] != 0 and never INT32_MIN / -1 (undefined in C);
 * out: 6 count words; count >= 0. No alignment beyond the words'. C only: the division helper
 * is the assembly under test. */
#ifndef BVB_DIVIDE_H
#define BVB_DIVIDE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

void bvb_divide_c(const uint32_t *num, const uint32_t *den, uint32_t *out, int32_t count);

#ifdef __cplusplus
}
#endif

#endif
