# The two memory DMA streams share the EBIU - under --timing bf537, transfers to or from
# SDRAM on MDMA stream 0 and stream 1 at once take, together, the sum of their times, not the
# time of one (sim/bfin/dv-bfin_dma.c, patch 0033).
#
# Each transfer is mdma-timing.s's A - 1280 bytes, 8-bit, SDRAM to L1 - at SSEL 5 -
# 10 SCLK to start, then 1280 SCLK of elements, 5 core cycles a SCLK. Alone it takes 6450
# core cycles from its CONFIG write to DMA_DONE.
#  A) stream 0 alone - DMA_DONE in [6450, 6550] (the poll loop sees it up to one iteration
#     late).
#  B) stream 0, then stream 1 started at once after it - the later DMA_DONE of the two
#     comes when both transfers' elements have been through the bus, 50 + 2 x 6400 = 12850
#     core cycles after stream 0's CONFIG write, up to one chunk of 256 elements (1280 core
#     cycles) late, as the streams take the bus a chunk at a time - the window is
#     [12850, 12850 + 1280 + 100]; streams that did not share the bus would both be done by
#     6550.
#  C) stream 0 SDRAM to L1 with stream 1 L1 bank B to L1 bank B - they do not share the EBIU,
#     so stream 0 is done in [6450, 6550] again.
# The code runs from L1 instruction SRAM - its fetches do not use the EBIU.
# mach: bfin
# ld: -Ttext=0xFFA00000 -Tdata=0xFF807000
# sim: --environment operating --timing bf537
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC0, 0x00100000	/* SDRAM, stream 0's source */
	.equ SRC1, 0x00180000	/* SDRAM, stream 1's source */
	.equ BUFA, 0xFF800000	/* L1 data bank A, stream 0's destination */
	.equ BUFA1, 0xFF801000	/* L1 data bank A, stream 1's destination */
	.equ BUFB, 0xFF900000	/* L1 data bank B */
	.equ BUFB1, 0xFF901000	/* L1 data bank B */
	.equ PLL_DIV, 0xFFC00004
	.equ MDMA_D0, 0xFFC00F00
	.equ MDMA_S0, 0xFFC00F40
	.equ MDMA_D1, 0xFFC00F80
	.equ MDMA_S1, 0xFFC00FC0
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ DI_EN, 0x0080

	# Set up 1280 bytes from \from to \to on the stream whose destination is P5 and
	# source P4, source started; the destination's CONFIG value in R0.
	.macro setup from:req, to:req
	mmr32 P4, 0x04, \from
	mmr16 P4, 0x10, 1280
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, \to
	mmr16 P5, 0x10, 1280
	mmr16 P5, 0x14, 1
	mmr16 P4, 0x08, DMAEN
	ldc R0, DMAEN | WNR | DI_EN
	.endm
	.macro clear_all
	ldc P3, MDMA_D0
	mmr16 P3, 0x28, 1
	ldc P3, MDMA_D1
	mmr16 P3, 0x28, 1
	.endm
	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	CSYNC;
	ldc P3, PLL_DIV
	R0 = 0x0005;
	W[P3] = R0;
	ldc P1, MDMA_D0
	ldc P2, MDMA_D1

	# A) stream 0 alone
	ldc P5, MDMA_D0
	ldc P4, MDMA_S0
	setup SRC0, BUFA
	R6 = CYCLES;
	W[P5 + 0x08] = R0;
	wait_done P1
	R7 = CYCLES;
	R7 = R7 - R6;
	chk_window 6450, 6550
	clear_all

	# B) both streams from SDRAM
	ldc P5, MDMA_D1
	ldc P4, MDMA_S1
	setup SRC1, BUFA1
	R5 = R0;
	ldc P5, MDMA_D0
	ldc P4, MDMA_S0
	setup SRC0, BUFA
	R6 = CYCLES;
	W[P1 + 0x08] = R0;
	W[P2 + 0x08] = R5;
	wait_done P1
	wait_done P2
	R7 = CYCLES;
	R7 = R7 - R6;
	chk_window 12850, 14230
	clear_all

	# C) stream 1 within L1 bank B
	ldc P5, MDMA_D1
	ldc P4, MDMA_S1
	setup BUFB, BUFB1
	R5 = R0;
	ldc P5, MDMA_D0
	ldc P4, MDMA_S0
	setup SRC0, BUFA
	R6 = CYCLES;
	W[P1 + 0x08] = R0;
	W[P2 + 0x08] = R5;
	wait_done P1
	R7 = CYCLES;
	R7 = R7 - R6;
	chk_window 6450, 6550
	wait_done P2
	clear_all

	dbg_pass
.Lfail:
	dbg_fail
