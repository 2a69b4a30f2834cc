/* 3x3 erosion (min) and dilation (max), replicated borders (bvb/morph.h).
 *
 * Separable: a 3x1 pass over each source row once (H, 16-bit lanes, kept for three rows in the
 * caller's scratch), then a 1x3 pass over three H rows per output row. Pixels travel as 16-bit
 * halfwords, two per register, because the Blackfin's vector MIN/MAX work on halfword pairs.
 *
 * Horizontal pass, per four pixels x..x+3: one source word is loaded (through I0, whose low bits
 * carry the row's misalignment: BYTEUNPACK picks the four pixels out of the last two words
 * loaded, so rows need no alignment); BYTEUNPACK gives [x, x+1] [x+2, x+3]; ALIGN8 of the two
 * words and a second BYTEUNPACK give the window one pixel to the right, [x+1, x+2] [x+3, x+4];
 * the left neighbours [x-1, x] are the previous group's right window. Four vector MIN (MAX)
 * finish the group: 7 ops per 4 pixels, and the two H stores ride in parallel slots.
 * Vertical pass, per two pixels: two vector MIN of three H words (loaded two per issue), one
 * shift to bring the second pixel's lane down, two byte stores (so the destination needs no
 * alignment either): 3 ops per 2 pixels.
 *
 * Lower bound: 3.25 cycles per pixel for this method (1.75 + 1.5 above: one ALU/video op per
 * issue, every load and store in a parallel slot). Measured (bfbench bench; erosion and dilation
 * take the same cycles):
 *   160x120: C 1,032,814, asm 72,417 (14.3x, 3.77 per pixel);
 *   320x240: C 4,120,779, asm 269,577 (15.3x, 3.51);
 *   640x480: C 16,460,934, asm 1,038,297 (15.9x, 3.38).
 * The difference from the bound is per row, about 80 cycles: set-up of the two passes (the
 * circular buffer over the source row), the right-edge fix-up, two subroutine calls.
 *
 * Source rows are read only within the aligned words that hold their bytes: I0 runs as a
 * circular buffer over exactly those words, so the pass's read-ahead wraps instead of running
 * past the row. The rightmost pixel's horizontal result, whose right neighbour is outside the
 * row, is recomputed afterwards from the last two pixels (replicated edge); the leftmost one
 * starts from [x0, x0] as its left neighbours.
 *
 * Working set: scratch, 3 rows of 8 * ceil(w / 8) + 8 halfwords (3.9 KB at 640 wide): L1 on
 * hardware. */

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
	r0 = [sp + A_SCRATCH];
	b2 = r0;			/* H of row y (after the first row's rotation: row y - 1) */
	r0 = r0 + r3;
	b3 = r0;
	r0 = r0 + r3;
	b1 = r0;
	r0 = [sp + A_SSTRIDE];
	m2 = r0;
	p5 = [sp + A_DSTRIDE];
	r7 = [sp + A_HEIGHT];
	[--sp] = r7;			/* rows, kept on the stack: every data register is busy */

	/* Row 0: H(0) into b2; a one-row image is H(0) three times. */
	i1 = b2;
	call .Lh_\@;
	r7 = [sp];
	cc = r7 == 1;
	if !cc jump .Lmore_\@ (bp);
	i0 = b2;
	i1 = b2;
	i2 = b2;
	call .Lv_\@;
	jump .Ldone_\@;
.Lmore_\@:
	i3 += m2;
	i1 = b3;
	call .Lh_\@;			/* H(1) */
	i0 = b2;
	i1 = b2;
	i2 = b3;
	call .Lv_\@;			/* output row 0: H(0), H(0), H(1) */
	p4 = p4 + p5;
	/* (b1, b2, b3) = H of rows (y - 1, y, y + 1): rotate so that y = 1. */
	p0 = b1;
	b1 = b2;
	b2 = b3;
	b3 = p0;
	r7 = [sp];
	r7 += -2;
	cc = r7 <= 0;
	if cc jump .Llast_\@;
	p0 = r7;
	lsetup (.Lrow_\@, .Lrow_end_\@) lc1 = p0;
.Lrow_\@:
	i3 += m2;
	i1 = b3;
	call .Lh_\@;			/* H(y + 1) */
	i0 = b1;
	i1 = b2;
	i2 = b3;
	call .Lv_\@;
	p4 = p4 + p5;
	p0 = b1;
	b1 = b2;
	b2 = b3;
.Lrow_end_\@:
	b3 = p0;
.Llast_\@:
	i0 = b1;			/* the last row: H(h - 2), H(h - 1), H(h - 1) */
	i1 = b2;
	i2 = b2;
	call .Lv_\@;
.Ldone_\@:
	sp += 4;
	rets = [sp++];
	(r7:4, p5:3) = [sp++];
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
