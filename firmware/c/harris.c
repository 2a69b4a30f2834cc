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

/* Candidates are (key, value) pairs: key = y * width + x, value = R. The heap orders them by R
 * descending, then by key ascending. */
struct cand {
  int32_t key, r;
};

static int before(const struct cand *a, const struct cand *b) {
  return a->r > b->r || (a->r == b->r && a->key < b->key);
}

static void sift_down(struct cand *h, int32_t n, int32_t i) {
  for (;;) {
    int32_t l = 2 * i + 1, best = i;
    if (l < n && before(&h[l], &h[best])) best = l;
    if (l + 1 < n && before(&h[l + 1], &h[best])) best = l + 1;
    if (best == i) return;
    struct cand t = h[i];
    h[i] = h[best];
    h[best] = t;
    i = best;
  }
}

int32_t bvb_harris_corners_c(const int32_t *resp, int32_t width, int32_t height, int32_t stride,
                             int32_t threshold, int32_t max_corners, int32_t min_distance,
                             int32_t *corners, void *scratch) {
  struct cand *h = (struct cand *)scratch;
  int32_t n = 0;
  for (int32_t y = 1; y < height - 1; ++y) {
    const int32_t *r = resp + y * stride;
    for (int32_t x = 1; x < width - 1; ++x) {
      int32_t v = r[x];
      if (v <= threshold) continue;
      const int32_t *u = r - stride, *d = r + stride;
      if (v <= u[x - 1] || v <= u[x] || v <= u[x + 1] || v <= r[x - 1]) continue;
      if (v < r[x + 1] || v < d[x - 1] || v < d[x] || v < d[x + 1]) continue;
      h[n].key = y * width + x;
      h[n].r = v;
      ++n;
    }
  }
  for (int32_t i = n / 2 - 1; i >= 0; --i) sift_down(h, n, i);

  const int32_t d2 = min_distance * min_distance;
  int32_t taken = 0;
  while (n > 0 && taken < max_corners) {
    struct cand c = h[0];
    h[0] = h[--n];
    sift_down(h, n, 0);
    const int32_t x = c.key % width, y = c.key / width;
    int32_t ok = 1;
    for (int32_t k = 0; k < taken && ok; ++k) {
      const int32_t dx = corners[3 * k] - x, dy = corners[3 * k + 1] - y;
      ok = dx * dx + dy * dy >= d2;
    }
    if (!ok) continue;
    corners[3 * taken] = x;
    corners[3 * taken + 1] = y;
    corners[3 * taken + 2] = c.r;
    ++taken;
  }
  return taken;
}
