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
 *   scratch               BVB_SOBEL3X3_SCRATCH_SIZE(width) bytes, 4-byte aligned, contents
 *                         ignored and clobbered; the C reference does not use it.
 * No other alignment is required of the frames or the strides. The assembly is fastest when the
 * frames are contiguous (every stride == width), width is a multiple of 4 (8 or more) and the
 * outputs are 4-byte aligned: it then runs over the frame as one stream. Other layouts go row
 * by row (see firmware/asm/sobel.S for what that costs).
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
 *   scratch holds two rows of box sums and horizontal pair sums (48 bytes per 4 pixels of width
 *   for u8, 32 for s16), one input row and the output row buffers: 2.3 KB at width 160, 9 KB at
 *   640; it belongs in L1. At 160x120 a frame (19 KB) fits L1 data memory; at 320x240 and
 *   640x480 frames live in SDRAM. The kernels read each input row once, in order, and write
 *   each output row once, so on the robot three input rows would circulate through an L1 ring
 *   filled by memory DMA (row y+2 arriving while row y+1 is processed), with output rows
 *   drained the same way; the simulator does not model SDRAM latency, so the kernels here
 *   read the frame in place. */
#ifndef BVB_SOBEL_H
#define BVB_SOBEL_H

#include <stdint.h>

/* Scratch bytes for a given width, for both kernels. */
#define BVB_SOBEL3X3_SCRATCH_SIZE(width) (56 * (((width) + 3) / 4) + 64)

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
