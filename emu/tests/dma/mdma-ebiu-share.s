# Memory DMA shares the EBIU with the core, and the core has priority - EBIU_AMGCTL.CDPRIO
# = 0, its reset value, ADSP-BF537 Hardware Reference, EBIU chapter. So a transfer to or
# from SDRAM is held up for as long as the core's own SDRAM traffic held the EBIU
# meanwhile (sim/bfin/dv-bfin_dma.c and timing-mem.c, patch 0032).
#
# The transfer is mdma-timing.s's A - 1280 bytes, 8-bit, SDRAM to L1, 10 + 1280 SCLK at
# SSEL 5 = 6450 core cycles from the CONFIG write to DMA_DONE when it has the bus alone.
#  A) alone - DMA_DONE in [6450, 6550] (the poll loop sees it up to one iteration late).
#  B) the same transfer, with 32 loads from uncached SDRAM right after the CONFIG write
#     (the caches are off at reset). Each load waits for its data, so the EBIU is busy for
#     the core exactly as long as the loads stall it - their cycles (CYCLES around them, in
#     R5) less one issue cycle each. DMA_DONE comes that much later - in
#     [6450 + R5 - 32, 6550 + R5 - 32]; the loads take several hundred cycles (each at least
#     the 2 SCLK synchronisation and a CAS latency of SDRAM, 5 core cycles a SCLK), so a DMA
#     that ignored them (before patch 0032) fails the window.
#  C) the same with 32 loads from L1 bank B - no EBIU traffic, DMA_DONE in [6450, 6550]
#     again.
# The code runs from L1 instruction SRAM - its fetches do not use the EBIU.
# mach: bfin
# ld: -Ttext=0xFFA00000 -Tdata=0xFF807000
# sim: --environment operating --timing bf537
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC, 0x00100000	/* SDRAM, the DMA's source */
	.equ CORE, 0x00180000	/* SDRAM, the core's loads */
	.equ BUFA, 0xFF800000	/* L1 data bank A, the DMA's destination */
	.equ BUFB, 0xFF900000	/* L1 data bank B, the core's loads in C */
	.equ PLL_DIV, 0xFFC00004
	.equ MDMA_D0, 0xFFC00F00
	.equ MDMA_S0, 0xFFC00F40
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ DI_EN, 0x0080

	# Set up transfer A on MDMA stream 0, source started.
	.macro setup_a
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 1280
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, BUFA
	mmr16 P5, 0x10, 1280
	mmr16 P5, 0x14, 1
	mmr16 P4, 0x08, DMAEN
	.endm
	# 32 dependent-free loads through P1, CYCLES around them: their cycles in R5.
	.macro loads
	R4 = CYCLES;
	LSETUP (1f, 1f) LC0 = P2;
1:	R1 = [P1++];
	R5 = CYCLES;
	R5 = R5 - R4;
	.endm
	# Poll DMA_DONE, core cycles from the CONFIG write to seeing it in R7, clear it.
	.macro wait_cycles
	timed_wait
	clr_done
	.endm
	# Fail unless R2 <= R7 <= R2 + 100.
	.macro chk_from_r2
	CC = R7 < R2;
	IF CC JUMP .Lfail;
	R0 = 100;
	R2 = R2 + R0;
	CC = R2 < R7;
	IF CC JUMP .Lfail;
	.endm

	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	CSYNC;
	# SSEL 5, CSEL 0: 5 core cycles per SCLK cycle.
	ldc P3, PLL_DIV
	R0 = 0x0005;
	W[P3] = R0;
	ldc P5, MDMA_D0
	ldc P4, MDMA_S0
	P2 = 32;

	# A) alone
	setup_a
	timed_start DMAEN | WNR | DI_EN
	wait_cycles
	ldc R2, 6450
	chk_from_r2

	# B) with 32 loads from SDRAM
	ldc P1, CORE
	setup_a
	timed_start DMAEN | WNR | DI_EN
	loads
	wait_cycles
	# The loads must have taken the EBIU for a while, or this checks nothing.
	R0 = 300;
	CC = R5 < R0;
	IF CC JUMP .Lfail;
	ldc R2, 6450 - 32
	R2 = R2 + R5;
	chk_from_r2

	# C) with 32 loads from L1
	ldc P1, BUFB
	setup_a
	timed_start DMAEN | WNR | DI_EN
	loads
	wait_cycles
	ldc R2, 6450
	chk_from_r2

	dbg_pass
.Lfail:
	dbg_fail
