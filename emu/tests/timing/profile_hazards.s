# mach: bfin
# sim: --environment operating --timing bf537
# ld: -Ttext=0xFFA00000 -Tdata=0xFF806800

# A hand-made program with one hazard of each kind the profile names, each at a labelled
# instruction, for --timing-profile (emu/tests/timing/profile.sh checks that every cause is
# charged to exactly the instruction that has it, with the cycles the rules give, and that
# nothing else in the window stalls):
#   h_load_use  address-register load stall, P0 loaded just before:  areg_load 3 (reg P0)
#   h_move_use  address-register move stall, P2 = R1 just before:    areg_move 4 (reg P2)
#   h_coll      two loads of one bundle in one L1 sub-bank:           l1_collision 1
#   h_jump      a taken unconditional short jump (the simulator's 5): multicycle 4
#   h_mmr       a system MMR read (PLL_DIV):                          mmr > 0
#   h_loop      a 10-iteration hardware loop of one instruction:      count 10, no stall
# The window is [h_start, h_end): the set-up before it is not in the profile.

	.include "testutils.inc"

	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	CSYNC;
	loadsym P1, ptr;
	loadsym I0, words;
	loadsym I1, words;
	R1 = I0;
	I1 += 4;
	I1 += 4;
	P4.L = 0x0004;		/* PLL_DIV, a system MMR at 0xFFC00004 */
	P4.H = 0xFFC0;
	P5 = 10;
	NOP; NOP; NOP; NOP; NOP;

	.global h_start
h_start:
	R5 = 1;
	P0 = [P1];
	.global h_load_use
h_load_use:
	R0 = [P0];
	NOP; NOP; NOP; NOP;
	P2 = R1;
	.global h_move_use
h_move_use:
	R0 = [P2];
	NOP; NOP; NOP; NOP;
	.global h_coll
h_coll:
	MNOP || R2 = [I0] || R3 = [I1];
	.global h_jump
h_jump:
	JUMP.S 1f;
	NOP;
1:
	.global h_mmr
h_mmr:
	R4 = W[P4] (Z);
	LSETUP (2f, 2f) LC0 = P5;	/* local labels: a global one is not resolved by gas */
	.global h_loop
h_loop:
2:	R5 += 1;
	.global h_end
h_end:
	NOP;
	CHECKREG R5, 11;
	dbg_pass

	.data
	.align 4
ptr:	.long words
words:	.long 1, 2, 3, 4, 5, 6, 7, 8
