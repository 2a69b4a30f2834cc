/* UYVY 4:2:2 to grey: the Y bytes of each row (bvb/yuv.h).
 *
 * Cycles (bfbench bench, simulator, contiguous rows):
 *   160x120: C 59,678, asm 14,501 (4.1x); 320x240: C 234,518, asm 57,701 (4.1x);
 *   640x480: C 929,798, asm 230,501 (4.0x).
 * Lower bound: 0.75 cycles per pixel. Four output pixels take two source words and one
 * destination word (three memory accesses, which fit in two issues), but the Y bytes sit at
 * odd byte positions and no Blackfin op gathers them from two words at once: one op per source
 * word moves its two Y bytes into byte lanes 0 and 2 (BYTEOP3P, which also absorbs any source
 * misalignment through I1), and BYTEPACK joins two such words: three ops per four pixels.
 * The loop runs at exactly that, 3 cycles per 4 pixels; the rest is per call (about 100
 * cycles) and per row (about 43: the destination-aligning head and the tail, pointer and
 * circular-buffer set-up, the pipeline's fill and drain).
 *
 * Rows are independent, so an image whose rows are contiguous in both buffers
 * (src_stride == 2 * width and dst_stride == width) is converted as one long row and pays the
 * per-row cost once. With padded strides every row pays it: 160x120 then takes 19,610 cycles
 * (1.02 per pixel, 3.0x the C), 640x480 251,090 (0.82, 3.7x).
 *
 * Alignment: none required. Each row's first 0..3 pixels are copied one by one until the
 * destination is word aligned; then source words are read through I1 with the source's own
 * misalignment (the video ops select bytes by I1's low bits, and their parallel loads ignore
 * it), and whole destination words are written. I1 runs as a circular buffer over exactly the
 * source words that hold the row's bytes, so the loop's read-ahead wraps instead of reading
 * past the row. Buffers may live in SDRAM or L1; the kernel needs no working memory.
 *
 * The DMA path (frames in SDRAM, scratch in L1: bvb/stream.h). Row bands come into L1 by
 * memory DMA and the grey rows leave the same way, double-buffered, through the shared stream
 * routines; each band, contiguous in L1, is converted as one long row. Other placements (and
 * what DMA refuses: the scratchpad) take the direct path above.
 * Bound: the bus, not the core. 2 bytes in and 1 out per pixel at 0.5 byte per core cycle
 * (bvb/dma.h: 2 bytes per SCLK, CCLK:SCLK = 4) is 6 cycles per pixel, against the loop's 0.75.
 * Modelled (bfbench bench, --timing bf537, frames in SDRAM, scratch in L1 bank B):
 *   160x120 119,969 (6.25 per pixel), 320x240 474,689 (6.18), 640x480 1,893,779 (6.17); the
 *   simulator's own count 23,194 / 84,634. Over the bus's 6.00: the stream's per-job cost
 *   (10 SCLK to start, 7 per descriptor, 2 per transfer), the gap between a job's end and the
 *   next start (the wait's poll and 5 MMR writes at SCLK), and band 0 set up before the stream
 *   starts. Before the DMA path (frames read and written through the data cache): 288,570
 *   (15.0) / 1,041,129 (13.6). */
#include "bvb/asm.h"
#include "bvb/stream.h"

#define PUSHED 44			/* R4-R7, P3-P5, RETS, 12 bytes of outgoing argument space */
#define ARG_HEIGHT BVB_ARG(4, PUSHED)
#define ARG_SRC_STRIDE BVB_ARG(5, PUSHED)
#define ARG_DST_STRIDE BVB_ARG(6, PUSHED)
#define ARG_SCRATCH BVB_ARG(7, PUSHED)

BVB_FUNC bvb_uyvy_to_grey_asm
	[--sp] = (r7:4, p5:3);
	[--sp] = rets;
	sp += -12;			/* the C routines' outgoing argument space */
	/* The stream's planes in the scratch: what the direct path reads back if it is refused. */
	p0 = [sp + ARG_SCRATCH];
	[p0 + ST_SRC0] = r0;
	[p0 + ST_DST] = r1;
	r3 = r2 << 1;
	[p0 + ST_SB0] = r3;
	[p0 + ST_DB] = r2;
	r3 = 0;
	[p0 + ST_SB1] = r3;
	r3 = [sp + ARG_SRC_STRIDE];
	[p0 + ST_SS0] = r3;
	r3 = [sp + ARG_DST_STRIDE];
	[p0 + ST_DS] = r3;
	r3 = [sp + ARG_HEIGHT];
	[p0 + ST_ROWS] = r3;
	r0 = p0;
	call _bvb_stream_open;
	cc = r0 == 0;
	if !cc jump .Ldirect;
	/* Bands: each one long row of n * width pixels, contiguous in L1 on both sides. */
.Lband:
	r0 = [sp + ARG_SCRATCH];
	call _bvb_stream_next;
	cc = r0 == 0;
	if cc jump .Lret;
	p0 = [sp + ARG_SCRATCH];
	r4 = [p0 + ST_DB];
	r4 *= r0;			/* pixels */
	r1 = [p0 + ST_IN0];
	r2 = [p0 + ST_OUT];
	i3 = r1;
	i2 = r2;
	r3 = 1;
	call .Lconv;
	jump .Lband;

.Ldirect:
	p0 = [sp + ARG_SCRATCH];
	r0 = [p0 + ST_SRC0];
	r1 = [p0 + ST_DST];
	r2 = [p0 + ST_DB];
	i3 = r0;			/* source row */
	i2 = r1;			/* destination row */
	r4 = r2;			/* width */
	r0 = [sp + ARG_SRC_STRIDE];
	r1 = [sp + ARG_DST_STRIDE];
	r3 = [sp + ARG_HEIGHT];
	m3 = r0;
	m2 = r1;
	/* Contiguous rows: one long row. */
	r5 = r4 << 1;
	cc = r0 == r5;
	r5 = r1 - r4;
	r6 = cc;
	cc = r5 == 0;
	r5 = cc;
	r5 = r5 & r6;
	cc = r5 == 0;
	if cc jump .Ldrows (bp);
	r4 *= r3;
	r3 = 1;
.Ldrows:
	call .Lconv;
.Lret:
	sp += 12;
	rets = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;

	/* r3 rows of r4 pixels from I3 (rows M3 apart) to I2 (M2 apart). Clobbers R0-R7, P0-P5,
	 * I1-I3, B1, L1 (left 0), LC0, LC1. */
.Lconv:
	p5 = r3;
	r0 = 0;				/* r1:0 is the zero pair of BYTEOP3P */
	r1 = 0;
	lsetup (.Lrow, .Lrow_end) lc1 = p5;
.Lrow:
	p0 = i3;
	p1 = i2;
	/* Head: pixels copied one by one until the destination is word aligned (out of line). */
	r7 = p1;
	r7 = -r7;
	r6 = 3;
	r7 = r7 & r6;
	r7 = min (r7, r4);
	r6 = r4 - r7;			/* pixels left after the head */
	cc = r7 == 0;
	if !cc jump .Lhead;
.Lhead_done:
	r7 = 3;
	r7 = r6 & r7;
	p4 = r7;			/* tail pixels */
	r5 = r6 >> 2;			/* groups of four pixels */
	cc = r5 == 0;
	if cc jump .Ltail;
	/* Circular buffer over the source words holding the groups' bytes [s, s + 8 * groups). */
	r2 = p0;
	r7 = 3;
	r3 = r2 & r7;			/* a: the source's misalignment */
	r7 = r2 - r3;
	i1 = r2;
	b1 = r7;
	r3 += 3;
	r7 = r5 << 3;
	p3 = r7;			/* source bytes of the groups */
	r3 = r3 + r7;
	r7 = -4;
	r3 = r3 & r7;			/* bytes of the words covering the groups */
	l1 = r3;
	p2 = r5;
	disalgnexcpt || r2 = [i1++];
	disalgnexcpt || r3 = [i1++];
	/* r5: Y0 _ Y1 _ of the first half of a group; r6: of the second half. */
	r5 = byteop3p (r1:0, r3:2) (lo) || r2 = [i1++];
	p2 += -1;
	cc = p2 == 0;
	if cc jump .Llast;
	lsetup (.Lv0, .Lv1) lc0 = p2;
.Lv0:	r6 = byteop3p (r1:0, r3:2) (lo, r) || r3 = [i1++];
	r5 = bytepack (r5, r6);
.Lv1:	r5 = byteop3p (r1:0, r3:2) (lo) || [p1++] = r5 || r2 = [i1++];
.Llast:
	r6 = byteop3p (r1:0, r3:2) (lo, r);
	r5 = bytepack (r5, r6);
	[p1++] = r5;
	p0 = p0 + p3;
	l1 = 0;
.Ltail:
	cc = p4 == 0;
	if !cc jump .Ltail_px;
.Lrow_next:
	i3 += m3;
.Lrow_end:
	i2 += m2;
	rts;

	/* Out of line, so that rows needing none fall straight through. */
.Lhead:
	p2 = r7;
	lsetup (.Lh0, .Lh1) lc0 = p2;
.Lh0:	r5 = b[p0 + 1] (z);
	p0 += 2;
.Lh1:	b[p1++] = r5;
	jump .Lhead_done;
.Ltail_px:
	lsetup (.Lt0, .Lt1) lc0 = p4;
.Lt0:	r5 = b[p0 + 1] (z);
	p0 += 2;
.Lt1:	b[p1++] = r5;
	jump .Lrow_next;
BVB_ENDFUNC bvb_uyvy_to_grey_asm
