/* Pyramidal Lucas-Kanade feature tracking in fixed point (Bouguet's iterative scheme: for every
 * feature and pyramid level, the spatial gradient matrix G of the template window and, per
 * iteration, the mismatch vector b of the interpolated window in the next frame; the update
 * eta = G^-1 b is the least-squares solution of the seed paper's equation 6).
 *
 * PYRAMID (bvb_lk_pyramid): level l+1 is level l downsampled by 2x2 box averaging with rounding,
 *   L_{l+1}(x, y) = (L_l(2x,2y) + L_l(2x+1,2y) + L_l(2x,2y+1) + L_l(2x+1,2y+1) + 2) >> 2,
 *   w_{l+1} = w_l >> 1, h_{l+1} = h_l >> 1 (an odd last row or column is dropped). Level 0 is the
 *   frame itself; levels 1 .. levels-1 are packed in one buffer: level l at byte offset
 *   BVB_LK_LEVEL_OFFSET, rows of BVB_LK_LEVEL_STRIDE(w_l) = (w_l + 3) & ~3 bytes (the padding
 *   bytes are not written). A level-l pixel covers level-0 pixels 2^l x .. 2^l x + 2^l - 1, so the
 *   level-l coordinate of a level-0 point p is (p + 1/2) / 2^l - 1/2.
 *
 * TRACKING (bvb_lk_track), per feature, from the coarsest level to level 0:
 *   Positions are Q16 pixels (int32; pixel centres at integers). At level L the template sits at
 *   pL = ((p0 + 32768) >> L) - 32768 and the search at pL + g, g the guess carried from the level
 *   above (doubled), 0 at the coarsest.
 *   Bilinear interpolation at a Q16 position q: q7 = (q + 256) >> 9 (round to 1/128 px),
 *   i = q7 >> 7, f = q7 & 127; with wx0 = 128 - fx, wx1 = fx (likewise y):
 *     h(x, y) = wx0 I(x, y) + wx1 I(x+1, y)                    [Q7, <= 32640]
 *     v(x, y) = wy0 h(x, y) + wy1 h(x, y+1)                    [Q14, <= 4177920]
 *     value = v >> 9                                           [Q5, truncated, <= 8160]
 *   Template T (frame I, level L) on (wx+2) x (wy+2) samples around the template position;
 *   gradients on the wx x wy window, central differences of T (twice the derivative, Q5):
 *     Ix = T(i+1, j) - T(i-1, j), Iy = T(i, j+1) - T(i, j-1)   [-8160, 8160]
 *   Structure tensor, exact sums >> 4 (floor; |.| < 2^30 for wx*wy <= 225):
 *     gxx = (sum Ix^2) >> 4, gxy = (sum Ix Iy) >> 4, gyy = (sum Iy^2) >> 4
 *   Flat window: gxx*gyy - gxy^2 < min_det * 65536 * (wx*wy)^2 (int64): the determinant of the
 *   mean tensor of the derivatives below min_det, in (grey levels per pixel)^4.
 *   The inverse, once per level: s = bitlen(max(gxx, gyy)) - 15; a, d, c = gxx, gyy, gxy
 *   shifted by s (right, floor; left when s < 0), c clamped to +-32767; D = a*d - c*c (int32,
 *   < 2^30), D <= 0 is flat too; u = bitlen(D) - 15, Dn = D shifted by u, R = 2^28 / Dn
 *   (integer division, in (2^13, 2^14]); M = ((d*R) >> 15, (-c*R) >> 15, (a*R) >> 15) (int16)
 *   and S = s + u - 4, so that G^-1 ~ M 2^-(S+17) in the units below.
 *   Each iteration at q (Q16, level L, frame J): the window must be inside: i - hx >= 0,
 *   i + hx + 1 <= w_L - 1 (likewise y), else the feature has left the image. Then
 *     dI = T(i, j) - J(q + (i, j))                             [-8160, 8160]
 *     bx = (sum dI Ix) >> 4, by = (sum dI Iy) >> 4             (exact sums, floor)
 *     t = max(0, 16 - min(signbits(bx), signbits(by)));  bx', by' = bx >> t, by >> t (int16)
 *     Px = Mxx bx' + Mxy by', Py = Mxy bx' + Myy by'           (int32)
 *     eta = P shifted right by S - t (floor; left when negative), clamped to +-2^22 (64 px)
 *     q += eta; converged when |eta_x| <= eps and |eta_y| <= eps.
 *   signbits(v) is the Blackfin's: the number of bits below the sign bit that equal it (0..31).
 *   Unless BVB_LK_FIXED_ITER, a level stops at convergence; with it every level runs max_iter
 *   iterations and the convergence test applies to the last update only.
 *   Levels where the template does not fit (i - hx - 1 >= 0, i + hx + 2 <= w_L - 1, likewise y)
 *   or the window is flat are skipped (the guess is doubled and passed on) except level 0,
 *   where the feature is lost. After level 0 the final position must be inside too.
 * Status: BVB_LK_TRACKED, BVB_LK_LEFT (the window left the image, or the feature's own window
 * at level 0 does not fit in the first frame), BVB_LK_FLAT, BVB_LK_NOT_CONVERGED (the level-0
 * iterations ran out).
 *
 * Arguments of bvb_lk_track: prev, next: level 0 of both frames (width x height, stride bytes
 * between rows, no alignment required); prev_pyr, next_pyr: their levels 1 .. levels-1 as
 * bvb_lk_pyramid writes them (ignored when levels = 1; 4-byte aligned); params: struct
 * bvb_lk_params; in: 2 int32 per feature (x, y, Q16, level 0 of prev); out: BVB_LK_OUT_WORDS
 * int32 per feature (x, y in Q16 in next, status, iterations summed over the levels, and the
 * last iteration's bx, by, 0 if none ran); a lost feature reports where it was lost (its input
 * position when its level-0 template was unusable). scratch: BVB_LK_SCRATCH_BYTES, 4-byte
 * aligned, any contents; in L1 where memory DMA reaches, the assembly also keeps there the
 * copies of each level step's windows that it brings from SDRAM (bvb_lk_track_run's fetch,
 * below), when the window's arrays leave room; only speed depends on it. width, height >= 1
 * and <= 16384; feature coordinates within +-16384 pixels. bvb_lk_pyramid: 1 <= levels <= BVB_LK_MAX_LEVELS (a level of zero size is
 * empty); pyr 4-byte aligned; its assembly reads the frame by aligned words (up to 3 bytes
 * either side of a row).
 *
 * STREAMED PYRAMID (bvb_lk_pyramid_streamed, the registry's lk_pyramid): the same levels, with
 * scratch: BVB_LK_PYRAMID_SCRATCH_BYTES(width) bytes, 4-byte aligned, any contents. With the
 * frame in SDRAM and the scratch in L1 where memory DMA reaches it, the assembly brings the
 * frame's rows into the scratch by memory DMA, BVB_LK_PYR_BAND(width) level-1 rows' worth a
 * band (twice as many frame rows), double-buffered, computes levels 1 to 3 of the band there
 * and sends them to pyr by DMA (or writes them straight into pyr when pyr is not in SDRAM);
 * level 4 (levels = 5) is made from level 3 afterwards. Elsewhere (the frame in L1, the
 * scratch where DMA does not reach, no level to make) it is bvb_lk_pyramid_asm. The C
 * reference is bvb_lk_pyramid_c (the scratch unused). */
#ifndef BVB_LK_H
#define BVB_LK_H

#define BVB_LK_MAX_LEVELS 5
#define BVB_LK_MAX_HALF 7          /* windows up to 15 x 15 */
#define BVB_LK_FIXED_ITER 1        /* params.flags */

#define BVB_LK_TRACKED 0
#define BVB_LK_LEFT 1
#define BVB_LK_FLAT 2
#define BVB_LK_NOT_CONVERGED 3
#define BVB_LK_REFETCH 4           /* the iteration step only: the window left the bytes it has */

#define BVB_LK_OUT_WORDS 6
#define BVB_LK_SCRATCH_BYTES 4096

#define BVB_LK_LEVEL_STRIDE(w) (((w) + 3) & ~3)

/* The streamed pyramid's scratch: two DMA jobs (bvb/dma.h's BVB_DMA_JOB_BYTES each) and, twice,
 * a band of 2 B frame rows (rows of (w + 3) & ~3 bytes) and its B, B/2, B/4 rows of levels 1 to
 * 3 (rows of their level strides), B = BVB_LK_PYR_BAND(w): 13,824 bytes at 160, 320 and 640
 * wide. B is a multiple of 4, so a band's level-2 and level-3 rows are whole. */
#define BVB_LK_PYR_BAND(w) ((w) <= 192 ? 16 : (w) <= 384 ? 8 : 4)
#define BVB_LK_PYR_JOB_BYTES 112
#define BVB_LK_PYRAMID_SCRATCH_BYTES(w)                                                        \
  (2 * BVB_LK_PYR_JOB_BYTES +                                                                  \
   2 * (2 * BVB_LK_PYR_BAND(w) * BVB_LK_LEVEL_STRIDE(w) +                                     \
        BVB_LK_PYR_BAND(w) * BVB_LK_LEVEL_STRIDE((w) >> 1) +                                  \
        (BVB_LK_PYR_BAND(w) >> 1) * BVB_LK_LEVEL_STRIDE((w) >> 2) +                           \
        (BVB_LK_PYR_BAND(w) >> 2) * BVB_LK_LEVEL_STRIDE((w) >> 3)))

/* The iteration block (int32 words) shared by the C and assembly iteration steps. */
#define BVB_LK_IT_STRIDE 0
#define BVB_LK_IT_WIDTH 1
#define BVB_LK_IT_HEIGHT 2
#define BVB_LK_IT_HX 3
#define BVB_LK_IT_HY 4
#define BVB_LK_IT_MXX 5
#define BVB_LK_IT_MXY 6
#define BVB_LK_IT_MYY 7
#define BVB_LK_IT_SHIFT 8
#define BVB_LK_IT_MAXITER 9
#define BVB_LK_IT_EPS 10
#define BVB_LK_IT_FIXED 11
#define BVB_LK_IT_QX 12            /* in and out */
#define BVB_LK_IT_QY 13
#define BVB_LK_IT_ITERS 14         /* out */
#define BVB_LK_IT_BX 15            /* out */
#define BVB_LK_IT_BY 16
#define BVB_LK_IT_RX0 17           /* the bytes the step may read: x in [RX0, RX1], y in [RY0, RY1] */
#define BVB_LK_IT_RY0 18
#define BVB_LK_IT_RX1 19
#define BVB_LK_IT_RY1 20
#define BVB_LK_IT_WORDS 21

/* The patch block (int32 words). */
#define BVB_LK_PA_STRIDE 0
#define BVB_LK_PA_IX 1
#define BVB_LK_PA_IY 2
#define BVB_LK_PA_FX 3
#define BVB_LK_PA_FY 4
#define BVB_LK_PA_HX 5
#define BVB_LK_PA_HY 6
#define BVB_LK_PA_GXX 7            /* out */
#define BVB_LK_PA_GXY 8
#define BVB_LK_PA_GYY 9
#define BVB_LK_PA_WORDS 10

#ifndef __ASSEMBLER__
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

struct bvb_lk_params {
  int32_t levels;    /* 1 .. BVB_LK_MAX_LEVELS; 1 = no pyramid */
  int32_t win_w;     /* odd, 3 .. 15 */
  int32_t win_h;     /* odd, 3 .. 15 */
  int32_t max_iter;  /* per level, 1 .. 100 */
  int32_t eps_q16;   /* >= 0 */
  int32_t min_det;   /* 0 .. 2^20 */
  int32_t flags;     /* BVB_LK_FIXED_ITER */
  int32_t count;     /* features, >= 0 */
};

/* Bytes of the packed levels 1 .. levels-1 of a width x height frame, and where level l starts. */
uint32_t bvb_lk_pyramid_bytes(int32_t width, int32_t height, int32_t levels);
uint32_t bvb_lk_level_offset(int32_t width, int32_t height, int32_t level);

void bvb_lk_pyramid_c(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                      int32_t levels, uint8_t *pyr);
void bvb_lk_pyramid_asm(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                        int32_t levels, uint8_t *pyr);

void bvb_lk_pyramid_streamed_c(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                               int32_t levels, uint8_t *pyr, void *scratch);
void bvb_lk_pyramid_streamed_asm(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                                 int32_t levels, uint8_t *pyr, void *scratch);
/* The streamed pyramid's driver (Blackfin only: it runs the DMA), with `level` making the
 * levels of a band (bvb_lk_pyramid_asm's signature). */
typedef void (*bvb_lk_level_fn)(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                                int32_t levels, uint8_t *pyr);
void bvb_lk_pyramid_stream_run(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                               int32_t levels, uint8_t *pyr, void *scratch, bvb_lk_level_fn level);

void bvb_lk_track_c(const uint8_t *prev, const uint8_t *prev_pyr, const uint8_t *next,
                    const uint8_t *next_pyr, int32_t width, int32_t height, int32_t stride,
                    const struct bvb_lk_params *params, const int32_t *in, int32_t *out,
                    void *scratch);
void bvb_lk_track_asm(const uint8_t *prev, const uint8_t *prev_pyr, const uint8_t *next,
                      const uint8_t *next_pyr, int32_t width, int32_t height, int32_t stride,
                      const struct bvb_lk_params *params, const int32_t *in, int32_t *out,
                      void *scratch);

/* The two inner steps, in C and in assembly, and the driver that runs them (bvb_lk_track_c and
 * bvb_lk_track_asm are the driver with one set or the other).
 * patch: the template, gradients and structure tensor of one level (block BVB_LK_PA_*): tmpl gets
 * T on the window (int16, rows of wx + 1, the last column 0), grad the words Ix | Iy << 16 (same
 * layout, the last column 0); work holds the extended template.
 * iterate: the iterations of one level (block BVB_LK_IT_*); returns BVB_LK_TRACKED (converged),
 * BVB_LK_NOT_CONVERGED or BVB_LK_LEFT, or BVB_LK_REFETCH when an iteration's window (the bytes
 * x = ix - hx .. ix + hx + 1, y = iy - hy .. iy + hy + 1) is inside the image but not inside
 * [RX0, RX1] x [RY0, RY1], the bytes img holds (a copy of part of the level): QX, QY and ITERS
 * are then those at that iteration's start, and the rest of the level runs again on the level
 * itself with MAXITER less ITERS. Its work holds h; the assembly keeps the differences
 * in the 2 wy (wx + 1) + 8 bytes after the template's end (the driver's scratch layout leaves
 * them free, in the template's L1 sub-bank). */
typedef void (*bvb_lk_patch_fn)(const uint8_t *img, int16_t *tmpl, int32_t *grad, int16_t *work,
                                int32_t *block);
typedef int32_t (*bvb_lk_iterate_fn)(const uint8_t *img, const int16_t *tmpl, const int32_t *grad,
                                     int16_t *work, int32_t *block);
void bvb_lk_patch_c(const uint8_t *img, int16_t *tmpl, int32_t *grad, int16_t *work, int32_t *block);
void bvb_lk_patch_asm(const uint8_t *img, int16_t *tmpl, int32_t *grad, int16_t *work, int32_t *block);
int32_t bvb_lk_iterate_c(const uint8_t *img, const int16_t *tmpl, const int32_t *grad, int16_t *work,
                         int32_t *block);
int32_t bvb_lk_iterate_asm(const uint8_t *img, const int16_t *tmpl, const int32_t *grad,
                           int16_t *work, int32_t *block);
/* fetch: copies of parts of the levels into L1 for the next level step (bvb_lk_track_run): up
 * to n blocks, bvb_dma_xfer's fields and a key (the same key: the same shape, level and image,
 * so a slot prepared for it need only be re-addressed); starts them on job (BVB_DMA_JOB_BYTES,
 * keys: BVB_DMA_MAX_XFERS words of the job's slot keys) and returns a mask of the blocks that
 * will be there after fetch_wait (the others stay where they are: the images already in L1).
 * fetch_wait: waits for the last fetch; nonzero when it failed (its blocks are not there).
 * Both NULL: no copies. fetch(scratch, 0, 0, 0): nonzero when copies into the scratch are
 * worth asking for (it is in L1 where DMA reaches); fetch(level, 0, 0, -1): nonzero when
 * copies from that level's image are (it is in SDRAM). */
struct bvb_lk_copy {
  const void *src;
  int32_t src_stride;
  void *dst;
  int32_t dst_stride;
  int32_t width;
  int32_t rows;
  int32_t key;
};
typedef int32_t (*bvb_lk_fetch_fn)(void *job, int32_t *keys, const struct bvb_lk_copy *c, int32_t n);
typedef int32_t (*bvb_lk_fetch_wait_fn)(void);
int32_t bvb_lk_fetch_dma(void *job, int32_t *keys, const struct bvb_lk_copy *c, int32_t n);
int32_t bvb_lk_fetch_wait_dma(void);
struct bvb_lk_ops {
  bvb_lk_patch_fn patch;
  bvb_lk_iterate_fn iterate;
  bvb_lk_fetch_fn fetch;
  bvb_lk_fetch_wait_fn fetch_wait;
};
/* Where in an area of `bytes` bytes (4-byte aligned, at least BVB_LK_SCRATCH_BYTES) a caller
 * with room to spare puts the tracker's scratch for win_w x win_h windows: the first 4-byte
 * aligned start at which the driver's layout can put the iteration's two groups of arrays in
 * different 4 KB sub-banks (see bvb_lk_track_run in firmware/c/lk.c), else the area itself.
 * Only speed depends on it. */
const uint8_t *bvb_lk_scratch_place(const uint8_t *area, uint32_t bytes, int32_t win_w, int32_t win_h);
void bvb_lk_track_run(const uint8_t *prev, const uint8_t *prev_pyr, const uint8_t *next,
                      const uint8_t *next_pyr, int32_t width, int32_t height, int32_t stride,
                      const struct bvb_lk_params *params, const int32_t *in, int32_t *out,
                      void *scratch, const struct bvb_lk_ops *ops);

#ifdef __cplusplus
}
#endif
#endif /* __ASSEMBLER__ */

#endif
