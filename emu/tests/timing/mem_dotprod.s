# mach: bfin
# sim: --environment operating --timing bf537 --timing-ext-sync=2 --timing-wbuf=5 --timing-mmr-sclk=2 --timing-ifetch-bytes=8 --timing-cwf=1 --timing-l1-collision=1
# ld: -Ttext=0xFFA00000 -Tdata=0xFF800800 --section-start=.sdram_text=0x00010000

# Reproduces a published Blackfin figure with code of our own: a dual-MAC dot product of
# 100 16-bit values, one bundle per two elements (two MACs and two 32-bit loads), timed with
# CYCLES around a 50-iteration hardware loop, as described in D. Rowe, "How to make your
# Blackfin fly, part 1" (rowetel.com/blog/?p=5), measured on a BF537 STAMP under uClinux:
# 53 cycles with the vectors at the top of L1 data banks A and B, 103 with the vectors on
# the stack in SDRAM (after a first run of 242).
#
# The timed window, as in the description: a CYCLES read, a register move, the loop setup,
# 50 bundles, a CYCLES read: 3 + 50 = 53 base cycles.
#   1. x in bank B, y in bank A (the published L1 case): no collision             = 53
#   2. x and y in one sub-bank of bank A: 50 collisions of 1 cycle           53 + 50 = 103
#   3. x and y in SDRAM, 200 bytes apart (the stack case), data cache on (write-back,
#      banks A and B, bank by address bit 14) and instruction cache on, kernel in SDRAM:
#      the vectors were just written, so every line is cached; both vectors sit in one
#      cache bank and, by address bits 13:12, one sub-bank: 50 collisions     53 + 50 = 103
#      from the second run on (the first also pays instruction cache misses: reported
#      by the test in R4, not checked)
#   4. the same vectors in SDRAM, caches off, kernel in L1: each of the 100 loads in the
#      window is a page hit read (one 1 KB row holds both vectors): sync 2 + CL 3 + 2
#      transfers = 7 SCLK = 28 CCLK (CCLK = 4 x SCLK), two per bundle, one after the
#      other: 53 + 50 x 56                                                       = 2853
# With --timing none cases 2-4 give 53 and fail.

	.include "testutils.inc"

	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	CSYNC;

	imm32 P2, 0xFFC00004;	/* PLL_DIV: SSEL 4 */
	R0 = 0x0004 (Z);
	W[P2] = R0;
	imm32 P0, 0xFFC00A10;	/* EBIU_SDGCTL: CL 3, tRAS 6, tRP 3, tRCD 3, tWR 2 */
	imm32 R0, 0x0011998D;
	[P0] = R0;
	imm32 P0, 0xFFC00A14;	/* EBIU_SDBCTL: 32 MB, 9 column bits */
	R0 = 0x0013 (Z);
	W[P0] = R0;
	SSYNC;

	/* Fill N=100 halfwords at P0 with 1.  */
	.macro fill_ones
	P1 = 100;
	R0 = 1;
	LSETUP (1f, 1f) LC0 = P1;
1:	W[P0++] = R0;
	.endm
	.macro pad
	.rept 200
	NOP;
	.endr
	.endm

	/* 1: x at the top of bank B, y at the top of bank A.  */
	imm32 P0, 0xFF903F38;
	fill_ones
	imm32 P0, 0xFF803F38;
	fill_ones
	imm32 R0, 0xFF903F38;
	imm32 R1, 0xFF803F38;
	CALL dot_l1;
	CHECKREG R7, 53;
	CHECKREG R0, 200;	/* 100 products of 1 x 1, doubled by the fractional MAC */

	/* 2: both in sub-bank 3 of bank A.  */
	imm32 P0, 0xFF803000;
	fill_ones
	imm32 P0, 0xFF803400;
	fill_ones
	imm32 R0, 0xFF803000;
	imm32 R1, 0xFF803400;
	CALL dot_l1;
	CHECKREG R7, 103;

	/* 4 (before the caches go on): SDRAM, uncached, kernel in L1.  */
	imm32 P0, 0x00200000;
	fill_ones
	imm32 P0, 0x002000C8;
	fill_ones
	pad
	imm32 R0, 0x00200000;
	imm32 R1, 0x002000C8;
	CALL dot_l1;
	CHECKREG R7, 2853;

	/* 3: caches on.  */
	imm32 P0, 0xFFE00100;	/* DCPLB_ADDR0 = 0 */
	R0 = 0;
	[P0] = R0;
	imm32 P0, 0xFFE00200;	/* DCPLB_DATA0: valid, rd/wr, dirty, cacheable, 4 MB, WB */
	imm32 R0, 0x0003109D;
	[P0] = R0;
	imm32 P0, 0xFFE01100;	/* ICPLB_ADDR0 = 0 */
	R0 = 0;
	[P0] = R0;
	imm32 P0, 0xFFE01200;	/* ICPLB_DATA0: valid, user rd, cacheable, 4 MB */
	imm32 R0, 0x00031005;
	[P0] = R0;
	imm32 P0, 0xFFE00004;	/* DMEM_CONTROL: A and B cache, DCPLBs on */
	R0 = 0xF (Z);
	[P0] = R0;
	imm32 P0, 0xFFE01004;	/* IMEM_CONTROL: cache, ICPLBs on */
	R0 = 0x7 (Z);
	[P0] = R0;
	SSYNC;

	imm32 P0, 0x00300000;	/* a fresh pair, so the writes allocate the lines */
	fill_ones
	imm32 P0, 0x003000C8;
	fill_ones
	pad
	imm32 R0, 0x00300000;
	imm32 R1, 0x003000C8;
	CALL dot_sdram;
	R4 = R7;		/* first run */
	P5 = 9;
	LSETUP (2f, 3f) LC1 = P5;
2:	imm32 R0, 0x00300000;
	imm32 R1, 0x003000C8;
3:	CALL dot_sdram;
	CHECKREG R7, 103;

	dbg_pass

	/* The kernel: R0 = x, R1 = y (100 halfwords each); returns the dot product in R0 and
	   the cycles of the timed window in R7.  */
	.macro dot_kernel
	I0 = R0;
	I1 = R1;
	P1 = 50;
	A1 = A0 = 0;
	NOP; NOP; NOP; NOP;
	R0 = [I0++] || R1 = [I1++];
	R2 = CYCLES;
	R3 = R2;
	LSETUP (1f, 1f) LC0 = P1;
1:	A1 += R0.H * R1.H, A0 += R0.L * R1.L || R0 = [I0++] || R1 = [I1++];
	R2 = CYCLES;
	R7 = R2 - R3;
	R0 = (A0 += A1);
	RTS;
	.endm

	.align 8
dot_l1:
	dot_kernel

	.section .sdram_text, "ax"
	.align 32
dot_sdram:
	dot_kernel
