/* Frame copy through L1 row bands by memory DMA (bvb/dma_copy.h): the DMA helper's test and
 * measure.
 *
 * Bound: the bus. Every byte crosses the SDRAM's 16-bit bus twice (in, then out), 2 bytes per
 * SCLK = 0.5 byte per core cycle at the SRV-1's CCLK:SCLK of 4 (bvb/dma.h): 4 cycles per pixel
 * with 16-bit elements (even addresses, strides and width), 8 with byte elements. The core only
 * starts jobs and waits. Measured (bfbench bench, --timing bf537, frames in SDRAM, scratch in
 * L1 bank A, bands of BVB_SOBEL3X3_BAND_ROWS rows: 16, 10, 4): 160x120 84,410 cycles (4.40 per
 * pixel), 320x240 329,488 (4.29), 640x480 1,336,406 (4.35), against 4.00. The rest, at 320x240
 * 22,300 cycles for 25 jobs, about 890 a job: the stream's start and descriptors (10 + 28 SCLK,
 * 152 cycles) and the core's work between one job's end and the next one's start (two
 * bvb_dma_prepare, bvb_dma_start, the poll that sees DMA_DONE: 17,827 cycles for the whole
 * call in the simulator's own count, where the transfers take almost no time), during which
 * the bus rests (this copy has nothing to overlap them with; the kernels do). */
#include "bvb/asm.h"
#include "bvb/dma.h"

#define K_SRC 0
#define K_SS 4
#define K_DST 8
#define K_DS 12
#define K_W 16
#define K_H 20
#define K_BAND 24
#define K_SCR 28
#define K_P 32			/* band rows' stride in L1: width rounded up to 4 */
#define K_X 36			/* a struct bvb_dma_xfer, 24 bytes */
#define KLOCALS 60
#define PUSHED (KLOCALS + 32)	/* R4-R7, P3-P5, RETS and the locals */
#define ARG_DST_STRIDE BVB_ARG(4, PUSHED)
#define ARG_WIDTH BVB_ARG(5, PUSHED)
#define ARG_HEIGHT BVB_ARG(6, PUSHED)
#define ARG_BAND BVB_ARG(7, PUSHED)
#define ARG_SCRATCH BVB_ARG(8, PUSHED)

BVB_FUNC bvb_dma_copy_u8_asm
	[--sp] = (r7:4, p5:3);
	[--sp] = rets;
	sp += -KLOCALS;
	[sp + K_SRC] = r0;
	[sp + K_SS] = r1;
	[sp + K_DST] = r2;
	r0 = [sp + ARG_DST_STRIDE];
	[sp + K_DS] = r0;
	r0 = [sp + ARG_WIDTH];
	[sp + K_W] = r0;
	r3 = r0;
	r0 = [sp + ARG_HEIGHT];
	[sp + K_H] = r0;
	r0 = [sp + ARG_BAND];
	[sp + K_BAND] = r0;
	r0 = [sp + ARG_SCRATCH];
	[sp + K_SCR] = r0;
	r3 += 3;
	r0 = -4;
	r3 = r3 & r0;
	[sp + K_P] = r3;

	/* DMA only when it reaches the frames and the band buffers; the core copies otherwise. */
	r0 = [sp + K_H];
	r0 += -1;
	r1 = [sp + K_SS];
	r0 *= r1;
	r1 = [sp + K_W];
	r1 = r0 + r1;
	r0 = [sp + K_SRC];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Lcore;
	r0 = [sp + K_H];
	r0 += -1;
	r1 = [sp + K_DS];
	r0 *= r1;
	r1 = [sp + K_W];
	r1 = r0 + r1;
	r0 = [sp + K_DST];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Lcore;
	r1 = [sp + K_BAND];
	r0 = [sp + K_P];
	r1 *= r0;
	r1 <<= 1;
	r0 = BVB_DMA_JOB_BYTES;
	r1 = r1 + r0;
	r0 = [sp + K_SCR];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Lcore;

	p5 = [sp + K_SCR];		/* the job */
	r5 = p5;
	r0 = BVB_DMA_JOB_BYTES;
	r5 = r5 + r0;			/* band buffer 0 */
	r0 = [sp + K_BAND];
	r1 = [sp + K_P];
	r0 *= r1;
	r6 = r5 + r0;			/* band buffer 1 */
	/* band 0 in */
	r0 = 0;
	r1 = 0;
	r2 = r5;
	call .Lcin;
	cc = r0 < 0;
	if cc jump .Lcore;
	r0 = p5;
	r1 = 1;
	call _bvb_dma_start;
	call _bvb_dma_wait;
	r4 = 0;				/* s: the first row of band j; r5 its buffer, r6 the other */
.Lband:
	r7 = 0;				/* transfers in this job */
	cc = r4 == 0;
	if cc jump .Lb_in;
	r0 = r7;
	r1 = [sp + K_BAND];
	r1 = r4 - r1;
	r2 = r6;
	call .Lcout;			/* band j-1 out, from the other buffer ... */
	cc = r0 < 0;
	if cc jump .Lfail;
	r7 += 1;
.Lb_in:
	r1 = [sp + K_BAND];
	r1 = r4 + r1;
	r0 = [sp + K_H];
	cc = r1 < r0;
	if !cc jump .Lb_go;
	r0 = r7;
	r2 = r6;
	call .Lcin;			/* ... then band j+1 into it */
	cc = r0 < 0;
	if cc jump .Lfail;
	r7 += 1;
.Lb_go:
	cc = r7 == 0;
	if cc jump .Lb_next;
	r0 = p5;
	r1 = r7;
	call _bvb_dma_start;
	call _bvb_dma_wait;
.Lb_next:
	r0 = r5;
	r5 = r6;
	r6 = r0;
	r0 = [sp + K_BAND];
	r4 = r4 + r0;
	r0 = [sp + K_H];
	cc = r4 < r0;
	if cc jump .Lband;
	/* the last band out */
	r0 = 0;
	r1 = [sp + K_BAND];
	r1 = r4 - r1;
	r2 = r6;
	call .Lcout;
	r0 = p5;
	r1 = 1;
	call _bvb_dma_start;
	call _bvb_dma_wait;
.Lfail:
.Ldone:
	sp += KLOCALS;
	rets = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;

	/* The core's copy, a byte at a time. */
.Lcore:
	p0 = [sp + K_SRC];
	p1 = [sp + K_DST];
	r4 = [sp + K_H];
	r5 = [sp + K_W];
	p2 = r5;
	r0 = [sp + K_SS];
	r6 = r0 - r5;
	r0 = [sp + K_DS];
	r7 = r0 - r5;
	p3 = r6;
	p4 = r7;
.Lc_row:
	lsetup (.Lc_b, .Lc_be) lc0 = p2;
.Lc_b:
	r0 = b[p0++] (z);
.Lc_be:
	b[p1++] = r0;
	p0 = p0 + p3;
	p1 = p1 + p4;
	r4 += -1;
	cc = r4 == 0;
	if !cc jump .Lc_row;
	jump .Ldone;

	/* r0 = slot, r1 = s, r2 = band buffer: the band's rows s .. s + n - 1 (n = min(band,
	 * h - s)) from src into the buffer. r0: bvb_dma_prepare's result. */
.Lcin:
	[--sp] = rets;
	[sp + K_X + 4 + DMAX_DST] = r2;
	r3 = [sp + 4 + K_P];
	[sp + K_X + 4 + DMAX_DS] = r3;
	r3 = [sp + 4 + K_SS];
	[sp + K_X + 4 + DMAX_SS] = r3;
	r2 = r1;
	r2 *= r3;
	r3 = [sp + 4 + K_SRC];
	r2 = r2 + r3;
	[sp + K_X + 4 + DMAX_SRC] = r2;
	jump .Lc_rows;
	/* The same out: the buffer to dst's rows s .. s + n - 1. */
.Lcout:
	[--sp] = rets;
	[sp + K_X + 4 + DMAX_SRC] = r2;
	r3 = [sp + 4 + K_P];
	[sp + K_X + 4 + DMAX_SS] = r3;
	r3 = [sp + 4 + K_DS];
	[sp + K_X + 4 + DMAX_DS] = r3;
	r2 = r1;
	r2 *= r3;
	r3 = [sp + 4 + K_DST];
	r2 = r2 + r3;
	[sp + K_X + 4 + DMAX_DST] = r2;
.Lc_rows:
	r3 = [sp + 4 + K_W];
	[sp + K_X + 4 + DMAX_W] = r3;
	r3 = [sp + 4 + K_H];
	r3 = r3 - r1;
	r2 = [sp + 4 + K_BAND];
	r3 = min (r3, r2);
	[sp + K_X + 4 + DMAX_ROWS] = r3;
	r1 = r0;
	r0 = p5;
	r2 = sp;
	r2 += K_X + 4;
	call _bvb_dma_prepare;
	rets = [sp++];
	rts;
BVB_ENDFUNC bvb_dma_copy_u8_asm
