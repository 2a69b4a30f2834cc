/* Sobel 3x3 edge filter on 8-bit grey frames.
 *
 *   Gx = [-1 0 1; -2 0 2; -1 0 1]      Gy = [-1 -2 -1; 0 0 0; 1 2 1]
 *
 * (rows top to bottom: y-1, y, y+1; columns x-1, x, x+1). At every interior pixel
 * (1 <= x <= width-2, 1 <= y <= height-2):
 *   gx, gy = the exact sums, int16 (each in [-1020, 1020]);
 *   mag    = min(255, |gx| + |gy|), uint8.
 * Every output is 0 on the outer ring of pixels (x = 0, x = width-1, y = 0, y = height-1).
 * All integer, no rounding: every implementation gives the same bits.
 *
 * Kernels
 *   sobel3x3_u8   the magnitude only (the kernel an edge detector runs every frame).
 *   sobel3x3_s16  gx and gy, and the magnitude too when mag is not NULL.
 *
 * Arguments
 *   src, src_stride       width x height bytes, src_stride bytes from row to row.
 *   dst / mag, *_stride   bytes from row to row; mag may be NULL (mag_stride is then unused).
 *   gx, gy, g_stride      int16 arrays (2-byte aligned) sharing g_stride, counted in elements.
 *   width, height         3 or more each. Strides >= width. Outputs overlap nothing.
 *   scratch               BVB_SOBEL3X3_SCRATCH_SIZE(width) bytes for u8,
 *                         BVB_SOBEL3X3_S16_SCRATCH_SIZE(width) for s16, 4-byte aligned, contents
 *                         ignored and clobbered; the C reference does not use it.
 * No other alignment is required of the frames or the strides. With frames in SDRAM and the
 * scratch in L1, the u8 assembly streams the frame through L1 by DMA at the same speed for
 * every layout (16-bit DMA elements when addresses, strides and width are even, bytes
 * otherwise). Reading frames in place, the assembly is fastest when they are contiguous
 * (every stride == width), width is a multiple of 4 (8 or more) and the outputs are 4-byte
 * aligned: it then runs over the frame as one stream. Other layouts go row by row (see
 * firmware/asm/sobel.S for what that costs).
 *
 * How the assembly computes it (bit-exact with the textbook form above)
 *   With the 2x2 box sum B(x, y) = p(x,y) + p(x+1,y) + p(x,y+1) + p(x+1,y+1):
 *     Gx + Gy = 2 (B(x,y) - B(x-1,y-1)),   Gx - Gy = 2 (B(x,y-1) - B(x-1,y))
 *   and |Gx| + |Gy| = max(|Gx + Gy|, |Gx - Gy|). So each output row needs one new row of box
 *   sums (one horizontal byte-pair add, BYTEOP16P, and one 16-bit add per two pixels, the
 *   horizontal pair sums of the row below being kept from the previous row), two 16-bit
 *   subtractions per two pixels, and then ABS, MAX, MIN and BYTEPACK.
 *
 * Working set and memory
 *   Frames live in SDRAM, where the camera's DMA puts them. scratch holds two rows of box sums
 *   and horizontal pair sums (48 bytes per 4 pixels of width for u8, 32 for s16), the band
 *   buffers and the DMA job(s): u8 (BVB_SOBEL3X3_SCRATCH_SIZE) 23.1 KB at widths 320 and 640,
 *   19.4 KB at 160; s16 (BVB_SOBEL3X3_S16_SCRATCH_SIZE) 20.2 KB at 160 and 640, 21.5 KB at
 *   320. It belongs in L1 data SRAM: bank B has room for either (bank A keeps 16 KB beside its
 *   data cache).
 *   sobel3x3_u8, when src or dst is in SDRAM and scratch in L1 data SRAM, never reads or writes
 *   a frame through the core: input rows come into L1 in bands by memory DMA (bvb/dma.h) and
 *   output rows leave the same way, double-buffered. While the core computes band j+1 from one
 *   input buffer into one output buffer, MDMA stream 0 sends band j's output rows to dst and
 *   then brings band j+2 into the input buffer band j has left. Bands are up to
 *   BVB_SOBEL3X3_BAND_ROWS(width) rows (8 at width 320, 16 at 160, 4 at 640): the first two
 *   hold 2 rows (rows 0 and 1 start the box sums) and they double up to that, so the compute
 *   starts after 2 rows have arrived; the last ones halve, so that little is left to send when
 *   the compute ends. In L1 the rows are the width rounded up to 4 apart, whatever the frame's
 *   strides, so every layout runs the same single stream of groups per band. The ring's two
 *   rows sit on either side of a 4 KB sub-bank boundary and the band buffers in other
 *   sub-banks, so the dual accesses of the inner loop never collide (firmware/asm/sobel.S).
 *   sobel3x3_s16, when src, gx, gy or mag is in SDRAM and scratch in L1 data SRAM, does the
 *   same with the same band schedule (bands of up to BVB_SOBEL3X3_S16_BAND_ROWS(width) rows:
 *   10 at width 160, 5 at 320, 2 at 640), its band buffers holding B rows each of gx, gy (2 P
 *   bytes apart) and mag (P): a band's job sends its gx, gy and mag rows (3 transfers, 2
 *   without mag) and brings the band after next in (the 4th). Its bus time, 1 byte in and 5
 *   out per pixel at 0.5 byte per core cycle, is 12 cycles per pixel against 4.5 of compute,
 *   so the job after next is prepared in a second job while one runs, and the stream idles
 *   only while the core starts it; the ring is not placed by sub-bank (the core waits anyway).
 *   Otherwise (every frame in L1, or scratch in SDRAM or the scratchpad, which DMA cannot
 *   reach), the kernels read each input row once, in order, and write each output row once,
 *   in place. */
#ifndef BVB_SOBEL_H
#define BVB_SOBEL_H

#include <stdint.h>

/* Rows per band of the u8 kernel's DMA path, from the band rows' stride in L1 (the width
 * rounded up to 4): as many as the scratch's 24 KB in L1 bank B allows for widths up to 640
 * (each band costs some 300 cycles of set-up on the core). */
#define BVB_SOBEL3X3_ROW_BYTES(width) (4 * (((width) + 3) / 4))
#define BVB_SOBEL3X3_BAND_ROWS(width)                   \
  (BVB_SOBEL3X3_ROW_BYTES(width) <= 160   ? 16          \
   : BVB_SOBEL3X3_ROW_BYTES(width) <= 320 ? 10          \
   : BVB_SOBEL3X3_ROW_BYTES(width) <= 640 ? 4 : 2)

/* Rows per band of the s16 kernel's DMA path: 10 at widths up to 160, 5 up to 320, else 2, so
 * that its scratch stays within L1 bank B's 24 KB up to width 640 (the bus, not the per-band
 * set-up, sets that path's pace: firmware/asm/sobel.S). */
#define BVB_SOBEL3X3_S16_BAND_ROWS(width)               \
  (BVB_SOBEL3X3_ROW_BYTES(width) <= 160   ? 10          \
   : BVB_SOBEL3X3_ROW_BYTES(width) <= 320 ? 5 : 2)

/* Scratch bytes for sobel3x3_s16: the ring (8 row strides P, the width rounded up to 4), the
 * band buffers (2 x B input rows, 2 x B rows each of gx and gy at 2 P and of mag at P), 8
 * bytes of over-read room and two DMA jobs; the direct paths use the first 56 bytes per 4
 * pixels of it (the ring, one input line, the row buffers). 20.2 KB at widths 160 and 640,
 * 21.5 KB at 320. */
#define BVB_SOBEL3X3_S16_SCRATCH_SIZE(width)                                        \
  ((8 + 12 * BVB_SOBEL3X3_S16_BAND_ROWS(width)) * BVB_SOBEL3X3_ROW_BYTES(width) + 232)

/* Scratch bytes for sobel3x3_u8: the ring of box sums (48 bytes per 4
 * pixels), up to 8 KB to put the boundary between its rows on a 4 KB sub-bank boundary and the
 * band buffers past its second sub-bank, the band buffers (2 x B input rows, 2 x (B + 1)
 * output rows) and the DMA job. 23.1 KB at widths 320 and 640, 19.4 KB at 160. */
#define BVB_SOBEL3X3_SCRATCH_SIZE(width)                                         \
  (6 * BVB_SOBEL3X3_ROW_BYTES(width) + 8192 +                                    \
   (4 * BVB_SOBEL3X3_BAND_ROWS(width) + 2) * BVB_SOBEL3X3_ROW_BYTES(width) + 120)

#ifdef __cplusplus
extern "C" {
#endif

void bvb_sobel3x3_u8_c(const uint8_t *src, int32_t src_stride, uint8_t *dst, int32_t dst_stride,
                       int32_t width, int32_t height, void *scratch);
void bvb_sobel3x3_u8_asm(const uint8_t *src, int32_t src_stride, uint8_t *dst, int32_t dst_stride,
                         int32_t width, int32_t height, void *scratch);

void bvb_sobel3x3_s16_c(const uint8_t *src, int32_t src_stride, int16_t *gx, int16_t *gy,
                        int32_t g_stride, uint8_t *mag, int32_t mag_stride, int32_t width,
                        int32_t height, void *scratch);
void bvb_sobel3x3_s16_asm(const uint8_t *src, int32_t src_stride, int16_t *gx, int16_t *gy,
                          int32_t g_stride, uint8_t *mag, int32_t mag_stride, int32_t width,
                          int32_t height, void *scratch);

#ifdef __cplusplus
}
#endif

#endif
