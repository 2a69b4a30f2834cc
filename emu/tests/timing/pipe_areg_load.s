# mach: bfin
# sim: --environment operating --timing bf537
# ld: -Ttext=0xffa00000 -Tdata=0xff800000

# Timing model (--timing bf537): a load into an address register, then a use of it in the
# address stage, stalls until the loaded value is there.
#
# Rule (sim/bfin/timing.c): GCC's Blackfin scheduler (gcc/config/bfin/bfin.cc,
# bfin_adjust_cost) gives a load into P/I/M/B/L/SP/FP latency 1 + 3: an address-stage use in
# the next instruction stalls 3 cycles, one after k unrelated single-cycle instructions
# stalls 3 - k (never below 0).  A data use of the pointer (R0 = P0) does not wait.
#
# Each block reads CYCLES before and after.  The difference is the cost of the first read
# (1 cycle: CYCLES is sampled before that instruction's own cycle is added) plus the
# instructions in between plus the stall.

	.include "testutils.inc"

	start

	/* CYCLES counts only with SYSCFG.CCEN (bit 1) set.  */
	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	loadsym P1, ptr;
	loadsym P2, ptr;
	nop; nop; nop; nop;

	/* 1. load P0, use it as an address at once:
	   1 (read) + 1 (load) + 1 (use) + 3 (stall) = 6.  The simulator alone: 3.  */
	R6 = CYCLES;
	P0 = [P1];
	R0 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 6;

	/* 2. two unrelated instructions between: the stall shrinks to 3 - 2 = 1:
	   1 + 1 + 2 + 1 + 1 = 6.  The simulator alone: 5.  */
	R6 = CYCLES;
	P0 = [P1];
	R1 = 1;
	R2 = 2;
	R0 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 6;

	/* 3. three unrelated instructions between: no stall left: 1 + 1 + 3 + 1 = 6.  */
	R6 = CYCLES;
	P0 = [P1];
	R1 = 1;
	R2 = 2;
	R3 = 3;
	R0 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 6;

	/* 4. the next instruction uses another pointer: no stall: 1 + 1 + 1 = 3.  */
	R6 = CYCLES;
	P0 = [P1];
	R0 = [P2];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 3;

	/* 5. pointer arithmetic on the loaded register is an address-stage use:
	   P0 += 4 right after the load: 1 + 1 + 1 + 3 = 6.  */
	R6 = CYCLES;
	P0 = [P1];
	P0 += 4;
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 6;

	/* 6. a data use of the loaded pointer does not wait: R0 = P0: 1 + 1 + 1 = 3.  */
	R6 = CYCLES;
	P0 = [P1];
	R0 = P0;
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 3;

	/* 7. an I register loaded by a pop, then used as an address by the next instruction:
	   1 + 1 (push) + 1 (pop) + 1 (use) + 3 = 7.  */
	loadsym I0, ptr;
	loadsym SP, stack_top;
	nop; nop; nop; nop;
	R6 = CYCLES;
	[--SP] = I0;
	I1 = [SP++];
	R0 = [I1];
	R7 = CYCLES;
	R7 = R7 - R6;
	CHECKREG R7, 7;

	dbg_pass

	.data
	.align 4
ptr:
	.long ptr
	.long ptr
stack:
	.space 64
stack_top:
