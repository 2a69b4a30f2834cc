# Timing of memory DMA under --timing bf537 - a transfer takes time on the system clock,
# DMA_DONE comes only when it is over, and the core computes meanwhile.
#
# The rule (sim/bfin/dv-bfin_dma.c, patch 0031), in SCLK cycles -
#   start       10 per CONFIG write that starts the destination (an assumption, the
#               default of --timing-dma-start)
#   descriptor  1 per 16-bit descriptor word fetched (16-bit DMA bus, ADSP-BF537 HRM ch. 2)
#   element     per side max(1, bytes / 2) (16-bit DCB and DEB); L1 to SDRAM or back the
#               larger side (source and destination granted together, "full SCLK rate",
#               HRM ch. 5 "Traffic Control"), L1 to L1 the sum of both sides (same memory
#               space, a conflict)
# and 5 core cycles per SCLK cycle (bfin_timing_sclk_ratio of PLL_DIV, which the test sets
# to SSEL 5, CSEL 0 first), rounded up once over the whole transfer. So, from the CONFIG write to DMA_DONE -
#  A) 1280 bytes, 8-bit, SDRAM to L1, stop mode
#       10 + 1280 * max(1, 1) = 1290 SCLK = 6450 core cycles
#  B) 300 words, 32-bit, L1 bank A to L1 bank B
#       10 + 300 * (2 + 2) = 1210 SCLK = 6050 core cycles
#  C) 2 x 640 halfwords, 16-bit, SDRAM to L1 through a small descriptor list of two 8-word
#     descriptors on the destination (source in stop mode)
#       10 + 2 * 8 + 1280 * max(1, 1) = 1306 SCLK = 6530 core cycles
#  D) A again, with 4000 cycles of computation right after the CONFIG write - the DMA is
#     still running after them (DMA_RUN set, DMA_DONE clear), and DMA_DONE still comes
#     6450 core cycles after the CONFIG write - the computation overlapped the transfer.
#  E) A again after PLL_DIV is set to SSEL 4 (CSEL 0) - 4 core cycles per SCLK cycle,
#       1290 SCLK = 5160 core cycles
#  F) 8 rows of 160 bytes into a 2D destination with DI_SEL (interrupt after every row),
#     still SSEL 4 - DMA_DONE after the first row with DMA_RUN still set, CURR_Y_COUNT 7
#     and CURR_X_COUNT reloaded to 160 (ADSP-BF537 HRM, DMAx_CONFIG.DI_SEL and the
#     count registers), 10 + 160 = 170 SCLK = 680 core cycles; cleared, DMA_DONE again
#     after the second row, 10 + 320 = 330 SCLK = 1320 core cycles after the CONFIG write.
# The firmware reads CYCLES (SYSCFG.CCEN set) just before the CONFIG write and after the
# poll loop that sees DMA_DONE; the poll loop (an MMR read at SCLK, a test, a branch, a
# counter) sees DMA_DONE up to one iteration late, so each count must lie in [T, T + 100].
# The code runs from L1 instruction SRAM, so that under the memory model the loop is not
# slowed by instruction fetches from SDRAM (with the series 0001-0031, 25 to 39 cycles
# over T).
# With the model off (--timing none) the same transfers complete within a few cycles and
# every check fails.
# mach: bfin
# ld: -Ttext=0xFFA00000 -Tdata=0xFF807000
# sim: --environment operating --timing bf537
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC, 0x00100000	/* SDRAM */
	.equ BUFA, 0xFF800000	/* L1 data bank A */
	.equ BUFB, 0xFF900000	/* L1 data bank B */
	.equ DESC, 0xFF804000
	.equ PLL_DIV, 0xFFC00004
	.equ MDMA_D0, 0xFFC00F00
	.equ MDMA_S0, 0xFFC00F40
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ WDSIZE_16, 0x0004
	.equ WDSIZE_32, 0x0008
	.equ DMA2D, 0x0010
	.equ DI_SEL, 0x0040
	.equ DI_EN, 0x0080
	.equ NDSIZE_8, 0x0800
	.equ FLOW_SMALL, 0x6000

	start

	# CYCLES counts only with SYSCFG.CCEN (bit 1).
	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	CSYNC;

	# SCLK = VCO / 5, CCLK = VCO (PLL_DIV SSEL 5, CSEL 0 - the chip's reset value; the
	# simulator's PLL starts at SSEL 4).
	ldc P3, PLL_DIV
	R0 = 0x0005;
	W[P3] = R0;

	ldc P5, MDMA_D0
	ldc P4, MDMA_S0

	# A) 1280 bytes SDRAM -> L1
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 1280
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, BUFA
	mmr16 P5, 0x10, 1280
	mmr16 P5, 0x14, 1
	mmr16 P4, 0x08, DMAEN
	timed_start DMAEN | WNR | DI_EN
	timed_wait
	chk_window 6450, 6550
	# The source ran without DI_EN - no DMA_DONE, and DMA_RUN clear as it is finished.
	chk16 P4, 0x28, 0x0000
	clr_done

	# B) 300 words L1 bank A -> L1 bank B
	mmr32 P4, 0x04, BUFA
	mmr16 P4, 0x10, 300
	mmr16 P4, 0x14, 4
	mmr32 P5, 0x04, BUFB
	mmr16 P5, 0x10, 300
	mmr16 P5, 0x14, 4
	mmr16 P4, 0x08, DMAEN | WDSIZE_32
	timed_start DMAEN | WNR | WDSIZE_32 | DI_EN
	timed_wait
	chk_window 6050, 6150
	clr_done

	# C) two small-list descriptors on the destination, 640 halfwords each
	ldc P3, DESC
	mmr16 P3, 0x00, (DESC + 0x20) & 0xffff
	mmr16 P3, 0x02, BUFA & 0xffff
	mmr16 P3, 0x04, BUFA >> 16
	mmr16 P3, 0x06, DMAEN | WNR | WDSIZE_16 | FLOW_SMALL | NDSIZE_8
	mmr16 P3, 0x08, 640
	mmr16 P3, 0x0a, 2
	mmr16 P3, 0x0c, 0
	mmr16 P3, 0x0e, 0
	mmr16 P3, 0x20, 0
	mmr16 P3, 0x22, (BUFA + 0x800) & 0xffff
	mmr16 P3, 0x24, (BUFA + 0x800) >> 16
	mmr16 P3, 0x26, DMAEN | WNR | WDSIZE_16 | DI_EN
	mmr16 P3, 0x28, 640
	mmr16 P3, 0x2a, 2
	mmr16 P3, 0x2c, 0
	mmr16 P3, 0x2e, 0
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 1280
	mmr16 P4, 0x14, 2
	mmr16 P4, 0x08, DMAEN | WDSIZE_16
	mmr32 P5, 0x00, DESC
	timed_start DMAEN | WNR | WDSIZE_16 | FLOW_SMALL | NDSIZE_8
	timed_wait
	chk_window 6530, 6630
	clr_done

	# D) A, overlapped with 4000 cycles of computation
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 1280
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, BUFA
	mmr16 P5, 0x10, 1280
	mmr16 P5, 0x14, 1
	mmr16 P4, 0x08, DMAEN
	R2 = 0;
	P1 = 4000;
	timed_start DMAEN | WNR | DI_EN
	LSETUP (1f, 1f) LC0 = P1;
1:	R2 += 1;
	R0 = W[P5 + 0x28] (Z);
	CHECKREG R0, 0x0008
	timed_wait
	chk_window 6450, 6550
	R0 = 4000;
	CC = R2 == R0;
	IF !CC JUMP .Lfail;
	clr_done

	# E) A with SCLK = VCO / 4 (PLL_DIV SSEL 4, CSEL 0, as the SRV-1 firmware sets it)
	ldc P3, PLL_DIV
	R0 = 0x0004;
	W[P3] = R0;
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 1280
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, BUFA
	mmr16 P5, 0x10, 1280
	mmr16 P5, 0x14, 1
	mmr16 P4, 0x08, DMAEN
	timed_start DMAEN | WNR | DI_EN
	timed_wait
	chk_window 5160, 5260
	clr_done

	# F) 8 rows of 160 bytes, destination 2D with DI_SEL - DMA_DONE after each row
	# (still SSEL 4)
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 1280
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, BUFA
	mmr16 P5, 0x10, 160
	mmr16 P5, 0x14, 1
	mmr16 P5, 0x18, 8
	mmr16 P5, 0x1c, 1
	mmr16 P4, 0x08, DMAEN
	timed_start DMAEN | WNR | DMA2D | DI_SEL | DI_EN
	timed_wait
	chk_window 680, 780
	# after row 1 - DMA_DONE with DMA_RUN, CURR_Y_COUNT 7, CURR_X_COUNT reloaded
	chk16 P5, 0x28, 0x0009
	chk16 P5, 0x38, 7
	chk16 P5, 0x30, 160
	mmr16 P5, 0x28, 1
	timed_wait
	chk_window 1320, 1420

	dbg_pass
.Lfail:
	dbg_fail
