# Memory DMA of 16-bit and 32-bit data with strides (stream S1/D1, stop mode) - a 16-bit
# pixel frame of 160x120 in SDRAM into L1 data bank B.
#  a) rows 60..67 into a buffer with 176-pixel rows (room for a kernel's borders) - source
#     1D, destination 2D with Y_MODIFY 2 + 16*2 = 34; the padding must stay untouched.
#  b) half resolution - every second pixel of every second row, X_MODIFY 4 on 16-bit
#     elements and Y_MODIFY 324, into a 1D destination.
#  c) 32-bit elements (WDSIZE 32) with X_MODIFY 8 on the source and 4 on the destination.
# Every element is checked against the frame's pattern q(x, y) = (37x + 1009y + 0x1234)
# & 0xffff, recomputed here, and the channels' CURR_ADDR, CURR_X_COUNT, CURR_Y_COUNT and
# IRQ_STATUS after each work unit (ADSP-BF537 HRM, chapter 5, DMA registers).
# mach: bfin
# sim: --environment operating
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC, 0x00200000	/* 160x120 frame, 16 bits a pixel, in SDRAM */
	.equ DST, 0xFF900000	/* L1 data bank B */
	.equ MDMA_D1, 0xFFC00F80
	.equ MDMA_S1, 0xFFC00FC0
	/* CONFIG bits (ADSP-BF537 HRM, DMAx_CONFIG) */
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ WDSIZE_16, 0x0004
	.equ WDSIZE_32, 0x0008
	.equ DMA2D, 0x0010
	.equ DI_EN, 0x0080

	start

	R5 = 1009 (X);
	# Fill the frame: q(x, y) = (37x + 1009y + 0x1234) & 0xffff.
	ldc P0, SRC
	ldc R1, 0x1234
	P1 = 120;
	LSETUP (1f, 4f) LC1 = P1;
1:	R0 = R1;
	P2 = 160;
	LSETUP (2f, 3f) LC0 = P2;
2:	W[P0++] = R0;
3:	R0 += 37;
4:	R1 = R1 + R5;

	# Mark the destination (8 rows of 176 pixels) with 0xdead.
	ldc P0, DST
	ldc R0, 0xdead
	P1 = 8 * 176;
	LSETUP (1f, 1f) LC0 = P1;
1:	W[P0++] = R0;

	ldc P5, MDMA_D1
	ldc P4, MDMA_S1

	# a) rows 60..67 into rows of 176 pixels (16 pixels of padding each).
	mmr32 P4, 0x04, SRC + 60 * 320
	mmr16 P4, 0x10, 1280
	mmr16 P4, 0x14, 2
	mmr32 P5, 0x04, DST
	mmr16 P5, 0x10, 160
	mmr16 P5, 0x14, 2
	mmr16 P5, 0x18, 8
	mmr16 P5, 0x1c, 2 + 16 * 2
	mmr16 P4, 0x08, DMAEN | WDSIZE_16 | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | WDSIZE_16 | DMA2D | DI_EN
	wait_done P5

	# dst[176 r + x] = q(x, 60 + r) for x < 160, padding untouched.
	ldc P0, DST
	ldc R1, 0x1234 + 60 * 1009
	ldc R4, 0xdead
	P1 = 8;
	LSETUP (1f, 6f) LC1 = P1;
1:	R0 = R1;
	P2 = 160;
	LSETUP (2f, 3f) LC0 = P2;
2:	R2 = W[P0++] (Z);
	R3 = R0.L (Z);
	CC = R2 == R3;
	IF !CC JUMP .Lfail;
3:	R0 += 37;
	P2 = 16;
	LSETUP (4f, 5f) LC0 = P2;
4:	R2 = W[P0++] (Z);
	CC = R2 == R4;
5:	IF !CC JUMP .Lfail;
6:	R1 = R1 + R5;

	chk32 P4, 0x24, SRC + 60 * 320 + 2560
	chk16 P4, 0x30, 0
	chk16 P4, 0x28, 0x0001
	# Last element at DST + 7*352 + 318, then X_MODIFY.
	chk32 P5, 0x24, DST + 7 * 352 + 320
	chk16 P5, 0x30, 0
	chk16 P5, 0x38, 1
	chk16 P5, 0x28, 0x0001

	# DMA_DONE is write-1-to-clear; clear it before starting again.
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1
	# b) every second pixel of every second row (rows 0, 2, 4, 6) - X_MODIFY 4 on
	# 16-bit elements, Y_MODIFY 2*320 - 316 = 324.
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 80
	mmr16 P4, 0x14, 4
	mmr16 P4, 0x18, 4
	mmr16 P4, 0x1c, 324
	mmr32 P5, 0x04, DST + 0x2000
	mmr16 P5, 0x10, 320
	mmr16 P5, 0x14, 2
	mmr16 P4, 0x08, DMAEN | WDSIZE_16 | DMA2D | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | WDSIZE_16 | DI_EN
	wait_done P5

	# dst[80 r + c] = q(2c, 2r).
	R6 = 74 (X);
	R7 = 2018 (X);
	ldc P0, DST + 0x2000
	ldc R1, 0x1234
	P1 = 4;
	LSETUP (1f, 4f) LC1 = P1;
1:	R0 = R1;
	P2 = 80;
	LSETUP (2f, 3f) LC0 = P2;
2:	R2 = W[P0++] (Z);
	R3 = R0.L (Z);
	CC = R2 == R3;
	IF !CC JUMP .Lfail;
3:	R0 = R0 + R6;
4:	R1 = R1 + R7;

	# Last source element at SRC + 6*320 + 316, then X_MODIFY.
	chk32 P4, 0x24, SRC + 6 * 320 + 320
	chk16 P4, 0x38, 1
	chk16 P4, 0x28, 0x0001
	chk32 P5, 0x24, DST + 0x2000 + 640
	chk16 P5, 0x28, 0x0001

	# DMA_DONE is write-1-to-clear; clear it before starting again.
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1
	# c) 32-bit elements, every second word of row 100 - X_MODIFY 8.
	mmr32 P4, 0x04, SRC + 100 * 320
	mmr16 P4, 0x10, 40
	mmr16 P4, 0x14, 8
	mmr32 P5, 0x04, DST + 0x3000
	mmr16 P5, 0x10, 40
	mmr16 P5, 0x14, 4
	mmr16 P4, 0x08, DMAEN | WDSIZE_32 | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | WDSIZE_32 | DI_EN
	wait_done P5

	# dst word i holds pixels 4i and 4i+1 of row 100 (little endian).
	R6 = 111 (X);
	ldc P0, DST + 0x3000
	ldc R0, 0x1234 + 100 * 1009
	P2 = 40;
	LSETUP (2f, 3f) LC0 = P2;
2:	R2 = W[P0++] (Z);
	R3 = R0.L (Z);
	CC = R2 == R3;
	IF !CC JUMP .Lfail;
	R0 += 37;
	R2 = W[P0++] (Z);
	R3 = R0.L (Z);
	CC = R2 == R3;
	IF !CC JUMP .Lfail;
3:	R0 = R0 + R6;

	chk32 P4, 0x24, SRC + 100 * 320 + 320
	chk16 P4, 0x28, 0x0001
	chk32 P5, 0x24, DST + 0x3000 + 160
	chk16 P5, 0x28, 0x0001

	dbg_pass
.Lfail:
	dbg_fail
