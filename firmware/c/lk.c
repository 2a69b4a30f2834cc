#include "bvb/lk.h"

/* ---- pyramid ---- */

uint32_t bvb_lk_level_offset(int32_t width, int32_t height, int32_t level) {
  uint32_t off = 0;
  for (int32_t l = 1; l < level; ++l) {
    width >>= 1;
    height >>= 1;
    off += (uint32_t)BVB_LK_LEVEL_STRIDE(width) * (uint32_t)height;
  }
  return off;
}

uint32_t bvb_lk_pyramid_bytes(int32_t width, int32_t height, int32_t levels) {
  return bvb_lk_level_offset(width, height, levels);
}

void bvb_lk_pyramid_c(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                      int32_t levels, uint8_t *pyr) {
  const uint8_t *in = src;
  int32_t in_stride = stride;
  for (int32_t l = 1; l < levels; ++l) {
    const int32_t w = width >> 1, h = height >> 1, s = BVB_LK_LEVEL_STRIDE(w);
    uint8_t *out = pyr;
    for (int32_t y = 0; y < h; ++y) {
      const uint8_t *a = in + 2 * y * in_stride, *b = a + in_stride;
      uint8_t *o = out + y * s;
      for (int32_t x = 0; x < w; ++x)
        o[x] = (uint8_t)((a[2 * x] + a[2 * x + 1] + b[2 * x] + b[2 * x + 1] + 2) >> 2);
    }
    in = out;
    in_stride = s;
    pyr += s * h;
    width = w;
    height = h;
  }
}

void bvb_lk_pyramid_streamed_c(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                               int32_t levels, uint8_t *pyr, void *scratch) {
  (void)scratch;
  bvb_lk_pyramid_c(src, width, height, stride, levels, pyr);
}

#if defined(__bfin__)
#include <stddef.h>

#include "bvb/dma.h"

typedef char lk_job_bytes_check[BVB_LK_PYR_JOB_BYTES == BVB_DMA_JOB_BYTES ? 1 : -1];
/* struct bvb_lk_copy begins with struct bvb_dma_xfer's fields */
typedef char lk_copy_check[offsetof(struct bvb_lk_copy, rows) == offsetof(struct bvb_dma_xfer, rows) &&
                                   offsetof(struct bvb_lk_copy, src_stride) == offsetof(struct bvb_dma_xfer, src_stride) &&
                                   offsetof(struct bvb_lk_copy, dst) == offsetof(struct bvb_dma_xfer, dst) &&
                                   offsetof(struct bvb_lk_copy, dst_stride) == offsetof(struct bvb_dma_xfer, dst_stride) &&
                                   offsetof(struct bvb_lk_copy, width) == offsetof(struct bvb_dma_xfer, width)
                               ? 1
                               : -1];

static int32_t lk_in_sdram(const void *p) { return (uintptr_t)p < 0x02000000u; }

/* Slot *slot of a job for x: re-addressed when it was last prepared for the same shape (key),
 * prepared again otherwise; what DMA refuses is copied by the core at once. */
static inline __attribute__((always_inline)) void lk_add(uint8_t *job, int32_t *keys, int32_t *slot,
                                                        const struct bvb_dma_xfer *x, int32_t key) {
  if (__builtin_expect(keys[*slot] == key, 1)) {
    bvb_dma_move(job, *slot, x);
  } else if (bvb_dma_prepare(job, *slot, x) == 0) {
    keys[*slot] = key;
  } else {
    const uint8_t *s = (const uint8_t *)x->src;
    uint8_t *d = (uint8_t *)x->dst;
    for (int32_t r = 0; r < x->rows; ++r, s += x->src_stride, d += x->dst_stride)
      for (int32_t i = 0; i < x->width; ++i) d[i] = s[i];
    keys[*slot] = -1;
    return;
  }
  ++*slot;
}

/* Band k (B level-1 rows, 2 B frame rows) is made from its frame rows in L1 while the job built
 * before it runs: band k-1's levels out to pyr, band k+1's frame rows in. The job is built in
 * the other job area before the wait, so the stream idles only between the wait and the
 * start. A DMA error redoes the whole pyramid in place. */
void bvb_lk_pyramid_stream_run(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                               int32_t levels, uint8_t *pyr, void *scratch, bvb_lk_level_fn level) {
  const int32_t w1 = width >> 1, h1 = height >> 1, B = BVB_LK_PYR_BAND(width);
  const int32_t nl = levels - 1 < 3 ? levels - 1 : 3; /* levels made band by band */
  const int32_t out_dma = lk_in_sdram(pyr);
  if (levels < 2 || w1 == 0 || h1 == 0 || !lk_in_sdram(src) || lk_in_sdram(scratch) ||
      !bvb_dma_reachable(scratch, BVB_LK_PYRAMID_SCRATCH_BYTES(width)) ||
      !bvb_dma_reachable(src, (2 * h1 - 1) * stride + width) ||
      (out_dma && !bvb_dma_reachable(pyr, (int32_t)bvb_lk_pyramid_bytes(width, height, nl + 1)))) {
    level(src, width, height, stride, levels, pyr);
    return;
  }
  int32_t lw[4], ls[4];
  uint32_t off[4];
  for (int32_t l = 1; l <= 3; ++l) {
    lw[l] = width >> l;
    ls[l] = BVB_LK_LEVEL_STRIDE(lw[l]);
    off[l] = bvb_lk_level_offset(width, height, l);
  }
  const int32_t pin = BVB_LK_LEVEL_STRIDE(width);
  uint8_t *m = (uint8_t *)scratch, *job[2], *in[2], *ob[2][4];
  job[0] = m;
  job[1] = m + BVB_LK_PYR_JOB_BYTES;
  m += 2 * BVB_LK_PYR_JOB_BYTES;
  for (int32_t par = 0; par < 2; ++par) {
    in[par] = m;
    m += 2 * B * pin;
    for (int32_t l = 1; l <= 3; ++l) {
      ob[par][l] = m;
      m += (B >> (l - 1)) * ls[l];
    }
  }
  int32_t keys[2][BVB_DMA_MAX_XFERS];
  for (int32_t j = 0; j < 2; ++j)
    for (int32_t s = 0; s < BVB_DMA_MAX_XFERS; ++s) keys[j][s] = -1;
  struct bvb_dma_xfer x;
  x.width = width;
  x.src_stride = stride;
  x.dst_stride = pin;

  /* band 0's rows in, on job 1 (band k's job is built in job k & 1) */
  x.src = src;
  x.dst = in[0];
  x.rows = 2 * (h1 < B ? h1 : B);
  if (bvb_dma_prepare(job[1], 0, &x) != 0) {
    level(src, width, height, stride, levels, pyr);
    return;
  }
  bvb_dma_start(job[1], 1);
  int32_t running = 1, failed = 0;
  for (int32_t r = 0, k = 0; r < h1 + B; r += B, ++k) {
    /* r: band k's first level-1 row; past the last band: its outputs alone */
    const int32_t j = k & 1, n = h1 - r < B ? h1 - r : B;
    int32_t slot = 0;
    if (out_dma && r > 0) {
      const int32_t rp = r - B, np = h1 - rp < B ? h1 - rp : B;
      for (int32_t l = 1; l <= nl; ++l) {
        const int32_t rows = np >> (l - 1);
        if (rows == 0 || lw[l] == 0) continue;
        x.src = ob[(k - 1) & 1][l];
        x.src_stride = ls[l];
        x.dst = pyr + off[l] + (uint32_t)((rp >> (l - 1)) * ls[l]);
        x.dst_stride = ls[l];
        x.width = lw[l];
        x.rows = rows;
        lk_add(job[j], keys[j], &slot, &x, rows * 8 + l);
      }
    }
    if (n > 0 && r + B < h1) {
      const int32_t rn = r + B, nn = h1 - rn < B ? h1 - rn : B;
      x.src = src + 2 * rn * stride;
      x.src_stride = stride;
      x.dst = in[(k + 1) & 1];
      x.dst_stride = pin;
      x.width = width;
      x.rows = 2 * nn;
      lk_add(job[j], keys[j], &slot, &x, 2 * nn * 8);
    }
    if (running && bvb_dma_wait() != 0) failed = 1;
    running = 0;
    if (slot && !failed) {
      bvb_dma_start(job[j], slot);
      running = 1;
    }
    if (n > 0 && !failed) {
      const uint8_t *a = in[k & 1];
      int32_t wa = width, ha = 2 * n, sa = pin;
      for (int32_t l = 1; l <= nl; ++l) {
        uint8_t *d = out_dma ? ob[k & 1][l] : pyr + off[l] + (uint32_t)((r >> (l - 1)) * ls[l]);
        level(a, wa, ha, sa, 2, d);
        a = d;
        wa = lw[l];
        ha >>= 1;
        sa = ls[l];
      }
    }
  }
  if (running && bvb_dma_wait() != 0) failed = 1;
  if (failed) {
    bvb_dma_reset();
    level(src, width, height, stride, levels, pyr);
    return;
  }
  /* level 4 from level 3 */
  if (levels > 4) level(pyr + off[3], lw[3], height >> 3, ls[3], levels - 3, pyr + bvb_lk_level_offset(width, height, 4));
}

/* The tracker's level copies by memory DMA (struct bvb_lk_ops): the blocks from SDRAM into L1
 * where DMA reaches. The stream runs one job at a time, and a caller may have left one of its
 * own running (the odometry's state copy runs while it tracks): a step whose copies would
 * find the stream busy (DMA_RUN), or its last job failed (DMA_ERR, left for its owner to
 * see), reads its windows where they are. After a job of the caller's that ended well the
 * tracker's own jobs end the same way, so the caller's wait still returns 0. */
#define LK_MDMA_D0_IRQ_STATUS ((volatile uint16_t *)0xFFC00F28)
#define LK_DMA_ERR 0x2
#define LK_DMA_RUN 0x8
static int32_t lk_fetch_running;

int32_t bvb_lk_fetch_dma(void *job, int32_t *keys, const struct bvb_lk_copy *c, int32_t n) {
  int32_t mask = 0, slot = 0;
  if (n == 0) return !lk_in_sdram(job) && bvb_dma_reachable(job, BVB_LK_SCRATCH_BYTES);
  if (n < 0) return lk_in_sdram(job);
  if (__builtin_expect(*LK_MDMA_D0_IRQ_STATUS & (LK_DMA_RUN | LK_DMA_ERR), 0)) return 0;
  for (int32_t i = 0; i < n; ++i) {
    /* the destination is the scratch, which the probe found where DMA reaches */
    if (__builtin_expect(c[i].rows <= 0 || c[i].width <= 0 || !lk_in_sdram(c[i].src), 0)) continue;
    lk_add((uint8_t *)job, keys, &slot, (const struct bvb_dma_xfer *)&c[i], c[i].key);
    mask |= 1 << i;
  }
  lk_fetch_running = 0;
  if (slot) {
    bvb_dma_start(job, slot);
    lk_fetch_running = 1;
  }
  return mask;
}

int32_t bvb_lk_fetch_wait_dma(void) {
  int32_t r = 0;
  if (lk_fetch_running && (r = bvb_dma_wait()) != 0) bvb_dma_reset();
  lk_fetch_running = 0;
  return r;
}
#endif

/* ---- fixed-point helpers ---- */

/* Bit length of v (0 for 0), v < 2^31 (every caller's). On the Blackfin one SIGNBITS (GCC's
 * __builtin_clrsb: the bits below the sign bit that equal it, 31 - bitlen for such v), where
 * the halving's five compares and branches took some 60 cycles a call (the driver takes two
 * per feature and level); elsewhere by halving, five steps. */
static int32_t bitlen(uint32_t v) {
#if defined(__bfin__)
  return 31 - __builtin_clrsb((int32_t)v);
#else
  int32_t n = 0;
  if (v >= 0x10000u) v >>= 16, n += 16;
  if (v >= 0x100u) v >>= 8, n += 8;
  if (v >= 0x10u) v >>= 4, n += 4;
  if (v >= 0x4u) v >>= 2, n += 2;
  if (v >= 0x2u) v >>= 1, n += 1;
  return n + (int32_t)v;
#endif
}

/* 2^28 / d for 2^14 <= d < 2^15 (the normalised determinant). The Blackfin's DIVS and 15
 * DIVQ steps take a dividend of twice the quotient's scale (2^29: they give the 16-bit
 * quotient of half the dividend) whose high half is below d, and give it truncated, the C's for
 * positive values: checked for every such d against the simulator's DIVS and DIVQ. 16 cycles,
 * where libgcc's division took some 190 (one per feature and level); elsewhere the C division. */
static int32_t div_2p28(int32_t d) {
#if defined(__bfin__)
  int32_t q = 1 << 29;
  __asm__("DIVS (%0, %1);\n\t"
          "DIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\t"
          "DIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\t"
          "DIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\t"
          "DIVQ (%0, %1);\n\tDIVQ (%0, %1);\n\tDIVQ (%0, %1);"
          : "+d"(q)
          : "d"(d)
          : "cc");
  return q & 0xFFFF;
#else
  return (1 << 28) / d;
#endif
}

/* The Blackfin's SIGNBITS of a 32-bit value. */
static int32_t signbits(int32_t v) {
  return 31 - bitlen(v < 0 ? ~(uint32_t)v : (uint32_t)v);
}

/* v * 2^-s with floor, or v * 2^-s exactly for s < 0 (the caller knows it fits). */
static int32_t shift_by(int32_t v, int32_t s) {
  return s >= 0 ? v >> s : v * (int32_t)(1u << -s);
}

/* floor(v / 16) for int64 without shifting a negative value. */
static int64_t floor16(int64_t v) {
  return v < 0 ? ~((~v) >> 4) : v >> 4;
}

/* The Q5 bilinear value at integer (x, y) with fractions fx, fy (Q7). */
static int32_t interp(const uint8_t *img, int32_t stride, int32_t x, int32_t y, int32_t fx, int32_t fy) {
  const uint8_t *p = img + y * stride + x;
  const int32_t h0 = (128 - fx) * p[0] + fx * p[1];
  const int32_t h1 = (128 - fx) * p[stride] + fx * p[stride + 1];
  return ((128 - fy) * h0 + fy * h1) >> 9;
}

/* ---- the inner steps, C ---- */

void bvb_lk_patch_c(const uint8_t *img, int16_t *tmpl, int32_t *grad, int16_t *work, int32_t *block) {
  const int32_t stride = block[BVB_LK_PA_STRIDE], ix = block[BVB_LK_PA_IX], iy = block[BVB_LK_PA_IY];
  const int32_t fx = block[BVB_LK_PA_FX], fy = block[BVB_LK_PA_FY];
  const int32_t hx = block[BVB_LK_PA_HX], hy = block[BVB_LK_PA_HY];
  const int32_t wx = 2 * hx + 1, wy = 2 * hy + 1, wxp = wx + 1, er = wx + 3;
  int16_t *g = (int16_t *)grad;
  /* the extended template, (wx + 2) x (wy + 2), rows of er */
  for (int32_t j = -hy - 1; j <= hy + 1; ++j)
    for (int32_t i = -hx - 1; i <= hx + 1; ++i)
      work[(j + hy + 1) * er + i + hx + 1] = (int16_t)interp(img, stride, ix + i, iy + j, fx, fy);
  int64_t sxx = 0, sxy = 0, syy = 0;
  for (int32_t j = 0; j < wy; ++j) {
    const int16_t *t = work + (j + 1) * er + 1;
    for (int32_t i = 0; i < wx; ++i) {
      const int32_t gx = t[i + 1] - t[i - 1], gy = t[i + er] - t[i - er];
      tmpl[j * wxp + i] = t[i];
      g[2 * (j * wxp + i)] = (int16_t)gx;
      g[2 * (j * wxp + i) + 1] = (int16_t)gy;
      sxx += gx * gx;
      sxy += gx * gy;
      syy += gy * gy;
    }
    tmpl[j * wxp + wx] = 0;
    g[2 * (j * wxp + wx)] = 0;
    g[2 * (j * wxp + wx) + 1] = 0;
  }
  block[BVB_LK_PA_GXX] = (int32_t)floor16(sxx);
  block[BVB_LK_PA_GXY] = (int32_t)floor16(sxy);
  block[BVB_LK_PA_GYY] = (int32_t)floor16(syy);
}

static int32_t clamp_step(int64_t v) {
  const int64_t lim = (int64_t)1 << 22;
  return (int32_t)(v > lim ? lim : v < -lim ? -lim : v);
}

/* eta = P 2^-(shift) clamped to +-2^22, shift in [-47, 26]. */
static int32_t scale_step(int32_t p, int32_t shift) {
  if (shift >= 0) return clamp_step(p >> shift);
  const int32_t k = -shift > 32 ? 32 : -shift;
  return clamp_step((int64_t)p * ((int64_t)1 << k));
}

int32_t bvb_lk_iterate_c(const uint8_t *img, const int16_t *tmpl, const int32_t *grad, int16_t *work,
                         int32_t *block) {
  (void)work;
  const int32_t stride = block[BVB_LK_IT_STRIDE], width = block[BVB_LK_IT_WIDTH];
  const int32_t height = block[BVB_LK_IT_HEIGHT], hx = block[BVB_LK_IT_HX], hy = block[BVB_LK_IT_HY];
  const int32_t mxx = block[BVB_LK_IT_MXX], mxy = block[BVB_LK_IT_MXY], myy = block[BVB_LK_IT_MYY];
  const int32_t shift = block[BVB_LK_IT_SHIFT], max_iter = block[BVB_LK_IT_MAXITER];
  const int32_t eps = block[BVB_LK_IT_EPS], fixed = block[BVB_LK_IT_FIXED];
  const int32_t wx = 2 * hx + 1, wy = 2 * hy + 1, wxp = wx + 1;
  const int16_t *g = (const int16_t *)grad;
  int32_t qx = block[BVB_LK_IT_QX], qy = block[BVB_LK_IT_QY];
  int32_t converged = 0;
  for (int32_t it = 1; it <= max_iter; ++it) {
    const int32_t q7x = (qx + 256) >> 9, q7y = (qy + 256) >> 9;
    const int32_t ix = q7x >> 7, iy = q7y >> 7, fx = q7x & 127, fy = q7y & 127;
    if (ix - hx < 0 || ix + hx + 1 > width - 1 || iy - hy < 0 || iy + hy + 1 > height - 1) {
      block[BVB_LK_IT_QX] = qx;
      block[BVB_LK_IT_QY] = qy;
      block[BVB_LK_IT_ITERS] = it - 1;
      return BVB_LK_LEFT;
    }
    if (ix - hx < block[BVB_LK_IT_RX0] || ix + hx + 1 > block[BVB_LK_IT_RX1] || iy - hy < block[BVB_LK_IT_RY0] ||
        iy + hy + 1 > block[BVB_LK_IT_RY1]) {
      block[BVB_LK_IT_QX] = qx;
      block[BVB_LK_IT_QY] = qy;
      block[BVB_LK_IT_ITERS] = it - 1;
      return BVB_LK_REFETCH;
    }
    int64_t sx = 0, sy = 0;
    for (int32_t j = 0; j < wy; ++j)
      for (int32_t i = 0; i < wx; ++i) {
        const int32_t k = j * wxp + i;
        const int32_t d = tmpl[k] - interp(img, stride, ix - hx + i, iy - hy + j, fx, fy);
        sx += d * g[2 * k];
        sy += d * g[2 * k + 1];
      }
    const int32_t bx = (int32_t)floor16(sx), by = (int32_t)floor16(sy);
    const int32_t sb = signbits(bx) < signbits(by) ? signbits(bx) : signbits(by);
    const int32_t t = sb < 16 ? 16 - sb : 0;
    const int32_t nx = bx >> t, ny = by >> t;
    const int32_t ex = scale_step(mxx * nx + mxy * ny, shift - t);
    const int32_t ey = scale_step(mxy * nx + myy * ny, shift - t);
    qx += ex;
    qy += ey;
    block[BVB_LK_IT_BX] = bx;
    block[BVB_LK_IT_BY] = by;
    converged = ex <= eps && ex >= -eps && ey <= eps && ey >= -eps;
    if (converged && !fixed) {
      block[BVB_LK_IT_QX] = qx;
      block[BVB_LK_IT_QY] = qy;
      block[BVB_LK_IT_ITERS] = it;
      return BVB_LK_TRACKED;
    }
  }
  block[BVB_LK_IT_QX] = qx;
  block[BVB_LK_IT_QY] = qy;
  block[BVB_LK_IT_ITERS] = max_iter;
  return converged ? BVB_LK_TRACKED : BVB_LK_NOT_CONVERGED;
}

/* ---- the driver ---- */

/* The inverse of the structure tensor for the iteration block; returns 0 when flat (det below
 * flat = min_det 65536 npix^2, which the driver computes once). */
static int32_t setup_solve(const int32_t *pa, int64_t flat, int32_t *it) {
  const int32_t gxx = pa[BVB_LK_PA_GXX], gxy = pa[BVB_LK_PA_GXY], gyy = pa[BVB_LK_PA_GYY];
  const int64_t det = (int64_t)gxx * gyy - (int64_t)gxy * gxy;
  if (det < flat) return 0;
  const int32_t m = gxx > gyy ? gxx : gyy;
  if (m <= 0) return 0;
  const int32_t s = bitlen((uint32_t)m) - 15;
  const int32_t a = shift_by(gxx, s), d = shift_by(gyy, s);
  int32_t c = shift_by(gxy, s);
  if (c > 32767) c = 32767;
  if (c < -32767) c = -32767;
  const int32_t dd = a * d - c * c;
  if (dd <= 0) return 0;
  const int32_t u = bitlen((uint32_t)dd) - 15;
  const int32_t r = div_2p28(shift_by(dd, u));
  it[BVB_LK_IT_MXX] = (d * r) >> 15;
  it[BVB_LK_IT_MXY] = (-c * r) >> 15;
  it[BVB_LK_IT_MYY] = (a * r) >> 15;
  it[BVB_LK_IT_SHIFT] = s + u - 4;
  return 1;
}

/* Where the steps' arrays go in the 4096-byte scratch. Two groups: Y, the template (2 n bytes,
 * n = wxp wy), a free word, 2 n bytes (the assembly iteration's differences, at
 * tmpl + 2 n + 4); X, the gradients (4 n) and work (the patch's h and Te rows: 2 wy + 5 rows of
 * 4 hx + 8 bytes and a word). The iteration's dual accesses pair an X array with a Y array
 * (h with the template, h with the differences, the gradients with the differences), so when
 * the scratch spans two 4 KB L1 sub-banks (or data-cache sub-banks: address bits 13:12) and
 * each group fits one side, each goes on its own side and those accesses never collide; else
 * Y then X. Only speed depends on it: the results do not. */
static void scratch_layout(void *scratch, int32_t hx, int32_t hy, int16_t **tmpl, int32_t **grad,
                           int16_t **work, uint32_t *room) {
  const uint32_t n = (uint32_t)((2 * hx + 2) * (2 * hy + 1));
  const uint32_t ysize = 4 * n + 8, xsize = 4 * n + (uint32_t)(2 * (2 * hy + 1) + 5) * (uint32_t)(4 * hx + 8) + 4;
  const uint32_t lo = (uint32_t)((uintptr_t)scratch & 4095u), b = lo ? 4096u - lo : 0;
  uint8_t *base = (uint8_t *)scratch;
  uint32_t y = 0, x = ysize;
  if (b >= ysize && b + xsize <= BVB_LK_SCRATCH_BYTES) {
    x = b;
  } else if (b >= xsize && b + ysize <= BVB_LK_SCRATCH_BYTES) {
    x = 0;
    y = b;
  }
  *tmpl = (int16_t *)(base + y);
  *grad = (int32_t *)(base + x);
  *work = (int16_t *)(base + x + 4 * n);
  /* What is left (both sizes are whole words): after Y up to X or the end (first: on Y's side
   * of a split, where the level copies' loads meet none of the accesses they pair with), and
   * after X up to Y or the end. */
  const uint32_t ye = y + ysize, xe = x + xsize;
  const uint32_t yend = x > y ? x : BVB_LK_SCRATCH_BYTES, xend = y > x ? y : BVB_LK_SCRATCH_BYTES;
  room[0] = ye;
  room[1] = yend > ye ? yend - ye : 0;
  room[2] = xe;
  room[3] = xend > xe ? xend - xe : 0;
}

const uint8_t *bvb_lk_scratch_place(const uint8_t *area, uint32_t bytes, int32_t win_w, int32_t win_h) {
  const uint32_t hx = (uint32_t)(win_w >> 1), hy = (uint32_t)(win_h >> 1);
  const uint32_t n = (2 * hx + 2) * (2 * hy + 1);
  const uint32_t ysize = 4 * n + 8, xsize = 4 * n + (2 * (2 * hy + 1) + 5) * (4 * hx + 8) + 4;
  if (bytes < BVB_LK_SCRATCH_BYTES || ysize + xsize > BVB_LK_SCRATCH_BYTES) return area;
  /* scratch_layout splits at the boundary b bytes in when ysize <= b <= 4096 - xsize: b = 4096 -
   * (address & 4095), so the start's low bits want to lie in [xsize, 4096 - ysize] */
  const uint32_t lo = (uint32_t)((uintptr_t)area & 4095u), room = bytes - BVB_LK_SCRATCH_BYTES;
  if (lo >= xsize && lo <= 4096 - ysize) return area;
  const uint32_t d = (((xsize + 3) & ~3u) + 4096 - lo) & 4095u;
  return d <= room ? area + d : area;
}

static int32_t inside(int32_t q7x, int32_t q7y, int32_t hx, int32_t hy, int32_t w, int32_t h, int32_t margin) {
  const int32_t ix = q7x >> 7, iy = q7y >> 7;
  /* one branch for the caller, not four (each test is cheap and none has effects) */
  return (ix - hx - margin >= 0) & (ix + hx + 1 + margin <= w - 1) & (iy - hy - margin >= 0) &
         (iy + hy + 1 + margin <= h - 1);
}

/* The level copies (ops->fetch): for each level step (a feature at a level) the bytes its
 * template reads from prev (wx + 3 by wy + 3 from ix - hx - 1, iy - hy - 1, the start rounded
 * down to even so that every slot of one level keeps its alignment) and those around the
 * template position in next that its iterations read while they move by at most FETCH_MARGIN
 * pixels, clipped to the level; one step ahead, in two sets of buffers (step s in set s & 1),
 * each step's two transfers one job. */
#define FETCH_MARGIN 4

struct lk_fetch {
  const struct bvb_lk_ops *ops;
  int32_t on, total, levels, hx, hy;
  const int32_t *in;
  const uint8_t *const *lp, *const *ln;
  const int32_t *lw, *lh, *ls;
  uint8_t *job[BVB_LK_MAX_LEVELS], *pb[2], *nb[2];
  int32_t keys[BVB_LK_MAX_LEVELS][4];
  /* a job area per level, so that a slot keeps its shape from feature to feature and is
   * only re-addressed (each is built after the job before it ended) */
  int32_t pw, ph, nw, nh;
  int32_t want[BVB_LK_MAX_LEVELS]; /* per level: 1 prev's blocks worth copying, 2 next's */
  int32_t flight;        /* the step whose copies are on their way (-1: none) */
  int32_t mask[2];       /* per set: 1 prev's block there, 2 next's */
  int32_t px0[2], py0[2], nx0[2], ny0[2], nx1[2], ny1[2];
};

/* Starts the copies of step s (feature f at level l) into set s & 1. */
static inline __attribute__((always_inline)) void fetch_issue(struct lk_fetch *fe, int32_t s, int32_t f,
                                                               int32_t l) {
  const int32_t par = s & 1, want = fe->want[l];
  fe->flight = s;
  fe->mask[par] = 0;
  if (__builtin_expect(!want, 0)) return;
  const int32_t px = fe->in[2 * f], py = fe->in[2 * f + 1], hx = fe->hx, hy = fe->hy;
  const int32_t tx = ((px + 32768) >> l) - 32768, ty = ((py + 32768) >> l) - 32768;
  const int32_t t7x = (tx + 256) >> 9, t7y = (ty + 256) >> 9, ix = t7x >> 7, iy = t7y >> 7;
  const int32_t w = fe->lw[l], h = fe->lh[l], st = fe->ls[l];
  if (__builtin_expect(!inside(t7x, t7y, hx, hy, w, h, 1), 0)) return; /* no template: nothing read */
  struct bvb_lk_copy c[2];
  int32_t x0 = (ix - hx - 1) & ~1, y0 = iy - hy - 1, x1 = x0 + fe->pw - 1 < w - 1 ? x0 + fe->pw - 1 : w - 1;
  fe->px0[par] = x0;
  fe->py0[par] = y0;
  c[0].src = fe->lp[l] + y0 * st + x0;
  c[0].src_stride = st;
  c[0].dst = fe->pb[par];
  c[0].dst_stride = fe->pw;
  c[0].width = x1 - x0 + 1;
  c[0].rows = want & 1 ? fe->ph : 0;
  c[0].key = (l * 2) << 24 | c[0].width << 12 | c[0].rows;
  x0 = ix - hx - FETCH_MARGIN;
  x0 = (x0 < 0 ? 0 : x0) & ~1;
  x1 = x0 + fe->nw - 1 < w - 1 ? x0 + fe->nw - 1 : w - 1;
  y0 = iy - hy - FETCH_MARGIN;
  y0 = y0 < 0 ? 0 : y0;
  int32_t y1 = iy + hy + 1 + FETCH_MARGIN < h - 1 ? iy + hy + 1 + FETCH_MARGIN : h - 1;
  fe->nx0[par] = x0;
  fe->ny0[par] = y0;
  fe->nx1[par] = x1;
  fe->ny1[par] = y1;
  c[1].src = fe->ln[l] + y0 * st + x0;
  c[1].src_stride = st;
  c[1].dst = fe->nb[par];
  c[1].dst_stride = fe->nw;
  c[1].width = x1 - x0 + 1;
  c[1].rows = want & 2 ? y1 - y0 + 1 : 0;
  c[1].key = (l * 2 + 1) << 24 | c[1].width << 12 | c[1].rows;
  fe->mask[par] = fe->ops->fetch(fe->job[l], fe->keys[l], c, 2);
}

/* Before step s: its copies there (mask of what is), the next step's on their way. */
static int32_t fetch_begin(struct lk_fetch *fe, int32_t s, int32_t f, int32_t l) {
  if (!fe->on) return 0;
  if (__builtin_expect(fe->flight != s, 0)) { /* a feature lost early: the steps between are not run */
    if (fe->flight >= 0 && fe->mask[fe->flight & 1]) fe->ops->fetch_wait();
    fetch_issue(fe, s, f, l);
  }
  int32_t m = fe->mask[s & 1];
  if (m && fe->ops->fetch_wait() != 0) m = 0;
  fe->flight = -1;
  if (__builtin_expect(s + 1 < fe->total, 1)) {
    const int32_t nl = l > 0 ? l - 1 : fe->levels - 1;
    if (__builtin_expect(fe->want[nl] != 0, 1)) {
      fetch_issue(fe, s + 1, l > 0 ? f : f + 1, nl);
    } else {
      fe->flight = s + 1;
      fe->mask[(s + 1) & 1] = 0;
    }
  }
  return m;
}

void bvb_lk_track_run(const uint8_t *prev, const uint8_t *prev_pyr, const uint8_t *next,
                      const uint8_t *next_pyr, int32_t width, int32_t height, int32_t stride,
                      const struct bvb_lk_params *params, const int32_t *in, int32_t *out,
                      void *scratch, const struct bvb_lk_ops *ops) {
  const int32_t levels = params->levels, hx = params->win_w >> 1, hy = params->win_h >> 1;
  const int32_t wy = 2 * hy + 1, npix = (2 * hx + 1) * wy;
  const int64_t flat = (int64_t)params->min_det * 65536 * npix * npix; /* setup_solve's test, once */
  int16_t *tmpl;
  int32_t *grad;
  int16_t *work;
  uint32_t room[4];
  scratch_layout(scratch, hx, hy, &tmpl, &grad, &work, room);
  const uint8_t *lp[BVB_LK_MAX_LEVELS], *ln[BVB_LK_MAX_LEVELS];
  int32_t lw[BVB_LK_MAX_LEVELS], lh[BVB_LK_MAX_LEVELS], ls[BVB_LK_MAX_LEVELS];
  for (int32_t l = 0; l < levels; ++l) {
    lw[l] = width >> l;
    lh[l] = height >> l;
    ls[l] = l == 0 ? stride : BVB_LK_LEVEL_STRIDE(lw[l]);
    const uint32_t off = bvb_lk_level_offset(width, height, l);
    lp[l] = l == 0 ? prev : prev_pyr + off;
    ln[l] = l == 0 ? next : next_pyr + off;
  }
  struct lk_fetch fe;
  fe.on = 0;
  fe.flight = -1;
  if (ops->fetch && ops->fetch_wait && params->count > 0 && ops->fetch(scratch, 0, 0, 0)) {
    fe.pw = 2 * hx + 6;
    fe.ph = wy + 3;
    fe.nw = 2 * hx + 4 + 2 * FETCH_MARGIN;
    fe.nh = wy + 1 + 2 * FETCH_MARGIN;
    const uint32_t pbytes = (uint32_t)((fe.pw * fe.ph + 3) & ~3), nbytes = (uint32_t)((fe.nw * fe.nh + 3) & ~3);
    const uint32_t need = (uint32_t)levels * BVB_LK_PYR_JOB_BYTES + 2 * (pbytes + nbytes);
    const int32_t r = room[1] >= need ? 0 : room[3] >= need ? 2 : -1;
    if (r >= 0) {
      uint8_t *m = (uint8_t *)scratch + room[r];
      for (int32_t par = 0; par < 2; ++par) {
        fe.pb[par] = m;
        m += pbytes;
        fe.nb[par] = m;
        m += nbytes;
      }
      for (int32_t j = 0; j < levels; ++j) {
        fe.job[j] = m;
        m += BVB_LK_PYR_JOB_BYTES;
        for (int32_t k = 0; k < 4; ++k) fe.keys[j][k] = -1;
      }
      fe.on = 0;
      for (int32_t l = 0; l < levels; ++l) {
        fe.want[l] = (ops->fetch((void *)(uintptr_t)lp[l], 0, 0, -1) ? 1 : 0) |
                     (ops->fetch((void *)(uintptr_t)ln[l], 0, 0, -1) ? 2 : 0);
        fe.on |= fe.want[l];
      }
      fe.ops = ops;
      fe.total = params->count * levels;
      fe.levels = levels;
      fe.hx = hx;
      fe.hy = hy;
      fe.in = in;
      fe.lp = lp;
      fe.ln = ln;
      fe.lw = lw;
      fe.lh = lh;
      fe.ls = ls;
      if (fe.on) fetch_issue(&fe, 0, 0, levels - 1);
    }
  }
  int32_t pa[BVB_LK_PA_WORDS], it[BVB_LK_IT_WORDS];
  for (int32_t f = 0; f < params->count; ++f) {
    const int32_t px = in[2 * f], py = in[2 * f + 1];
    int32_t gx = 0, gy = 0, status = BVB_LK_TRACKED, iters = 0, qx = px, qy = py;
    it[BVB_LK_IT_BX] = it[BVB_LK_IT_BY] = 0;
    for (int32_t l = levels - 1; l >= 0; --l) {
      const int32_t step = f * levels + levels - 1 - l, have = fetch_begin(&fe, step, f, l), par = step & 1;
      const int32_t tx = ((px + 32768) >> l) - 32768, ty = ((py + 32768) >> l) - 32768;
      const int32_t t7x = (tx + 256) >> 9, t7y = (ty + 256) >> 9;
      const int32_t fits = inside(t7x, t7y, hx, hy, lw[l], lh[l], 1);
      int32_t usable = 0;
      if (fits) {
        const uint8_t *img = lp[l];
        pa[BVB_LK_PA_STRIDE] = ls[l];
        if (__builtin_expect(have & 1, 1)) { /* the copy's origin: where pixel (0, 0) would be */
          img = (const uint8_t *)((uintptr_t)fe.pb[par] - (uintptr_t)(fe.py0[par] * fe.pw + fe.px0[par]));
          pa[BVB_LK_PA_STRIDE] = fe.pw;
        }
        pa[BVB_LK_PA_IX] = t7x >> 7;
        pa[BVB_LK_PA_IY] = t7y >> 7;
        pa[BVB_LK_PA_FX] = t7x & 127;
        pa[BVB_LK_PA_FY] = t7y & 127;
        pa[BVB_LK_PA_HX] = hx;
        pa[BVB_LK_PA_HY] = hy;
        ops->patch(img, tmpl, grad, work, pa);
        usable = setup_solve(pa, flat, it);
      }
      if (!usable) {
        if (l > 0) {
          gx *= 2;
          gy *= 2;
          continue;
        }
        status = fits ? BVB_LK_FLAT : BVB_LK_LEFT;
        qx = px;
        qy = py;
        break;
      }
      const uint8_t *img = ln[l];
      it[BVB_LK_IT_STRIDE] = ls[l];
      it[BVB_LK_IT_RX0] = 0;
      it[BVB_LK_IT_RY0] = 0;
      it[BVB_LK_IT_RX1] = lw[l] - 1;
      it[BVB_LK_IT_RY1] = lh[l] - 1;
      if (__builtin_expect((have & 2) != 0, 1)) {
        img = (const uint8_t *)((uintptr_t)fe.nb[par] - (uintptr_t)(fe.ny0[par] * fe.nw + fe.nx0[par]));
        it[BVB_LK_IT_STRIDE] = fe.nw;
        it[BVB_LK_IT_RX0] = fe.nx0[par];
        it[BVB_LK_IT_RY0] = fe.ny0[par];
        it[BVB_LK_IT_RX1] = fe.nx1[par];
        it[BVB_LK_IT_RY1] = fe.ny1[par];
      }
      it[BVB_LK_IT_WIDTH] = lw[l];
      it[BVB_LK_IT_HEIGHT] = lh[l];
      it[BVB_LK_IT_HX] = hx;
      it[BVB_LK_IT_HY] = hy;
      it[BVB_LK_IT_MAXITER] = params->max_iter;
      it[BVB_LK_IT_EPS] = params->eps_q16;
      it[BVB_LK_IT_FIXED] = params->flags & BVB_LK_FIXED_ITER;
      it[BVB_LK_IT_QX] = tx + gx;
      it[BVB_LK_IT_QY] = ty + gy;
      int32_t st = ops->iterate(img, tmpl, grad, work, it);
      if (st == BVB_LK_REFETCH) { /* the rest of the level on the level itself */
        const int32_t done = it[BVB_LK_IT_ITERS];
        it[BVB_LK_IT_STRIDE] = ls[l];
        it[BVB_LK_IT_RX0] = 0;
        it[BVB_LK_IT_RY0] = 0;
        it[BVB_LK_IT_RX1] = lw[l] - 1;
        it[BVB_LK_IT_RY1] = lh[l] - 1;
        it[BVB_LK_IT_MAXITER] = params->max_iter - done;
        st = ops->iterate(ln[l], tmpl, grad, work, it);
        it[BVB_LK_IT_ITERS] += done;
      }
      iters += it[BVB_LK_IT_ITERS];
      qx = it[BVB_LK_IT_QX];
      qy = it[BVB_LK_IT_QY];
      if (st == BVB_LK_LEFT) {
        status = BVB_LK_LEFT;
        break;
      }
      if (l > 0) {
        gx = 2 * (qx - tx);
        gy = 2 * (qy - ty);
      } else if (!inside((qx + 256) >> 9, (qy + 256) >> 9, hx, hy, lw[0], lh[0], 0)) {
        status = BVB_LK_LEFT;
      } else {
        status = st;
      }
    }
    int32_t *o = out + BVB_LK_OUT_WORDS * f;
    o[0] = qx;
    o[1] = qy;
    o[2] = status;
    o[3] = iters;
    o[4] = it[BVB_LK_IT_BX];
    o[5] = it[BVB_LK_IT_BY];
  }
  if (fe.on && fe.flight >= 0 && fe.mask[fe.flight & 1]) ops->fetch_wait();
}

void bvb_lk_track_c(const uint8_t *prev, const uint8_t *prev_pyr, const uint8_t *next,
                    const uint8_t *next_pyr, int32_t width, int32_t height, int32_t stride,
                    const struct bvb_lk_params *params, const int32_t *in, int32_t *out,
                    void *scratch) {
  static const struct bvb_lk_ops c_ops = {bvb_lk_patch_c, bvb_lk_iterate_c, 0, 0};
  bvb_lk_track_run(prev, prev_pyr, next, next_pyr, width, height, stride, params, in, out, scratch,
                   &c_ops);
}
