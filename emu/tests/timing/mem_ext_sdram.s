# mach: bfin
# sim: --environment operating --timing bf537 --timing-ext-sync=2 --timing-wbuf=5 --timing-mmr-sclk=2 --timing-ifetch-bytes=8
# ld: -Ttext=0xFFA00000 -Tdata=0xFF806800 --section-start=.sdram_text=0x00010000

# BF537 timing model, external memory (timing-mem.c): core reads and writes of SDRAM through
# the EBIU, open rows per internal bank, the write buffer, system MMRs at SCLK, and
# instruction fetch from SDRAM without the instruction cache.
#
# Set up here: PLL_DIV = 0x0004 (SSEL 4, CSEL 0: CCLK = 4 x SCLK); EBIU_SDGCTL = 0x0011998D
# (CL 3, tRAS 6, tRP 3, tRCD 3, tWR 2); EBIU_SDBCTL = 0x0013 (enabled, 32 MB, 9 column bits:
# 1 KB rows, internal bank = address bits 24:23).  Options as in the header: 2 SCLK of
# core/EBIU synchronisation per access, 5-entry write buffer, 2 SCLK per system MMR access,
# 8-byte instruction fetches.  SDRAM is 16 bits wide: a 32-bit access is 2 transfers.
#
# Every window is timed twice, with the same code, once on L1 (no extra cycles) and once on
# the case under test, so the difference is the memory model's alone (SCLK x 4 = CCLK):
#   read A (bank 0, no open row):  sync 2 + tRCD 3 + CL 3 + 2 = 10 SCLK = 40
#   read A+4 (row open, hit):      2 + 3 + 2                  =  7 SCLK = 28
#   read B (bank 0, other row):    2 + tRP 3 + 3 + 3 + 2      = 13 SCLK = 52
#   read C (bank 1, no open row):  2 + 3 + 3 + 2              = 10 SCLK = 40
#   read B+8 (bank 0 row still open, bank 1 did not close it): 7 SCLK = 28
#   16-bit read B+2 (hit):         2 + 3 + 1                  =  6 SCLK = 24
#   system MMR read (PLL_DIV):     2 SCLK                              =  8
#   core MMR read (IMASK):                                                0
#   hit read with SSEL 5:          7 SCLK x 5                          = 35
#   hit read with SSEL 5, CSEL 1:  7 SCLK x 5/2 = 17.5, rounded up     = 18
#   5 stores (row open, hit):      into the buffer, no stall            =  0
#   7 stores: each takes 2 + 2 = 4 SCLK = 16 on the bus; store k issues at t+k; the 6th
#     (k=5) finds 5 buffered and waits for the 1st, done at t+16: 11; it issues at t+17,
#     the 7th finds the buffer full again and waits for the 2nd, done at t+32: 15 -> 26
#   call of NOP x4; RTS at 0x10000 (8-byte aligned), bank 0 row 0x40 while row 0x401 is
#     open: block 0x10000: 2 + tRP 3 + tRCD 3 + CL 3 + 4 = 15 SCLK = 60; block 0x10008
#     (the RTS), same row: 2 + 3 + 4 = 9 SCLK = 36 -> 96
#   the same call again: both blocks hit the row, nothing is kept (no cache): 36 + 36 = 72
# With --timing none every difference is 0, so every non-zero check fails.

	.include "testutils.inc"

	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	CSYNC;

	imm32 P2, 0xFFC00004;	/* PLL_DIV */
	R0 = 0x0004 (Z);
	W[P2] = R0;
	imm32 P0, 0xFFC00A10;	/* EBIU_SDGCTL */
	imm32 R0, 0x0011998D;
	[P0] = R0;
	imm32 P0, 0xFFC00A14;	/* EBIU_SDBCTL */
	R0 = 0x0013 (Z);
	W[P0] = R0;
	SSYNC;

	/* R7 = cycles of one "R0 = [P1]" (or W[P1]) between two CYCLES reads.  */
	.macro time_read
	NOP; NOP; NOP; NOP; NOP;
	R6 = CYCLES;
	R0 = [P1];
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm
	.macro time_read16
	NOP; NOP; NOP; NOP; NOP;
	R6 = CYCLES;
	R0 = W[P1] (Z);
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm
	.macro check_read addr, expect
	imm32 P1, \addr;
	time_read
	R7 = R7 - R5;
	CHECKREG R7, \expect;
	.endm

	/* Reference: a read of L1 data.  */
	imm32 P1, 0xFF801000;
	time_read
	R5 = R7;

	check_read 0x00100000, 40	/* A: bank 0, no row open */
	check_read 0x00100004, 28	/* A+4: hit */
	check_read 0x00100400, 52	/* B: bank 0, other row */
	check_read 0x00900000, 40	/* C: bank 1 */
	check_read 0x00100408, 28	/* B+8: bank 0 row kept */

	imm32 P1, 0xFF801000;
	time_read16
	R4 = R7;
	imm32 P1, 0x00100402;
	time_read16
	R7 = R7 - R4;
	CHECKREG R7, 24;

	imm32 P1, 0xFF801000;
	time_read16
	R4 = R7;
	imm32 P1, 0xFFC00004;	/* PLL_DIV, a system MMR */
	time_read16
	R7 = R7 - R4;
	CHECKREG R7, 8;
	check_read 0xFFE02104, 0	/* IMASK, a core MMR */

	R0 = 0x0005 (Z);	/* SSEL 5 */
	W[P2] = R0;
	SSYNC;
	check_read 0x0010040C, 35
	R0 = 0x0015 (Z);	/* SSEL 5, CSEL 1 */
	W[P2] = R0;
	SSYNC;
	check_read 0x00100410, 18
	R0 = 0x0004 (Z);
	W[P2] = R0;
	SSYNC;

	/* Write buffer.  */
	.macro time_stores n
	NOP; NOP; NOP; NOP; NOP;
	R6 = CYCLES;
	.rept \n
	[P1++] = R0;
	.endr
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm

	imm32 P1, 0xFF802000;
	time_stores 5
	R4 = R7;
	imm32 P1, 0x00100000;
	R0 = [P1];		/* opens row 0x400 of bank 0 */
	time_stores 5
	R7 = R7 - R4;
	CHECKREG R7, 0;

	imm32 P1, 0xFF802000;
	time_stores 7
	R4 = R7;
	imm32 P1, 0x00100020;
	R0 = [P1];		/* waits until the buffer has drained */
	imm32 P1, 0x00100040;
	time_stores 7
	R7 = R7 - R4;
	CHECKREG R7, 26;

	/* Instruction fetch from SDRAM.  Open row 0x401 of bank 0 (this read waits for the
	   buffered stores and precharges the written row).  */
	imm32 P1, 0x00100400;
	R0 = [P1];
	.macro time_call f
	NOP; NOP; NOP; NOP; NOP;
	R6 = CYCLES;
	CALL \f;
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm
	time_call f_l1
	R4 = R7;
	time_call f_sdram
	R7 = R7 - R4;
	CHECKREG R7, 96;
	time_call f_sdram
	R7 = R7 - R4;
	CHECKREG R7, 72;

	dbg_pass

	.align 8
f_l1:
	NOP; NOP; NOP; NOP;
	RTS;

	.section .sdram_text, "ax"
	.align 8
f_sdram:
	NOP; NOP; NOP; NOP;
	RTS;
