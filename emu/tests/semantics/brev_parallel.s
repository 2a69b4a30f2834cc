# mach: bfin

# Bit-reversed DAG update in a multi-issue instruction.
# All three slots of a multi-issue instruction read their operands before any slot writes, so a
# load through Ix in the same instruction as `Ix += Mx (BREV)` uses the old Ix (Blackfin
# Processor Programming Reference, "Issuing Parallel Instructions"; the bit-reversed FFT
# fetch `R6 = [I0] || I0 += M3 (BREV)` depends on it). Expected values are worked out below
# from that rule: bit-reversed addition adds with the carry running from the MSB towards the
# LSB.

.include "testutils.inc"
	start

	# Eight words at 0x00F00000 (mapped memory in the virtual environment): word k = 0x5A00 + k.
	imm32 P0, 0x00F00000;
	R0 = 0x5A00 (Z);
	P1 = 8;
	LSETUP (1f, 2f) LC0 = P1;
1:	[P0++] = R0;
2:	R0 += 1;

	# 1. The instruction from the issue. I0 = base + 0x18, M3 = 8: bit 3 is set in both, so
	# the sum's bit 3 is 0 and the carry goes down into bit 2: new I0 = base + 0x14. The load
	# reads the old I0 = base + 0x18, word 6 = 0x5A06. R7: each 16-bit half shifted
	# arithmetically by 2: 0x4000 >>> 2 = 0x1000, 0x8000 >>> 2 = 0xE000.
	imm32 I0, 0x00F00018;
	M3 = 8 (X);
	L0 = 0;
	imm32 R7, 0x40008000;
	imm32 R6, 0xDEADBEEF;
	R7 = R7 >>> 2 (V) || I0 += M3 (BREV) || R6 = [I0];
	CHECKREG R6, 0x00005A06;
	CHECKREG I0, 0x00F00014;
	CHECKREG R7, 0x1000E000;

	# 2. A carry that runs into bit 1: I0 = base + 0x0C, M3 = 4. Bit 2: 1 + 1 = 0, carry into
	# bit 1 (0 + 0 + 1 = 1): new I0 = base + 0x0A, which is not word aligned. Reading the new
	# I0 would raise a misaligned-access exception (the FFT's fault); the old I0 = base + 0x0C
	# holds word 3 = 0x5A03.
	imm32 I0, 0x00F0000C;
	M3 = 4 (X);
	R6 = 0;
	MNOP || I0 += M3 (BREV) || R6 = [I0];
	CHECKREG R6, 0x00005A03;
	CHECKREG I0, 0x00F0000A;

	# 3. A bit-reversed fetch of 8 words, as an FFT does: I0 starts at the base, M3 = 16
	# (half the buffer in bytes). I0 visits byte offsets 0, 16, 8, 24, 4, 20, 12, 28 and the
	# load in the same instruction reads the current I0 each time, so the words come out in
	# bit-reversed index order 0, 4, 2, 6, 1, 5, 3, 7. The last update, 28 + 16, carries out of
	# bits 4, 3 and 2 down into bit 1: I0 ends at offset 2. The copies go to 0x00F00040.
	imm32 I0, 0x00F00000;
	M3 = 16 (X);
	imm32 P0, 0x00F00040;
	P1 = 8;
	LSETUP (3f, 4f) LC0 = P1;
3:	MNOP || I0 += M3 (BREV) || R6 = [I0];
4:	[P0++] = R6;
	CHECKREG I0, 0x00F00002;
	imm32 P0, 0x00F00040;
	R0 = [P0++]; CHECKREG R0, 0x00005A00;
	R0 = [P0++]; CHECKREG R0, 0x00005A04;
	R0 = [P0++]; CHECKREG R0, 0x00005A02;
	R0 = [P0++]; CHECKREG R0, 0x00005A06;
	R0 = [P0++]; CHECKREG R0, 0x00005A01;
	R0 = [P0++]; CHECKREG R0, 0x00005A05;
	R0 = [P0++]; CHECKREG R0, 0x00005A03;
	R0 = [P0++]; CHECKREG R0, 0x00005A07;

	pass
