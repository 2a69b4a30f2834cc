/* 3x3 erosion (min) and dilation (max), replicated borders (bvb/morph.h).
 *
 * Separable: a 3x1 pass over each source row once (H, 16-bit lanes, kept for four rows in the
 * caller's scratch), then a 1x3 pass over four H rows for each pair of output rows. Pixels
 * travel as 16-bit halfwords, two per register, because the Blackfin's vector MIN/MAX work on
 * halfword pairs.
 *
 * Horizontal pass, per four pixels x..x+3: one source word is loaded (through I0, whose low bits
 * carry the row's misalignment: BYTEUNPACK picks the four pixels out of the last two words
 * loaded, so rows need no alignment); BYTEUNPACK gives [x, x+1] [x+2, x+3]; ALIGN8 of the two
 * words and a second BYTEUNPACK give the window one pixel to the right, [x+1, x+2] [x+3, x+4];
 * the left neighbours [x-1, x] are the previous group's right window. Four vector MIN (MAX)
 * finish the group: 7 ops per 4 pixels, and the two H stores ride in parallel slots.
 * Vertical pass, per two pixels of two output rows y, y+1: the min of H rows y and y+1 is
 * shared, one more MIN with row y-1 and one with row y+2 give both outputs (four H words
 * loaded, two per issue), one shift per output row brings its second pixel's lane down, four
 * byte stores (so the destination needs no alignment either): 5 ops per 2 x 2 pixels.
 *
 * Lower bound: 3.0 cycles per pixel for this method (1.75 + 1.25 above: one ALU/video op per
 * issue, every load and store in a parallel slot). With the frames in SDRAM the bound is the
 * bus: memory DMA moves 2 bytes per SCLK (bvb/dma.h), 0.5 byte per core cycle at CCLK:SCLK = 4,
 * and each pixel is 1 byte in and 1 byte out: 4.0 cycles per pixel, above the compute's 3.0.
 *
 * Measured (bfbench bench, --timing bf537, frames in SDRAM, scratch in L1 bank B; erosion and
 * dilation take the same cycles; the simulator's own count, --timing none, after it), against
 * the bus's 4.00 per pixel (the bench's bound column: the larger of compute and bus), 1.15x
 * at 160x120 and 1.04x at 320x240:
 *   160x120:  88,286 (4.60 per pixel; C 1,481,123: 16.8x)   sim  77,373
 *   320x240: 319,260 (4.16; C 5,872,735: 18.4x)              sim 266,014
 *   640x480: 1,271,114 (4.14; bfbench budgets)
 *   Before the DMA path (frames read and written in place through the write-back data cache,
 *   scratch in SDRAM): 215,317 (11.21), 784,265 (10.21) and 3,099,699 (10.09; the budgets).
 * Where the 320x240 cycles go over the bus bound (307,200: 76,800 pixels x 4), 12,060 in
 * all; the parts are estimates from bvb/dma.h's costs, not measured one by one: the stream's
 * own overheads, per job 10 SCLK to start and 4 descriptors of 7 halfwords (28 jobs, some
 * 4,300 cycles); the gaps between jobs while the core sees DMA_DONE and
 * starts the next one (5 system MMR writes at 2 SCLK each, about 100 cycles a job); the start
 * (the plan and band 0, 2 rows, before the compute starts) and the end (the last band is
 * computed after its rows arrive, then its output rows, up to 7, go out alone: some 4,500).
 * The core is the shorter side there: 266,014 in the simulator's count, including its polls
 * of DMA_DONE; its L1 sub-bank collisions (3,256 in the run, --timing-report) are hidden.
 * At 160x120 (8-row bands: the scratch must leave seg_avoid's map room in L1 bank B) the
 * core is nearly as long as the stream: the per-row overheads below (about 70 cycles a row),
 * the per-band work (wait, re-address two slots, start: some 400 cycles, an estimate) and the
 * collisions add to its 3.0 per pixel.
 *
 * The in-place path (both frames in L1, or the scratch in SDRAM or the scratchpad), in the
 * simulator's count with everything in L1: 160x120 66,132 (3.44 per pixel), 320x240 247,392
 * (3.22), 640x480 955,512 (3.11). The difference from the bound is per row, about 70 cycles:
 * set-up of the horizontal pass (the circular buffer over the source row), the right-edge
 * fix-up, the calls, and per pair of rows the vertical pass's set-up and the rotation of the
 * four H rows.
 *
 * Source rows are read only within the aligned words that hold their bytes: I0 runs as a
 * circular buffer over exactly those words, so the pass's read-ahead wraps instead of running
 * past the row. The rightmost pixel's horizontal result, whose right neighbour is outside the
 * row, is recomputed afterwards from the last two pixels (replicated edge); the leftmost one
 * starts from [x0, x0] as its left neighbours. The top output row takes H(0) as its row above,
 * the bottom one H(h-1) as its row below.
 *
 * The DMA path (frames in SDRAM, scratch in L1 data SRAM; .Lmplan, .Lmstart, .Lmsw, .Lmfin
 * after the kernels). Source rows come into L1 in bands by memory DMA (bvb/dma.h) and output
 * rows leave the same way, on one stream, double-buffered: the source row pointer I3 and the
 * output row pointer P4 walk the band buffers (rows P = 4 ceil(w / 4) bytes apart) exactly as
 * they walk the frames in place, and the step to the next source row (.Lnx) at the end of a
 * band switches bands (.Lmsw): it prepares the other of two jobs with the output rows made
 * since the last switch and the band after next (into the input buffer just finished), waits
 * for the running job (the next band in), starts the prepared one and goes on in the other
 * buffers. Bands: 2, 2, 4, 8 rows, then BVB_MORPH3X3_BAND_ROWS (10 at width 320). Preparing
 * while the stream runs keeps the stream's gaps to the wait and the start.
 *
 * Working set: scratch, BVB_MORPH3X3_SCRATCH_BYTES (bvb/morph.h): four H rows of
 * 8 * ceil(w / 8) + 8 halfwords, and for the DMA path the band buffers and two jobs (7.5 KB
 * at width 160, 17.2 KB at 320): L1 bank B. */

#include "bvb/asm.h"
#include "bvb/dma.h"

/* The stack frame (LOC bytes below the 7 registers and RETS pushed). */
#define L_ROWS 0	/* rows */
#define L_CNT 4		/* rows of the current input band after I3's (huge off the DMA path) */
#define L_JOB 8		/* the job running or last run, or 0: no DMA path */
#define L_JOBB 12	/* the other job, prepared while that one runs */
#define L_IN0 16	/* input band buffers: the current band's, the next band's */
#define L_IN1 20
#define L_OUT0 24	/* output band buffers: being written, being sent */
#define L_OUT1 28
#define L_S1 32		/* the next input band: first row, rows (0: none) */
#define L_N1 36
#define L_OSENT 40	/* the first output row not yet sent */
#define L_X 44		/* a struct bvb_dma_xfer, 24 bytes */
#define L_P 68		/* band rows' stride in L1: the width rounded up to 4 */
#define L_B 72		/* rows per band at most */
#define L_HB 76		/* the DMA path's H rows: b2's, in a sub-bank of its own (.Lmplan) */
#define L_SRC 80
#define L_SS 84
#define L_DST 88
#define L_DS 92
#define L_W 96
#define LOC 100
/* Arguments after the prologue's pushes (7 registers and RETS, 32 bytes, then LOC). */
#define A_HEIGHT (44 + LOC)
#define A_SSTRIDE (48 + LOC)
#define A_DSTRIDE (52 + LOC)
#define A_SCRATCH (56 + LOC)
#define Q 4	/* the frame is 4 bytes further while a helper has RETS pushed */

	.section .l1.text, "ax"

.macro MORPH3X3 name, op
BVB_FUNC \name
	[--sp] = (r7:4, p5:3);
	[--sp] = rets;
	sp += -52;
	sp += -48;			/* LOC */
	[sp + L_SRC] = r0;
	[sp + L_DST] = r1;
	[sp + L_W] = r2;
	i3 = r0;			/* source row of the next horizontal pass */
	p4 = r1;			/* destination row */
	m1 = r2;			/* width */
	r3 = r2 >> 1;
	m0 = r3;			/* pixel pairs of the vertical pass */
	r3 = r2;
	r3 += 7;
	r3 >>= 3;
	p3 = r3;			/* horizontal pass: pairs of 4-pixel groups */
	r3 <<= 4;
	r3 += 16;			/* bytes per H row */
	/* Four H rows: (b1, b2, b3, m3) = rows (y - 1, y, y + 1, y + 2) of the output pair y, y + 1. */
	r0 = [sp + A_SCRATCH];
	b2 = r0;
	r0 = r0 + r3;
	b3 = r0;
	r0 = r0 + r3;
	m3 = r0;
	r0 = r0 + r3;
	b1 = r0;
	r0 = [sp + A_SSTRIDE];
	m2 = r0;
	[sp + L_SS] = r0;
	p5 = [sp + A_DSTRIDE];
	[sp + L_DS] = p5;
	r7 = [sp + A_HEIGHT];
	[sp + L_ROWS] = r7;		/* rows, kept on the stack: every data register is busy */
	r0 = [sp + A_SCRATCH];
	[sp + L_HB] = r0;
	call .Lmplan;			/* the DMA path, or L_JOB = 0 */
	r3 = p3;
	r3 <<= 4;
	r3 += 16;			/* bytes per H row, again */
	r0 = [sp + L_JOB];
	cc = r0 == 0;
	if cc jump .Lgo_\@;
	/* DMA path: the H rows where .Lmplan put them, every row in L1 P bytes from the next */
	r1 = [sp + A_SCRATCH];
	b1 = r1;
	r0 = [sp + L_HB];
	b2 = r0;
	r0 = r0 + r3;
	m3 = r0;
	r0 = r0 + r3;
	b3 = r0;
	r0 = [sp + L_P];
	m2 = r0;
	p5 = [sp + L_P];
	call .Lmstart;			/* I3, P4: band 0 in L1, the output buffer */
.Lgo_\@:
	i1 = b2;
	call .Lh_\@;			/* H(0) */
	r7 = [sp];
	cc = r7 == 1;
	if !cc jump .Lmore_\@ (bp);
	i0 = b2;			/* one row: H(0) three times */
	i1 = b2;
	i2 = b2;
	call .Lv_\@;
	jump .Ldone_\@;
.Lmore_\@:
	call .Lnx_\@;
	i1 = b3;
	call .Lh_\@;			/* H(1) */
	r7 = [sp];
	cc = r7 == 2;
	if !cc jump .Lmore3_\@ (bp);
	i0 = b2;			/* two rows: H(0), H(0), H(1), H(1) */
	i1 = b2;
	i2 = b3;
	p2 = b3;
	call .Lv2_\@;
	jump .Ldone_\@;
.Lmore3_\@:
	call .Lnx_\@;
	i1 = m3;
	call .Lh_\@;			/* H(2) */
	i0 = b2;			/* rows 0 and 1: H(0), H(0), H(1), H(2) */
	i1 = b2;
	i2 = b3;
	p2 = m3;
	call .Lv2_\@;
	p4 = p4 + p5;			/* next pair: rotate the H rows by two */
	p4 = p4 + p5;
	p0 = b1;
	b1 = b3;
	b3 = p0;
	p0 = b2;
	b2 = m3;
	m3 = p0;
	/* Then pairs y, y + 1 while y + 2 is a row: (h - 2 - 1) / 2 of them. */
	r7 = [sp];
	r7 += -3;
	r7 >>= 1;
	cc = r7 == 0;
	if cc jump .Lpairs_done_\@;
	p0 = r7;
	lsetup (.Lpair_\@, .Lpair_end_\@) lc1 = p0;
.Lpair_\@:
	call .Lnx_\@;
	i1 = b3;
	call .Lh_\@;			/* H(y + 1) */
	call .Lnx_\@;
	i1 = m3;
	call .Lh_\@;			/* H(y + 2) */
	i0 = b1;
	i1 = b2;
	i2 = b3;
	p2 = m3;
	call .Lv2_\@;
	p4 = p4 + p5;
	p4 = p4 + p5;
	p0 = b1;
	b1 = b3;
	b3 = p0;
	p0 = b2;
	b2 = m3;
.Lpair_end_\@:
	m3 = p0;
.Lpairs_done_\@:
	/* One or two rows left: h - 2 - 2 * pairs. */
	r7 = [sp];
	cc = bittst (r7, 0);
	if cc jump .Lone_left_\@;
	call .Lnx_\@;			/* two: the second one's row below is itself */
	i1 = b3;
	call .Lh_\@;			/* H(h - 1) */
	i0 = b1;
	i1 = b2;
	i2 = b3;
	p2 = b3;
	call .Lv2_\@;
	jump .Ldone_\@;
.Lone_left_\@:
	i0 = b1;			/* one: H(h - 2), H(h - 1), H(h - 1) */
	i1 = b2;
	i2 = b2;
	call .Lv_\@;
.Ldone_\@:
	call .Lmfin;			/* DMA path: the last output rows out */
	sp += 52;
	sp += 48;			/* LOC */
	rets = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;

	/* The next source row: I3 += M2, or on the DMA path at the end of a band, the next
	 * band (.Lmsw, which returns to our caller). */
.Lnx_\@:
	r0 = [sp + L_CNT];
	r0 += -1;
	cc = r0 < 0;
	if !cc jump .Lnx1_\@ (bp);
	jump.l .Lmsw;
.Lnx1_\@:
	[sp + L_CNT] = r0;
	i3 += m2;
	rts;

	/* Vertical pass for two output rows: H rows I0, I1, I2, P2 (y - 1 .. y + 2) into the
	 * destination rows P4 and P4 + P5. The two middle rows' min is shared. */
.Lv2_\@:
	b0 = i3;			/* the source row pointer, back at the end */
	i3 = p2;
	p1 = p4;
	p0 = p4 + p5;
	p2 = m0;
	r0 = [i0++] || r1 = [i1++];
	r2 = [i2++] || r3 = [i3++];
	r4 = \op (r1, r2) (v) || r1 = [i1++];
	cc = p2 == 0;
	if cc jump .Lv2odd_\@;
	lsetup (.Lw0_\@, .Lw4_\@) lc0 = p2;
.Lw0_\@:
	r5 = \op (r4, r0) (v) || r0 = [i0++] || r2 = [i2++];
	r6 = \op (r4, r3) (v) || b[p1++] = r5 || r3 = [i3++];
	r7 = r5 >> 16 || b[p0++] = r6;
	r5 = r6 >> 16 || b[p1++] = r7;
.Lw4_\@:
	r4 = \op (r1, r2) (v) || b[p0++] = r5 || r1 = [i1++];
.Lv2odd_\@:
	r7 = m1;
	cc = bittst (r7, 0);
	if !cc jump .Lv2end_\@ (bp);
	r5 = \op (r4, r0) (v);
	r6 = \op (r4, r3) (v);
	b[p1++] = r5;
	b[p0++] = r6;
.Lv2end_\@:
	i3 = b0;
	rts;

	/* Horizontal pass: source row I3 (width M1), into the H row at I1; P3 pairs of groups. */
.Lh_\@:
	p2 = i1;			/* H row start, for the edge fix-up */
	r0 = i3;
	r1 = m1;
	r2 = r0 + r1;
	r2 += -1;			/* last byte of the row */
	r3 = -4;
	r2 = r2 & r3;
	r3 = r0 & r3;			/* first word of the row */
	r2 = r2 - r3;
	r2 += 4;			/* bytes of the words holding the row */
	i0 = r0;
	b0 = r3;
	l0 = r2;
	disalgnexcpt || r0 = [i0++];
	disalgnexcpt || r1 = [i0++];
	r2 = align8 (r1, r0);
	(r5, r4) = byteunpack r1:0 || r0 = [i0++];
	r7 = pack (r4.l, r4.l);		/* left neighbours of pixel 0: itself */
	lsetup (.Lha_\@, .Lhz_\@) lc0 = p3;
	/* r1:0 source words, r3:2 the same shifted one byte; r4, r5 the group; r6, r7 its right
	 * window; r7 from the previous group holds the left neighbours. */
.Lha_\@:
	r4 = \op (r4, r7) (v);
	r3 = align8 (r0, r1);
	(r7, r6) = byteunpack r3:2;
	r4 = \op (r4, r6) (v);
	r5 = \op (r5, r7) (v) || [i1++] = r4;
	r5 = \op (r5, r6) (v);
	(r5, r4) = byteunpack r1:0 (r) || [i1++] = r5 || r1 = [i0++];
	r4 = \op (r4, r7) (v);
	r2 = align8 (r1, r0);
	(r7, r6) = byteunpack r3:2 (r);
	r4 = \op (r4, r6) (v);
	r5 = \op (r5, r7) (v) || [i1++] = r4;
	r5 = \op (r5, r6) (v);
.Lhz_\@:
	(r5, r4) = byteunpack r1:0 || [i1++] = r5 || r0 = [i0++];
	l0 = 0;
	/* Rightmost pixel: its right neighbour is itself (a one-pixel row: only itself). */
	r0 = i3;
	r1 = m1;
	r1 += -1;			/* w - 1 */
	r2 = r0 + r1;
	p0 = r2;
	r3 = 0;
	r2 = r1;
	r2 += -1;
	r2 = max (r2, r3);		/* max(w - 2, 0) */
	r2 = r0 + r2;
	p1 = r2;
	r4 = b[p0] (z);
	r5 = b[p1] (z);
	r1 = r1 << 1;
	p0 = r1;
	r4 = \op (r4, r5);
	p2 = p2 + p0;
	w[p2] = r4;
	rts;

	/* Vertical pass: H rows I0, I1, I2 (above, at, below) into the destination row P4. */
.Lv_\@:
	p1 = p4;
	p0 = m0;
	r0 = [i0++] || r1 = [i1++];
	r2 = [i2++];
	r4 = \op (r0, r1) (v) || r0 = [i0++];
	cc = p0 == 0;
	if cc jump .Lvodd_\@;
	lsetup (.Lva_\@, .Lvz_\@) lc0 = p0;
.Lva_\@:
	r4 = \op (r4, r2) (v) || r2 = [i2++];
	r5 = r4 >> 16 || b[p1++] = r4 || r1 = [i1++];
.Lvz_\@:
	r4 = \op (r0, r1) (v) || b[p1++] = r5 || r0 = [i0++];
.Lvodd_\@:
	r0 = m1;
	cc = bittst (r0, 0);
	if !cc jump .Lvend_\@ (bp);
	r4 = \op (r4, r2) (v);
	b[p1++] = r4;
.Lvend_\@:
	rts;
BVB_ENDFUNC \name
.endm

	MORPH3X3 bvb_erode3x3_u8_asm, min
	MORPH3X3 bvb_dilate3x3_u8_asm, max

	/* The DMA path (frames in SDRAM, scratch in L1 data SRAM): helpers shared by both
	 * kernels, called with the kernel's frame at [sp] (at [sp + Q] once RETS is pushed).
	 *
	 * .Lmplan: L_JOB = a job when src or dst is in SDRAM, the scratch in L1 data SRAM and DMA
	 * reaches all three (else 0: the frames are read and written in place). The scratch,
	 * BVB_MORPH3X3_SCRATCH_BYTES: H row b1; two output band buffers of B + 3 rows (between
	 * two band switches up to N + 1 output rows are made, after the last one up to N + 3);
	 * two input band buffers of B rows (band rows P bytes apart); H rows b2, m3, b3; the two
	 * jobs. The vertical pass loads b1 and b3 in one issue (the two swap roles, as do b2 and
	 * m3) and stores output bytes beside b2 or m3 loads; the horizontal pass loads source
	 * words beside H stores. With the band buffers between b1 and the others, b1 and b3 never
	 * share a sub-bank once the buffers span 4 KB, nor do the output buffers and b2, m3 (when
	 * the input buffers span 4 KB). No padding to sub-bank boundaries (which would cost up to
	 * 4 KB): the collisions left (3,256 at 320x240, --timing-report) cost the core cycles that
	 * the stream's time hides. Clobbers R0-R7, P0-P2. */
.Lmplan:
	[--sp] = rets;
	r0 = 0;
	[sp + Q + L_JOB] = r0;
	r0.l = 0xffff;
	r0.h = 0x7fff;
	[sp + Q + L_CNT] = r0;		/* off the DMA path .Lnx never switches */
	r2.l = 0;
	r2.h = 0x0200;			/* the end of SDRAM */
	r0 = [sp + Q + L_SRC];
	r1 = [sp + Q + L_DST];
	cc = r0 < r2 (iu);
	if cc jump .Lmp_f;
	cc = r1 < r2 (iu);
	if !cc jump .Lmp_x;		/* both frames in L1: in place */
.Lmp_f:
	r7 = [sp + Q + L_W];
	r6 = r7;
	r6 += 3;
	r6 >>= 2;
	r6 <<= 2;			/* P */
	[sp + Q + L_P] = r6;
	r5 = 8;				/* B: BVB_MORPH3X3_BAND_ROWS */
	r0 = 160 (x);
	r1 = 10;
	cc = r0 < r6;
	if cc r5 = r1;
	r0 = 320 (x);
	r1 = 4;
	cc = r0 < r6;
	if cc r5 = r1;
	r0 = 640 (x);
	r1 = 2;
	cc = r0 < r6;
	if cc r5 = r1;
	[sp + Q + L_B] = r5;
	r4 = r7;
	r4 += 7;
	r4 >>= 3;
	r4 <<= 4;
	r4 += 16;			/* HR: bytes per H row */
	r0 = r5 << 2;
	r0 += 6;
	r0 *= r6;			/* (4 B + 6) P */
	r1 = r4 << 2;
	r0 = r0 + r1;
	r1 = 240 (x);
	r1 = r0 + r1;			/* BVB_MORPH3X3_SCRATCH_BYTES */
	r0 = [sp + Q + L_HB];		/* the scratch */
	r2.l = 0;
	r2.h = 0xff80;
	cc = r0 < r2 (iu);
	if cc jump .Lmp_x;		/* scratch in SDRAM: nothing to gain */
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Lmp_x;
	r0 = [sp + Q + L_ROWS];
	r0 += -1;
	r1 = [sp + Q + L_SS];
	r0 *= r1;
	r1 = r0 + r7;
	r0 = [sp + Q + L_SRC];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Lmp_x;
	r0 = [sp + Q + L_ROWS];
	r0 += -1;
	r1 = [sp + Q + L_DS];
	r0 *= r1;
	r1 = r0 + r7;
	r0 = [sp + Q + L_DST];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Lmp_x;
	r0 = [sp + Q + L_HB];		/* b1 at the scratch's start */
	r0 = r0 + r4;
	[sp + Q + L_OUT0] = r0;
	r1 = r5;
	r1 *= r6;			/* B P */
	r2 = r6 + r6;
	r2 = r2 + r6;
	r2 = r2 + r1;			/* (B + 3) P */
	r0 = r0 + r2;
	[sp + Q + L_OUT1] = r0;
	r0 = r0 + r2;
	[sp + Q + L_IN0] = r0;
	r0 = r0 + r1;
	[sp + Q + L_IN1] = r0;
	r0 = r0 + r1;
	[sp + Q + L_HB] = r0;		/* b2, then m3, b3 */
	r1 = r4 << 1;
	r1 = r1 + r4;
	r0 = r0 + r1;			/* above b3: the jobs */
	[sp + Q + L_JOB] = r0;
	p0 = r0;
	r0 += 60;
	r0 += 60;
	[sp + Q + L_JOBB] = r0;
	p1 = r0;
	r0 = -1;			/* what each slot was last prepared for: nothing */
	[p0 + 112] = r0;
	[p0 + 116] = r0;
	[p1 + 112] = r0;
	[p1 + 116] = r0;
.Lmp_x:
	rets = [sp++];
	rts;

	/* r0 = s: the rows of the input band from row s: up to B, from 2 doubling (2, 2, 4, 8,
	 * ...), so that the compute starts soon; 0 past the last row. Clobbers R1, R2. */
.Lmband:
	r1 = [sp + Q + Q + L_B];
	r1 = min (r0, r1);
	r2 = 2;
	r1 = max (r1, r2);
	r2 = [sp + Q + Q + L_ROWS];
	r2 = r2 - r0;			/* rows left */
	r0 = 0;
	r2 = max (r2, r0);
	r0 = min (r1, r2);
	rts;

	/* Slot r0 of job r1: r3 input rows from row r2 into band buffer L_IN0 (.Lmin; L_IN1
	 * with .Lmin1), or r3 output rows from L_OUT0 to dst's rows
	 * from L_OSENT (.Lmout). Called from a helper (the frame at [sp + Q + Q]); clobbers
	 * R0-R3, P0-P2. */
#define QQ (Q + Q)
.Lmin1:
	p0 = r2;
	r2 = [sp + QQ + L_IN1];
	[sp + QQ + L_X + DMAX_DST] = r2;
	r2 = p0;
	jump .Lmin_s;
.Lmin:
	p0 = r2;
	r2 = [sp + QQ + L_IN0];
	[sp + QQ + L_X + DMAX_DST] = r2;
	r2 = p0;
.Lmin_s:
	p0 = r1;
	p1 = r0;
	p2 = 1;				/* in */
	r0 = [sp + QQ + L_P];
	[sp + QQ + L_X + DMAX_DS] = r0;
	r0 = [sp + QQ + L_SS];
	[sp + QQ + L_X + DMAX_SS] = r0;
	r2 *= r0;
	r0 = [sp + QQ + L_SRC];
	r2 = r2 + r0;
	[sp + QQ + L_X + DMAX_SRC] = r2;
	jump .Lm_go;
.Lmout:
	p0 = r1;
	p1 = r0;
	p2 = 0;				/* out */
	r0 = [sp + QQ + L_OUT0];
	[sp + QQ + L_X + DMAX_SRC] = r0;
	r0 = [sp + QQ + L_P];
	[sp + QQ + L_X + DMAX_SS] = r0;
	r0 = [sp + QQ + L_DS];
	[sp + QQ + L_X + DMAX_DS] = r0;
	r2 = [sp + QQ + L_OSENT];
	r2 *= r0;
	r0 = [sp + QQ + L_DST];
	r2 = r2 + r0;
	[sp + QQ + L_X + DMAX_DST] = r2;
.Lm_go:
	[sp + QQ + L_X + DMAX_ROWS] = r3;
	r0 = [sp + QQ + L_W];
	[sp + QQ + L_X + DMAX_W] = r0;
	/* The slot's key, 2 rows + direction (kept after the job's descriptors): the same as
	 * last time, and only the addresses move (bvb_dma_move: some 200 cycles less). */
	r2 = p2;
	r3 <<= 1;
	r3 = r3 + r2;
	r0 = p0;
	r1 = p1;
	p2 = p0 + (p1 << 2);
	r2 = [p2 + 112];
	[p2 + 112] = r3;
	cc = r2 == r3;
	r2 = sp;
	r3 = QQ + L_X;
	r2 = r2 + r3;
	if cc jump .Lm_mv;
	jump.l _bvb_dma_prepare;	/* returns to our caller */
.Lm_mv:
	jump.l _bvb_dma_move;

	/* Band 0 (2 rows) in, waited for; band 1 on its way: I3 = band 0's first row, P4 =
	 * the output buffer. Clobbers R0-R7, P0-P2. */
.Lmstart:
	[--sp] = rets;
	r0 = 0;
	[sp + Q + L_OSENT] = r0;
	[--sp] = rets;			/* .Lmband and .Lmin read the frame at [sp + Q + Q] */
	call .Lmband;
	r7 = r0;
	r3 = r0;
	r2 = 0;
	r0 = 0;
	r1 = [sp + QQ + L_JOB];
	call .Lmin;
	r0 = [sp + QQ + L_JOB];
	r1 = 1;
	call _bvb_dma_start;
	call _bvb_dma_wait;
	r0 = r7;
	call .Lmband;
	[sp + QQ + L_S1] = r7;
	[sp + QQ + L_N1] = r0;
	r6 = r0;
	r7 += -1;
	[sp + QQ + L_CNT] = r7;
	cc = r6 == 0;
	if cc jump .Lms_x;
	r3 = r6;
	r2 = [sp + QQ + L_S1];
	r0 = 0;
	r1 = [sp + QQ + L_JOB];
	call .Lmin1;
	r0 = [sp + QQ + L_JOB];
	r1 = 1;
	call _bvb_dma_start;
.Lms_x:
	sp += 4;
	r0 = [sp + Q + L_IN0];
	i3 = r0;
	p4 = [sp + Q + L_OUT0];
	rets = [sp++];
	rts;

	/* .Lnx at the end of an input band: prepare the other job (the output rows made into
	 * L_OUT0 since the last switch, then the band after next into L_IN0, which the band just
	 * finished has left), wait for the running one (the next band in, the output rows before
	 * out), start the prepared one, and go on with the next band: I3 its first row, P4 the
	 * other output buffer. Clobbers R0-R7, P0-P2 (not P3, P5). */
.Lmsw:
	[--sp] = rets;
	[--sp] = rets;			/* the frame at [sp + QQ] */
	r0 = [sp + QQ + L_OUT0];
	r1 = p4;
	r2 = [sp + QQ + L_P];
	r3 = 0;
.Lmsw_n:
	cc = r0 < r1 (iu);
	if !cc jump .Lmsw_nx;
	r0 = r0 + r2;
	r3 += 1;
	jump .Lmsw_n;
.Lmsw_nx:
	r7 = 0;				/* slots */
	cc = r3 == 0;
	if cc jump .Lmsw_in;
	r5 = r3;
	r0 = 0;
	r1 = [sp + QQ + L_JOBB];
	call .Lmout;
	r0 = [sp + QQ + L_OSENT];
	r0 = r0 + r5;
	[sp + QQ + L_OSENT] = r0;
	r7 = 1;
.Lmsw_in:
	r0 = [sp + QQ + L_S1];
	r1 = [sp + QQ + L_N1];
	r6 = r0 + r1;			/* the band after next */
	r0 = r6;
	call .Lmband;
	r5 = r0;
	cc = r5 == 0;
	if cc jump .Lmsw_w;
	r3 = r5;
	r2 = r6;
	r0 = r7;
	r1 = [sp + QQ + L_JOBB];
	call .Lmin;
	r7 += 1;
.Lmsw_w:
	call _bvb_dma_wait;
	cc = r7 == 0;
	if cc jump .Lmsw_b;
	r0 = [sp + QQ + L_JOBB];
	r1 = r7;
	call _bvb_dma_start;
	r0 = [sp + QQ + L_JOB];
	r1 = [sp + QQ + L_JOBB];
	[sp + QQ + L_JOB] = r1;
	[sp + QQ + L_JOBB] = r0;
.Lmsw_b:
	r0 = [sp + QQ + L_IN0];
	r1 = [sp + QQ + L_IN1];
	[sp + QQ + L_IN0] = r1;
	[sp + QQ + L_IN1] = r0;
	i3 = r1;
	r0 = [sp + QQ + L_OUT0];
	r1 = [sp + QQ + L_OUT1];
	[sp + QQ + L_OUT0] = r1;
	[sp + QQ + L_OUT1] = r0;
	p4 = r1;
	r0 = [sp + QQ + L_N1];
	r0 += -1;
	[sp + QQ + L_CNT] = r0;
	[sp + QQ + L_S1] = r6;
	[sp + QQ + L_N1] = r5;
	sp += 4;
	rets = [sp++];
	rts;

	/* After the last row: wait for the running job, send the output rows not yet sent. */
.Lmfin:
	r0 = [sp + L_JOB];
	cc = r0 == 0;
	if cc jump .Lmf_x;
	[--sp] = rets;
	[--sp] = rets;
	call _bvb_dma_wait;
	r3 = [sp + QQ + L_ROWS];
	r0 = [sp + QQ + L_OSENT];
	r3 = r3 - r0;
	r0 = 0;
	r1 = [sp + QQ + L_JOBB];
	call .Lmout;
	r0 = [sp + QQ + L_JOBB];
	r1 = 1;
	call _bvb_dma_start;
	call _bvb_dma_wait;
	sp += 4;
	rets = [sp++];
.Lmf_x:
	rts;
#undef QQ
