# Speed benchmark of the simulator (not a test: not globbed by ctest).  Build and time:
#   bfin-elf-as -I SUITE alubench.s -o alubench.o && bfin-elf-ld alubench.o -o alubench.x
#   time bfin-elf-run [--timing none|bf537] alubench.x
# loads + ALU loop: 2M iterations x 8 instructions, data in the 128 MB virtual RAM
# mach: bfin
	.include "testutils.inc"
	start
	P0.L = 0; P0.H = 0x100;
	R0 = 1; R1 = 2;
	[P0] = R0; [P0+4] = R1;
	P1.L = 0x8480; P1.H = 0x1e;	/* 2000000 */
	LSETUP (1f, 2f) LC0 = P1;
1:	R2 = [P0];
	R3 = [P0 + 4];
	R4 = R2 + R3;
	R5 = R4 << 2;
	P2 = R2;
	R6 = R5 - R1;
	R7 = [P0++P2];
2:	P0 += -1;
	pass
