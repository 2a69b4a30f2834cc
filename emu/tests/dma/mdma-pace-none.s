# The pace of memory DMA without the timing model (--timing none) is the simulator's own,
# unchanged by the strided-DMA fix - the rule - the destination's CONFIG write schedules
# its first event one core cycle later; each event moves up to 4 KiB or the rest of the
# destination's current row (one element when its X_MODIFY is negative) and schedules the
# next one a cycle later; DMA_DONE comes with the event that moves the last element. So,
# from the CONFIG write to DMA_DONE -
#  N1) 32 rows of 64 bytes (destination 2D, source 1D)    32 events = 32 cycles
#  N2) 40960 words, 32-bit 1D (1024 words per event)        40 events = 40 cycles
#  N3) 48 bytes with destination X_MODIFY -1                48 events = 48 cycles
# The firmware reads CYCLES (SYSCFG.CCEN set) just before the CONFIG write and after a
# poll loop - a load at 2 + 7k cycles after the first CYCLES read (k = 0, 1, ...; load 1,
# test 1, predicted taken branch 5), then, once the load sees DMA_DONE, the test (1),
# the mispredicted branch falling through (9) and the CYCLES read (1). The last event of
# N comes about N + 1 cycles after the first CYCLES read, so each count lies in
# [N + 11, N + 19] - N1 48, N2 55, N3 62 on the unpatched simulator and on this one.
# The unpatched simulator passes this test too (it guards the pace); the timing model
# (--timing bf537) fails it.
# mach: bfin
# sim: --environment operating
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC, 0x00100000	/* SDRAM */
	.equ DST, 0x00200000	/* SDRAM */
	.equ MDMA_D0, 0xFFC00F00
	.equ MDMA_S0, 0xFFC00F40
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ WDSIZE_32, 0x0008
	.equ DMA2D, 0x0010
	.equ DI_EN, 0x0080

	# Start the destination, poll DMA_DONE with the tightest loop, cycles in R7.
	.macro timed_run cfg:req
	ldc R0, \cfg
	R6 = CYCLES;
	W[P5 + 0x08] = R0;
1:	R0 = W[P5 + 0x28] (Z);
	CC = BITTST (R0, 0);
	IF !CC JUMP 1b (BP);
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm
	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	CSYNC;

	ldc P5, MDMA_D0
	ldc P4, MDMA_S0

	# N1
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 2048
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, DST
	mmr16 P5, 0x10, 64
	mmr16 P5, 0x14, 1
	mmr16 P5, 0x18, 32
	mmr16 P5, 0x1c, 1
	mmr16 P4, 0x08, DMAEN
	timed_run DMAEN | WNR | DMA2D | DI_EN
	chk_window 32 + 11, 32 + 19
	clr_done

	# N2
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 40960
	mmr16 P4, 0x14, 4
	mmr32 P5, 0x04, DST
	mmr16 P5, 0x10, 40960
	mmr16 P5, 0x14, 4
	mmr16 P4, 0x08, DMAEN | WDSIZE_32
	timed_run DMAEN | WNR | WDSIZE_32 | DI_EN
	chk_window 40 + 11, 40 + 19
	clr_done

	# N3
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 48
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, DST + 47
	mmr16 P5, 0x10, 48
	mmr16 P5, 0x14, -1
	mmr16 P4, 0x08, DMAEN
	timed_run DMAEN | WNR | DI_EN
	chk_window 48 + 11, 48 + 19

	dbg_pass
.Lfail:
	dbg_fail
