/* C reference for bvb/divide.h: the compiler's divisions, on the host its own, on the Blackfin
 * the runtime's ___udivsi3 and libgcc's helpers around it. */
#include "bvb/divide.h"

void bvb_divide_c(const uint32_t *num, const uint32_t *den, uint32_t *out, int32_t count) {
  for (int32_t i = 0; i < count; ++i) {
    const uint32_t n = num[i], d = den[i];
    const int32_t sn = (int32_t)n, sd = (int32_t)d;
    const int64_t a = (int64_t)sn * 65536 + (int64_t)(n >> 7);
    const int64_t q = a / sd;
    out[6 * i + 0] = n / d;
    out[6 * i + 1] = n % d;
    out[6 * i + 2] = (uint32_t)(sn / sd);
    out[6 * i + 3] = (uint32_t)(sn % sd);
    out[6 * i + 4] = (uint32_t)q;
    out[6 * i + 5] = (uint32_t)((uint64_t)q >> 32);
  }
}
