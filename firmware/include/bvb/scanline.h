/* Scan-line intensity profiles and the shift between two of them: the visual-odometry rotation
 * estimate (a camera that turns moves the whole profile sideways).
 *
 * 1. scanline_profile_u8: the intensity profile of a band of rows.
 *      profile[x] = round(S[x] / rows),  S[x] = sum over r = 0..rows-1 of src[r * stride + x]
 *    i.e. the mean of column x over the band, rounded half up, as an 8-bit value (the same
 *    scale as the pixels). Exactly: profile[x] = (S[x] + rows / 2) / rows with integer
 *    division. src points at the band's first row; 1 <= rows <= 256, width >= 1,
 *    stride >= width, no alignment required. The assembly divides by multiplying with
 *    R = ceil(2^24 / rows) and keeping bits 24 and up, which equals the division for every
 *    sum a band of at most 256 rows can produce (the host unit test checks all of them).
 *    scratch: BVB_SCANLINE_PROFILE_SCRATCH_BYTES(width) bytes, 4-byte aligned (the
 *    assembly's 16-bit column sums and its row-band stream; the C reference does not use it).
 *
 * 2. scanline_shift_u8: the shift between two profiles, by mean absolute difference.
 *    p1 and p2 are the compared windows, w bytes each (the caller picks the window inside a
 *    longer profile by pointer and length). For a shift t,
 *      O(t) = { i : 0 <= i < w and 0 <= i + t < w },  |O(t)| = w - |t|   (the overlap)
 *      S(t) = sum over i in O(t) of |p1[i] - p2[i + t]|
 *      f(t) = S(t) / (w - |t|)                                      (mean absolute difference)
 *    for every t with |t| <= T = w - rho, so that the overlap is never below rho pixels.
 *    So w is the length of the compared window (not a half-width): with windows of w pixels
 *    the overlap at shift t is w - |t|, and "minimum overlap rho" is exactly |t| <= w - rho.
 *    The seed's setting, w = 88 and rho = 40, compares 88-pixel windows over shifts -48..48.
 *    Worked example, w = 6, rho = 4 (T = 2), p1 = 10 20 30 40 50 60 and p2 = 10 10 20 30 40 50
 *    (p1 moved right by one pixel, the edge repeated):
 *      t = -2: p1[2..5] against p2[0..3], S = 20 + 30 + 30 + 30 = 110, |O| = 4, f = 27.5
 *      t = -1: p1[1..5] against p2[0..4], S = 10 + 20 + 20 + 20 + 20 = 90, |O| = 5, f = 18
 *      t =  0: p1[0..5] against p2[0..5], S = 0 + 10 + 10 + 10 + 10 + 10 = 50, |O| = 6
 *      t = +1: p1[0..4] against p2[1..5], S = 0, |O| = 5, f = 0     <- the shift found
 *      t = +2: p1[0..3] against p2[2..5], S = 10 + 10 + 10 + 10 = 40, |O| = 4, f = 10
 *    so result = {1, 0, 5} and curve = {110, 90, 50, 0, 40}. In general p2 = p1 moved right by
 *    d pixels (p2[x] = p1[x - d]) gives S(d) = 0 and the shift d: t > 0 when the scene moved
 *    right between the frames of p1 and p2, i.e. when the robot turned left.
 *    The shift found minimises f. f is compared exactly, never divided: f(a) < f(b) when
 *    S(a) * (w - |b|) < S(b) * (w - |a|), products below 2^28. Ties go to the smallest |t|,
 *    then to the negative t (the search visits 0, -1, +1, -2, +2, ... and keeps the first
 *    strict minimum).
 *    result[0] = the shift t, result[1] = S(t), result[2] = w - |t| (so f = result[1] /
 *    result[2]). curve: NULL, or 2T + 1 words: curve[t + T] = S(t) for t = -T..T, the whole
 *    f(t) curve as numerators over the known overlaps w - |t|.
 *    Limits: 1 <= rho <= w <= 1024 (the assembly's SAA lanes hold 16-bit sums: 256 terms of
 *    at most 255 each). No alignment required of p1, p2; result and curve are 4-byte aligned. */
#ifndef BVB_SCANLINE_H
#define BVB_SCANLINE_H

#include <stdint.h>

#include "bvb/stream.h"

/* A pad word, 8 * ceil(width / 8) column sums of 16 bits, and a word of read-ahead; then the
 * row-band stream (bvb/stream.h) the assembly brings the band's rows in by when they are in
 * SDRAM and the scratch in L1: 11.0 KB at width 320 (bands of 16 rows), 5.7 KB at 160. */
#define BVB_SCANLINE_PROFILE_SUMS_BYTES(width) (16 * (((width) + 7) / 8) + 8)
#define BVB_SCANLINE_PROFILE_SCRATCH_BYTES(width) \
  (BVB_SCANLINE_PROFILE_SUMS_BYTES(width) + BVB_STREAM_SCRATCH_BYTES((width), 0, 0))
#define BVB_SCANLINE_MAX_ROWS 256
#define BVB_SCANLINE_MAX_WINDOW 1024

#ifdef __cplusplus
extern "C" {
#endif

void bvb_scanline_profile_u8_c(const uint8_t *src, int32_t width, int32_t rows, int32_t stride,
                               uint8_t *profile, void *scratch);
void bvb_scanline_profile_u8_asm(const uint8_t *src, int32_t width, int32_t rows, int32_t stride,
                                 uint8_t *profile, void *scratch);

void bvb_scanline_shift_u8_c(const uint8_t *p1, const uint8_t *p2, int32_t w, int32_t rho,
                             int32_t *result, uint32_t *curve);
void bvb_scanline_shift_u8_asm(const uint8_t *p1, const uint8_t *p2, int32_t w, int32_t rho,
                               int32_t *result, uint32_t *curve);

#ifdef __cplusplus
}
#endif

#endif
