# Memory DMA in the descriptor modes (stream S0/D0), the way a kernel double-buffers row
# bands - one chain fills two L1 buffers in turn.
#  a) descriptor array on the destination - CURR_DESC_PTR set by software, two 7-word
#     descriptors (SA, CONFIG, X_COUNT, X_MODIFY, Y_COUNT, Y_MODIFY) one after the other,
#     rows 0..7 into buffer A and rows 8..15 into buffer B from a 1D source.
#  b) small descriptor list on the source - 8-word descriptors (NDPL first, NDPH kept from
#     NEXT_DESC_PTR), each a 2D tile of 32x8 bytes at column 16 (Y_MODIFY 129), into a
#     1D destination.
#  c) large descriptor list on the destination - 9-word descriptors (NDPL, NDPH first),
#     the second one below the first in memory.
#  d) a small list on the destination whose second descriptor switches from 8-bit to
#     16-bit elements (WDSIZE comes from the descriptor just loaded).
# Every byte is checked against the frame's pattern p(x, y) = (5x + 11y + 7) & 0xff
# recomputed here; so are CURR_DESC_PTR (just past the last descriptor fetched),
# NEXT_DESC_PTR, the CONFIG loaded from the last descriptor and IRQ_STATUS (DMA_DONE
# from the last descriptor's DI_EN, DMA_RUN clear) (ADSP-BF537 HRM, chapter 5,
# descriptor-based DMA and DMA registers).
# mach: bfin
# sim: --environment operating
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC, 0x00100000	/* 160x120 frame, 8 bits a pixel, in SDRAM */
	.equ BUFA, 0xFF800000	/* L1 data bank A */
	.equ BUFB, 0xFF801000
	.equ BUFC, 0xFF802000
	.equ BUFD, 0xFF803000
	.equ BUFE, 0xFF803400
	.equ DESC, 0xFF804000
	.equ MDMA_D0, 0xFFC00F00
	.equ MDMA_S0, 0xFFC00F40
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ WDSIZE_16, 0x0004
	.equ DMA2D, 0x0010
	.equ DI_EN, 0x0080
	.equ NDSIZE_7, 0x0700
	.equ NDSIZE_8, 0x0800
	.equ NDSIZE_9, 0x0900
	.equ FLOW_ARRAY, 0x4000
	.equ FLOW_SMALL, 0x6000
	.equ FLOW_LARGE, 0x7000

	# Expect nrows rows of ncols bytes from P0 on to be p(x0 + c, y0 + r).
	.macro chk_band x0:req, y0:req, ncols:req, nrows:req
	R1 = \y0 * 11 + \x0 * 5 + 7 (X);
	P1 = \nrows;
	LSETUP (1f, 4f) LC1 = P1;
1:	R0 = R1;
	P2 = \ncols;
	LSETUP (2f, 3f) LC0 = P2;
2:	R2 = B[P0++] (Z);
	R3 = R0.B (Z);
	CC = R2 == R3;
	IF !CC JUMP 9f;
3:	R0 += 5;
4:	R1 += 11;
	JUMP.S 5f;
9:	JUMP.L .Lfail;
5:
	.endm

	start

	ldc P0, SRC
	R1 = 7;
	P1 = 120;
	LSETUP (1f, 4f) LC1 = P1;
1:	R0 = R1;
	P2 = 160;
	LSETUP (2f, 3f) LC0 = P2;
2:	B[P0++] = R0;
3:	R0 += 5;
4:	R1 += 11;

	ldc P5, MDMA_D0
	ldc P4, MDMA_S0
	ldc P3, DESC

	# a) descriptor array at DESC
	mmr16 P3, 0, BUFA & 0xffff
	mmr16 P3, 2, BUFA >> 16
	mmr16 P3, 4, DMAEN | WNR | FLOW_ARRAY | NDSIZE_7
	mmr16 P3, 6, 1280
	mmr16 P3, 8, 1
	mmr16 P3, 10, 0
	mmr16 P3, 12, 0
	mmr16 P3, 14, BUFB & 0xffff
	mmr16 P3, 16, BUFB >> 16
	mmr16 P3, 18, DMAEN | WNR | DI_EN
	mmr16 P3, 20, 1280
	mmr16 P3, 22, 1
	mmr16 P3, 24, 0
	mmr16 P3, 26, 0

	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 2560
	mmr16 P4, 0x14, 1
	mmr16 P4, 0x08, DMAEN | DI_EN
	mmr32 P5, 0x20, DESC
	mmr16 P5, 0x08, DMAEN | WNR | FLOW_ARRAY | NDSIZE_7
	wait_done P5

	ldc P0, BUFA
	chk_band 0, 0, 160, 8
	ldc P0, BUFB
	chk_band 0, 8, 160, 8
	chk32 P5, 0x20, DESC + 28
	chk16 P5, 0x08, DMAEN | WNR | DI_EN
	chk32 P5, 0x24, BUFB + 1280
	chk16 P5, 0x28, 0x0001
	chk32 P4, 0x24, SRC + 2560
	chk16 P4, 0x28, 0x0001
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1

	# b) small descriptor list at DESC + 0x40 and DESC + 0x80, on the source
	mmr16 P3, 0x40, (DESC + 0x80) & 0xffff
	mmr16 P3, 0x42, (SRC + 16) & 0xffff
	mmr16 P3, 0x44, (SRC + 16) >> 16
	mmr16 P3, 0x46, DMAEN | DMA2D | FLOW_SMALL | NDSIZE_8
	mmr16 P3, 0x48, 32
	mmr16 P3, 0x4a, 1
	mmr16 P3, 0x4c, 8
	mmr16 P3, 0x4e, 160 - 32 + 1
	mmr16 P3, 0x80, 0x1234
	mmr16 P3, 0x82, (SRC + 8 * 160 + 16) & 0xffff
	mmr16 P3, 0x84, (SRC + 8 * 160 + 16) >> 16
	mmr16 P3, 0x86, DMAEN | DMA2D | DI_EN
	mmr16 P3, 0x88, 32
	mmr16 P3, 0x8a, 1
	mmr16 P3, 0x8c, 8
	mmr16 P3, 0x8e, 160 - 32 + 1

	mmr32 P4, 0x00, DESC + 0x40
	mmr16 P4, 0x08, DMAEN | DMA2D | FLOW_SMALL | NDSIZE_8
	mmr32 P5, 0x04, BUFC
	mmr16 P5, 0x10, 512
	mmr16 P5, 0x14, 1
	mmr16 P5, 0x08, DMAEN | WNR | DI_EN
	wait_done P5

	ldc P0, BUFC
	chk_band 16, 0, 32, 16
	chk32 P4, 0x20, DESC + 0x80 + 16
	chk32 P4, 0x00, (DESC & 0xffff0000) | 0x1234
	chk16 P4, 0x08, DMAEN | DMA2D | DI_EN
	chk16 P4, 0x38, 1
	chk16 P4, 0x28, 0x0001
	chk16 P5, 0x28, 0x0001
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1

	# c) large descriptor list, DESC + 0x100 then DESC + 0xc0, on the destination
	mmr16 P3, 0x100, (DESC + 0xc0) & 0xffff
	mmr16 P3, 0x102, (DESC + 0xc0) >> 16
	mmr16 P3, 0x104, BUFD & 0xffff
	mmr16 P3, 0x106, BUFD >> 16
	mmr16 P3, 0x108, DMAEN | WNR | FLOW_LARGE | NDSIZE_9
	mmr16 P3, 0x10a, 320
	mmr16 P3, 0x10c, 1
	mmr16 P3, 0x10e, 0
	mmr16 P3, 0x110, 0
	mmr16 P3, 0xc0, 0
	mmr16 P3, 0xc2, 0
	mmr16 P3, 0xc4, BUFE & 0xffff
	mmr16 P3, 0xc6, BUFE >> 16
	mmr16 P3, 0xc8, DMAEN | WNR | DI_EN
	mmr16 P3, 0xca, 320
	mmr16 P3, 0xcc, 1
	mmr16 P3, 0xce, 0
	mmr16 P3, 0xd0, 0

	mmr32 P4, 0x04, SRC + 20 * 160
	mmr16 P4, 0x10, 640
	mmr16 P4, 0x14, 1
	mmr16 P4, 0x08, DMAEN | DI_EN
	mmr32 P5, 0x00, DESC + 0x100
	mmr16 P5, 0x08, DMAEN | WNR | FLOW_LARGE | NDSIZE_9
	wait_done P5

	ldc P0, BUFD
	chk_band 0, 20, 160, 2
	ldc P0, BUFE
	chk_band 0, 22, 160, 2
	chk32 P5, 0x20, DESC + 0xc0 + 18
	chk32 P5, 0x00, 0
	chk32 P5, 0x24, BUFE + 320
	chk16 P5, 0x28, 0x0001
	chk16 P4, 0x28, 0x0001
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1

	# d) small list on the destination whose second descriptor changes the element size -
	# 160 bytes of row 30 as 8-bit elements into BUFC, then row 31 as 80 16-bit elements
	# into BUFC + 0x200, from an 8-bit source.
	mmr16 P3, 0x140, (DESC + 0x160) & 0xffff
	mmr16 P3, 0x142, BUFC & 0xffff
	mmr16 P3, 0x144, BUFC >> 16
	mmr16 P3, 0x146, DMAEN | WNR | FLOW_SMALL | NDSIZE_8
	mmr16 P3, 0x148, 160
	mmr16 P3, 0x14a, 1
	mmr16 P3, 0x14c, 0
	mmr16 P3, 0x14e, 0
	mmr16 P3, 0x160, 0
	mmr16 P3, 0x162, (BUFC + 0x200) & 0xffff
	mmr16 P3, 0x164, (BUFC + 0x200) >> 16
	mmr16 P3, 0x166, DMAEN | WNR | WDSIZE_16 | DI_EN
	mmr16 P3, 0x168, 80
	mmr16 P3, 0x16a, 2
	mmr16 P3, 0x16c, 0
	mmr16 P3, 0x16e, 0

	mmr32 P4, 0x04, SRC + 30 * 160
	mmr16 P4, 0x10, 320
	mmr16 P4, 0x14, 1
	mmr16 P4, 0x08, DMAEN | DI_EN
	mmr32 P5, 0x00, DESC + 0x140
	mmr16 P5, 0x08, DMAEN | WNR | FLOW_SMALL | NDSIZE_8
	wait_done P5

	ldc P0, BUFC
	chk_band 0, 30, 160, 1
	ldc P0, BUFC + 0x200
	chk_band 0, 31, 160, 1
	chk32 P5, 0x24, BUFC + 0x200 + 160
	chk16 P5, 0x08, DMAEN | WNR | WDSIZE_16 | DI_EN
	chk16 P5, 0x28, 0x0001
	chk32 P4, 0x24, SRC + 32 * 160
	chk16 P4, 0x28, 0x0001

	dbg_pass
.Lfail:
	dbg_fail
