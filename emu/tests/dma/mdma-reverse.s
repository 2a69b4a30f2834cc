# Memory DMA with negative and zero modifies (stream S1/D1, stop mode).
#  a) a band flipped upside down - source 2D from row 47 up to row 40 of a 160x120 8-bit
#     frame, X_MODIFY 1, Y_MODIFY 1 - 2*160 = -319.
#  b) a row mirrored, 16-bit elements - source X_MODIFY -2 from the row's last pixel pair.
#  c) a fill - a 32-bit source with X_MODIFY 0 repeated 256 times into SDRAM.
#  d) a row written mirrored - destination X_MODIFY -1.
# Every byte is checked against the frame's pattern p(x, y) = (5x + 11y + 7) & 0xff
# recomputed here, and the channels' CURR_ADDR (X_MODIFY applied after the last element
# too), CURR_Y_COUNT and IRQ_STATUS (ADSP-BF537 HRM, chapter 5, DMA registers).
# mach: bfin
# sim: --environment operating
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC, 0x00100000	/* 160x120 frame, 8 bits a pixel, in SDRAM */
	.equ DST, 0xFF800000	/* L1 data bank A */
	.equ FILL, 0x00400000	/* SDRAM */
	.equ MDMA_D1, 0xFFC00F80
	.equ MDMA_S1, 0xFFC00FC0
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ WDSIZE_16, 0x0004
	.equ WDSIZE_32, 0x0008
	.equ DMA2D, 0x0010
	.equ DI_EN, 0x0080

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

	ldc P5, MDMA_D1
	ldc P4, MDMA_S1

	# a) rows 47, 46, ... 40.
	mmr32 P4, 0x04, SRC + 47 * 160
	mmr16 P4, 0x10, 160
	mmr16 P4, 0x14, 1
	mmr16 P4, 0x18, 8
	mmr16 P4, 0x1c, 1 - 2 * 160
	mmr32 P5, 0x04, DST
	mmr16 P5, 0x10, 1280
	mmr16 P5, 0x14, 1
	mmr16 P4, 0x08, DMAEN | DMA2D | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | DI_EN
	wait_done P5

	# dst[160 r + x] = p(x, 47 - r).
	ldc P0, DST
	R1 = 47 * 11 + 7 (X);
	P1 = 8;
	LSETUP (1f, 4f) LC1 = P1;
1:	R0 = R1;
	P2 = 160;
	LSETUP (2f, 3f) LC0 = P2;
2:	R2 = B[P0++] (Z);
	R3 = R0.B (Z);
	CC = R2 == R3;
	IF !CC JUMP .Lfail;
3:	R0 += 5;
4:	R1 += -11;

	# Last element at SRC + 40*160 + 159, then X_MODIFY.
	chk32 P4, 0x24, SRC + 40 * 160 + 160
	chk16 P4, 0x30, 0
	chk16 P4, 0x38, 1
	chk16 P4, 0x28, 0x0001
	chk32 P5, 0x24, DST + 1280
	chk16 P5, 0x28, 0x0001

	# DMA_DONE is write-1-to-clear; clear it before starting again.
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1
	# b) row 10 as 80 pixel pairs, last pair first.
	mmr32 P4, 0x04, SRC + 10 * 160 + 158
	mmr16 P4, 0x10, 80
	mmr16 P4, 0x14, -2
	mmr32 P5, 0x04, DST + 0x800
	mmr16 P5, 0x10, 80
	mmr16 P5, 0x14, 2
	mmr16 P4, 0x08, DMAEN | WDSIZE_16 | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | WDSIZE_16 | DI_EN
	wait_done P5

	# dst bytes 2j, 2j+1 = p(158 - 2j, 10), p(159 - 2j, 10).
	ldc P0, DST + 0x800
	R0 = 10 * 11 + 158 * 5 + 7 (X);
	P2 = 80;
	LSETUP (2f, 3f) LC0 = P2;
2:	R2 = B[P0++] (Z);
	R3 = R0.B (Z);
	CC = R2 == R3;
	IF !CC JUMP .Lfail;
	R2 = B[P0++] (Z);
	R3 = R0;
	R3 += 5;
	R3 = R3.B (Z);
	CC = R2 == R3;
	IF !CC JUMP .Lfail;
3:	R0 += -10;

	# Last element at SRC + 10*160, then X_MODIFY -2.
	chk32 P4, 0x24, SRC + 10 * 160 - 2
	chk16 P4, 0x28, 0x0001
	chk32 P5, 0x24, DST + 0x800 + 160
	chk16 P5, 0x28, 0x0001

	# DMA_DONE is write-1-to-clear; clear it before starting again.
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1
	# c) 0x5aa5c33c 256 times.
	ldc P0, DST + 0xf00
	ldc R4, 0x5aa5c33c
	[P0] = R4;
	ldc P0, FILL
	R0 = 0;
	P1 = 258;
	LSETUP (1f, 1f) LC0 = P1;
1:	[P0++] = R0;
	mmr32 P4, 0x04, DST + 0xf00
	mmr16 P4, 0x10, 256
	mmr16 P4, 0x14, 0
	mmr32 P5, 0x04, FILL
	mmr16 P5, 0x10, 256
	mmr16 P5, 0x14, 4
	mmr16 P4, 0x08, DMAEN | WDSIZE_32 | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | WDSIZE_32 | DI_EN
	wait_done P5

	ldc P0, FILL
	P2 = 256;
	LSETUP (2f, 3f) LC0 = P2;
2:	R2 = [P0++];
	CC = R2 == R4;
3:	IF !CC JUMP .Lfail;
	# and not one more
	R2 = [P0];
	CC = R2 == 0;
	IF !CC JUMP .Lfail;

	chk32 P4, 0x24, DST + 0xf00
	chk16 P4, 0x30, 0
	chk16 P4, 0x28, 0x0001
	chk32 P5, 0x24, FILL + 1024
	chk16 P5, 0x28, 0x0001

	# DMA_DONE is write-1-to-clear; clear it before starting again.
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1
	# d) row 20 written from DST + 0x1000 + 159 down to DST + 0x1000.
	mmr32 P4, 0x04, SRC + 20 * 160
	mmr16 P4, 0x10, 160
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, DST + 0x1000 + 159
	mmr16 P5, 0x10, 160
	mmr16 P5, 0x14, -1
	mmr16 P4, 0x08, DMAEN | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | DI_EN
	wait_done P5

	# dst[0x1000 + 159 - x] = p(x, 20), read from the top down.
	ldc P0, DST + 0x1000 + 159
	R0 = 20 * 11 + 7 (X);
	P2 = 160;
	LSETUP (2f, 3f) LC0 = P2;
2:	R2 = B[P0--] (Z);
	R3 = R0.B (Z);
	CC = R2 == R3;
	IF !CC JUMP .Lfail;
3:	R0 += 5;

	chk32 P4, 0x24, SRC + 20 * 160 + 160
	chk32 P5, 0x24, DST + 0x1000 - 1
	chk16 P5, 0x28, 0x0001

	dbg_pass
.Lfail:
	dbg_fail
