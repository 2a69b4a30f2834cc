# mach: bfin
# sim: --environment operating --timing bf537
# ld: -Ttext=0xFFA00000 -Tdata=0xFF806800

# BF537 timing model, L1 data memory: two data accesses of one multi-issue instruction that
# hit the same 4 KB sub-bank of one L1 data bank cost one extra cycle, unless they are in the
# same 32-bit word; the 4 KB scratchpad is one sub-bank (timing-mem.c, l1_collision_cycles).
#
# Each measurement times a 10-iteration hardware loop of one bundle between two CYCLES reads,
# once with the two pointers in different sub-banks (the reference) and once in the case
# under test; the code is the same, only the addresses differ, so every other cost (base
# cycles, pipeline stalls) cancels and the difference is the memory model's alone:
#   same sub-bank, different words:  10 iterations x 1 stall = 10
#   load + store, same sub-bank:     10 x 1                  = 10
#   bank A and bank B:               0 (different banks never collide)
#   same 32-bit word:                0
#   scratchpad, two words:           10 x 1                  = 10
# With --timing none every difference is 0, so each check fails.

	.include "testutils.inc"

	start

	/* CYCLES counts only with SYSCFG.CCEN set.  */
	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	CSYNC;
	P1 = 10;

	/* time: R7 = cycles of 10 x "R0 = [I0++] || R1 = [I1++]" from I0, I1 (set by caller).
	   NOPs keep the pointer writes away from their use, so no pipeline stall lands inside
	   the timed window.  */
	.macro time_loads
	NOP; NOP; NOP; NOP; NOP;
	R6 = CYCLES;
	LSETUP (1f, 1f) LC0 = P1;
1:	MNOP || R0 = [I0++] || R1 = [I1++];
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm

	.macro time_load_store
	NOP; NOP; NOP; NOP; NOP;
	R6 = CYCLES;
	LSETUP (1f, 1f) LC0 = P1;
1:	MNOP || R0 = [I0++] || [I1++] = R1;
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm

	.macro time_same_word
	NOP; NOP; NOP; NOP; NOP;
	R6 = CYCLES;
	LSETUP (1f, 1f) LC0 = P1;
1:	MNOP || R0.L = W[I0] || R1.L = W[I1];
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm

	/* Reference: bank A sub-bank 0 and bank A sub-bank 1.  */
	imm32 I0, 0xFF800000;
	imm32 I1, 0xFF801000;
	time_loads
	R5 = R7;

	/* Same sub-bank 0 of bank A, different words: +10.  */
	imm32 I0, 0xFF800000;
	imm32 I1, 0xFF800100;
	time_loads
	R7 = R7 - R5;
	CHECKREG R7, 10;

	/* Same sub-bank 7 of bank B: +10.  */
	imm32 I0, 0xFF907000;
	imm32 I1, 0xFF907F00;
	time_loads
	R7 = R7 - R5;
	CHECKREG R7, 10;

	/* Bank A sub-bank 2 and bank B sub-bank 2: different banks, +0.  */
	imm32 I0, 0xFF802000;
	imm32 I1, 0xFF902000;
	time_loads
	R7 = R7 - R5;
	CHECKREG R7, 0;

	/* Scratchpad, two words: one sub-bank, +10.  */
	imm32 I0, 0xFFB00000;
	imm32 I1, 0xFFB00800;
	time_loads
	R7 = R7 - R5;
	CHECKREG R7, 10;

	/* Load and store in one sub-bank: +10; reference in two sub-banks first.  */
	imm32 I0, 0xFF803000;
	imm32 I1, 0xFF804000;
	time_load_store
	R5 = R7;
	imm32 I0, 0xFF803000;
	imm32 I1, 0xFF803800;
	time_load_store
	R7 = R7 - R5;
	CHECKREG R7, 10;

	/* Two halfword loads from one 32-bit word: +0; from two words of the sub-bank: +10.  */
	imm32 I0, 0xFF805000;
	imm32 I1, 0xFF806000;
	time_same_word
	R5 = R7;
	imm32 I0, 0xFF805000;
	imm32 I1, 0xFF805002;
	time_same_word
	R4 = R7 - R5;
	CHECKREG R4, 0;
	imm32 I0, 0xFF805000;
	imm32 I1, 0xFF805004;
	time_same_word
	R7 = R7 - R5;
	CHECKREG R7, 10;

	dbg_pass
