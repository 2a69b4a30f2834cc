# Memory DMA of an 8-bit row band and of a tile out of a 160x120 frame in SDRAM into L1
# data bank A, the way a kernel brings its input in (stream S0/D0, stop mode).
#  a) rows 40..47, 160 bytes each - source 2D (X_COUNT 160, X_MODIFY 1, Y_COUNT 8,
#     Y_MODIFY 1), destination 1D (X_COUNT 1280) - source and destination with different
#     shapes.
#  b) a 64x8 tile at column 48 of rows 40..47 - source 2D with Y_MODIFY 160 - 64 + 1 = 97
#     jumping from the end of one row to the start of the next, destination 1D.
# Every byte is checked against the frame's pattern p(x, y) = (5x + 11y + 7) & 0xff,
# recomputed here; so are the channels' registers after the work unit - CURR_ADDR one
# X_MODIFY past the last element, CURR_X_COUNT 0, CURR_Y_COUNT 1 in 2D, IRQ_STATUS
# DMA_DONE (DI_EN is set) with DMA_RUN clear (ADSP-BF537 HRM, chapter 5, DMA registers).
# mach: bfin
# sim: --environment operating
# timeout: 20

	.include "testutils.inc"

	.include "mdma.inc"

	.equ SRC, 0x00100000	/* 160x120 frame, 8 bits a pixel, in SDRAM */
	.equ DST, 0xFF800000	/* L1 data bank A */
	.equ MDMA_D0, 0xFFC00F00
	.equ MDMA_S0, 0xFFC00F40
	/* CONFIG bits (ADSP-BF537 HRM, DMAx_CONFIG) */
	.equ DMAEN, 0x0001
	.equ WNR, 0x0002
	.equ DMA2D, 0x0010
	.equ DI_EN, 0x0080

	start

	# Fill the frame: p(x, y) = (5x + 11y + 7) & 0xff.
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

	# a) the band
	mmr32 P4, 0x04, SRC + 40 * 160
	mmr16 P4, 0x10, 160
	mmr16 P4, 0x14, 1
	mmr16 P4, 0x18, 8
	mmr16 P4, 0x1c, 1
	mmr32 P5, 0x04, DST
	mmr16 P5, 0x10, 1280
	mmr16 P5, 0x14, 1
	mmr16 P4, 0x08, DMAEN | DMA2D | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | DI_EN
	wait_done P5

	# Contents: dst[160 r + x] = p(x, 40 + r).
	ldc P0, DST
	R1 = 40 * 11 + 7 (X);
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
4:	R1 += 11;

	chk32 P4, 0x24, SRC + 40 * 160 + 1280
	chk16 P4, 0x30, 0
	chk16 P4, 0x38, 1
	chk16 P4, 0x28, 0x0001
	chk32 P5, 0x24, DST + 1280
	chk16 P5, 0x30, 0
	chk16 P5, 0x28, 0x0001

	# DMA_DONE is write-1-to-clear.
	mmr16 P4, 0x28, 1
	mmr16 P5, 0x28, 1
	chk16 P4, 0x28, 0
	chk16 P5, 0x28, 0

	# b) the tile, into DST + 0x800
	mmr32 P4, 0x04, SRC + 40 * 160 + 48
	mmr16 P4, 0x10, 64
	mmr16 P4, 0x14, 1
	mmr16 P4, 0x18, 8
	mmr16 P4, 0x1c, 97
	mmr32 P5, 0x04, DST + 0x800
	mmr16 P5, 0x10, 512
	mmr16 P5, 0x14, 1
	mmr16 P4, 0x08, DMAEN | DMA2D | DI_EN
	mmr16 P5, 0x08, DMAEN | WNR | DI_EN
	wait_done P5

	# dst[64 r + c] = p(48 + c, 40 + r).
	ldc P0, DST + 0x800
	R1 = 40 * 11 + 48 * 5 + 7 (X);
	P1 = 8;
	LSETUP (1f, 4f) LC1 = P1;
1:	R0 = R1;
	P2 = 64;
	LSETUP (2f, 3f) LC0 = P2;
2:	R2 = B[P0++] (Z);
	R3 = R0.B (Z);
	CC = R2 == R3;
	IF !CC JUMP .Lfail;
3:	R0 += 5;
4:	R1 += 11;

	# Last source element at SRC + 40*160 + 48 + 7*160 + 63, then X_MODIFY.
	chk32 P4, 0x24, SRC + 40 * 160 + 48 + 7 * 160 + 64
	chk16 P4, 0x30, 0
	chk16 P4, 0x38, 1
	chk16 P4, 0x28, 0x0001
	chk32 P5, 0x24, DST + 0x800 + 512
	chk16 P5, 0x28, 0x0001

	dbg_pass
.Lfail:
	dbg_fail
