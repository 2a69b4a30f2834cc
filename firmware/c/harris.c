#include "bvb/harris.h"

/* Three rows of column sums (cxx, cyy, cxy), one entry per column, live in scratch. */
void bvb_harris_response_c(const uint8_t *src, int32_t *dst, int32_t width, int32_t height,
                           int32_t src_stride, int32_t dst_stride, void *scratch) {
  int32_t *cxx = (int32_t *)scratch;
  int32_t *cyy = cxx + width;
  int32_t *cxy = cyy + width;
  for (int32_t y = 0; y < height; ++y) {
    int32_t *out = dst + y * dst_stride;
    if (y < 2 || y > height - 3) {
      for (int32_t x = 0; x < width; ++x) out[x] = 0;
      continue;
    }
    for (int32_t x = 1; x < width - 1; ++x) {
      int32_t sxx = 0, syy = 0, sxy = 0;
      for (int32_t dy = -1; dy <= 1; ++dy) {
        const uint8_t *p = src + (y + dy) * src_stride + x;
        int32_t gx = p[1] - p[-1];
        int32_t gy = p[src_stride] - p[-src_stride];
        sxx += gx * gx;
        syy += gy * gy;
        sxy += gx * gy;
      }
      cxx[x] = sxx >> 5;
      cyy[x] = syy >> 5;
      cxy[x] = sxy >> 5;
    }
    out[0] = out[1] = 0;
    for (int32_t x = 2; x < width - 2; ++x) {
      int32_t a = cxx[x - 1] + cxx[x] + cxx[x + 1];
      int32_t b = cyy[x - 1] + cyy[x] + cyy[x + 1];
      int32_t c = cxy[x - 1] + cxy[x] + cxy[x + 1];
      int32_t hh = (a + b) >> 1;
      int32_t kh = (hh * BVB_HARRIS_K4_Q15) >> 15;
      out[x] = a * b - c * c - kh * hh;
    }
    out[width - 2] = out[width - 1] = 0;
  }
}

int32_t bvb_harris_nms_c(const int32_t *resp, int32_t width, int32_t height, int32_t stride,
                         int32_t threshold, int32_t *cand, int32_t *count, void *scratch) {
  (void)scratch;
  int32_t n = 0;
  for (int32_t y = 1; y < height - 1; ++y) {
    const int32_t *r = resp + y * stride;
    for (int32_t x = 1; x < width - 1; ++x) {
      int32_t v = r[x];
      if (v <= threshold) continue;
      const int32_t *u = r - stride, *d = r + stride;
      if (v <= u[x - 1] || v <= u[x] || v <= u[x + 1] || v <= r[x - 1]) continue;
      if (v < r[x + 1] || v < d[x - 1] || v < d[x] || v < d[x + 1]) continue;
      cand[2 * n] = y << 16 | x;
      cand[2 * n + 1] = v;
      ++n;
    }
  }
  *count = n;
  return n;
}

/* The heap holds (key, R) pairs and puts first the larger R, then the smaller key. A sentinel
 * after its last entry (R = INT32_MIN, below every candidate since R > threshold >= 0) makes the
 * second child always readable. */
static void sift_down(int32_t *h, int32_t n, int32_t i) {
  const int32_t tk = h[2 * i], tr = h[2 * i + 1];
  for (;;) {
    int32_t c = 2 * i + 1;
    if (c >= n) break;
    const int32_t *a = &h[2 * c];
    if (a[3] > a[1] || (a[3] == a[1] && a[2] < a[0])) {
      a += 2;
      ++c;
    }
    if (a[1] < tr || (a[1] == tr && a[0] > tk)) break;
    h[2 * i] = a[0];
    h[2 * i + 1] = a[1];
    i = c;
  }
  h[2 * i] = tk;
  h[2 * i + 1] = tr;
}

/* Removes the first candidate: the hole left at the root sinks along the better children to a
 * leaf (one comparison per level), then the last entry moves into it and rises as far as it must
 * (rarely more than a level). */
static void pop(int32_t *h, int32_t n) {
  const int32_t lk = h[2 * (n - 1)], lr = h[2 * (n - 1) + 1];
  --n;
  h[2 * n] = 0x7FFFFFFF;
  h[2 * n + 1] = INT32_MIN;
  int32_t i = 0;
  for (;;) {
    int32_t c = 2 * i + 1;
    if (c >= n) break;
    const int32_t *a = &h[2 * c];
    if (a[3] > a[1] || (a[3] == a[1] && a[2] < a[0])) {
      a += 2;
      ++c;
    }
    h[2 * i] = a[0];
    h[2 * i + 1] = a[1];
    i = c;
  }
  while (i > 0) {
    const int32_t p = (i - 1) >> 1;
    const int32_t *a = &h[2 * p];
    if (lr < a[1] || (lr == a[1] && lk > a[0])) break;
    h[2 * i] = a[0];
    h[2 * i + 1] = a[1];
    i = p;
  }
  h[2 * i] = lk;
  h[2 * i + 1] = lr;
}

int32_t bvb_harris_select_c(int32_t *cand, int32_t n, int32_t max_corners, int32_t min_distance,
                            int32_t *corners) {
  cand[2 * n] = 0x7FFFFFFF;
  cand[2 * n + 1] = INT32_MIN;
  for (int32_t i = n / 2 - 1; i >= 0; --i) sift_down(cand, n, i);
  const int32_t d2 = min_distance * min_distance;
  int32_t taken = 0;
  while (n > 0 && taken < max_corners) {
    const int32_t key = cand[0], r = cand[1];
    pop(cand, n);
    --n;
    const int16_t x = (int16_t)(key & 0xFFFF), y = (int16_t)(key >> 16);
    const int32_t *p = corners;
    int32_t k = taken;
    for (; k > 0; --k, p += 3) {
      const int16_t dx = (int16_t)(p[0] - x), dy = (int16_t)(p[1] - y);
      if (dx * dx + dy * dy < d2) break;
    }
    if (k > 0) continue;
    corners[3 * taken] = x;
    corners[3 * taken + 1] = y;
    corners[3 * taken + 2] = r;
    ++taken;
  }
  return taken;
}
