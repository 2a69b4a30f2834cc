/* Saturating 8-bit add, dst = min(255, a + b) (bvb/add_sat.h).
 *
 * Cycles (bfbench bench, simulator): 5 per pixel, 8 per row, 12 per call; 160x120: 96,972. Lower bound: each pixel needs two byte loads and one byte store, and one issue carries
 * at most two loads or one load and one store: 1.5 cycles per pixel with byte accesses, 0.75 with
 * word accesses and packed byte arithmetic. This kernel exists to exercise the harness, so it
 * keeps the plain byte loop and uses only scratch registers (no saves). */
	.section .l1.text, "ax"
	.align 4
	.global _bvb_add_sat_u8_asm
	.type _bvb_add_sat_u8_asm, STT_FUNC
_bvb_add_sat_u8_asm:
	i0 = r0;
	i1 = r1;
	i2 = r2;
	r0 = [sp + 20];		/* src_stride */
	m0 = r0;
	r0 = [sp + 24];		/* dst_stride */
	m1 = r0;
	r0 = [sp + 16];		/* height */
	lc1 = r0;
	r2 = [sp + 12];		/* width */
	r3 = 255;
	lsetup (.Lrow, .Lrow_end) lc1;
.Lrow:
	p0 = i0;
	p1 = i1;
	p2 = i2;
	lc0 = r2;
	lsetup (.Lpix, .Lpix_end) lc0;
.Lpix:	r0 = b[p0++] (z);
	r1 = b[p1++] (z);
	r0 = r0 + r1;
	r0 = min (r0, r3);
.Lpix_end:
	b[p2++] = r0;
	i0 += m0;
	i1 += m0;
.Lrow_end:
	i2 += m1;
	rts;
	.size _bvb_add_sat_u8_asm, . - _bvb_add_sat_u8_asm
