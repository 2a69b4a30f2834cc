/* Horn-Schunck optical flow (bvb/hornschunck.h): header comment to be completed. */

/* ---------------------------------------------------------------------------------------------
 * bvb_hs_iterate_asm(coef, uv_in, in_stride, uv_out, out_stride, width, height)
 * --------------------------------------------------------------------------------------------- */

/* One interior pixel. Column sums cl = ra, c0 = rb (carried), cr = rc (computed here); on entry
 * R0 = G and R3.L = e of the previous pixel, A1:A0 its exact sums, I2 at M(x-1). */
.macro HS_PIX ra, rb, rc
	R3.H = (A1 -= R3.L * R0.H), R3.L = (A0 -= R3.L * R0.L) (IH) || R0 = [I0++] || R1 = [I1++];
	\rc = R0 +|+ R1 (S) || [P1++] = R3 || R0 = [I2 ++ M0];
	A1 = \ra\().H * R7.L, A0 = \ra\().L * R7.L || R1 = [I2 ++ M1];
	R2 = R0 +|+ R1 (S) || R1 = W[P0++] (X) || R0 = [I3++];
	A1 += \rc\().H * R7.L, A0 += \rc\().L * R7.L;
	A1 += R2.H * R7.H, A0 += R2.L * R7.H;
	R3.H = (A1 += \rb\().H * R7.H), R3.L = (A0 += \rb\().L * R7.H);
	R3.H = R3.H * R0.H, R3.L = R3.L * R0.L (S2RND);
	R3.L = R3.L + R3.H (S);
.endm

/* The rows of one call, for (width - 2) mod 3 == m: pixel 0 leaves c(0), c(1) in x0, x1, the
 * registers the first rotation step after it expects. */
.macro HS_ROWS m, x0, x1
	lsetup (.Lit_row\m, .Lit_row_end\m) lc1;
.Lit_row\m:
	i0 = b2;
	r0 = p3;
	r1 = b0;
	r0 = r0 + r1;
	r1 = b3;
	r0 = min (r0, r1);
	i1 = r0;
	i2 = p3;
	i3 = p4;
	p0 = p4 + fp;
	p1 = p5;
	/* Pixel 0: left neighbours are the pixel itself. */
	mnop || r0 = [i0++] || r1 = [i1++];
	\x0 = r0 +|+ r1 (s) || r0 = [i0++] || r1 = [i1++];
	\x1 = r0 +|+ r1 (s) || r0 = [i2 ++ m2];
	a1 = \x0\().h * r7.l, a0 = \x0\().l * r7.l || r1 = [i2 ++ m1];
	r2 = r0 +|+ r1 (s) || r1 = w[p0++] (x) || r0 = [i3++];
	a1 += \x1\().h * r7.l, a0 += \x1\().l * r7.l;
	a1 += r2.h * r7.h, a0 += r2.l * r7.h;
	r3.h = (a1 += \x0\().h * r7.h), r3.l = (a0 += \x0\().l * r7.h);
	r3.h = r3.h * r0.h, r3.l = r3.l * r0.l (s2rnd);
	r3.l = r3.l + r3.h (s);
	r3.l = r3.l + r1.l (s);
.if \m == 1
	HS_PIX r6, r4, r5
	r3.l = r3.l + r1.l (s);
.endif
.if \m == 2
	HS_PIX r5, r6, r4
	r3.l = r3.l + r1.l (s);
	HS_PIX r6, r4, r5
	r3.l = r3.l + r1.l (s);
.endif
	cc = p2 == 0;
	if cc jump .Lit_last\m;
	lsetup (.Lit_pix\m, .Lit_pix_end\m) lc0 = p2;
.Lit_pix\m:
	HS_PIX r4, r5, r6
	r3.l = r3.l + r1.l (s);
	HS_PIX r5, r6, r4
	r3.l = r3.l + r1.l (s);
	HS_PIX r6, r4, r5
.Lit_pix_end\m:
	r3.l = r3.l + r1.l (s);
.Lit_last\m:
	/* Pixel width-1: cl = R4, c0 = R5 and cr = c0. */
	r3.h = (a1 -= r3.l * r0.h), r3.l = (a0 -= r3.l * r0.l) (ih) || r0 = [i2 ++ m2];
	a1 = r4.h * r7.l, a0 = r4.l * r7.l || [p1++] = r3 || r1 = [i2];
	r2 = r0 +|+ r1 (s) || r1 = w[p0++] (x) || r0 = [i3++];
	a1 += r5.h * r7.l, a0 += r5.l * r7.l;
	a1 += r2.h * r7.h, a0 += r2.l * r7.h;
	r3.h = (a1 += r5.h * r7.h), r3.l = (a0 += r5.l * r7.h);
	r3.h = r3.h * r0.h, r3.l = r3.l * r0.l (s2rnd);
	r3.l = r3.l + r3.h (s);
	r3.l = r3.l + r1.l (s);
	r3.h = (a1 -= r3.l * r0.h), r3.l = (a0 -= r3.l * r0.l) (ih);
	[p1] = r3;
	/* Next row: top = this row, then advance the three row pointers. */
	b2 = p3;
	r0 = p3;
	r1 = b0;
	r0 = r0 + r1;
	p3 = r0;
	r0 = p4;
	r1 = m3;
	r0 = r0 + r1;
	p4 = r0;
	r0 = p5;
	r1 = b1;
	r0 = r0 + r1;
.Lit_row_end\m:
	p5 = r0;
.endm

	.section .l1.text, "ax"
	.align 4
	.global _bvb_hs_iterate_asm
	.type _bvb_hs_iterate_asm, STT_FUNC
_bvb_hs_iterate_asm:
	[--sp] = (r7:4, p5:3);
	[--sp] = fp;
	/* Arguments 4-7 sit 32 bytes further up after the saves. */
	p4 = r0;
	p3 = r1;
	b0 = r2;
	b2 = r1;
	p5 = [sp + 44];
	r0 = [sp + 48];
	b1 = r0;
	r6 = [sp + 52];
	r5 = [sp + 56];
	lc1 = r5;
	r0 = r5;
	r0 += -1;
	r0 *= r2;
	r0 = r0 + r1;
	b3 = r0;
	r0 = r6 << 2;
	fp = r0;
	r1 = r6 << 1;
	r0 = r0 + r1;
	r1 = 1;
	r1 = r1 & r6;
	r1 = r1 << 1;
	r0 = r0 + r1;
	m3 = r0;
	/* n = (width - 2) / 3 rotations of the loop, m = (width - 2) mod 3 pixels before it. */
	r0 = r6;
	r0 += -2;
	r1.l = 0xaaab;
	r1.h = 0;
	r2 = r0;
	r2 *= r1;
	r2 >>= 17;
	p2 = r2;
	r1 = r2 << 1;
	r1 = r1 + r2;
	r0 = r0 - r1;
	r1 = 8;
	m0 = r1;
	r1 = -4;
	m1 = r1;
	r1 = 4;
	m2 = r1;
	r7.l = 2731;
	r7.h = 5461;
	cc = r0 == 0;
	if cc jump .Lit_m0;
	cc = r0 == 1;
	if cc jump .Lit_m1;
	HS_ROWS 2, r5, r6
	jump .Lit_done;
.Lit_m1:
	HS_ROWS 1, r6, r4
	jump .Lit_done;
.Lit_m0:
	HS_ROWS 0, r4, r5
.Lit_done:
	fp = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;
	.size _bvb_hs_iterate_asm, . - _bvb_hs_iterate_asm
