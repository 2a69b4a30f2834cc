/* Horn-Schunck optical flow (B. K. P. Horn, B. G. Schunck, "Determining optical flow", 1981),
 * fixed point, for two 8-bit grey frames I1 -> I2.
 *
 * DEFINITIONS (shared bit for bit with harness/flow/hs_double.cpp, which computes them in double)
 *   Derivatives at pixel (x, y), each the average of four first differences over the cube
 *   (x..x+1, y..y+1, frames 1..2), as in the 1981 paper. Past the right/bottom edge the last
 *   column/row is repeated, so Ex = 0 on the last column and Ey = 0 on the last row.
 *     Ex = 1/4 [I1(x+1,y)-I1(x,y) + I1(x+1,y+1)-I1(x,y+1) + I2(x+1,y)-I2(x,y) + I2(x+1,y+1)-I2(x,y+1)]
 *     Ey = 1/4 [I1(x,y+1)-I1(x,y) + I1(x+1,y+1)-I1(x+1,y) + same for I2]
 *     Et = 1/4 [I2(x,y)-I1(x,y) + I2(x+1,y)-I1(x+1,y) + I2(x,y+1)-I1(x,y+1) + I2(x+1,y+1)-I1(x+1,y+1)]
 *   The kernels carry gx = 4 Ex, gy = 4 Ey, gt = 4 Et (integers, |g| <= 1020).
 *   Local average: ubar = (u(x-1,y) + u(x+1,y) + u(x,y-1) + u(x,y+1)) / 6
 *                       + (u(x-1,y-1) + u(x+1,y-1) + u(x-1,y+1) + u(x+1,y+1)) / 12,
 *   coordinates outside the frame clamped to the nearest edge pixel (replicated border).
 *   N Jacobi iterations from u = v = 0:
 *     u' = ubar - Ex (Ex ubar + Ey vbar + Et) / (alpha^2 + Ex^2 + Ey^2), v' likewise with Ey.
 *   u points right and v down, in pixels, as in Middlebury .flo files.
 *
 * REFORMULATION. With D = 16 (alpha^2 + Ex^2 + Ey^2) = alpha2_q4 + gx^2 + gy^2 and
 *   g' = (gx, gy) / sqrt(D), gt' = gt / sqrt(D) (pixels), the update is
 *     e = gx' ubar + gy' vbar + gt',   u' = ubar - gx' e,   v' = vbar - gy' e,
 *   identical to the one above. The square root and the division happen once per frame
 *   (bvb_hs_prepare); an iteration is averages and 16 x 16 multiplies only.
 *
 * PARAMETER alpha2_q4 = 16 alpha^2 (alpha^2 in Q4, alpha in grey levels per pixel), legal
 *   range 1024..1048576 (alpha 8..256); values outside are clamped to it. The lower bound keeps
 *   |gt'| <= 255 / alpha < 32 px inside gt' (Q10); the upper bound keeps D < 2^22.
 *
 * FORMATS
 *   Flow: interleaved int16 pairs (u, v), Q9 (1/512 px), range [-64, 64) px; as a little-endian
 *     32-bit word: u in the low half, v in the high half. Host conversion: u = value / 512.0
 *     (exact in float). BVB_HS_UV_FRAC_BITS.
 *   Coefficients, one row per image row, BVB_HS_COEF_PITCH(width) int16 apart:
 *     [gx'0, gy'0, gx'1, gy'1, ..., gx'(w-1), gy'(w-1)]   g' in Q15, as words (gy':gx')
 *     [gt'0, gt'1, ..., gt'(w-1)]                          gt' in Q10 (pixels)
 *     [0] when the width is odd (so that every row starts 4-byte aligned).
 *     6 bytes per pixel.
 *
 * ROUNDING AND SATURATION. Every rounding is round-to-nearest, ties to even, at the point where
 *   a MAC/multiplier result is extracted to a half register: what the Blackfin does with
 *   ASTAT.RND_MOD = 0 (the reset state, which the kernels rely on) and what the GNU simulator
 *   always does. Saturations happen only where the named instruction saturates ((S) adds and
 *   half-register extractions).
 *
 * PREPARE (per pixel; exact operations, see bvb_hs_coefficients_c):
 *   D = alpha2_q4 + gx^2 + gy^2                     in [1024, 3129376] < 2^22
 *   k = the integer with Dn = D * 4^k in [2^28, 2^30); k in [4, 9]
 *   S = bvb_hs_rsqrt_table[(Dn >> 20) - 256]       ~ 2^29 / sqrt(Dn), in [16388, 32736],
 *                                                  relative error < 0.985e-3
 *   gx' = sat16(round(2 (gx 2^k) S / 2^15))        (S2RND); |gx 2^k| < sqrt(Dn) < 2^15
 *   gy' likewise
 *   gt' = sat16(round(2 tn S / 2^15)),  tn = gt 2^(k-5) (k >= 5) or gt >> 1 (k = 4, floor):
 *         |tn| <= |gt| / sqrt(D) 2^10 <= 1020 / 32 * 1024 = 32640
 *   gx', gy' are within [-1.001, 1.001) before saturation; gt' within +-32 px (alpha >= 8).
 *
 * ITERATE (per pixel, per component c in {u, v}; T, M, B = rows y-1, y, y+1 of the input,
 *   clamped; L, R = columns x-1, x+1, clamped; W12 = 2731 = round(2^15/12), W6 = 5461: their
 *   weights sum to exactly 2^15, so a constant field is reproduced exactly):
 *   cl = sat16(T(L) + B(L)), c0 = sat16(T(x) + B(x)), cr = sat16(T(R) + B(R)),
 *   e1 = sat16(M(L) + M(R))                                 four (S) adds, exact for |u| < 32 px
 *   acc = 2 (cl W12 + cr W12 + e1 W6 + c0 W6)               exact, |acc| <= 2^30 (= ubar 2^25)
 *   bar = sat16(round(acc / 2^16))                          ubar in Q9, |bar| <= 16384
 *   p_u = sat16(round(2 ubar gx' / 2^15)), p_v likewise     (S2RND) Q10
 *   e = sat16(sat16(p_u + p_v) + gt')                       Q10, exact while |e| < 32 px
 *   u' = sat16(round((acc_u - e gx') / 2^16))               integer (IH) product; one rounding
 *   v' = sat16(round((acc_v - e gy') / 2^16))               |acc - e g| <= 2^31 - 2^16
 *   Nothing saturates while |u|, |v| < 22 px (so |g'.(ubar, vbar)| < 32 px) and |e| < 32 px;
 *   where something does, it is the hardware's saturation, so the assembly still matches. No
 *   fractional product can be -1 * -1 (|bar| <= 16384; S and the weights are positive), the
 *   one product whose fractional value, +1.0, does not fit 32 bits. All accumulators stay within int32 (the
 *   hardware's are 40-bit), so the C needs no 64-bit arithmetic.
 *
 * ACCURACY (harness/flow/hs_accuracy.cpp, six ground-truth sequences of frames-real): mean
 *   endpoint distance to the double-precision version 0.0009-0.0011 px at alpha 8 with 10
 *   iterations, 0.0012-0.0017 px with 100; below 0.008 px for alpha 16..256 at 100 iterations and
 *   below 0.013 px at alpha 8 with 1000. The once-per-iteration rounding of the flow dominates,
 *   which is why the flow is Q9 and is rounded once per iteration, not twice.
 *
 * MEMORY. Working set 14 bytes per pixel during the iterations (6 coefficients + 4 flow in + 4
 *   flow out), 8 during prepare (2 frame + 6 coefficients). 160x120: 263 KB, more than the 64 KB
 *   of L1 data, so whole frames live in SDRAM at every size; L1 holds row bands streamed by DMA:
 *   one iteration needs 3 input flow rows + 1 coefficient row + 1 output row = 22 bytes x width
 *   (3.5 KB at 160, 14 KB at 640; twice that double-buffered), and alone it is bus-bound: 14
 *   bytes a pixel at 0.5 byte a cycle is 28 cycles, against 10 of compute. Doing L iterations in
 *   one pass down the frame (level k works 1 row behind level k-1) needs 18 (L + 1) width bytes
 *   (FUSED ITERATIONS above: bvb_hs_iterate_n_asm, 12 (L + 1) width of flow rows, (L + 1)
 *   coefficient rows) and moves the 14 bytes once for the L: 28 / L cycles an iteration, under
 *   the compute from L = 3. bvb_hs_prepare_asm streams its rows too (the frames' rows in, the
 *   coefficient rows out, through BVB_HS_PREPARE_SCRATCH_BYTES of L1); bvb_hs_iterate_asm (one
 *   iteration) reads and writes the frames where they are; bvb_hornschunck_asm is prepare
 *   and one bvb_hs_iterate_n_asm.
 *
 * ASSEMBLY PLAN (BF537; one 32-bit ALU/MAC instruction per cycle plus two loads or one load and
 *   one store in parallel; counts are issue slots per pixel, loads ride in the parallel slots).
 *   bvb_hs_iterate_asm, 10 slots/pixel (budget 14), interior pixels, u/v packed in one register:
 *     loads: T(x+1), B(x+1), M(x-1), M(x+1), G = (gy':gx') (32-bit each), gt' into a half
 *     (16-bit); one store of (v':u'). State carried between pixels: cl, c0 (rotate cl/c0/cr).
 *      1  cr = T +|+ B (S)
 *      2  e1 = ML +|+ MR (S)
 *      3  A1 = cl.H * K.L, A0 = cl.L * K.L              K = (W6:W12), default fractional mode
 *      4  A1 += cr.H * K.L, A0 += cr.L * K.L
 *      5  A1 += e1.H * K.H, A0 += e1.L * K.H
 *      6  W.H = (A1 += c0.H * K.H), W.L = (A0 += c0.L * K.H)   bar; A1:A0 keep the exact sums
 *      7  P.H = W.H * G.H, P.L = W.L * G.L (S2RND)       multiply without accumulate
 *      8  P.L = P.L + P.H (S)
 *      9  P.L = P.L + Tg.L (S)                           gt'
 *     10  O.H = (A1 -= P.L * G.H), O.L = (A0 -= P.L * G.L) (IH)   store O
 *     8 data registers suffice (K, G, cl, c0, cr/T, B/e1, W/P, Tg). First and last pixel of a
 *     row are peeled (left/right neighbour = itself); the first/last row reuse the row pointer.
 *   bvb_hs_prepare_asm, about 19.5 slots/pixel (budget 20), 4 columns per loop:
 *     derivatives ~5: BYTEOP16P/M give per-row frame sums I1+I2 and differences I2-I1 for 4
 *       columns (4 slots/4 px); one quad add +|+ / -|- per column pair gives column sums s and
 *       vertical differences p, one add gives q (2/px together); PACK (p:s) per column (1/px);
 *       G = C(x+1) +|- C(x) = (gy:gx) (1/px); gt pairs by ALIGN16 + add (1/px).
 *     D 3: A0 = 2 alpha2_q4; A0 += G.L*G.L; R = (A0 += G.H*G.H) -> 2D (fractional doubles it).
 *     normalise 4: SIGNBITS(2D) = 2k+{0,1}; k = that >> 1; 2k; 2Dn = 2D << 2k.
 *     table 3: j = 2Dn >> 21; P0 = j; P0 = P5 + (P0 << 1); S = W[P0] (P5 = table - 512).
 *     scale 3.5: G <<= k (V); t = k - 5; gt.L/H = ASHIFT gt BY t; three dual S2RND multiplies
 *       per 2 pixels: (gy':gx') for each pixel and the gt' pair (S_b:S_a) against (tn_b:tn_a).
 *     Stores: one word of (gy':gx') per pixel and one word per gt' pair.
 *
 * SIZES AND LAYOUT. 2 <= width, height (the C also accepts 1); no upper limit is imposed by the
 *   arithmetic (tested up to 640x480, odd sizes included). Frames: 8-bit, `stride` bytes per
 *   row (>= width), both frames with the same stride. Flow buffers: 4-byte aligned, strides in
 *   bytes, multiples of 4, >= 4 * width; uv_in and uv_out must not overlap. Coefficients:
 *   4-byte aligned, BVB_HS_COEF_BYTES(width, height) bytes. */
#ifndef BVB_HORNSCHUNCK_H
#define BVB_HORNSCHUNCK_H

#include <stdint.h>

#include "bvb/stream.h"

#ifdef __cplusplus
extern "C" {
#endif

#define BVB_HS_ALPHA2_Q4_MIN 1024    /* alpha = 8 */
#define BVB_HS_ALPHA2_Q4_MAX 1048576 /* alpha = 256 */
#define BVB_HS_MIN_DIM 2
#define BVB_HS_UV_FRAC_BITS 9 /* flow Q format */
#define BVB_HS_G_FRAC_BITS 15 /* gx', gy' */
#define BVB_HS_GT_FRAC_BITS 10 /* gt' */
#define BVB_HS_W12 2731       /* diagonal neighbour weight, Q15 */
#define BVB_HS_W6 5461        /* edge neighbour weight, Q15; 4 * (W12 + W6) == 32768 */
#define BVB_HS_RSQRT_ENTRIES 768

/* Coefficient row pitch in int16 units, bytes for a whole frame, and the scratch that
 * bvb_hornschunck needs (coefficients, then one zero row of flow and the word after it: the
 * start field, read with stride 0). */
#define BVB_HS_COEF_PITCH(w) (3 * (w) + ((w) & 1))
#define BVB_HS_COEF_BYTES(w, h) (2 * BVB_HS_COEF_PITCH(w) * (h))
#define BVB_HS_SCRATCH_BYTES(w, h) (BVB_HS_COEF_BYTES(w, h) + 4 * (w) + 4)

/* The L1 scratch of bvb_hs_prepare_asm's streamed path: the row-band stream (bvb/stream.h) of
 * rows 1..h-1 of both frames in and coefficient rows 0..h-2 out, and two rows of per-row sums
 * (4 bytes a pixel: the pass-A data of the row above a band's first row, and of the row below
 * its last). 11.6 KB at 160 wide (bands of 4 rows), 12.9 KB at 320 (2), 15.4 KB at 640 (1). */
#define BVB_HS_PREPARE_SCRATCH_BYTES(w)                                                      \
  (BVB_STREAM_SCRATCH_BYTES((w), (w), 2 * BVB_HS_COEF_PITCH(w)) + 8 * (w))

/* FUSED ITERATIONS (bvb_hs_iterate_n_asm). Iteration level k of row y needs level k-1 of rows
 * y-1..y+1 and coefficient row y, so L levels run one pass down the frame, level k one row behind
 * level k-1: at step t level k makes row t-k+1. Each level 1..L-1 keeps a ring of 3 rows, the
 * input (level 0) a ring of 4 (3 read, 1 arriving), the output 2 (1 written, 1 leaving), the
 * coefficients L+1 (L read, 1 arriving): 12 (L+1) width bytes of flow rows and (L+1) coefficient
 * rows. A pass moves 14 bytes a pixel through SDRAM once for its L iterations (28 / L cycles a
 * pixel an iteration at 0.5 byte a cycle). L is the most levels (at most 8) whose flow rows fit
 * BVB_HS_ITER_L1_BUDGET (22.5 KB: most of the 24 KB that L1 bank B has beside the stack; the
 * coefficient rows, 11.6 KB at most, go in bank A): 8 at 160 wide, 5 at 320, 2 at 640. n
 * iterations take ceil(n / L) passes of as equal a number of levels as they can (10 at 160 and
 * 320 wide: 5 and 5; at 640, five of 2, bus-bound at 14 cycles a pixel an iteration; vertical
 * tiles with halos would let wider frames fuse more levels, not built). Each pass after the
 * first works in place in uv_out: an input row is in L1 before the output row that replaces it
 * leaves. */
#define BVB_HS_ITER_L1_BUDGET 23040
#define BVB_HS_ITER_MAX_LEVELS 8
#define BVB_HS_ITER_LEVELS(w)                                                                \
  (BVB_HS_ITER_L1_BUDGET / (12 * (w)) - 1 > BVB_HS_ITER_MAX_LEVELS ? BVB_HS_ITER_MAX_LEVELS  \
   : BVB_HS_ITER_L1_BUDGET / (12 * (w)) - 1 < 1                    ? 1                       \
                                                                   : BVB_HS_ITER_L1_BUDGET / (12 * (w)) - 1)
#define BVB_HS_ITER_FLOW_SCRATCH_BYTES(w) (12 * (w) * (BVB_HS_ITER_LEVELS(w) + 1))
#define BVB_HS_ITER_COEF_SCRATCH_BYTES(w) (2 * BVB_HS_COEF_PITCH(w) * (BVB_HS_ITER_LEVELS(w) + 1))

/* bvb_hornschunck's flow-row scratch: prepare's stream, then the fused iterations' rings. */
#define BVB_HS_FLOW_SCRATCH_BYTES(w)                                                         \
  (BVB_HS_PREPARE_SCRATCH_BYTES(w) > BVB_HS_ITER_FLOW_SCRATCH_BYTES(w)                       \
       ? BVB_HS_PREPARE_SCRATCH_BYTES(w)                                                     \
       : BVB_HS_ITER_FLOW_SCRATCH_BYTES(w))

/* rsqrt mantissas used by prepare (1536 bytes; the assembly reads the same table). */
extern const int16_t bvb_hs_rsqrt_table[BVB_HS_RSQRT_ENTRIES];

/* The per-pixel coefficient arithmetic of prepare, exposed for tests: from gx, gy, gt
 * (|.| <= 1020) to out[0] = gx' (Q15), out[1] = gy' (Q15), out[2] = gt' (Q10). */
void bvb_hs_coefficients_c(int32_t gx, int32_t gy, int32_t gt, int32_t alpha2_q4, int16_t *out);

/* Derivatives and coefficients for the frame pair, once per frame. scratch:
 * BVB_HS_PREPARE_SCRATCH_BYTES(width) bytes, 4-byte aligned, or NULL: with a frame or the
 * coefficients in SDRAM and the scratch in L1 the assembly streams row bands through it
 * (bvb/stream.h); otherwise, and in the C reference, it is not used. */
void bvb_hs_prepare_c(const uint8_t *i1, const uint8_t *i2, int32_t width, int32_t height,
                      int32_t stride, int32_t alpha2_q4, int16_t *coef, void *scratch);
void bvb_hs_prepare_asm(const uint8_t *i1, const uint8_t *i2, int32_t width, int32_t height,
                        int32_t stride, int32_t alpha2_q4, int16_t *coef, void *scratch);

/* One Jacobi iteration uv_in -> uv_out; the caller ping-pongs the two buffers. flow_scratch
 * and coef_scratch: NULL, or as bvb_hs_iterate_n's (BVB_HS_ITER_FLOW_SCRATCH_BYTES(width) and
 * BVB_HS_ITER_COEF_SCRATCH_BYTES(width) bytes, 4-byte aligned): given, the assembly is
 * bvb_hs_iterate_n_asm with one iteration, the rows streamed through them by DMA where it
 * reaches (the frames in SDRAM, the scratches in L1: bus-bound, 14 bytes a pixel at 0.5 a
 * cycle); NULL, it reads and writes the buffers where they are. The C reference uses neither. */
void bvb_hs_iterate_c(const int16_t *coef, const int16_t *uv_in, int32_t in_stride,
                      int16_t *uv_out, int32_t out_stride, int32_t width, int32_t height,
                      void *flow_scratch, void *coef_scratch);
void bvb_hs_iterate_asm(const int16_t *coef, const int16_t *uv_in, int32_t in_stride,
                        int16_t *uv_out, int32_t out_stride, int32_t width, int32_t height,
                        void *flow_scratch, void *coef_scratch);

/* `iterations` (>= 1; fewer: nothing is written) Jacobi iterations uv_in -> uv_out, exactly
 * those of as many bvb_hs_iterate calls ping-ponging two buffers (uv_in is left as it was).
 * in_stride may also be 0: every row of the field is the one row at uv_in (4 width + 4 bytes
 * there: the assembly reads the word after it), as bvb_hornschunck starts from zero flow.
 * The assembly fuses them (FUSED ITERATIONS below): up to BVB_HS_ITER_LEVELS(width) in one pass
 * down the frame, the intermediate rows in flow_scratch, the coefficient rows in coef_scratch.
 * flow_scratch: BVB_HS_ITER_FLOW_SCRATCH_BYTES(width) bytes, coef_scratch:
 * BVB_HS_ITER_COEF_SCRATCH_BYTES(width) bytes, both 4-byte aligned (the C reference uses two
 * rows of flow_scratch). With the frames in SDRAM and the scratches in DMA-reachable L1 the rows
 * move by memory DMA, double-buffered; elsewhere the core copies them. */
void bvb_hs_iterate_n_c(const int16_t *coef, const int16_t *uv_in, int32_t in_stride,
                        int16_t *uv_out, int32_t out_stride, int32_t width, int32_t height,
                        int32_t iterations, void *flow_scratch, void *coef_scratch);
void bvb_hs_iterate_n_asm(const int16_t *coef, const int16_t *uv_in, int32_t in_stride,
                          int16_t *uv_out, int32_t out_stride, int32_t width, int32_t height,
                          int32_t iterations, void *flow_scratch, void *coef_scratch);

/* Prepare plus `iterations` iterations from zero flow (bvb_hs_prepare, then one
 * bvb_hs_iterate_n); the result is in uv_out (zero flow for iterations < 1). scratch:
 * BVB_HS_SCRATCH_BYTES(width, height) bytes, 4-byte aligned (the coefficients; SDRAM on the
 * robot). flow_scratch: BVB_HS_FLOW_SCRATCH_BYTES(width) bytes, coef_scratch:
 * BVB_HS_ITER_COEF_SCRATCH_BYTES(width) bytes, 4-byte aligned: prepare's stream and the
 * iterations' rings (L1 banks B and A on the robot, as bvb_hs_iterate_n says). */
void bvb_hornschunck_c(const uint8_t *i1, const uint8_t *i2, int32_t width, int32_t height,
                       int32_t stride, int32_t alpha2_q4, int32_t iterations, int16_t *uv_out,
                       int32_t out_stride, void *scratch, void *flow_scratch, void *coef_scratch);
void bvb_hornschunck_asm(const uint8_t *i1, const uint8_t *i2, int32_t width, int32_t height,
                         int32_t stride, int32_t alpha2_q4, int32_t iterations, int16_t *uv_out,
                         int32_t out_stride, void *scratch, void *flow_scratch, void *coef_scratch);

#ifdef __cplusplus
}
#endif

#endif
