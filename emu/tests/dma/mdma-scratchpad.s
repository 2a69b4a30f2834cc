# Memory DMA cannot reach the L1 scratchpad - the ADSP-BF537 Hardware Reference, Memory
# chapter, says scratchpad SRAM cannot be accessed by DMA. A memory DMA with either side in
# it ends in a DMA error (DMA_ERR, bit 1 of the destination's IRQ_STATUS) and moves nothing
# (sim/bfin/dv-bfin_dma.c, patch 0033), as with the model off - this is not timing.
#  A) SDRAM to the scratchpad - DMA_ERR set, DMA_DONE clear, the scratchpad keeps its words.
#  B) the scratchpad to L1 bank A - DMA_ERR set, bank A keeps its words.
#  C) SDRAM to L1 bank A, the same size - done, no error, the bytes arrive (the check
#     above is not a refusal of everything).
# mach: bfin
# ld: -Ttext=0xFFA00000 -Tdata=0xFF807000
# sim: --environment operating
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC, 0x00100000	/* SDRAM */
	.equ BUFA, 0xFF800000	/* L1 data bank A */
	.equ SPAD, 0xFFB00000	/* L1 scratchpad */
	.equ MDMA_D0, 0xFFC00F00
	.equ MDMA_S0, 0xFFC00F40
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ WDSIZE_32, 0x0008
	.equ DI_EN, 0x0080

	# 64 words from \from to \to, 32-bit elements, both channels started.
	.macro xfer from:req, to:req
	mmr32 P4, 0x04, \from
	mmr16 P4, 0x10, 64
	mmr16 P4, 0x14, 4
	mmr32 P5, 0x04, \to
	mmr16 P5, 0x10, 64
	mmr16 P5, 0x14, 4
	mmr16 P4, 0x08, DMAEN | WDSIZE_32
	mmr16 P5, 0x08, DMAEN | WNR | WDSIZE_32 | DI_EN
	.endm
	# Wait until the destination's IRQ_STATUS has DMA_DONE or DMA_ERR; leave it in R0.
	.macro wait_end
	imm32 R1, 100000
1:	R0 = W[P5 + 0x28] (Z);
	R2 = 3;
	R2 = R0 & R2;
	CC = R2 == 0;
	IF !CC JUMP 2f;
	R1 += -1;
	CC = R1 == 0;
	IF !CC JUMP 1b;
	dbg_fail
2:	R0 = W[P5 + 0x28] (Z);
	.endm
	# Stop both channels and clear their status.
	.macro stop
	mmr16 P4, 0x08, 0
	mmr16 P5, 0x08, 0
	mmr16 P4, 0x28, 3
	mmr16 P5, 0x28, 3
	.endm
	# Fill 64 words at \at with \val.
	.macro fill at:req, val:req
	ldc P0, \at
	ldc R0, \val
	P1 = 64;
	LSETUP (1f, 1f) LC0 = P1;
1:	[P0++] = R0;
	.endm
	# Fail unless the 64 words at \at all hold \val.
	.macro expect at:req, val:req
	ldc P0, \at
	ldc R1, \val
	P1 = 64;
	LSETUP (1f, 2f) LC0 = P1;
1:	R0 = [P0++];
	CC = R0 == R1;
2:	IF !CC JUMP .Lfail;
	.endm

	start

	ldc P5, MDMA_D0
	ldc P4, MDMA_S0
	fill SRC, 0x11223344
	fill SPAD, 0x55667788
	fill BUFA, 0x99AABBCC

	# A) SDRAM -> scratchpad
	xfer SRC, SPAD
	wait_end
	R1 = 3;
	R0 = R0 & R1;
	CHECKREG R0, 2
	expect SPAD, 0x55667788
	stop

	# B) scratchpad -> L1 bank A
	xfer SPAD, BUFA
	wait_end
	R1 = 3;
	R0 = R0 & R1;
	CHECKREG R0, 2
	expect BUFA, 0x99AABBCC
	stop

	# C) SDRAM -> L1 bank A
	xfer SRC, BUFA
	wait_end
	R1 = 3;
	R0 = R0 & R1;
	CHECKREG R0, 1
	expect BUFA, 0x11223344
	stop

	dbg_pass
.Lfail:
	dbg_fail
