/* Harris corners: the corner response of every pixel (bvb_harris_response) and the strongest
 * corners picked from it (bvb_harris_corners).
 *
 * RESPONSE, fixed point throughout (every bound below holds for all 8-bit inputs):
 *   Gradients, central differences (twice the derivative), for 1 <= x <= w-2, 1 <= y <= h-2:
 *     gx(x,y) = I(x+1,y) - I(x-1,y),  gy(x,y) = I(x,y+1) - I(x,y-1)          in [-255, 255]
 *   Column sums over three rows, scaled by 1/32 with floor (an arithmetic shift), 2 <= y <= h-3:
 *     cxx(x) = (gx(x,y-1)^2 + gx(x,y)^2 + gx(x,y+1)^2) >> 5                 in [0, 6096]
 *     cyy(x) = (same with gy) >> 5                                         in [0, 6096]
 *     cxy(x) = (gx*gy summed over the same three pixels) >> 5              in [-6097, 6096]
 *   Window sums over a 3x3 window (three columns), 2 <= x <= w-3, all int16:
 *     a = cxx(x-1) + cxx(x) + cxx(x+1)                                     in [0, 18288]
 *     b = cyy(...), c = cxy(...)                                           b likewise, c in [-18291, 18288]
 *   Response det - k * trace^2 with the trace halved so that it stays a 16-bit quantity:
 *     hh = (a + b) >> 1                                                    in [0, 18288]
 *     kh = (hh * BVB_HARRIS_K4_Q15) >> 15        (4k in Q15, k = 0.0400009) in [0, 2926]
 *     R  = a*b - c*c - kh*hh                                               in [-388071369, 334450944]
 *   so R ~ det(S) - k * trace(S)^2 for the structure tensor S = [a c; c b] (in units of
 *   (2 * derivative)^2 / 32); each product and each partial sum fits int32.
 * Output: R as int32 for 2 <= x <= w-3, 2 <= y <= h-3; 0 on the two-pixel border.
 * A corner gives R > 0 (both eigenvalues large), an edge R < 0, a flat area R ~ 0.
 *
 * src: width x height bytes, src_stride bytes between rows. dst: int32, dst_stride elements between
 * rows. width, height >= 5; src_stride >= width, dst_stride >= width; no alignment required of src,
 * dst 4-byte aligned. scratch: BVB_HARRIS_SCRATCH_BYTES(width) bytes, 4-byte aligned, any
 * contents (working rows; the assembly keeps them there, the C reference uses part of it).
 * Frames in SDRAM, scratch in L1 data SRAM (where the robot runs it): the assembly brings the
 * image rows into L1 and sends the response rows out by memory DMA (bvb/dma.h, one job per
 * output row on MDMA stream 0; firmware/asm/harris.S), or writes them itself when dst is in
 * L1 too, the same results; elsewhere it reads and writes the frames in place.
 * The assembly reads the frame by aligned words: bytes of the 4-byte words that hold the rows'
 * pixels, so up to 3 bytes either side of a row, never further. */
#ifndef BVB_HARRIS_H
#define BVB_HARRIS_H

#define BVB_HARRIS_K4_Q15 5243
/* The working rows (24 * (width + 16) bytes), then the assembly's DMA region: the job, a ring of
 * four image rows and two output rows (12 * width + 188 bytes at most). */
#define BVB_HARRIS_SCRATCH_BYTES(width) (36 * (width) + 640)

/* CORNERS from a response map, in two kernels:
 * bvb_harris_nms, the candidates (C and assembly; the scan reads every pixel, which in C costs
 * more than the assembly response itself):
 *   1 <= x <= w-2, 1 <= y <= h-2, R > threshold, and a local maximum over the 8 neighbours with
 *   ties broken in raster order: R strictly greater than the four neighbours that come before it
 *   in raster order ((x-1,y-1), (x,y-1), (x+1,y-1), (x-1,y)) and >= the four after it. Of a run
 *   of equal values only the first in raster order survives.
 *   cand: pairs of int32 (y << 16 | x, R) in raster order, at most
 *   BVB_HARRIS_NMS_CAPACITY(width, height) of them (maxima are never 8-adjacent); entries past
 *   the count are left alone. *count and the return value: the number of candidates.
 *   resp: width x height int32, stride elements between rows (for example bvb_harris_response's
 *   output), every value > INT32_MIN; threshold >= 0 (so the zero border never qualifies);
 *   3 <= width, height <= 32767. scratch: BVB_HARRIS_NMS_SCRATCH_BYTES(width) bytes, 4-byte
 *   aligned, any contents (the assembly keeps the lower row's candidates of a row pair there).
 * bvb_harris_select, the greedy choice (C only: its cost depends on the number of candidates,
 * a few hundred to a few thousand, not on the pixels; harness/checks/harris.cpp has the numbers):
 *   candidates in order of decreasing R, equal R in raster order (smaller key first); a candidate
 *   is taken when its squared Euclidean distance to every corner already taken is
 *   >= min_distance^2; stop after max_corners. cand (n pairs as bvb_harris_nms leaves them, and
 *   room for one more: BVB_HARRIS_NMS_CAPACITY + 1 pairs always do) is reordered in place (a
 *   heap, with a sentinel pair after it). corners: 3 int32 per corner (x, y, R) in the order
 *   taken. Candidates must have R >= 0 (bvb_harris_nms gives R > threshold >= 0).
 *   Returns the number taken. max_corners >= 0, 0 <= min_distance <= 46340. */
#define BVB_HARRIS_NMS_CAPACITY(width, height) ((((width) - 1) / 2) * (((height) - 1) / 2))
#define BVB_HARRIS_NMS_SCRATCH_BYTES(width) (8 * (((width) - 1) / 2) + 8)
/* bvb_harris_nms_stream_asm's scratch: the waiting list, two DMA jobs, two sections of two
 * pairs' candidates and ten L1 rows in two regions a 4 KB boundary apart
 * (firmware/asm/harris.S): 23.0 KB at 320 wide. */
#define BVB_HARRIS_NMS_STREAM_SCRATCH_BYTES(width) \
  (5 * BVB_HARRIS_NMS_SCRATCH_BYTES(width) + 40 * (width) + 4399)

#ifndef __ASSEMBLER__
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

void bvb_harris_response_c(const uint8_t *src, int32_t *dst, int32_t width, int32_t height,
                           int32_t src_stride, int32_t dst_stride, void *scratch);
void bvb_harris_response_asm(const uint8_t *src, int32_t *dst, int32_t width, int32_t height,
                             int32_t src_stride, int32_t dst_stride, void *scratch);

int32_t bvb_harris_nms_c(const int32_t *resp, int32_t width, int32_t height, int32_t stride,
                         int32_t threshold, int32_t *cand, int32_t *count, void *scratch);
int32_t bvb_harris_nms_asm(const int32_t *resp, int32_t width, int32_t height, int32_t stride,
                           int32_t threshold, int32_t *cand, int32_t *count, void *scratch);
/* The same with the map in SDRAM streamed through an L1 scratch of
 * BVB_HARRIS_NMS_STREAM_SCRATCH_BYTES(width) (elsewhere it is bvb_harris_nms_asm). */
int32_t bvb_harris_nms_stream_asm(const int32_t *resp, int32_t width, int32_t height, int32_t stride,
                                  int32_t threshold, int32_t *cand, int32_t *count, void *scratch);

int32_t bvb_harris_select_c(int32_t *cand, int32_t n, int32_t max_corners, int32_t min_distance,
                            int32_t *corners);

#ifdef __cplusplus
}
#endif
#endif /* __ASSEMBLER__ */

#endif
