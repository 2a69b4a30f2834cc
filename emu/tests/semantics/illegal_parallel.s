# mach: bfin
# sim: --environment operating

# Illegal multi-issue combinations raise EXCAUSE 0x22 (illegal instruction combination) and
# change nothing: not the registers slot 0 writes (D, accumulator, ASTAT), not the memory a
# store would write. Rules: Blackfin Processor Programming Reference, "Issuing Parallel
# Instructions" (one store at most; the two 16-bit slots may not modify one I register or
# load one D register; SEARCH only with a load through P0 and a NOP; slot 1 holds a load,
# store or DAG op).
# The assembler refuses these, so they are written as halfwords. The EVT3 handler counts the
# exceptions in R7 (after checking EXCAUSE) and returns past the 8-byte instruction; it uses
# R5, R6 and P4.

.include "testutils.inc"
	start

	imm32 P0, 0xFFE0200C;	/* EVT3 */
	R0.L = xhandler;
	R0.H = xhandler;
	[P0] = R0;
	R0.L = 1f;
	R0.H = 1f;
	RETI = R0;
	RTI;			/* on to 1f in user mode */
1:
	# L1 data at 0xFF800000: word 0 = 0x0000AAAA, word 0x10 = 0x0000BBBB.
	imm32 P1, 0xFF800000;
	imm32 I2, 0xFF800010;
	L1 = 0; L2 = 0; B1 = 0; B2 = 0;
	R0.L = 0xAAAA; R0.H = 0;
	[P1] = R0;
	R0.L = 0xBBBB;
	[P1 + 0x10] = R0;
	imm32 R0, 0x10203040;
	imm32 R1, 0x7FFFFFFF;
	imm32 R2, 0x7FFFFFFF;
	imm32 R3, 0x33333333;
	imm32 R4, 0x44444444;
	imm32 I1, 0xFF800020;
	M1 = 8;
	A0 = 0;
	R5 = 0;
	ASTAT = R5;
	R7 = 0;

	# 1. A0 = R0 || [P1] = R3 || [I2] = R4: two stores.
	.short 0xCC09, 0x2000, 0x930B, 0x9F14;
	CHECKREG R7, 1;
	R6 = [P1];
	CHECKREG R6, 0x0000AAAA;
	R6 = [P1 + 0x10];
	CHECKREG R6, 0x0000BBBB;
	R6 = A0.W;
	CHECKREG R6, 0;

	# 2. A0 = R0 || I1 += M1 || R4 = [I1++]: I1 modified by both 16-bit slots.
	.short 0xCC09, 0x2000, 0x9E65, 0x9C0C;
	CHECKREG R7, 2;
	CHECKREG I1, 0xFF800020;
	CHECKREG R4, 0x44444444;

	# 3. A0 = R0 || R3 = [P1] || R3 = [I2]: R3 loaded by both.
	.short 0xCC09, 0x2000, 0x910B, 0x9D13;
	CHECKREG R7, 3;
	CHECKREG R3, 0x33333333;

	# 4. (R0, R1) = SEARCH R2 (GT) || [P1] = R3 || NOP: SEARCH with a store.
	.short 0xCC0D, 0x0210, 0x930B, 0x0000;
	CHECKREG R7, 4;
	CHECKREG R0, 0x10203040;
	CHECKREG R1, 0x7FFFFFFF;
	R6 = [P1];
	CHECKREG R6, 0x0000AAAA;

	# 5. A0 = R0 || RAISE 15 || NOP: program control in slot 1; A0 keeps its old value.
	.short 0xCC09, 0x2000, 0x009F, 0x0000;
	CHECKREG R7, 5;
	R6 = A0.W;
	CHECKREG R6, 0;

	# 6. R5 = R1 + R2 (S) || [P1] = R3 || [I2] = R4: two stores after a saturating add,
	# whose result (0x7FFFFFFF) and ASTAT (V, VS set) must not appear.
	.short 0xCC04, 0x2A0A, 0x930B, 0x9F14;
	CHECKREG R7, 6;
	CHECKREG R5, 0;
	R6 = ASTAT;
	CHECKREG R6, 0;

	# 7. (R0, R1) = SEARCH R2 (GT) || R4 = [P1++] || NOP: SEARCH goes only with a load
	# through P0 (PRM text quoted in the simulator's decode_dsp32alu_0).
	.short 0xCC0D, 0x0210, 0x900C, 0x0000;
	CHECKREG R7, 7;
	CHECKREG P1, 0xFF800000;
	CHECKREG R4, 0x44444444;

	# 8. Legal: (R0, R1) = SEARCH R2 (GT) || R4 = [P0++] || NOP.
	imm32 P0, 0xFF800010;
	(R0, R1) = SEARCH R2 (GT) || R4 = [P0++] || NOP;
	CHECKREG R7, 7;
	CHECKREG R4, 0x0000BBBB;
	CHECKREG P0, 0xFF800014;

	# 9. Legal: A0 = R0 || R3 = [P1] || R4 = [I2] runs without an exception.
	imm32 R0, 0x10203040;
	A0 = R0 || R3 = [P1] || R4 = [I2];
	CHECKREG R7, 7;
	CHECKREG R3, 0x0000AAAA;
	CHECKREG R4, 0x0000BBBB;
	R6 = A0.W;
	CHECKREG R6, 0x10203040;

	dbg_pass;

xhandler:
	# Only EXCAUSE 0x22 is expected; anything else fails the test. ASTAT is kept in P4:
	# the compare and the count change it.
	P4 = ASTAT;
	R6 = SEQSTAT;
	R5 = 0x3F;
	R6 = R6 & R5;
	R5 = 0x22;
	CC = R6 == R5;
	IF !CC JUMP 9f;
	R7 += 1;
	R6 = RETX;
	R6 += 8;
	RETX = R6;
	R5 = 0;
	ASTAT = P4;
	RTX;
9:	dbg_fail;
