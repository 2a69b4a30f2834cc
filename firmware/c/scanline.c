#include "bvb/scanline.h"

void bvb_scanline_profile_u8_c(const uint8_t *src, int32_t width, int32_t rows, int32_t stride,
                               uint8_t *profile, void *scratch) {
  (void)scratch;
  for (int32_t x = 0; x < width; ++x) {
    uint32_t s = 0;
    const uint8_t *p = src + x;
    for (int32_t r = 0; r < rows; ++r) {
      s += *p;
      p += stride;
    }
    profile[x] = (uint8_t)((s + (uint32_t)rows / 2) / (uint32_t)rows);
  }
}

/* S(t) over the overlap of p1[i] and p2[i + t]. */
static uint32_t sad_at(const uint8_t *p1, const uint8_t *p2, int32_t w, int32_t t) {
  const int32_t i0 = t < 0 ? -t : 0, i1 = t < 0 ? w : w - t;
  uint32_t s = 0;
  for (int32_t i = i0; i < i1; ++i) {
    const int32_t d = p1[i] - p2[i + t];
    s += (uint32_t)(d < 0 ? -d : d);
  }
  return s;
}

void bvb_scanline_shift_u8_c(const uint8_t *p1, const uint8_t *p2, int32_t w, int32_t rho,
                             int32_t *result, uint32_t *curve) {
  const int32_t T = w - rho;
  int32_t best_t = 0;
  uint32_t best_s = sad_at(p1, p2, w, 0), best_n = (uint32_t)w;
  if (curve) curve[T] = best_s;
  /* 0, -1, +1, -2, +2, ...: the first strict minimum has the smallest |t|, negative first. */
  for (int32_t k = 1; k <= T; ++k) {
    for (int32_t t = -k; t <= k; t += 2 * k) {
      const uint32_t s = sad_at(p1, p2, w, t), n = (uint32_t)(w - k);
      if (curve) curve[t + T] = s;
      if (s * best_n < best_s * n) {
        best_t = t;
        best_s = s;
        best_n = n;
      }
    }
  }
  result[0] = best_t;
  result[1] = (int32_t)best_s;
  result[2] = (int32_t)best_n;
}
