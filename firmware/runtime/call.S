/* The checked-call trampoline: calls a kernel with up to 12 word arguments, counts its cycles,
 * arms the watchdog, and checks that it kept the ABI: R4-R7, P3-P5, FP and SP preserved, L0-L3
 * zero, no hardware loop of its own left counting. As checkasm does, the call is adversarial:
 * each callee-saved register enters holding a canary drawn from the canary seed and must come
 * back with it; every caller-saved register the ABI leaves undefined on entry holds junk drawn
 * from the call's junk seed (R0-R2 and stack slots beyond the kernel's arguments are junk from
 * the monitor, runtime/main.c), so a kernel that reads a register it never set sees garbage.
 * P1 holds the kernel's own address (the CALL needs it in a register). L0-L3 enter zero, as the
 * ABI promises every callee. The junk goes in before the first CYCLES read, so it costs the
 * count nothing; the cycles between the two CYCLES reads include a fixed overhead (the stores,
 * the last two junk loads, CALL, RTS), measured once by calling bvb_null the same way and
 * subtracted by the monitor. */
#include "runtime.h"
#include "bvb/mailbox.h"

#define IMM32(reg, val) reg##.l = ((val) & 0xFFFF); reg##.h = (((val) >> 16) & 0xFFFF)
/* Set bit N of R3 unless CC; CC is the outcome of "register equals its canary". */
#define FLAG_UNLESS_CC(n) if cc jump 1f; bitset (r3, n); 1:
/* xorshift32 (Marsaglia 2003) of x, with t as a temporary: zero stays zero. */
#define XORSHIFT(x, t) t = x << 13; x = x ^ t; t = x >> 17; x = x ^ t; t = x << 5; x = x ^ t
/* Loop n: set up by the kernel (LBn is no longer the junk it entered with) and still counting. */
#define FLAG_LOOP_ARMED(n, bit) \
	r1 = lc##n; cc = r1 == 0; if cc jump 1f; \
	r1 = lb##n; r2 = [p2 + FR_J_LB##n]; cc = r1 == r2; if cc jump 1f; \
	bitset (r3, bit); 1:
/* A junk loop address: even, in reserved address space; written back so the check sees it. */
#define JUNK_LOOP_REG(reg, slot) \
	r0 = [p2 + slot]; r0 = r0 & r1; r0 = r0 | r2; [p2 + slot] = r0; reg = r0

	.section .l1.text, "ax"
	.align 4
	.global _bvb_call
	.type _bvb_call, STT_FUNC
_bvb_call:
	[--sp] = (r7:4, p5:3);
	[--sp] = fp;
	[--sp] = rets;
	r6 = r1;	/* junk seed */
	r7 = r2;	/* canary seed */
	p0.l = _bvb_call_state; p0.h = _bvb_call_state;
	[p0 + ST_CALL] = r0;
	[p0 + ST_MONITOR_SP] = sp;
	r1 = BVB_OK (z);
	[p0 + ST_STATUS] = r1;
	p1 = r0;

	/* The frame (runtime.h FR_*): outgoing arguments (12 bytes the callee may use for R0-R2,
	 * then args[3..11]), CYCLES before the call, the junk, the canaries. */
	p2 = -FR_SIZE (x);
	sp = sp + p2;
	p2 = sp;
	p2 += 12;
	p3 = p1;
	p3 += CALL_ARGS + 12;
	p4 = 9;
	lsetup (.Lcopy0, .Lcopy1) lc0 = p4;
.Lcopy0: r1 = [p3++];
.Lcopy1: [p2++] = r1;
	[p0 + ST_EXPECT_SP] = sp;

	/* The junk words, then the canaries, each a step of xorshift32 on from its seed. */
	p2 = sp;
	p2 += FR_JUNK;
	p4 = FR_JUNK_WORDS;
	r0 = r6;
	lsetup (.Ljunk0, .Ljunk1) lc0 = p4;
.Ljunk0: XORSHIFT(r0, r1);
.Ljunk1: [p2++] = r0;
	r0 = r7;
	cc = r0 == 0;
	if !cc jump 1f;
	IMM32(r0, CANARY_SEED_DEFAULT);
1:	p4 = FR_CANARY_WORDS;
	lsetup (.Lcanary0, .Lcanary1) lc0 = p4;
.Lcanary0: XORSHIFT(r0, r1);
	r2 = r0;
	bitset (r2, 0);
.Lcanary1: [p2++] = r2;

	/* Junk into the registers nothing below touches: DAG, accumulators, loops (loop addresses
	 * before counts, so no loop is ever armed with one of ours). */
	p2 = sp;
	r0 = [p2 + FR_J_I0 + 0]; i0 = r0;
	r0 = [p2 + FR_J_I0 + 4]; i1 = r0;
	r0 = [p2 + FR_J_I0 + 8]; i2 = r0;
	r0 = [p2 + FR_J_I0 + 12]; i3 = r0;
	r0 = [p2 + FR_J_M0 + 0]; m0 = r0;
	r0 = [p2 + FR_J_M0 + 4]; m1 = r0;
	r0 = [p2 + FR_J_M0 + 8]; m2 = r0;
	r0 = [p2 + FR_J_M0 + 12]; m3 = r0;
	r0 = [p2 + FR_J_B0 + 0]; b0 = r0;
	r0 = [p2 + FR_J_B0 + 4]; b1 = r0;
	r0 = [p2 + FR_J_B0 + 8]; b2 = r0;
	r0 = [p2 + FR_J_B0 + 12]; b3 = r0;
	r0 = [p2 + FR_J_A0W]; a0.w = r0;
	r0 = [p2 + FR_J_A0X]; a0.x = r0.l;
	r0 = [p2 + FR_J_A1W]; a1.w = r0;
	r0 = [p2 + FR_J_A1X]; a1.x = r0.l;
	cc = r6 == 0;
	if cc jump .Lloops_done;	/* no junk: the loop registers stay as they are, LC0/LC1 zero */
	IMM32(r1, JUNK_LOOP_MASK);
	IMM32(r2, JUNK_LOOP_BASE);
	JUNK_LOOP_REG(lt0, FR_J_LT0);
	JUNK_LOOP_REG(lb0, FR_J_LB0);
	JUNK_LOOP_REG(lt1, FR_J_LT1);
	JUNK_LOOP_REG(lb1, FR_J_LB1);
	r0 = [p2 + FR_J_LC0]; lc0 = r0;
	r0 = [p2 + FR_J_LC1]; lc1 = r0;
.Lloops_done:

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
	p2 = sp;
	r4 = [p2 + FR_CANARY + 0];
	r5 = [p2 + FR_CANARY + 4];
	r6 = [p2 + FR_CANARY + 8];
	r7 = [p2 + FR_CANARY + 12];
	p3 = [p2 + FR_CANARY + 16];
	p4 = [p2 + FR_CANARY + 20];
	p5 = [p2 + FR_CANARY + 24];
	fp = [p2 + FR_CANARY + 28];
	p0 = [p2 + FR_J_P0];
	p2 += FR_T0;
	/* bvb_call_t0/t1 mark the two reads: bfbench profile records the instructions from the
	 * first up to the second (bfin-elf-run --timing-profile-window), which are exactly the
	 * cycles the difference counts. */
	.global _bvb_call_t0
_bvb_call_t0:
	r3 = cycles;
	[p2] = r3;
	r3 = [p2 + FR_J_R3 - FR_T0];
	p2 = [p2 + FR_J_P2 - FR_T0];
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
	p2 = [p0 + ST_EXPECT_SP];
	r2 = [p2 + FR_T0];
	r3 = r3 - r2;
	[p1 + CALL_CYCLES] = r3;

	r3 = 0;
	r2 = [p2 + FR_CANARY + 0]; cc = r4 == r2; FLAG_UNLESS_CC(0)
	r2 = [p2 + FR_CANARY + 4]; cc = r5 == r2; FLAG_UNLESS_CC(1)
	r2 = [p2 + FR_CANARY + 8]; cc = r6 == r2; FLAG_UNLESS_CC(2)
	r2 = [p2 + FR_CANARY + 12]; cc = r7 == r2; FLAG_UNLESS_CC(3)
	r1 = p3; r2 = [p2 + FR_CANARY + 16]; cc = r1 == r2; FLAG_UNLESS_CC(4)
	r1 = p4; r2 = [p2 + FR_CANARY + 20]; cc = r1 == r2; FLAG_UNLESS_CC(5)
	r1 = p5; r2 = [p2 + FR_CANARY + 24]; cc = r1 == r2; FLAG_UNLESS_CC(6)
	r1 = fp; r2 = [p2 + FR_CANARY + 28]; cc = r1 == r2; FLAG_UNLESS_CC(7)
	r1 = sp; r2 = p2; cc = r1 == r2; FLAG_UNLESS_CC(8)
	r2 = 0;
	r1 = l0; cc = r1 == r2; FLAG_UNLESS_CC(9)
	r1 = l1; cc = r1 == r2; FLAG_UNLESS_CC(10)
	r1 = l2; cc = r1 == r2; FLAG_UNLESS_CC(11)
	r1 = l3; cc = r1 == r2; FLAG_UNLESS_CC(12)
	FLAG_LOOP_ARMED(0, 13)
	FLAG_LOOP_ARMED(1, 14)
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
