# mach: bfin
# sim: --environment operating --timing bf537
# ld: -Ttext=0xffa00000 -Tdata=0xff800000

# Timing model (--timing bf537): a move from a data register into an address register, then
# a use of it in the address stage, stalls.
#
# Rule (sim/bfin/timing.c): GCC's Blackfin scheduler (gcc/config/bfin/bfin.cc,
# bfin_adjust_cost) gives a move from a data register into P/I/M/B/L/SP/FP latency 1 + 4:
# an address-stage use in the next instruction stalls 4 cycles, one after k unrelated
# single-cycle instructions stalls 4 - k.  A move from another address register or an
# immediate load does not.
#
# Each block: CYCLES difference = 1 (the first read) + the instructions between + stall.

	.include "testutils.inc"

	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	loadsym R5, buf;
	loadsym P4, buf;
	R4 = 1;
	nop; nop; nop; nop;

	/* 1. P0 = R5, then a load through P0: 1 + 1 + 1 + 4 = 7.  The simulator alone: 3.  */
	R6 = CYCLES;
	P0 = R5;
	R0 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 7;

	/* 2. the per-pixel index of hs_prepare: p0 = r4; p0 = p4 + (p0 << 2), the shift-add
	   being pointer arithmetic: 1 + 1 + 1 + 4 = 7.  */
	R6 = CYCLES;
	P0 = R4;
	P0 = P4 + (P0 << 2);
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 7;

	/* 3. three unrelated instructions between: 4 - 3 = 1 left: 1 + 1 + 3 + 1 + 1 = 7.  */
	R6 = CYCLES;
	P0 = R5;
	R1 = 1;
	R2 = 2;
	R3 = 3;
	R0 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 7;

	/* 4. four between: no stall: 1 + 1 + 4 + 1 = 7.  */
	R6 = CYCLES;
	P0 = R5;
	R1 = 1;
	R2 = 2;
	R3 = 3;
	R1 = 4;
	R0 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 7;

	/* 5. the source is an address register, not a data register: P0 = P4, no stall:
	   1 + 1 + 1 = 3.  */
	R6 = CYCLES;
	P0 = P4;
	R0 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 3;

	/* 6. an I register from a data register, then I0 += M0 (a DAG modify):
	   1 + 1 + 1 + 4 = 7.  */
	M0 = 0 (X);
	nop; nop; nop; nop;
	R6 = CYCLES;
	I0 = R5;
	I0 += M0;
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 7;

	/* 7. the stall is charged once: a second use right after the first pays nothing more:
	   1 + 1 + 1 + 4 + 1 = 8.  */
	R6 = CYCLES;
	P0 = R5;
	R0 = [P0];
	R1 = [P0 + 4];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 8;

	dbg_pass

	.data
	.align 4
buf:
	.long 0, 0, 0, 0
