# Memory DMA writing results back from L1 into a frame in SDRAM with a destination stride
# (stream S0/D0, stop mode).
#  a) a band of 32-bit results, 8 rows of 40 words, into columns 20..59 of a frame with
#     160-word rows - destination 2D with Y_MODIFY 4 + 120*4 = 484; the words around it
#     must stay untouched.
#  b) an 8x8 byte block written transposed - destination X_MODIFY 160 walks down a column
#     of a 160-byte-wide frame, Y_MODIFY 1 - 7*160 = -1119 goes back up to the top of the
#     next column.
# The results are a pattern made here (r(i) = 0x01020304 + 0x00010203 i, s(k) = 3k + 1) and
# every word and byte of the frame area is checked against it, as are the channels'
# CURR_ADDR and IRQ_STATUS (ADSP-BF537 HRM, chapter 5, DMA registers).
# mach: bfin
# sim: --environment operating
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC, 0xFF800000	/* results in L1 data bank A */
	.equ FRM, 0x00300000	/* frame of 160 words a row (a), 160 bytes a row (b), SDRAM */
	.equ MDMA_D0, 0xFFC00F00
	.equ MDMA_S0, 0xFFC00F40
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ WDSIZE_32, 0x0008
	.equ DMA2D, 0x0010
	.equ DI_EN, 0x0080

	start

	# Results r(i), i = 0..319, in L1.
	ldc P0, SRC
	ldc R0, 0x01020304
	ldc R5, 0x00010203
	P1 = 320;
	LSETUP (1f, 2f) LC0 = P1;
1:	[P0++] = R0;
2:	R0 = R0 + R5;

	# Clear 10 rows of the frame (rows 0..9, 160 words each).
	ldc P0, FRM
	R0 = 0;
	P1 = 1600;
	LSETUP (1f, 1f) LC0 = P1;
1:	[P0++] = R0;

	ldc P5, MDMA_D0
	ldc P4, MDMA_S0

	# a) rows 1..8, columns 20..59.
	mmr32 P4, 0x04, SRC
	mmr16 P4, 0x10, 320
	mmr16 P4, 0x14, 4
	mmr32 P5, 0x04, FRM + 160 * 4 + 20 * 4
	mmr16 P5, 0x10, 40
	mmr16 P5, 0x14, 4
	mmr16 P5, 0x18, 8
	mmr16 P5, 0x1c, 4 + 120 * 4
	mmr16 P4, 0x08, DMAEN | WDSIZE_32 | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | WDSIZE_32 | DMA2D | DI_EN
	wait_done P5

	# frame[y][x] = r(40 (y - 1) + x - 20) inside the band, 0 elsewhere (rows 0..9).
	ldc P0, FRM
	ldc R0, 0x01020304
	R4 = 0;
	P1 = 10;
	LSETUP (1f, 8f) LC1 = P1;
1:	P2 = 160;
	R6 = 0;			/* x */
	LSETUP (2f, 7f) LC0 = P2;
2:	R2 = [P0++];
	R3 = 0;
	# inside when 1 <= y <= 8 and 20 <= x <= 59
	CC = R4 == 0;
	IF CC JUMP 6f;
	R7 = 9;
	CC = R4 == R7;
	IF CC JUMP 6f;
	R7 = 20;
	CC = R6 < R7;
	IF CC JUMP 6f;
	R7 = 60 (X);
	CC = R6 < R7;
	IF !CC JUMP 6f;
	R3 = R0;
	R0 = R0 + R5;
6:	CC = R2 == R3;
	IF !CC JUMP .Lfail;
7:	R6 += 1;
8:	R4 += 1;

	chk32 P4, 0x24, SRC + 1280
	chk16 P4, 0x28, 0x0001
	# Last element at FRM + 8*640 + 59*4, then X_MODIFY.
	chk32 P5, 0x24, FRM + 8 * 640 + 60 * 4
	chk16 P5, 0x38, 1
	chk16 P5, 0x28, 0x0001

	# DMA_DONE is write-1-to-clear; clear it before starting again.
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1
	# b) s(k) = 3k + 1, k = 0..63, at SRC + 0x1000; frame of 160-byte rows at FRM + 0x2000.
	ldc P0, SRC + 0x1000
	R0 = 1;
	P1 = 64;
	LSETUP (1f, 2f) LC0 = P1;
1:	B[P0++] = R0;
2:	R0 += 3;
	ldc P0, FRM + 0x2000
	R0 = 0;
	P1 = 8 * 40;
	LSETUP (1f, 1f) LC0 = P1;
1:	[P0++] = R0;

	mmr32 P4, 0x04, SRC + 0x1000
	mmr16 P4, 0x10, 64
	mmr16 P4, 0x14, 1
	mmr32 P5, 0x04, FRM + 0x2000 + 100
	mmr16 P5, 0x10, 8
	mmr16 P5, 0x14, 160
	mmr16 P5, 0x18, 8
	mmr16 P5, 0x1c, 1 - 7 * 160
	mmr16 P4, 0x08, DMAEN | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | DMA2D | DI_EN
	wait_done P5

	# frame[i][100 + j] = s(8j + i) for i, j < 8, the rest of the 8 rows 0.
	ldc P0, FRM + 0x2000
	R4 = 0;			/* row i */
	P1 = 8;
	LSETUP (1f, 8f) LC1 = P1;
1:	P2 = 160;
	R6 = 0;			/* column */
	LSETUP (2f, 7f) LC0 = P2;
2:	R2 = B[P0++] (Z);
	R3 = 0;
	R7 = 100 (X);
	R1 = R6 - R7;		/* j */
	CC = R1 < 0;
	IF CC JUMP 6f;
	R7 = 8;
	CC = R1 < R7;
	IF !CC JUMP 6f;
	R1 <<= 3;
	R1 = R1 + R4;		/* k = 8j + i */
	R3 = R1 + R1;
	R3 = R3 + R1;
	R3 += 1;		/* 3k + 1 */
6:	CC = R2 == R3;
	IF !CC JUMP .Lfail;
7:	R6 += 1;
8:	R4 += 1;

	chk32 P4, 0x24, SRC + 0x1000 + 64
	# Last element (i 7, j 7) at FRM + 0x2000 + 100 + 7*160 + 7, then X_MODIFY.
	chk32 P5, 0x24, FRM + 0x2000 + 100 + 7 * 160 + 7 + 160
	chk16 P5, 0x30, 0
	chk16 P5, 0x38, 1
	chk16 P5, 0x28, 0x0001

	dbg_pass
.Lfail:
	dbg_fail
