/* Absolute difference of two 8-bit frames, dst = |a - b| (absdiff.h).
 *
 * The plain byte loop: two byte loads, a subtract, an absolute value and a byte store per pixel,
 * in two hardware loops (rows, pixels). Only scratch registers, so nothing is saved.
 * Lower bound, frames in SDRAM as the bench places them: the bus, 2 bytes in and 1 out per
 * pixel at 0.5 byte per core cycle (bvb/dma.h), 6 cycles per pixel.
 * Modelled (bfbench-absdiff bench, --timing bf537, frames in SDRAM): 160x120 333,739 (17.4 per
 * pixel), 320x240 1,277,003 (16.6), 640x480 5,049,963 (16.4). bfbench-absdiff profile: 5 issue
 * cycles per pixel, the rest (71%) data-cache misses on the frames; the tree's row-band stream
 * (bvb/stream.h, as its add_sat.S uses it) would bring the frames into L1 by DMA instead. */
	.section .l1.text, "ax"
	.align 4
	.global _absdiff_u8_asm
	.type _absdiff_u8_asm, STT_FUNC
_absdiff_u8_asm:
	/* r0 a, r1 b, r2 dst; [sp + 12] width, [sp + 16] height, [sp + 20] src_stride,
	 * [sp + 24] dst_stride */
	i0 = r0;
	i1 = r1;
	i2 = r2;
	r0 = [sp + 20];
	m0 = r0;
	r0 = [sp + 24];
	m1 = r0;
	r2 = [sp + 12];
	r0 = [sp + 16];
	lc1 = r0;
	lsetup (.Lrow, .Lrow_end) lc1;
.Lrow:
	p0 = i0;
	p1 = i1;
	p2 = i2;
	lc0 = r2;
	lsetup (.Lpix, .Lpix_end) lc0;
.Lpix:	r0 = b[p0++] (z);
	r1 = b[p1++] (z);
	r0 = r0 - r1;
	r0 = abs r0;
.Lpix_end:
	b[p2++] = r0;
	i0 += m0;
	i1 += m0;
.Lrow_end:
	i2 += m1;
	rts;
	.size _absdiff_u8_asm, . - _absdiff_u8_asm
