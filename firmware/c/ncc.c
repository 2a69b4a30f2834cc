/* NCC matching, C reference (bvb/ncc.h): every candidate computed directly from its window, the
 * best kept with the exact comparison and the tie rule. */
#include "bvb/ncc.h"

/* x * y for x < 2^64, y < 2^32, as hi * 2^32 + lo. */
static void mul_64_32(uint64_t x, uint32_t y, uint64_t *hi, uint32_t *lo) {
  uint64_t l = (x & 0xffffffffu) * y;
  *hi = (x >> 32) * y + (l >> 32);
  *lo = (uint32_t)l;
}

static uint32_t abs_u32(int32_t v) { return v < 0 ? 0u - (uint32_t)v : (uint32_t)v; }

int32_t bvb_ncc_compare(int32_t num_a, uint32_t v_a, int32_t num_b, uint32_t v_b) {
  const int32_t sa = (num_a > 0) - (num_a < 0), sb = (num_b > 0) - (num_b < 0);
  uint64_t a2, b2, ah, bh;
  uint32_t al, bl, ua, ub;
  int32_t c;
  if (sa != sb) return sa > sb ? 1 : -1;
  if (sa == 0) return 0;
  ua = abs_u32(num_a);
  ub = abs_u32(num_b);
  a2 = (uint64_t)ua * ua;
  b2 = (uint64_t)ub * ub;
  mul_64_32(a2, v_b, &ah, &al);
  mul_64_32(b2, v_a, &bh, &bl);
  if (ah != bh) c = ah > bh ? 1 : -1;
  else if (al != bl) c = al > bl ? 1 : -1;
  else c = 0;
  return sa > 0 ? c : -c;
}

static uint32_t isqrt32(uint32_t x) {
  uint32_t r = 0, bit = 1u << 30;
  while (bit > x) bit >>= 2;
  while (bit) {
    if (x >= r + bit) {
      x -= r + bit;
      r = (r >> 1) + bit;
    } else {
      r >>= 1;
    }
    bit >>= 2;
  }
  return r;
}

int32_t bvb_ncc_score_q15(int32_t num, uint32_t vt, uint32_t v) {
  uint64_t p = (uint64_t)vt * v;
  int32_t b = 0, e;
  uint32_t pn, root, a, q;
  if (num == 0 || p == 0) return 0;
  while (b < 64 && (p >> b) != 0) ++b;
  e = ((b - 31) >> 1) * 2;
  pn = (uint32_t)(e >= 0 ? p >> e : p << -e);
  root = isqrt32(pn);
  a = abs_u32(num);
  a = e >= 0 ? a >> (e / 2) : a << (-e / 2);
  q = (a * 32768u) / root;
  if (q > 32767u) q = 32767u;
  return num < 0 ? -(int32_t)q : (int32_t)q;
}

/* Does offset a win a tie against offset b? */
static int tie_first(int32_t dxa, int32_t dya, int32_t dxb, int32_t dyb) {
  const int32_t ka = (dxa < 0 ? -dxa : dxa) + (dya < 0 ? -dya : dya);
  const int32_t kb = (dxb < 0 ? -dxb : dxb) + (dyb < 0 ? -dyb : dyb);
  if (ka != kb) return ka < kb;
  if (dya != dyb) return dya < dyb;
  return dxa < dxb;
}

static int params_ok(int32_t r, int32_t s) {
  return r >= 1 && r <= BVB_NCC_MAX_RADIUS && s >= 1 && s <= BVB_NCC_MAX_SEARCH;
}

static int inside(int32_t x, int32_t y, int32_t width, int32_t height, int32_t r, int32_t s) {
  return x - r - s >= 0 && x + r + s <= width - 1 && y - r - s >= 0 && y + r + s <= height - 1;
}

/* The zero-mean template T' of the point into tz (N entries); returns vt. */
static uint32_t make_template(const uint8_t *frame1, int32_t stride, int32_t x, int32_t y,
                              int32_t r, int16_t *tz) {
  const int32_t w = 2 * r + 1, n = w * w;
  int32_t st = 0, stt = 0, i, j;
  for (i = 0; i < w; ++i)
    for (j = 0; j < w; ++j) {
      const int32_t t = frame1[(y - r + i) * stride + (x - r + j)];
      st += t;
      stt += t * t;
    }
  for (i = 0; i < w; ++i)
    for (j = 0; j < w; ++j)
      tz[i * w + j] = (int16_t)(n * frame1[(y - r + i) * stride + (x - r + j)] - st);
  return (uint32_t)(n * stt - st * st);
}

/* num and v of the window of frame 2 centred at (cx, cy). */
static void candidate(const uint8_t *frame2, int32_t stride, int32_t cx, int32_t cy, int32_t r,
                      const int16_t *tz, int32_t *num, uint32_t *v) {
  const int32_t w = 2 * r + 1, n = w * w;
  int32_t sum = 0, si = 0, sii = 0, i, j;
  for (i = 0; i < w; ++i) {
    const uint8_t *row = frame2 + (cy - r + i) * stride + (cx - r);
    for (j = 0; j < w; ++j) {
      const int32_t p = row[j];
      sum += tz[i * w + j] * p;
      si += p;
      sii += p * p;
    }
  }
  *num = sum;
  *v = (uint32_t)(n * sii - si * si);
}

void bvb_ncc_match_c(const uint8_t *frame1, const uint8_t *frame2, int32_t stride, int32_t width,
                     int32_t height, const int16_t *points, int32_t npoints, int32_t radius,
                     int32_t search, int16_t *results, void *scratch) {
  int16_t tz[(2 * BVB_NCC_MAX_RADIUS + 1) * (2 * BVB_NCC_MAX_RADIUS + 1)];
  const int32_t r = radius, s = search;
  int32_t k;
  (void)scratch;
  for (k = 0; k < npoints; ++k) {
    const int32_t x = points[2 * k], y = points[2 * k + 1];
    int16_t *res = results + 4 * k;
    int32_t best_num = 0, best_dx = 0, best_dy = 0, dx, dy, status;
    uint32_t best_v = 0, vt;
    res[0] = res[1] = res[2] = 0;
    if (!params_ok(r, s)) status = BVB_NCC_BAD_PARAMS;
    else if (!inside(x, y, width, height, r, s)) status = BVB_NCC_BORDER;
    else if ((vt = make_template(frame1, stride, x, y, r, tz)) == 0) status = BVB_NCC_FLAT;
    else {
      status = BVB_NCC_OK;
      for (dy = -s; dy <= s; ++dy)
        for (dx = -s; dx <= s; ++dx) {
          int32_t num, c;
          uint32_t v;
          candidate(frame2, stride, x + dx, y + dy, r, tz, &num, &v);
          c = (dx == -s && dy == -s) ? 1 : bvb_ncc_compare(num, v, best_num, best_v);
          if (c > 0 || (c == 0 && tie_first(dx, dy, best_dx, best_dy))) {
            best_num = num;
            best_v = v;
            best_dx = dx;
            best_dy = dy;
          }
        }
      res[0] = (int16_t)best_dx;
      res[1] = (int16_t)best_dy;
      res[2] = (int16_t)bvb_ncc_score_q15(best_num, vt, best_v);
    }
    res[3] = (int16_t)status;
  }
}

void bvb_ncc_scoremap_c(const uint8_t *frame1, const uint8_t *frame2, int32_t stride,
                        int32_t width, int32_t height, int32_t x, int32_t y, int32_t radius,
                        int32_t search, int16_t *map, void *scratch) {
  int16_t tz[(2 * BVB_NCC_MAX_RADIUS + 1) * (2 * BVB_NCC_MAX_RADIUS + 1)];
  const int32_t r = radius, s = search, side = 2 * s + 1;
  int32_t dx, dy, status;
  uint32_t vt = 0;
  (void)scratch;
  if (!params_ok(r, s)) {
    map[0] = BVB_NCC_BAD_PARAMS;
    return;
  }
  if (!inside(x, y, width, height, r, s)) status = BVB_NCC_BORDER;
  else if ((vt = make_template(frame1, stride, x, y, r, tz)) == 0) status = BVB_NCC_FLAT;
  else status = BVB_NCC_OK;
  for (dy = -s; dy <= s; ++dy)
    for (dx = -s; dx <= s; ++dx) {
      int32_t num = 0, q = 0;
      uint32_t v;
      if (status == BVB_NCC_OK) {
        candidate(frame2, stride, x + dx, y + dy, r, tz, &num, &v);
        q = bvb_ncc_score_q15(num, vt, v);
      }
      map[(dy + s) * side + (dx + s)] = (int16_t)q;
    }
  map[side * side] = (int16_t)status;
}
