# mach: bfin
# sim: --environment operating --timing bf537 --timing-areg-consumers=all
# ld: -Ttext=0xffa00000 -Tdata=0xff800000

# Timing model (--timing bf537 --timing-areg-consumers=all): the address-register stalls
# charged to every read of the register, data uses too, as GCC's bfin_adjust_cost assumes
# (gcc/config/bfin/bfin.cc: it adds 3 after a load and 4 after a move from a data register
# into P/I/M/B/L/SP/FP whatever the dependant is).  With the default (dag) these data uses
# cost nothing: pipe_areg_load.s block 6.
#
# Each block: CYCLES difference = 1 (the first read) + the instructions between + stall.

	.include "testutils.inc"

	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	loadsym P1, ptr;
	loadsym R5, ptr;
	nop; nop; nop; nop;

	/* 1. load P0, copy it to a data register: 1 + 1 + 1 + 3 = 6 (dag: 3).  */
	R6 = CYCLES;
	P0 = [P1];
	R0 = P0;
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 6;

	/* 2. P0 = R5, then store P0 as data: 1 + 1 + 1 + 4 = 7 (dag: 3).  */
	R6 = CYCLES;
	P0 = R5;
	[P1 + 4] = P0;
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 7;

	/* 3. load P0, compare it one instruction later: 3 - 1 = 2 left:
	   1 + 1 + 1 + 1 + 2 = 6 (dag: 4).  */
	R6 = CYCLES;
	P0 = [P1];
	R1 = 1;
	CC = P0 == P1;
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 6;

	/* 4. an unrelated data use of another pointer: no stall: 1 + 1 + 1 = 3.  */
	R6 = CYCLES;
	P0 = [P1];
	R0 = P1;
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 3;

	dbg_pass

	.data
	.align 4
ptr:
	.long ptr
	.long ptr
