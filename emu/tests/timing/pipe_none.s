# mach: bfin
# sim: --environment operating --timing none
# ld: -Ttext=0xffa00000 -Tdata=0xff800000

# Timing model off (--timing none): the pipeline part changes nothing; every count is the
# simulator's own (1 per instruction, push multiple 14 and pop multiple 11 whatever the
# count: sim/bfin/bfin-sim.c decode_PushPopMultiple_0).  The same sequences as
# pipe_areg_load.s, pipe_areg_move.s and pipe_pushpop.s, with the counts worked out from
# those base costs alone.
#
# Each block: CYCLES difference = 1 (the first read) + the instructions between.

	.include "testutils.inc"

	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	loadsym P1, ptr;
	loadsym R5, ptr;
	loadsym SP, stack_top;
	nop; nop; nop; nop;

	/* load P0, use at once: 1 + 1 + 1 = 3 (bf537: 6).  */
	R6 = CYCLES;
	P0 = [P1];
	R0 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 3;

	/* P0 = R5, use at once: 1 + 1 + 1 = 3 (bf537: 7).  */
	R6 = CYCLES;
	P0 = R5;
	R0 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 3;

	/* push 6 registers: 1 + 14 = 15 (bf537: 7).  */
	R6 = CYCLES;
	[--SP] = (R7:5, P5:3);
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 15;

	/* pop 5 and one more instruction: 1 + 11 + 1 = 13 (bf537: 7).  */
	R0 = CYCLES;
	(R7:6, P5:3) = [SP++];
	R2 = 0;
	R1 = CYCLES;
	R1 = R1 - R0;
	CHECKREG R1, 13;
	R0 = [SP++];

	/* push P5 alone, pop it and use it: 1 + 14 = 15, then 1 + 11 + 1 = 13
	   (bf537: 2, then 6).  */
	loadsym P5, ptr;
	R6 = CYCLES;
	[--SP] = (P5:5);
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 15;
	R6 = CYCLES;
	(P5:5) = [SP++];
	R0 = [P5];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 13;

	dbg_pass

	.data
	.align 4
ptr:
	.long ptr
	.long ptr
stack:
	.space 64
stack_top:
