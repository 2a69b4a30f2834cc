/* The checked-call trampoline: calls a kernel with up to 12 word arguments, counts its cycles,
 * arms the watchdog, and checks that it kept the ABI: R4-R7, P3-P5, FP and SP preserved, L0-L3
 * zero. Each callee-saved register enters the kernel holding a canary value (runtime.h) and must
 * come back with it. The cycles between the two CYCLES reads include a fixed overhead (the store,
 * CALL, RTS), measured once by calling bvb_null the same way and subtracted by the monitor. */
#include "runtime.h"
#include "bvb/mailbox.h"

#define IMM32(reg, val) reg##.l = ((val) & 0xFFFF); reg##.h = (((val) >> 16) & 0xFFFF)
/* Set bit N of R3 unless CC; CC is the outcome of "register equals its canary". */
#define FLAG_UNLESS_CC(n) if cc jump 1f; bitset (r3, n); 1:

	.section .l1.text, "ax"
	.align 4
	.global _bvb_call
	.type _bvb_call, STT_FUNC
_bvb_call:
	[--sp] = (r7:4, p5:3);
	[--sp] = fp;
	[--sp] = rets;
	p0.l = _bvb_call_state; p0.h = _bvb_call_state;
	[p0 + ST_CALL] = r0;
	[p0 + ST_MONITOR_SP] = sp;
	r1 = BVB_OK (z);
	[p0 + ST_STATUS] = r1;
	p1 = r0;

	/* Outgoing arguments: 12 bytes the callee may use for R0-R2, then args[3..11]. */
	sp += -48;
	p2 = sp;
	p2 += 12;
	p3 = p1;
	p3 += CALL_ARGS + 12;
	p4 = 9;
	lsetup (.Lcopy0, .Lcopy1) lc0 = p4;
.Lcopy0: r1 = [p3++];
.Lcopy1: [p2++] = r1;
	[p0 + ST_EXPECT_SP] = sp;

	/* Arm the watchdog: the core timer counts the call's cycles down from the limit. */
	IMM32(p2, TSCALE);
	r1 = 0;
	[p2] = r1;
	IMM32(p2, TCOUNT);
	r1 = [p1 + CALL_LIMIT];
	[p2] = r1;
	IMM32(p2, TCNTL);
	r1 = TMPWR | TMREN (z);
	r2 = 1;
	[p0 + ST_IN_CALL] = r2;
	[p2] = r1;

	r0 = [p1 + CALL_ARGS + 0];
	r1 = [p1 + CALL_ARGS + 4];
	r2 = [p1 + CALL_ARGS + 8];
	p1 = [p1 + CALL_FN];
	p2 = p0;
	p2 += ST_T0;
	IMM32(r4, CANARY_R4);
	IMM32(r5, CANARY_R5);
	IMM32(r6, CANARY_R6);
	IMM32(r7, CANARY_R7);
	IMM32(p3, CANARY_P3);
	IMM32(p4, CANARY_P4);
	IMM32(p5, CANARY_P5);
	IMM32(fp, CANARY_FP);
	/* bvb_call_t0/t1 mark the two reads: bfbench profile records the instructions from the
	 * first up to the second (bfin-elf-run --timing-profile-window), which are exactly the
	 * cycles the difference counts. */
	.global _bvb_call_t0
_bvb_call_t0:
	r3 = cycles;
	[p2] = r3;
	call (p1);
	.global _bvb_call_t1
_bvb_call_t1:
	r3 = cycles;

	/* Disarm before anything else, then leave the call. */
	IMM32(p2, TCNTL);
	r1 = TMPWR (z);
	[p2] = r1;
	p0.l = _bvb_call_state; p0.h = _bvb_call_state;
	r1 = 0;
	[p0 + ST_IN_CALL] = r1;
	p1 = [p0 + ST_CALL];
	[p1 + CALL_RET] = r0;
	r2 = [p0 + ST_T0];
	r3 = r3 - r2;
	[p1 + CALL_CYCLES] = r3;

	r3 = 0;
	IMM32(r2, CANARY_R4); cc = r4 == r2; FLAG_UNLESS_CC(0)
	IMM32(r2, CANARY_R5); cc = r5 == r2; FLAG_UNLESS_CC(1)
	IMM32(r2, CANARY_R6); cc = r6 == r2; FLAG_UNLESS_CC(2)
	IMM32(r2, CANARY_R7); cc = r7 == r2; FLAG_UNLESS_CC(3)
	r1 = p3; IMM32(r2, CANARY_P3); cc = r1 == r2; FLAG_UNLESS_CC(4)
	r1 = p4; IMM32(r2, CANARY_P4); cc = r1 == r2; FLAG_UNLESS_CC(5)
	r1 = p5; IMM32(r2, CANARY_P5); cc = r1 == r2; FLAG_UNLESS_CC(6)
	r1 = fp; IMM32(r2, CANARY_FP); cc = r1 == r2; FLAG_UNLESS_CC(7)
	r1 = sp; r2 = [p0 + ST_EXPECT_SP]; cc = r1 == r2; FLAG_UNLESS_CC(8)
	r2 = 0;
	r1 = l0; cc = r1 == r2; FLAG_UNLESS_CC(9)
	r1 = l1; cc = r1 == r2; FLAG_UNLESS_CC(10)
	r1 = l2; cc = r1 == r2; FLAG_UNLESS_CC(11)
	r1 = l3; cc = r1 == r2; FLAG_UNLESS_CC(12)
	[p1 + CALL_ABI] = r3;

.Lleave:
	/* Also the way back from an abandoned call: put the monitor's state back whatever the
	 * kernel did to it, including circular buffers and hardware loops left running. */
	p0.l = _bvb_call_state; p0.h = _bvb_call_state;
	sp = [p0 + ST_MONITOR_SP];
	r0 = [p0 + ST_STATUS];
	r1 = 0;
	l0 = r1; l1 = r1; l2 = r1; l3 = r1;
	lc0 = r1; lc1 = r1;
	rets = [sp++];
	fp = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;
	.size _bvb_call, . - _bvb_call

/* Where the fault and watchdog handlers resume the monitor (at IVG15). */
	.align 4
	.global _bvb_call_abandon
	.type _bvb_call_abandon, STT_FUNC
_bvb_call_abandon:
	jump .Lleave;
	.size _bvb_call_abandon, . - _bvb_call_abandon

/* The empty kernel: its cycles through _bvb_call are the call overhead. */
	.align 4
	.global _bvb_null
	.type _bvb_null, STT_FUNC
_bvb_null:
	rts;
	.size _bvb_null, . - _bvb_null

	.section .l1.bss.a, "aw", @nobits
	.align 4
	.global _bvb_call_state
_bvb_call_state:
	.space 32
