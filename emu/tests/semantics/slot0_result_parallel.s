# mach: bfin

# The 32-bit slot's result and the 16-bit slots of one multi-issue instruction.
# All slots read their operands before any slot writes (Blackfin Processor Programming
# Reference, "Issuing Parallel Instructions"), so a store in slot 1 or 2 of the D register
# that slot 0 writes stores the old value. These are 32-bit ALU ops that the simulator wrote
# at once (patch 0003). Expected values are worked out by hand below.

.include "testutils.inc"
	start

	# 16 zero words at 0x00F00000 (mapped memory of the virtual environment).
	imm32 P0, 0x00F00000;
	R0 = 0;
	P1 = 16;
	LSETUP (1f, 1f) LC0 = P1;
1:	[P0++] = R0;

	# 1. Saturating add: 0x7FFF0000 + 0x00020000 overflows, so R0 = 0x7FFFFFFF; the store
	# in slot 1 writes the old R0 = 0x12345678 to base + 0x00.
	imm32 P1, 0x00F00000;
	imm32 R0, 0x12345678;
	imm32 R1, 0x7FFF0000;
	imm32 R2, 0x00020000;
	R0 = R1 + R2 (S) || [P1] = R0 || NOP;
	CHECKREG R0, 0x7FFFFFFF;
	R6 = [P1];
	CHECKREG R6, 0x12345678;

	# 2. MAX (5, -3) = 5 into R0; slot 2 stores the old R0 = 0x0BADF00D at base + 0x10.
	imm32 I2, 0x00F00010;
	imm32 R0, 0x0BADF00D;
	R1 = 5;
	R2 = -3;
	R0 = MAX (R1, R2) || NOP || [I2] = R0;
	CHECKREG R0, 0x00000005;
	imm32 P2, 0x00F00010;
	R6 = [P2];
	CHECKREG R6, 0x0BADF00D;

	# 3. The three-slot shape: vector add into R5 (0x00010002 +|+ 0x00030004 = 0x00040006),
	# I1 += M1 and a halfword store of R5.L through I1. The store uses the old I1
	# (base + 0x20) and the old R5.L (0x5555); I1 ends at base + 0x24.
	imm32 I1, 0x00F00020;
	M1 = 4;
	L1 = 0;
	imm32 R5, 0xAAAA5555;
	imm32 R1, 0x00010002;
	imm32 R2, 0x00030004;
	R5 = R1 +|+ R2 || I1 += M1 || W[I1] = R5.L;
	CHECKREG R5, 0x00040006;
	CHECKREG I1, 0x00F00024;
	imm32 P2, 0x00F00020;
	R6 = [P2];
	CHECKREG R6, 0x00005555;

	# 4. A half write: R0.H = R1.L + R2.H = 3 + 4 = 7, R0.L stays 0x2222; the post-increment
	# store writes the old R0 = 0x11112222 at base + 0x30 and P1 moves on by 4.
	imm32 P1, 0x00F00030;
	imm32 R0, 0x11112222;
	imm32 R1, 0x00000003;
	imm32 R2, 0x00040000;
	R0.H = R1.L + R2.H (NS) || [P1++] = R0 || NOP;
	CHECKREG R0, 0x00072222;
	CHECKREG P1, 0x00F00034;
	imm32 P2, 0x00F00030;
	R6 = [P2];
	CHECKREG R6, 0x11112222;

	pass
