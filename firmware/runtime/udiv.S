/* ___udivsi3: unsigned 32-bit division, R0 = R0 / R1: the C compiler's helper for '/' on
 * unsigned ints, and (through libgcc's ___divsi3, ___modsi3 and ___umodsi3, which call it) for
 * signed division and both remainders. Defined here, the linker does not take libgcc's, which
 * runs a fixed 32 restoring steps (5 cycles each, some 170 cycles a call); this one runs only
 * the quotient's bits, k + 1 of them for k = clz(d) - clz(n), and returns 0 at once when d > n.
 * In the odometry's frame most quotients are short (a Q26 value over a Q16 one, a pixel count
 * over a pixel count). The result is the quotient by definition: the check divide
 * (harness/checks/divide.cpp) compares it with the host's division on edge and random pairs.
 * Division by zero (undefined in C) returns some value after at most 32 steps, never hangs.
 *
 * The convention of libgcc's Blackfin helper, which its ___umodsi3 relies on: the quotient in
 * R0 and the remainder in R3; clobbers R0-R3, P0, LC0/LT0/LB0 and ASTAT, as libgcc's does (the
 * compiler keeps no hardware loop across a call). Runs from SDRAM, cached, as its callers
 * (the C code) do. */
	.text
	.align 4
	.global ___udivsi3
	.type ___udivsi3, STT_FUNC
___udivsi3:
	cc = r1 <= r0 (iu);
	if !cc jump .Lud_zero;
	/* clz of n and of d: SIGNBITS of the value halved (bit 31 clear) is clz of the value,
	 * for every value but 0 (31, where clz is 32: only a zero divisor, which gets k + 1 = 32
	 * steps at most). */
	r2 = r0 >> 1;
	r2.l = signbits r2;
	r2 = r2.l (z);
	r3 = r1 >> 1;
	r3.l = signbits r3;
	r3 = r3.l (z);
	r3 = r3 - r2;                   /* k = clz(d) - clz(n) >= 0, as d <= n */
	r1 <<= r3;                      /* d aligned under n's top bit */
	r3 += 1;
	p0 = r3;
	r2 = 0;
	/* One quotient bit a step, from bit k down: subtract where it goes, shift it in. */
	lsetup (.Lud_step, .Lud_step_end) lc0 = p0;
.Lud_step:
	r3 = r0 - r1;
	cc = r1 <= r0 (iu);
	if cc r0 = r3;
	r2 = rot r2 by 1;
.Lud_step_end:
	r1 >>= 1;
	r3 = r0;                        /* the remainder */
	r0 = r2;
	rts;
.Lud_zero:
	r3 = r0;
	r0 = 0;
	rts;
	.size ___udivsi3, . - ___udivsi3
