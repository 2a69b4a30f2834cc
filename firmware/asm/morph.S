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
 * issue, every load and store in a parallel slot). Measured (bfbench bench; erosion and dilation
 * take the same cycles):
 *   160x120: C 1,032,814, asm 66,132 (15.6x, 3.44 per pixel);
 *   320x240: C 4,120,779, asm 247,392 (16.7x, 3.22);
 *   640x480: C 16,460,934, asm 955,512 (17.2x, 3.11).
 * The difference from the bound is per row, about 70 cycles: set-up of the horizontal pass
 * (the circular buffer over the source row), the right-edge fix-up, the calls, and per pair of
 * rows the vertical pass's set-up and the rotation of the four H rows.
 *
 * Source rows are read only within the aligned words that hold their bytes: I0 runs as a
 * circular buffer over exactly those words, so the pass's read-ahead wraps instead of running
 * past the row. The rightmost pixel's horizontal result, whose right neighbour is outside the
 * row, is recomputed afterwards from the last two pixels (replicated edge); the leftmost one
 * starts from [x0, x0] as its left neighbours. The top output row takes H(0) as its row above,
 * the bottom one H(h-1) as its row below.
 *
 * Working set: scratch, 4 rows of 8 * ceil(w / 8) + 8 halfwords (5.2 KB at 640 wide): L1 on
 * hardware.
 *
 * Modelled (bfbench bench, --timing bf537, frames in SDRAM through the write-back data cache,
 * scratch in L1): 160x120 215,317 (11.2 cycles per pixel against the 3.0 bound), 320x240
 * 784,265 (10.2), 3.3x and 3.2x the simulator's own count: the difference is SDRAM line fills
 * of the source rows and write-backs of the output rows (2 bytes per pixel over the 16-bit bus
 * at SCLK = CCLK / 4, at least 4 cycles per pixel of bus time), not hidden by the loop. */

/* Arguments after the prologue's pushes (7 registers and RETS, 32 bytes). */
#define A_HEIGHT 44
#define A_SSTRIDE 48
#define A_DSTRIDE 52
#define A_SCRATCH 56

	.section .l1.text, "ax"

.macro MORPH3X3 name, op
	.align 4
	.global \name
	.type \name, STT_FUNC
\name:
	[--sp] = (r7:4, p5:3);
	[--sp] = rets;
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
	p5 = [sp + A_DSTRIDE];
	r7 = [sp + A_HEIGHT];
	[--sp] = r7;			/* rows, kept on the stack: every data register is busy */

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
	i3 += m2;
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
	i3 += m2;
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
	i3 += m2;
	i1 = b3;
	call .Lh_\@;			/* H(y + 1) */
	i3 += m2;
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
	i3 += m2;			/* two: the second one's row below is itself */
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
	sp += 4;
	rets = [sp++];
	(r7:4, p5:3) = [sp++];
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
	.size \name, . - \name
.endm

	MORPH3X3 _bvb_erode3x3_u8_asm, min
	MORPH3X3 _bvb_dilate3x3_u8_asm, max
