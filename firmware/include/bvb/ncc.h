/* Normalised cross-correlation (NCC) block matching: feature tracking between two frames.
 *
 * For each feature point (x, y) of frame 1, the (2r+1)x(2r+1) template T around it is compared
 * with every (2r+1)x(2r+1) window I of frame 2 centred at (x+dx, y+dy), -s <= dx, dy <= s,
 * using the zero-mean normalised cross-correlation
 *
 *   score(dx,dy) = sum (T - Tbar)(I - Ibar) / sqrt( sum (T - Tbar)^2 * sum (I - Ibar)^2 )
 *
 * (Ibar is the mean of the window at that offset). Everything is integer:
 *   N  = (2r+1)^2, ST = sum T, STT = sum T^2, SI = sum I, SII = sum I^2,
 *   T'(i,j) = N*T(i,j) - ST            the zero-mean template, |T'| <= 121*255 < 2^15
 *   num     = sum T'*I = N*sum (T-Tbar)(I-Ibar)              |num| < 2^28
 *   vt      = N*STT - ST^2 = N*sum (T-Tbar)^2                 0 <= vt < 2^28
 *   v       = N*SII - SI^2 = N*sum (I-Ibar)^2                 0 <= v  < 2^28
 *   score   = num / sqrt(vt * v).
 *
 * Finding the best offset needs no division, and the comparison is exact. Candidate a scores
 * higher than b exactly when
 *   sign(num_a)*num_a^2 * v_b  >  sign(num_b)*num_b^2 * v_a,
 * compared as signs first and then as 96-bit unsigned products (num^2 < 2^56, v < 2^28); vt is
 * common to both sides and cancels. A window of zero variance (v = 0) has num = 0 and scores
 * exactly 0. Equal scores are ties, broken by the offset: the smallest |dx|+|dy| wins, then the
 * smallest dy, then the smallest dx (so a flat search area, or a periodic pattern, gives the
 * match nearest to no motion). The result is the unique maximum of this total order, whatever
 * order an implementation visits the candidates in.
 *
 * Reported score: Q15 in an int16 (32767 ~ 1.0), computed from the winner's num and v as follows
 * (bit for bit in every implementation):
 *   P = vt*v (64-bit); if num == 0 or P == 0 the score is 0. Otherwise let b = bit length of P,
 *   e = 2*floor((b - 31)/2) (an even shift, possibly negative), P' = P >> e (P << -e when e < 0),
 *   so 2^30 <= P' < 2^32; R = floor(sqrt(P')) (2^15 <= R < 2^16); a = |num| >> e/2 (|num| << -e/2);
 *   q = min(32767, floor(a*32768 / R)); score = sign(num)*q.
 * It is within 3 LSB of 32768 * the exact NCC (tests/ncc_test.cpp checks this against doubles).
 *
 * Borders: a point is matched only if the whole search area lies in the frame:
 *   x-r-s >= 0, x+r+s <= width-1, y-r-s >= 0, y+r+s <= height-1
 * (the template, x-r..x+r, then lies in frame 1 too). Otherwise its status is BVB_NCC_BORDER and
 * no pixel of either frame is read for it.
 *
 * Limits: 1 <= r <= BVB_NCC_MAX_RADIUS (5: the zero-mean template T' must fit 16 bits), 1 <= s <=
 * BVB_NCC_MAX_SEARCH. Other values give status BVB_NCC_BAD_PARAMS for every point (no reads).
 * Frames: 8-bit, width x height, the same row stride (>= width) for both, no alignment needed.
 * points: npoints (x, y) int16 pairs; results: npoints records of four int16
 *   { dx, dy, score (Q15), status },  both 2-byte aligned; npoints >= 0.
 * Points that are not BVB_NCC_OK report dx = dy = score = 0. A flat template (vt = 0) reports
 * BVB_NCC_FLAT (every score would be 0).
 * scratch: BVB_NCC_SCRATCH_SIZE(r, s) bytes, 4-byte aligned (working buffers of the assembly;
 * the C reference does not use it). For r = 5, s = 8 it is 15,304 bytes (banked, below): L1 data
 * bank A in the robot's firmware, frames in SDRAM. */
#ifndef BVB_NCC_H
#define BVB_NCC_H

#include <stdint.h>

#define BVB_NCC_MAX_RADIUS 5
#define BVB_NCC_MAX_SEARCH 16

#define BVB_NCC_OK 0
#define BVB_NCC_BORDER 1
#define BVB_NCC_FLAT 2
#define BVB_NCC_BAD_PARAMS 3

/* Scratch of the assembly, in bytes (L = 2s+2r+1 is the side of the search area, w = 2r+1,
 * N = w^2): a context block, two 16-bit copies of the search area (even and odd word alignment),
 * the zero-mean template flat and with padded rows, the 2r-row column sums of the filter's
 * sub-windows, the numerators; for r = 5 and 5 <= s <= 10 also a spare pair of copies (the next
 * point's search area, copied while this point's MACs run) and the copy program (12 bytes per
 * pair of candidates of the column pairs that run it, at most 4L + 2s + 1 of them). */
#define BVB_NCC_L(r, s) (2 * (s) + 2 * (r) + 1)
#define BVB_NCC_PIPELINED(r, s) ((r) == 5 && (s) >= 5 && (s) <= 10)
/* The banked layout (r = 5, 5 <= s <= 8, the robot's matcher): four 4 KB blocks, each holding
 * buffers that are never accessed in one cycle with another in the same block (the context and
 * the search area's copies; the spare copies; the template, numerators, copy program and column
 * sums; the squared column sums), so that with the scratch at the start of a bank (within 350
 * bytes after a 4 KB boundary) the kernel's dual accesses never meet in one L1 sub-bank. */
#define BVB_NCC_BANKED(r, s) ((r) == 5 && (s) >= 5 && (s) <= 8)
/* The banked layout ends (in the fourth block, after the squared column sums) with the memory
 * DMA area: a job, its state and two sets of (search area, template) bytes, one filled by DMA
 * while the other is read (used when both frames are in SDRAM and the area is where DMA
 * reaches, bvb/dma.h; otherwise the frames are read in place through the cache). */
#define BVB_NCC_DMA_BYTES 1888
#define BVB_NCC_SCRATCH_SIZE(r, s)                                                                 \
  (BVB_NCC_BANKED(r, s) ? 12288 + 8 * (BVB_NCC_L(r, s) + 1) * (((s) + 3) / 2) + 8 + BVB_NCC_DMA_BYTES : \
  336 + 4 * BVB_NCC_L(r, s) * (BVB_NCC_L(r, s) + 1) + 4                                           \
   + 4 * (((2 * (r) + 1) * (2 * (r) + 1) + 1) / 2) + 4 * (2 * (r) + 1) * ((r) + 1)                \
   + 12 * (BVB_NCC_L(r, s) + 1) * (((s) + 3) / 2) + 4 * (2 * (s) + 2) * (2 * (s) + 2)               \
   + (BVB_NCC_PIPELINED(r, s)                                                                      \
          ? 4 * BVB_NCC_L(r, s) * (BVB_NCC_L(r, s) + 1) + 4 + 12 * (4 * BVB_NCC_L(r, s) + 2 * (s) + 1) \
          : 0))

#ifdef __cplusplus
extern "C" {
#endif

/* The matcher: results for npoints points (see above). */
void bvb_ncc_match_c(const uint8_t *frame1, const uint8_t *frame2, int32_t stride, int32_t width,
                     int32_t height, const int16_t *points, int32_t npoints, int32_t radius,
                     int32_t search, int16_t *results, void *scratch);
void bvb_ncc_match_asm(const uint8_t *frame1, const uint8_t *frame2, int32_t stride, int32_t width,
                       int32_t height, const int16_t *points, int32_t npoints, int32_t radius,
                       int32_t search, int16_t *results, void *scratch);

/* The dense form, for inspection: the Q15 score (computed as above) of every offset for the one
 * point (x, y), map[(dy+s)*(2s+1) + (dx+s)], followed by one more int16, map[(2s+1)^2], holding
 * the point's status. A point that is not BVB_NCC_OK gets an all-zero map (a flat template too:
 * every score is 0). With r or s out of range only map[0] is written (BVB_NCC_BAD_PARAMS). map is
 * 2-byte aligned; scratch as for the matcher. */
void bvb_ncc_scoremap_c(const uint8_t *frame1, const uint8_t *frame2, int32_t stride,
                        int32_t width, int32_t height, int32_t x, int32_t y, int32_t radius,
                        int32_t search, int16_t *map, void *scratch);
void bvb_ncc_scoremap_asm(const uint8_t *frame1, const uint8_t *frame2, int32_t stride,
                          int32_t width, int32_t height, int32_t x, int32_t y, int32_t radius,
                          int32_t search, int16_t *map, void *scratch);

/* Helpers of the reference, exported for the host tests. */
/* Q15 score from num, vt, v as described above. */
int32_t bvb_ncc_score_q15(int32_t num, uint32_t vt, uint32_t v);
/* +1, 0, -1: the exact comparison of the scores num_a/sqrt(v_a) and num_b/sqrt(v_b). */
int32_t bvb_ncc_compare(int32_t num_a, uint32_t v_a, int32_t num_b, uint32_t v_b);

#ifdef __cplusplus
}
#endif

#endif
