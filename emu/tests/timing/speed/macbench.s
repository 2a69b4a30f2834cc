# Speed benchmark of the simulator (not a test: not globbed by ctest).  Build and time:
#   bfin-elf-as -I SUITE macbench.s -o macbench.o && bfin-elf-ld macbench.o -o macbench.x
#   time bfin-elf-run [--timing none|bf537] macbench.x
# MAC-heavy loop: 2M iterations x 8 MAC/multiply instructions
# mach: bfin
	.include "testutils.inc"
	start
	R0 = 3; R1 = 5; R2 = 7; R3 = 9;
	A0 = 0; A1 = 0;
	P1.L = 0x8480; P1.H = 0x1e;	/* 2000000 */
	LSETUP (1f, 2f) LC0 = P1;
1:	A1 += R0.H * R1.L, A0 += R0.L * R1.L;
	R4 = (A0 += R2.L * R3.L);
	R5.H = (A1 += R2.H * R3.H), R5.L = (A0 += R2.L * R3.L);
	R6 = R0.L * R1.L;
	R6.H = R2.L * R3.H, R6.L = R2.H * R3.L;
	A0 -= R3.L * R0.L;
	R7 = A1, R6 = A0 (FU);
2:	A1 = R1.L * R2.L;
	pass
