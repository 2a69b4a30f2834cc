# mach: bfin
# sim: --environment operating --timing bf537
# ld: -Ttext=0xffa00000 -Tdata=0xff800000

# Timing model (--timing bf537): push and pop multiple take one cycle per register.
#
# Rule (sim/bfin/timing.c): ADI EE-171 ("Push Multiple/Pop Multiple"): these instructions
# take n cycles, n the number of registers pushed or popped (its examples: 14 for
# [--SP] = (R7:0, P5:0), 11 for (R7:0, P5:3) = [SP++]).  The simulator alone charges 14 for
# every push multiple and 11 for every pop multiple.  P registers popped are loads into
# address registers: an address-stage use right after the pop stalls 3 (GCC bfin_adjust_cost).
#
# Each block: CYCLES difference = 1 (the first read) + the instructions between + stall.

	.include "testutils.inc"

	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	loadsym SP, stack_top;
	loadsym P5, buf;
	nop; nop; nop; nop;

	/* 1. push 3 + 3 = 6 registers: 1 + 6 = 7 (the simulator alone: 1 + 14 = 15).  */
	R6 = CYCLES;
	[--SP] = (R7:5, P5:3);
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 7;

	/* 2. pop 2 + 3 = 5 of them back, use none: 1 + 5 + 1 = 7 (alone: 1 + 11 + 1 = 13).
	   R7 and R6 are popped, so the count goes through R0, R1.  */
	R0 = CYCLES;
	(R7:6, P5:3) = [SP++];
	R2 = 0;
	R1 = CYCLES;
	R1 = R1 - R0;
	CHECKREG R1, 7;
	R0 = [SP++];

	/* 3. push 1 register: 1 + 1 = 2 (alone: 15).  */
	R6 = CYCLES;
	[--SP] = (P5:5);
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 2;

	/* 4. pop it and use P5 as an address right away: 1 + 1 + 1 + 3 (load into an address
	   register) = 6.  */
	R6 = CYCLES;
	(P5:5) = [SP++];
	R0 = [P5];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 6;

	/* 5. EE-171's own examples, which the simulator's fixed costs come from: pushing all
	   14 registers: 1 + 14 = 15; popping 11 (the start count kept in I0, an address
	   register the pop does not touch; I0 = R0 is not used in an address): 1 + 1 + 11 = 13.
	   Then drop the remaining 3 words.  */
	R6 = CYCLES;
	[--SP] = (R7:0, P5:0);
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 15;
	R0 = CYCLES;
	I0 = R0;
	(R7:0, P5:3) = [SP++];
	R1 = CYCLES;
	R0 = I0;
	R1 = R1 - R0;
	CHECKREG R1, 13;
	SP += 12;

	dbg_pass

	.data
	.align 4
buf:
	.long 0, 0, 0, 0
stack:
	.space 256
stack_top:
