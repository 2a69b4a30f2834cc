/* Lucas-Kanade tracking (bvb/lk.h), bit-exact with firmware/c/lk.c.
 *
 * bvb_lk_track_asm is the C driver (bvb_lk_track_run, shared with the C reference) running the
 * two inner steps below, which do the per-pixel work: bvb_lk_patch_asm (once per feature and
 * level: the extended template, its gradients, the structure tensor) and bvb_lk_iterate_asm
 * (every iteration: the bilinear window of the next frame, the differences, b, the 2x2 solve,
 * the update and the tests). The driver's per-level work (bounds, the flat test and the inverse,
 * one division) stays C.
 *
 * Iteration, per window row pair of pixels (wx + 1 columns, the last one padding with zero
 * gradients so that pairs never straddle a row):
 *   horizontal: h(i), h(i+1) from J(i), J(i+1), J(i+2): one dual MAC on J(i+1) and one on
 *     PACK(J(i+2), J(i)) (the previous PACK's high half is J(i)), integer mode: 3 issues per
 *     pair, two byte loads in the slots; wy + 1 rows;
 *   vertical and difference, over the flattened window: one dual MAC per row, weights x64 in
 *     fractional mode with truncation, so the extracted half is floor(v / 512), the Q5 value;
 *     then one vector subtract from the template: 3 issues per pair;
 *   b: two dual MACs per pair into the 40-bit accumulators (dI x Ix in A0, dI x Iy in A1), then
 *     an arithmetic shift by 4.
 * Bench (bfbench bench): 32 Harris corners of the repository's integer texture and the same
 * texture moved by (2.3, -1.4) pixels, 3 levels, 7x7, 10 iterations per level fixed; work
 * count 32 x 49 x 10 x 3. An iteration of a 7x7 window takes 398 cycles (the horizontal pass
 * 8 rows x 18, vertical 84, b 56, the rest about 115); the template step about 980 a level;
 * the rest is the C driver (the flat test and the inverse with its division, the copies).
 * Lower bound: 3.5 issues per window pixel and iteration (4 bilinear products: 2 dual-MAC
 * issues, half a vector subtract, 2 products for b: 1 issue), not counting the per-level work.
 * Level copies. The windows' rows came through the data cache from SDRAM (a line fill per
 * 32 bytes the first time a window touches them: 157k stall cycles of 749,689 at 320x240).
 * Now the driver brings each level step's bytes (a feature at a level: the template's
 * wx + 3 by wy + 3 of prev, and next's around the template position with 4 pixels of margin)
 * into L1 in the scratch by memory DMA one step ahead, two small transfers a job
 * (bvb_lk_fetch_dma in firmware/c/lk.c), and runs the steps on the copies; an iteration whose
 * window leaves the copy (BVB_LK_REFETCH) has the rest of its level run on the level itself.
 * The copies go in the scratch's room on the template's side of its 4 KB split; frames in
 * L1, a scratch DMA cannot reach or one with no room (large windows) read in place, and so
 * does a step that finds the DMA stream busy with a caller's job (the odometry's state copy).
 * Modelled (--timing bf537, bfbench bench, frames and levels in SDRAM, the scratch in L1 bank B
 * across a 4 KB boundary, as bvb_lk_scratch_place puts it): 529,107 at 160x120 (11.2 per
 * window pixel and iteration against the bound's 3.5: 3.21x), 609,403 at 320x240 (13.0:
 * 3.70x), 613,725 at 640x480 (13.0: 3.73x); the simulator's own count 497,603 / 581,983 /
 * 587,073. Before the copies (the scratch in SDRAM, the division by libgcc, the iteration
 * with its branches and unpaired frame accesses): 607,794 / 749,689 / 811,391 (sim 483,731 /
 * 575,038 / 581,091); before the driver's bit lengths by SIGNBITS: 617,443 / 761,874 /
 * 823,847; before the scratch layout below and the bit lengths by halving: 710,633 /
 * 869,867 / 934,317.
 * Where the rest goes (bfbench profile lk_track, 320x240): the iteration step 383k (930
 * iterations of 398 cycles against their 390 issues: the passes at their rates above, 284,
 * and some 115 of per-iteration work: the window's position and bounds, the weights, the
 * passes' set-up, the solve and the update; the horizontal pass's rows cost 18 for their 12
 * pair issues), the template step 91k (9k of it the dual loads of two Te rows in one
 * sub-bank), the C driver 87k (its per-level bounds, the flat test and the inverse, the
 * copies' addresses; its code from SDRAM, 11k of instruction-cache fills) and the copies'
 * jobs on the core 44k (the slots re-addressed, the start, the waits). The iteration's dual
 * accesses pair h with the
 * template, h with the differences and the gradients with the differences: bvb_lk_track_run
 * puts the template and the differences on one side of a 4 KB sub-bank boundary of the
 * scratch and h and the gradients on the other whenever the scratch spans one
 * (firmware/c/lk.c), so they do not collide; a caller with room to spare lets
 * bvb_lk_scratch_place pick a start where it does (the odometry: 28k collision cycles a frame
 * at 160x120 before, where its fast buffer put the scratch too near a boundary for the layout
 * to split at it).
 * Working set: the window rows of two levels' images and under 4 KB of scratch (L1 on hardware). */
#include "bvb/asm.h"
#include "bvb/lk.h"

	.section .l1.text, "ax"
	.align 4

/* ---- bvb_lk_track_asm: the driver with the assembly steps ---- */

BVB_FUNC bvb_lk_track_asm
	/* bvb_lk_track_run takes the same 11 arguments and the step table: the caller's stack
	 * arguments 4..11 are copied below a new frame, the table appended. */
	link 48;
	p0 = fp;
	p1 = sp;
	r3 = [p0 + 20];          /* arguments 4 .. 11 of the caller, at its SP + 12 .. SP + 40 */
	[p1 + 12] = r3;
	r3 = [p0 + 24];
	[p1 + 16] = r3;
	r3 = [p0 + 28];
	[p1 + 20] = r3;
	r3 = [p0 + 32];
	[p1 + 24] = r3;
	r3 = [p0 + 36];
	[p1 + 28] = r3;
	r3 = [p0 + 40];
	[p1 + 32] = r3;
	r3 = [p0 + 44];
	[p1 + 36] = r3;
	r3 = [p0 + 48];
	[p1 + 40] = r3;
	p2.l = _bvb_lk_asm_ops;
	p2.h = _bvb_lk_asm_ops;
	[p1 + 44] = p2;
	call _bvb_lk_track_run;
	unlink;
	rts;
BVB_ENDFUNC bvb_lk_track_asm

/* ---- bvb_lk_pyramid_streamed_asm: the stream's driver (firmware/c/lk.c) with the level
 * routine below. The driver is compiled C, whose convention leaves a hardware loop counting
 * when it leaves one early; this entry clears both counters so that no caller's loop end
 * fires on a stale count. Once per call: in SDRAM. */
BVB_FUNC bvb_lk_pyramid_streamed_asm, .text
	link 32;
	p0 = fp;
	p1 = sp;
	r3 = [p0 + 20];          /* arguments 4 .. 7 of the caller, at its SP + 12 .. SP + 24 */
	[p1 + 12] = r3;
	r3 = [p0 + 24];
	[p1 + 16] = r3;
	r3 = [p0 + 28];
	[p1 + 20] = r3;
	r3 = [p0 + 32];
	[p1 + 24] = r3;
	p2.l = _bvb_lk_pyramid_asm;
	p2.h = _bvb_lk_pyramid_asm;
	[p1 + 28] = p2;
	call _bvb_lk_pyramid_stream_run;
	r0 = 0;
	lc0 = r0;
	lc1 = r0;
	unlink;
	rts;
BVB_ENDFUNC bvb_lk_pyramid_streamed_asm

	.section .rodata
	.align 4
_bvb_lk_asm_ops:
	.long _bvb_lk_patch_asm
	.long _bvb_lk_iterate_asm
	.long _bvb_lk_fetch_dma
	.long _bvb_lk_fetch_wait_dma

	.section .l1.text, "ax"
	.align 4

/* ---- bvb_lk_iterate_asm(img, tmpl, grad, work, block) ---- */

#define I_IMG   -4
#define I_TMPL  -8
#define I_GRAD  -12
#define I_H     -16    /* work: wy + 1 rows of h, wx + 1 int16 each */
#define I_D     -20    /* the differences: after the template (tmpl + 2 wy (wx + 1) + 4) */
#define I_STR   -24
                       /* -28, -32: free */
#define I_H1    -36    /* h's second row (h + 2 (wx + 1)) */
#define I_NPAIR -40    /* pairs in the window: wy (wx + 1) / 2 */
                       /* -44, -48: free */
#define I_MA    -52    /* Mxy << 16 | Mxx */
#define I_MB    -56    /* Myy << 16 | Mxy */
#define I_S     -60
#define I_LEFT  -64    /* iterations left */
#define I_EPS   -68
#define I_FIXED -72
#define I_QX    -76
#define I_QY    -80
#define I_CONV  -84
#define I_INNER -88    /* hx - 1: regular pairs of a row after the first */
#define I_ROWS  -92    /* wy + 1 */
#define I_IT    -96    /* iterations done */
#define I_XLO   -100   /* the window's integer x and y bounds: inside the image and the bytes */
#define I_XHI   -104   /* img holds (RX0 .. RX1, RY0 .. RY1) */
#define I_YLO   -108
#define I_YHI   -112
#define I_ORG   -116   /* img - hy stride - hx: the window's first pixel is ORG + iy stride + ix */
#define I_D4    -120   /* I_D - 4 */
#define I_HSKIP -124   /* stride - (wx + 1) */
#define I_SIZE  124
#define I_ARG_WORK  48
#define I_ARG_BLOCK 52
#define BLK(n) ((n) * 4)

BVB_FUNC bvb_lk_iterate_asm
	[--sp] = (r7:4, p5:3);
	link I_SIZE;
	[fp + I_IMG] = r0;
	[fp + I_TMPL] = r1;
	[fp + I_GRAD] = r2;
	p5 = [fp + I_ARG_BLOCK];
	r0 = [fp + I_ARG_WORK];
	[fp + I_H] = r0;
	r1 = [p5 + BLK(BVB_LK_IT_STRIDE)];
	[fp + I_STR] = r1;
	r6 = [p5 + BLK(BVB_LK_IT_HX)];
	r7 = [p5 + BLK(BVB_LK_IT_HY)];
	r2 = r6 << 2;
	r2 += 4;                 /* bytes per row of h: 4 hx + 4 */
	r0 = r0 + r2;
	[fp + I_H1] = r0;        /* h's second row */
	r0 = r2 >> 1;            /* wx + 1: the bytes a row of the window reads */
	r0 = r1 - r0;
	[fp + I_HSKIP] = r0;     /* from the end of a row's bytes to the next row's first */
	r3 = r7 << 1;
	r3 += 2;                 /* wy + 1 */
	[fp + I_ROWS] = r3;
	r3 = r7 << 1;
	r3 += 1;                 /* wy */
	r2 = r6;
	r2 += 1;
	r3 *= r2;
	[fp + I_NPAIR] = r3;
	/* the differences after the template (2 wy (wx + 1) bytes) and a word of gap, for the
	 * pipelined first store: the driver keeps them in the template's sub-bank, away from h
	 * and the gradients (bvb_lk_track_run's scratch layout) */
	r0 = [fp + I_TMPL];
	r2 = r3 << 2;
	r0 = r0 + r2;
	r0 += 4;
	[fp + I_D] = r0;
	r0 += -4;
	[fp + I_D4] = r0;        /* the differences' first store goes a word before them */
	r2 = r6;
	r2 += -1;
	[fp + I_INNER] = r2;
	/* the bounds the loop tests: those of the image (x <= width - 2 - hx, likewise y) and of
	 * the bytes img holds at once (a window outside them is sorted out at .Lbounds, off the
	 * loop's path) */
	r0 = [p5 + BLK(BVB_LK_IT_WIDTH)];
	r0 += -2;
	r0 = r0 - r6;
	r1 = [p5 + BLK(BVB_LK_IT_RX1)];
	r1 = r1 - r6;
	r1 += -1;
	r0 = min (r0, r1);
	[fp + I_XHI] = r0;
	r0 = [p5 + BLK(BVB_LK_IT_HEIGHT)];
	r0 += -2;
	r0 = r0 - r7;
	r1 = [p5 + BLK(BVB_LK_IT_RY1)];
	r1 = r1 - r7;
	r1 += -1;
	r0 = min (r0, r1);
	[fp + I_YHI] = r0;
	r1 = [p5 + BLK(BVB_LK_IT_RX0)];
	r1 = r1 + r6;
	r0 = max (r1, r6);
	[fp + I_XLO] = r0;
	r1 = [p5 + BLK(BVB_LK_IT_RY0)];
	r1 = r1 + r7;
	r0 = max (r1, r7);
	[fp + I_YLO] = r0;
	r0 = [fp + I_STR];
	r0 *= r7;
	r0 = r0 + r6;
	r1 = [fp + I_IMG];
	r1 = r1 - r0;
	[fp + I_ORG] = r1;
	r0 = [p5 + BLK(BVB_LK_IT_MXX)];
	r1 = [p5 + BLK(BVB_LK_IT_MXY)];
	r2 = [p5 + BLK(BVB_LK_IT_MYY)];
	r3 = pack (r1.l, r0.l);
	[fp + I_MA] = r3;
	r3 = pack (r2.l, r1.l);
	[fp + I_MB] = r3;
	r0 = [p5 + BLK(BVB_LK_IT_SHIFT)];
	[fp + I_S] = r0;
	r0 = [p5 + BLK(BVB_LK_IT_MAXITER)];
	[fp + I_LEFT] = r0;
	r0 = [p5 + BLK(BVB_LK_IT_EPS)];
	[fp + I_EPS] = r0;
	r0 = [p5 + BLK(BVB_LK_IT_FIXED)];
	cc = r0 == 0;
	r0 = cc;
	[fp + I_FIXED] = r0;     /* 1: stop at convergence */
	r0 = [p5 + BLK(BVB_LK_IT_QX)];
	[fp + I_QX] = r0;
	r0 = [p5 + BLK(BVB_LK_IT_QY)];
	[fp + I_QY] = r0;
	r0 = 0;
	[fp + I_IT] = r0;
	[fp + I_CONV] = r0;
	/* the loops' counts and the row step, for every iteration (nothing below changes them) */
	p1 = [fp + I_NPAIR];
	p2 = [fp + I_HSKIP];
	p3 = [fp + I_ROWS];
	p4 = [fp + I_INNER];

.Lit:
	/* the window: integer position and Q7 fractions, the bounds, the weights */
	r1 = 256 (x);
	r0 = [fp + I_QX];
	r0 = r0 + r1 (ns) || r4 = [fp + I_QY];
	r0 = r0 >>> 9 || r6 = [fp + I_XLO];      /* q7x */
	r4 = r4 + r1 (ns) || r7 = [fp + I_XHI];
	r2 = r0 >>> 7 || r1 = [fp + I_YLO];      /* ix */
	r4 = r4 >>> 9 || r3 = [fp + I_YHI];      /* q7y */
	r5 = r4 >>> 7;           /* iy */
	cc = r2 < r6;
	if cc jump .Lbounds;
	cc = r7 < r2;
	if cc jump .Lbounds;
	cc = r5 < r1;
	if cc jump .Lbounds;
	cc = r3 < r5;
	if cc jump .Lbounds;
	r3 = 127 (x);
	r0 = r0 & r3;            /* fx */
	r4 = r4 & r3;            /* fy */
	r1 = [fp + I_STR];
	r5 *= r1;
	r5 = r5 + r2 (ns) || r1 = [fp + I_ORG];
	r5 = r5 + r1;
	p0 = r5;                 /* the window's first pixel */
	r1 = 128 (x);
	r6 = r1 - r0;            /* 128 - fx */
	r6 = pack (r0.l, r6.l);  /* W = fx | 128 - fx */
	r7 = r1 - r4;
	r7 <<= 6;
	r4 = r4 << 6 || r0 = [fp + I_H];
	r7 = pack (r4.l, r7.l);  /* V = 64 fy | 64 (128 - fy) */

	/* horizontal: h rows 0 .. wy */
	i0 = r0;
	cc = p4 == 0;            /* no regular pairs (hx = 1): CC stays, nothing below sets it */
	lsetup (.Lh_row, .Lh_row_end) lc1 = p3;
.Lh_row:
	r4 = b[p0++] (z);
	r4 = r4 << 16 || r1 = b[p0++] (z);
	a1 = r1.l * r6.l, a0 = r1.l * r6.h (is) || r2 = b[p0++] (z);
	if cc jump .Lh_last;
	lsetup (.Lh_s, .Lh_e) lc0 = p4;
.Lh_s:	r4 = pack (r2.l, r4.h) || r1 = b[p0++] (z);
	r5.h = (a1 += r4.h * r6.h), r5.l = (a0 += r4.l * r6.l) (is);
.Lh_e:	a1 = r1.l * r6.l, a0 = r1.l * r6.h (is) || r2 = b[p0++] (z) || [i0++] = r5;
.Lh_last:
	r4 = pack (r2.l, r4.h) || r1 = b[p0++] (z);
	r5.h = (a1 += r4.h * r6.h), r5.l = (a0 += r4.l * r6.l) (is);
	a1 = r1.l * r6.l, a0 = r1.l * r6.h (is) || [i0++] = r5;
	r4 >>= 16;               /* the padding column: J(wx + 1) taken as 0 */
	r5.h = (a1 += r4.h * r6.h), r5.l = (a0 += r4.l * r6.l) (is);
	[i0++] = r5;
.Lh_row_end:
	p0 = p0 + p2;

	/* vertical and the differences, over the flattened window */
	r0 = [fp + I_H];
	i0 = r0;
	r0 = [fp + I_H1];
	i1 = r0;
	r0 = [fp + I_TMPL];
	i2 = r0;
	r0 = [fp + I_D4];
	i3 = r0;
	r0 = [i0++];
	r1 = [i1++];
	lsetup (.Lv_s, .Lv_e) lc0 = p1;
.Lv_s:	a1 = r0.h * r7.l, a0 = r0.l * r7.l || r0 = [i0++] || r2 = [i2++];
	r3.h = (a1 += r1.h * r7.h), r3.l = (a0 += r1.l * r7.h) (t) || r1 = [i1++] || [i3++] = r4;
.Lv_e:	r4 = r2 -|- r3;
	[i3++] = r4;

	/* b */
	r0 = [fp + I_D];
	i0 = r0;
	r0 = [fp + I_GRAD];
	i1 = r0;
	a1 = a0 = 0;
	r0 = [i0++];
	r1 = [i1++];
	r2 = [i1++];
	lsetup (.Lb_s, .Lb_e) lc0 = p1;
.Lb_s:	a1 += r0.l * r1.h, a0 += r0.l * r1.l (is) || r1 = [i1++];
.Lb_e:	a1 += r0.h * r2.h, a0 += r0.h * r2.l (is) || r2 = [i1++] || r0 = [i0++];
	a0 = a0 >>> 4;
	a1 = a1 >>> 4;
	r0 = a0;
	r1 = a1;
	[p5 + BLK(BVB_LK_IT_BX)] = r0;
	[p5 + BLK(BVB_LK_IT_BY)] = r1;

	/* the solve: b to 16 bits, P = M b, eta = P 2^-(S - t), clamped */
	r2.l = signbits r0;
	r3.l = signbits r1;
	r2 = r2.l (x);
	r3 = r3.l (x);
	r2 = min (r2, r3);
	r3 = 16;
	r2 = r3 - r2;
	r3 = 0;
	/* (the frame's loads ride beside the 32-bit ALU and MAC operations from here on, each
	 * into a register the operation beside it neither reads nor writes) */
	r2 = max (r2, r3) || r4 = [fp + I_MB];   /* t */
	r0 >>>= r2;
	r1 >>>= r2;
	r0 = pack (r1.l, r0.l) || r3 = [fp + I_MA];  /* ny | nx */
	a1 = r0.l * r3.h, a0 = r0.l * r3.l (is) || r5 = [fp + I_S];
	r1 = (a1 += r0.h * r4.h), r0 = (a0 += r0.h * r4.l) (is);
	/* by 2^-n, n = S - t in [-63, 26]: one saturating ASHIFT by -n, capped at 31 (a right
	 * shift, floor, when n >= 0; a left shift that saturates when n < 0, which the clamp
	 * below makes the C's clamped product), with no branch */
	r2 = r2 - r5;            /* -n */
	r4 = 31;
	r2 = min (r2, r4);
	r0 = ashift r0 by r2.l (s);
	r1 = ashift r1 by r2.l (s);
	r4.l = 0;
	r4.h = 0x40;             /* 2^22 */
	r5 = -r4;
	r0 = min (r0, r4) || r2 = [fp + I_QX];
	r0 = max (r0, r5) || r3 = [fp + I_QY];
	r1 = min (r1, r4);
	r1 = max (r1, r5);
	r2 = r2 + r0 (ns);
	r3 = r3 + r1 (ns) || [fp + I_QX] = r2;
	r0 = abs r0 || [fp + I_QY] = r3;
	r1 = abs r1 || r2 = [fp + I_EPS];
	r0 = max (r0, r1) || r3 = [fp + I_IT];
	cc = r0 <= r2;
	r0 = cc;
	[fp + I_CONV] = r0;
	r3 += 1;
	[fp + I_IT] = r3;
	r1 = [fp + I_FIXED];     /* 1 unless BVB_LK_FIXED_ITER */
	r1 = r1 & r0;
	cc = r1 == 0;
	if !cc jump .Lconverged;
	r0 = [fp + I_LEFT];
	r0 += -1;
	[fp + I_LEFT] = r0;
	cc = r0 == 0;
	if !cc jump .Lit (bp);
	/* out of iterations: converged if the last update was small */
	r0 = [fp + I_CONV];
	cc = r0 == 0;
	r0 = BVB_LK_TRACKED;
	r1 = BVB_LK_NOT_CONVERGED;
	if cc r0 = r1;
	jump .Lout;
.Lconverged:
	r0 = BVB_LK_TRACKED;
	jump .Lout;
.Lbounds:
	/* outside the image: left; inside it but outside the bytes img holds: the caller runs
	 * the rest on the level itself */
	r0 = BVB_LK_LEFT;
	r6 = [p5 + BLK(BVB_LK_IT_HX)];
	cc = r2 < r6;
	if cc jump .Lout;
	r7 = [p5 + BLK(BVB_LK_IT_WIDTH)];
	r7 += -2;
	r7 = r7 - r6;
	cc = r7 < r2;
	if cc jump .Lout;
	r6 = [p5 + BLK(BVB_LK_IT_HY)];
	cc = r5 < r6;
	if cc jump .Lout;
	r7 = [p5 + BLK(BVB_LK_IT_HEIGHT)];
	r7 += -2;
	r7 = r7 - r6;
	cc = r7 < r5;
	if cc jump .Lout;
	r0 = BVB_LK_REFETCH;
.Lout:
	r1 = [fp + I_QX];
	[p5 + BLK(BVB_LK_IT_QX)] = r1;
	r1 = [fp + I_QY];
	[p5 + BLK(BVB_LK_IT_QY)] = r1;
	r1 = [fp + I_IT];
	[p5 + BLK(BVB_LK_IT_ITERS)] = r1;
	unlink;
	(r7:4, p5:3) = [sp++];
	rts;
BVB_ENDFUNC bvb_lk_iterate_asm

/* ---- bvb_lk_patch_asm(img, tmpl, grad, work, block) ----
 * The extended template Te, (wx + 2) x (wy + 2) Q5 values, by the same horizontal and vertical
 * stages as the iteration (rows of er = wx + 3 values, the last one padding); then per window
 * pixel pair, from aligned pairs of Te only: Ix = Te(i+2) - Te(i) on the centre row (one vector
 * subtract), the template pair and Iy by PACK of misaligned halves, the words Ix | Iy << 16 by
 * two PACKs, and sum Ix^2 on the dual MAC; a last pass sums Ix Iy and Iy^2 over the words (one
 * dual MAC each). The padding column is cleared before it is stored or summed. */
#define P_H     -4     /* work: wy + 3 rows of h */
#define P_TE    -8     /* work, after them: wy + 2 rows of Te */
#define P_ERB   -12    /* bytes per row of h and Te: 4 hx + 8 */
#define P_HX    -16
#define P_HY    -20
#define P_TMPL  -24
#define P_GRAD  -28
#define P_SIZE  28
#define P_ARG_WORK  48
#define P_ARG_BLOCK 52

BVB_FUNC bvb_lk_patch_asm
	[--sp] = (r7:4, p5:3);
	link P_SIZE;
	[fp + P_TMPL] = r1;
	[fp + P_GRAD] = r2;
	p5 = [fp + P_ARG_BLOCK];
	r1 = [fp + P_ARG_WORK];
	[fp + P_H] = r1;
	r6 = [p5 + BLK(BVB_LK_PA_HX)];
	[fp + P_HX] = r6;
	r7 = [p5 + BLK(BVB_LK_PA_HY)];
	[fp + P_HY] = r7;
	r2 = r6 << 2;
	r2 += 8;
	[fp + P_ERB] = r2;       /* 4 hx + 8 */
	r3 = r7 << 1;
	r3 += 4;                 /* wy + 3 */
	r3 *= r2;
	r1 = r1 + r3;
	r1 += 4;                 /* a word of gap: the vertical stage's pipelined first store */
	[fp + P_TE] = r1;
	/* the first pixel: (ix - hx - 1, iy - hy - 1) */
	r1 = [p5 + BLK(BVB_LK_PA_IY)];
	r1 = r1 - r7;
	r1 += -1;
	r2 = [p5 + BLK(BVB_LK_PA_STRIDE)];
	r1 *= r2;
	r3 = [p5 + BLK(BVB_LK_PA_IX)];
	r3 = r3 - r6;
	r3 += -1;
	r1 = r1 + r3;
	r0 = r0 + r1;
	p0 = r0;
	r3 = r6 << 1;
	r3 += 4;                 /* wx + 3: the bytes a row reads */
	r2 = r2 - r3;
	p2 = r2;                 /* from the end of a row's bytes to the next row's first */
	r0 = [p5 + BLK(BVB_LK_PA_FX)];
	r1 = 128 (x);
	r2 = r1 - r0;
	r6 = pack (r0.l, r2.l);  /* W = fx | 128 - fx */
	r0 = [p5 + BLK(BVB_LK_PA_FY)];
	r2 = r1 - r0;
	r2 <<= 6;
	r0 <<= 6;
	r7 = pack (r0.l, r2.l);  /* V = 64 fy | 64 (128 - fy) */

	/* horizontal: wy + 3 rows of wx + 2 values (hx + 1 full pairs) and the padding */
	r0 = [fp + P_H];
	i0 = r0;
	r0 = [fp + P_HY];
	r0 <<= 1;
	r0 += 4;
	p3 = r0;
	p4 = [fp + P_HX];
	lsetup (.Lph_row, .Lph_row_end) lc1 = p3;
.Lph_row:
	r4 = b[p0++] (z);
	r4 = r4 << 16 || r1 = b[p0++] (z);
	a1 = r1.l * r6.l, a0 = r1.l * r6.h (is) || r2 = b[p0++] (z);
	lsetup (.Lph_s, .Lph_e) lc0 = p4;
.Lph_s:	r4 = pack (r2.l, r4.h) || r1 = b[p0++] (z);
	r5.h = (a1 += r4.h * r6.h), r5.l = (a0 += r4.l * r6.l) (is);
.Lph_e:	a1 = r1.l * r6.l, a0 = r1.l * r6.h (is) || r2 = b[p0++] (z) || [i0++] = r5;
	r4 = pack (r2.l, r4.h) || r1 = b[p0++] (z);
	r5.h = (a1 += r4.h * r6.h), r5.l = (a0 += r4.l * r6.l) (is);
	a1 = r1.l * r6.l, a0 = r1.l * r6.h (is) || [i0++] = r5;
	r4 >>= 16;
	r5.h = (a1 += r4.h * r6.h), r5.l = (a0 += r4.l * r6.l) (is);
	[i0++] = r5;
.Lph_row_end:
	p0 = p0 + p2;

	/* vertical: wy + 2 rows of Te, flattened */
	r0 = [fp + P_H];
	i0 = r0;
	r1 = [fp + P_ERB];
	r0 = r0 + r1;
	i1 = r0;
	r0 = [fp + P_TE];
	r0 += -4;
	i3 = r0;
	r0 = [fp + P_HY];
	r0 <<= 1;
	r0 += 3;                 /* wy + 2 */
	r0 *= r1;
	r0 >>= 2;                /* pairs */
	p3 = r0;
	r0 = [i0++];
	r1 = [i1++];
	lsetup (.Lpv_s, .Lpv_e) lc0 = p3;
.Lpv_s:	a1 = r0.h * r7.l, a0 = r0.l * r7.l || r0 = [i0++] || [i3++] = r3;
.Lpv_e:	r3.h = (a1 += r1.h * r7.h), r3.l = (a0 += r1.l * r7.h) (t) || r1 = [i1++];
	[i3++] = r3;

	/* the window: template, gradients, sum Ix^2 */
	p0 = [fp + P_TMPL];
	p1 = [fp + P_GRAD];
	r0 = [fp + P_TE];
	p2 = r0;                 /* Te row of the row above the current window row */
	r0 = [fp + P_HY];
	r0 <<= 1;
	r0 += 1;
	p3 = r0;                 /* wy rows */
	p4 = [fp + P_HX];        /* full pairs per row; then the one with the padding */
	p5 = [fp + P_ERB];
	a1 = a0 = 0;
	lsetup (.Lpw_row, .Lpw_row_end) lc1 = p3;
.Lpw_row:
	i1 = p2;                 /* up */
	p2 = p2 + p5;
	i0 = p2;                 /* centre */
	r0 = p2;
	r1 = p5;
	r0 = r0 + r1;
	i2 = r0;                 /* down */
	cc = p4 == 0;
	if cc jump .Lpw_last;
	lsetup (.Lpw_s, .Lpw_e) lc0 = p4;
.Lpw_s:	mnop || r0 = [i0++] || r2 = [i1++];      /* A = Te(i, i+1), U */
	mnop || r1 = [i0] || r3 = [i1];          /* A' = Te(i+2, i+3), U' */
	r6 = r1 -|- r0 || r4 = [i2++];           /* Ix pair; D */
	r0 = pack (r1.l, r0.h) || r5 = [i2];     /* template pair; D' */
	r4 = r4 -|- r2 || [p0++] = r0;           /* down - up of Te(i, i+1) */
	r5 = r5 -|- r3;                          /* of Te(i+2, i+3) */
	r4 = pack (r5.l, r4.h);                  /* Iy pair */
	r7 = pack (r4.l, r6.l);
	a1 += r6.h * r6.h, a0 += r6.l * r6.l (is) || [p1++] = r7;
	r7 = pack (r4.h, r6.h);
.Lpw_e:	[p1++] = r7;
.Lpw_last:
	mnop || r0 = [i0++] || r2 = [i1++];
	mnop || r1 = [i0] || r3 = [i1];
	r6 = r1 -|- r0 || r4 = [i2++];
	r0 = pack (r1.l, r0.h) || r5 = [i2];
	r4 = r4 -|- r2;
	r5 = r5 -|- r3;
	r4 = pack (r5.l, r4.h);
	r6 = r6.l (z);                           /* the padding column: zero */
	r0 = r0.l (z);
	r4 = r4.l (z);
	r7 = pack (r4.l, r6.l) || [p0++] = r0;
	a1 += r6.h * r6.h, a0 += r6.l * r6.l (is) || [p1++] = r7;
	r7 = 0;
.Lpw_row_end:
	[p1++] = r7;
	p5 = [fp + P_ARG_BLOCK];
	a0 += a1;
	a0 = a0 >>> 4;
	r0 = a0;
	[p5 + BLK(BVB_LK_PA_GXX)] = r0;

	/* sum Ix Iy and Iy^2 over the words (the padding words are 0) */
	r0 = [fp + P_GRAD];
	i0 = r0;
	r0 = [fp + P_HY];
	r0 <<= 1;
	r0 += 1;
	r1 = [fp + P_HX];
	r1 <<= 1;
	r1 += 2;
	r0 *= r1;
	p3 = r0;
	a1 = a0 = 0;
	r0 = [i0++];
	lsetup (.Lps, .Lps) lc0 = p3;
.Lps:	a1 += r0.h * r0.h, a0 += r0.l * r0.h (is) || r0 = [i0++];
	a0 = a0 >>> 4;
	a1 = a1 >>> 4;
	r0 = a0;
	r1 = a1;
	[p5 + BLK(BVB_LK_PA_GXY)] = r0;
	[p5 + BLK(BVB_LK_PA_GYY)] = r1;
	unlink;
	(r7:4, p5:3) = [sp++];
	rts;
BVB_ENDFUNC bvb_lk_patch_asm

/* ---- bvb_lk_pyramid_asm(src, width, height, stride, levels, pyr) ----
 * Four output pixels per three issues: BYTEOP2P averages the 2x2 blocks of two outputs with
 * rounding ((sum + 2) >> 2, the C's), twice on a sliding pair of words per row (normal and (R)
 * order), and BYTEPACK packs the four bytes for one aligned store. BYTEOP2P aligns both rows by
 * I0, so this path needs rows of the same alignment (a stride that is a multiple of 4: always
 * true above level 0, where rows are (w + 3) & ~3 bytes, and true of the bench's frames); other
 * strides, and the last few outputs of a row (so that no load leaves the row), take a byte loop
 * of about 7 cycles per output.
 * Cycles (bfbench bench, levels 1 and 2 of a frame with stride = width): 12,364 at 160x120,
 * 33,604 at 320x240, 103,084 at 640x480 (2.06, 1.40, 1.07 per output pixel: the row tails and
 * set-up weigh on small levels); the C reference takes 12.1-12.3 (6.0x, 8.7x, 11.2x).
 * Lower bound: 0.75 issues per output pixel (BYTEOP2P: 2 outputs per issue, BYTEPACK: 4).
 *
 * The registry's lk_pyramid is bvb_lk_pyramid_streamed_asm (above): this routine over bands in
 * L1, driven by bvb_lk_pyramid_stream_run (firmware/c/lk.c), which brings the frame's rows in
 * and sends levels 1 to 3 out by memory DMA, one band ahead. Then the bus is the bound: the
 * frame's 76,800 bytes in and the levels' 24,000 out at 0.5 byte per core cycle (bvb/dma.h),
 * 201,600 cycles at 320x240, 8.4 per level byte (3 levels). Modelled (bfbench bench, frame
 * and levels in SDRAM, scratch in L1 bank B): 59,026 at 160x120 (9.84 per level byte, 1.17x),
 * 214,149 at 320x240 (8.92, 1.06x), 836,791 at 640x480 (8.72, 1.04x); before (the frame and
 * the levels through the data cache): 120,753 / 507,715 / 1,930,121. Where the rest goes: the
 * core waits for the bus for 69% of the call (bfbench profile); the compute, 1.38x its issue
 * bound (the two rows' dual loads share a 4 KB sub-bank in the band buffer: 11k collision
 * cycles), is hidden under it. The time over the bus's: each band's job start and
 * descriptors (16 jobs of 2 to 4 transfers), the set-up before band 0's rows start, and the
 * last band's compute and its levels' transfer after the last rows are in. */
#define Y_IN    -4
#define Y_INSTR -8
#define Y_W     -12    /* input width */
#define Y_H     -16
#define Y_OUT   -20
#define Y_LEFT  -24    /* levels left */
#define Y_N4    -28    /* four-pixel groups per row on the fast path */
#define Y_ROWS  -32
#define Y_OSTR  -36
#define Y_SIZE  36
#define Y_ARG_STRIDE 48
#define Y_ARG_LEVELS 52
#define Y_ARG_PYR    56

/* Aligned to 2 only: it starts where bvb_lk_patch_asm ends, so the L1 code after it keeps its
 * addresses (and its cycles). */
BVB_FUNC bvb_lk_pyramid_asm, .l1.text, 2
	[--sp] = (r7:4, p5:3);
	link Y_SIZE;
	[fp + Y_IN] = r0;
	[fp + Y_W] = r1;
	[fp + Y_H] = r2;
	r0 = [fp + Y_ARG_STRIDE];
	[fp + Y_INSTR] = r0;
	r0 = [fp + Y_ARG_PYR];
	[fp + Y_OUT] = r0;
	r0 = [fp + Y_ARG_LEVELS];
	r0 += -1;
	[fp + Y_LEFT] = r0;
	cc = r0 <= 0;
	if cc jump .Ly_done;
.Ly_level:
	r1 = [fp + Y_W];
	r1 >>= 1;                /* w */
	r2 = [fp + Y_H];
	r2 >>= 1;                /* h */
	[fp + Y_ROWS] = r2;
	r3 = r1;
	r3 += 3;
	r4 = -4;
	r3 = r3 & r4;
	[fp + Y_OSTR] = r3;      /* s */
	/* fast path groups: (2w - 5) >> 3 when the input rows share their alignment, else none */
	r4 = r1 << 1;
	r4 += -5;
	r4 >>>= 3;
	r5 = 0;
	r4 = max (r4, r5);
	r6 = [fp + Y_INSTR];
	r7 = 3;
	r6 = r6 & r7;
	cc = r6 == 0;
	if !cc r4 = r5;
	[fp + Y_N4] = r4;
	cc = r2 == 0;
	if cc jump .Ly_next_level;
	p3 = [fp + Y_IN];        /* row a of the current output row */
	p4 = [fp + Y_OUT];       /* the output row */
.Ly_row:
	r0 = [fp + Y_INSTR];
	r1 = p3;
	i0 = r1;
	r1 = r1 + r0;
	i1 = r1;
	i2 = p4;
	p2 = [fp + Y_N4];
	r7 = p2;
	cc = r7 == 0;
	if cc jump .Ly_tail;
	disalgnexcpt || r0 = [i0++] || r2 = [i1++];
	disalgnexcpt || r1 = [i0++] || r3 = [i1++];
	r4 = byteop2p (r1:0, r3:2) (rndl) || r0 = [i0++] || r2 = [i1++];
	r5 = byteop2p (r1:0, r3:2) (rndl, r) || r1 = [i0++] || r3 = [i1++];
	r6 = bytepack (r4, r5);
	p2 += -1;
	cc = p2 == 0;
	if cc jump .Ly_vec_end;
	lsetup (.Ly_s, .Ly_e) lc0 = p2;
.Ly_s:	r4 = byteop2p (r1:0, r3:2) (rndl) || r0 = [i0++] || r2 = [i1++];
	r5 = byteop2p (r1:0, r3:2) (rndl, r) || r1 = [i0++] || r3 = [i1++];
.Ly_e:	r6 = bytepack (r4, r5) || [i2++] = r6;
.Ly_vec_end:
	[i2++] = r6;
.Ly_tail:
	/* outputs 4 n4 .. w - 1, one at a time */
	r7 <<= 2;                /* x0 = 4 n4 */
	r0 = [fp + Y_W];
	r0 >>= 1;
	r0 = r0 - r7;            /* outputs left */
	cc = r0 == 0;
	if cc jump .Ly_row_end;
	p2 = r0;
	r1 = p3;
	r2 = r7 << 1;
	r1 = r1 + r2;
	p0 = r1;                 /* row a at 2 x0 */
	r2 = [fp + Y_INSTR];
	r1 = r1 + r2;
	p1 = r1;                 /* row b */
	r1 = p4;
	r1 = r1 + r7;
	p5 = r1;                 /* the output */
	lsetup (.Ly_t_s, .Ly_t_e) lc0 = p2;
.Ly_t_s: r0 = b[p0++] (z);
	r1 = b[p0++] (z);
	r0 = r0 + r1 (ns) || r2 = b[p1++] (z);
	r0 = r0 + r2 (ns) || r3 = b[p1++] (z);
	r0 = r0 + r3 (ns);
	r0 += 2;
	r0 >>= 2;
.Ly_t_e: b[p5++] = r0;
.Ly_row_end:
	r0 = [fp + Y_INSTR];
	r0 <<= 1;
	r1 = p3;
	r1 = r1 + r0;
	p3 = r1;
	r0 = [fp + Y_OSTR];
	r1 = p4;
	r1 = r1 + r0;
	p4 = r1;
	r0 = [fp + Y_ROWS];
	r0 += -1;
	[fp + Y_ROWS] = r0;
	cc = r0 == 0;
	if !cc jump .Ly_row;
.Ly_next_level:
	/* this level becomes the next one's input */
	r0 = [fp + Y_OUT];
	[fp + Y_IN] = r0;
	r1 = [fp + Y_OSTR];
	[fp + Y_INSTR] = r1;
	r2 = [fp + Y_H];
	r2 >>= 1;
	[fp + Y_H] = r2;
	r1 *= r2;
	r0 = r0 + r1;
	[fp + Y_OUT] = r0;
	r0 = [fp + Y_W];
	r0 >>= 1;
	[fp + Y_W] = r0;
	r0 = [fp + Y_LEFT];
	r0 += -1;
	[fp + Y_LEFT] = r0;
	cc = r0 == 0;
	if !cc jump .Ly_level;
.Ly_done:
	unlink;
	(r7:4, p5:3) = [sp++];
	rts;
BVB_ENDFUNC bvb_lk_pyramid_asm
