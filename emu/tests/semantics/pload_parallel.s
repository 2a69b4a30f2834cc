# mach: bfin

# A P-register based load in slot 1 and a store of the same D register in slot 2.
# All slots read their operands before any slot writes (Blackfin Processor Programming
# Reference, "Issuing Parallel Instructions"), so the store writes the D register's old value
# (the simulator wrote these loads at once: patch 0004). Expected values are worked out by
# hand below.

.include "testutils.inc"
	start

	# At 0x00F00000 (mapped memory of the virtual environment): three words, then zeros.
	imm32 P0, 0x00F00000;
	imm32 R0, 0xA1A2A3A4;
	[P0] = R0;
	imm32 R0, 0xB1B2B3B4;
	[P0 + 4] = R0;
	imm32 R0, 0xC1C2C3C4;
	[P0 + 8] = R0;
	R0 = 0;
	P0 += 12;
	P1 = 29;
	LSETUP (1f, 1f) LC0 = P1;
1:	[P0++] = R0;

	# 1. Post-increment load: R3 = word 0 = 0xA1A2A3A4, P1 += 4; slot 2 stores the old
	# R3 = 0x33333333 at base + 0x40.
	imm32 P1, 0x00F00000;
	imm32 I2, 0x00F00040;
	L2 = 0;
	imm32 R3, 0x33333333;
	MNOP || R3 = [P1++] || [I2] = R3;
	CHECKREG R3, 0xA1A2A3A4;
	CHECKREG P1, 0x00F00004;
	imm32 P2, 0x00F00040;
	R6 = [P2];
	CHECKREG R6, 0x33333333;

	# 2. Offset load: R3 = [base + 8] = 0xC1C2C3C4; the old R3 = 0x44444444 goes to
	# base + 0x44, I2 moves to base + 0x48.
	imm32 P1, 0x00F00000;
	imm32 I2, 0x00F00044;
	imm32 R3, 0x44444444;
	MNOP || R3 = [P1 + 8] || [I2++] = R3;
	CHECKREG R3, 0xC1C2C3C4;
	CHECKREG I2, 0x00F00048;
	imm32 P2, 0x00F00044;
	R6 = [P2];
	CHECKREG R6, 0x44444444;

	# 3. FP-relative load: FP = base + 12, R3 = [FP - 8] = word 1 = 0xB1B2B3B4; slot 2
	# stores the old R3.H = 0x5566 as a halfword at base + 0x48 (the word reads 0x00005566).
	imm32 FP, 0x00F0000C;
	imm32 R3, 0x55667788;
	MNOP || R3 = [FP - 8] || W[I2] = R3.H;
	CHECKREG R3, 0xB1B2B3B4;
	imm32 P2, 0x00F00048;
	R6 = [P2];
	CHECKREG R6, 0x00005566;

	# 4. Byte load, sign-extended: base + 3 holds 0xA1 (the top byte of the little-endian
	# word 0xA1A2A3A4), so R3 = 0xFFFFFFA1; the old R3 = 0x66666666 goes to base + 0x50.
	imm32 P1, 0x00F00003;
	imm32 I2, 0x00F00050;
	imm32 R3, 0x66666666;
	MNOP || R3 = B[P1] (X) || [I2] = R3;
	CHECKREG R3, 0xFFFFFFA1;
	imm32 P2, 0x00F00050;
	R6 = [P2];
	CHECKREG R6, 0x66666666;

	pass
