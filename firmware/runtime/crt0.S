/* Start-up, event vectors and the fault/watchdog handlers.
 *
 * We run in the simulator's "operating" environment, not its default "virtual" one: only the
 * operating environment maps the BF537's L1 SRAM (where real firmware keeps its hot code and
 * working buffers) and models the core event controller and core timer. The price is that we own
 * the exception vectors; the reward is that a kernel's fault or runaway loop becomes an event
 * this firmware catches, records against the kernel, and survives, so one simulator run checks
 * many kernels. The simulator stops on HLT (exit 0) or ABORT (exit 1). */
#include "runtime.h"
#include "bvb/mailbox.h"

#define IMM32(reg, val) reg##.l = LO(val); reg##.h = HI(val)
#define LO(x) ((x) & 0xFFFF)
#define HI(x) (((x) >> 16) & 0xFFFF)
#define IVHW_BIT 5
#define IVTMR_BIT 6

	.section .l1.text.start, "ax"
	.align 4
	.global __start
	.type __start, STT_FUNC
__start:
	sp.l = __stack_top; sp.h = __stack_top;
	usp = sp;
	fp = 0;
	r0 = 0;
	l0 = r0; l1 = r0; l2 = r0; l3 = r0;
	lc0 = r0; lc1 = r0;

	/* Clocks and SDRAM as the robot has them: the timing model charges SDRAM and system MMR
	 * accesses at SCLK, CCLK:SCLK from PLL_DIV, SDRAM latencies from EBIU_SDGCTL. Only the
	 * divider changes (no PLL relock): CSEL and SSEL may change on the fly. */
	IMM32(p0, PLL_DIV);
	r1 = SRV1_PLL_DIV (z);
	w[p0] = r1;
	IMM32(p0, EBIU_SDRRC);
	r1 = SRV1_EBIU_SDRRC (z);
	w[p0] = r1;
	IMM32(p0, EBIU_SDBCTL);
	r1 = SRV1_EBIU_SDBCTL (z);
	w[p0] = r1;
	IMM32(p0, EBIU_SDGCTL);
	IMM32(r1, SRV1_EBIU_SDGCTL);
	[p0] = r1;
	ssync;

	/* Caches as a robot build has them: code and data in SDRAM cached (the instruction cache
	 * in the upper 16 KB of L1 code memory, a write-back data cache in the upper 16 KB of bank
	 * A; bank B stays SRAM), L1 SRAM and MMRs need no CPLB. Locked 4 MB CPLBs: eight cover
	 * the 32 MB of SDRAM for instructions and for data, eight more the window, uncached. The
	 * data kernels stream from SDRAM pays line fills; C code runs from the instruction cache. */
	IMM32(p0, ICPLB_ADDR0);
	IMM32(p1, ICPLB_DATA0);
	IMM32(p2, DCPLB_ADDR0);
	IMM32(p3, DCPLB_DATA0);
	IMM32(r2, ICPLB_SDRAM);
	IMM32(r3, DCPLB_SDRAM);
	r0 = 0;
	IMM32(r1, 0x400000);
	p4 = 8;
	lsetup (.Lcplb0, .Lcplb1) lc0 = p4;
.Lcplb0:
	[p0++] = r0;
	[p1++] = r2;
	[p2++] = r0;
	[p3++] = r3;
.Lcplb1:
	r0 = r0 + r1;
	IMM32(r0, BVB_WINDOW_ADDR);
	IMM32(r3, DCPLB_WINDOW);
	lsetup (.Lcplb2, .Lcplb3) lc0 = p4;
.Lcplb2:
	[p2++] = r0;
	[p3++] = r3;
.Lcplb3:
	r0 = r0 + r1;
	ssync;
	IMM32(p0, IMEM_CONTROL);
	r0 = [p0];
	r1 = ENCPLB | IMC (z);
	r0 = r0 | r1;
	[p0] = r0;
	ssync;
	IMM32(p0, DMEM_CONTROL);
	r0 = [p0];
	r1 = ENCPLB | DMC_ACACHE_BSRAM (z);
	r0 = r0 | r1;
	[p0] = r0;
	ssync;

	/* Event vectors: everything we do not expect is fatal. */
	IMM32(p0, EVT0);
	r1.l = _bvb_unexpected; r1.h = _bvb_unexpected;
	p1 = 16;
	lsetup (.Lvec, .Lvec) lc0 = p1;
.Lvec:	[p0++] = r1;
	IMM32(p0, EVT0);
	r1.l = _bvb_exception; r1.h = _bvb_exception;
	[p0 + 3 * 4] = r1;
	r1.l = _bvb_interrupt; r1.h = _bvb_interrupt;
	[p0 + 5 * 4] = r1;	/* hardware error */
	[p0 + 6 * 4] = r1;	/* core timer: the watchdog */
	r1.l = .Livg15; r1.h = .Livg15;
	[p0 + 15 * 4] = r1;
	IMM32(p0, IMASK_MMR);
	r1 = (1 << IVHW_BIT) | (1 << IVTMR_BIT) | (1 << 15) (z);
	[p0] = r1;
	/* SYSCFG: keep the reset value, enable the cycle counter (CCEN). */
	r1 = syscfg;
	bitset (r1, 1);
	syscfg = r1;
	csync;

	/* Leave the reset level for IVG15, the lowest supervisor level, where the monitor runs. */
	raise 15;
	r1.l = .Lidle; r1.h = .Lidle;
	reti = r1;
	rti;
.Lidle:
	jump .Lidle;

.Livg15:
	/* Re-enable interrupts while at IVG15: the watchdog must be able to preempt a kernel. */
	[--sp] = reti;
	/* Zero .bss in SDRAM and both L1 data banks. */
	r0.l = __bss_start; r0.h = __bss_start;
	r1.l = __bss_end; r1.h = __bss_end;
	call .Lzero;
	r0.l = __l1a_bss_start; r0.h = __l1a_bss_start;
	r1.l = __l1a_bss_end; r1.h = __l1a_bss_end;
	call .Lzero;
	r0.l = __l1b_bss_start; r0.h = __l1b_bss_start;
	r1.l = __l1b_bss_end; r1.h = __l1b_bss_end;
	call .Lzero;
	sp += -12;
	call _main;
	cc = r0 == 0;
	if !cc jump .Lfailed;
	hlt;
.Lfailed:
	abort;

/* r0 = start, r1 = end (both word-aligned) */
.Lzero:
	p0 = r0;
	r1 = r1 - r0;
	r1 >>= 2;
	cc = r1 == 0;
	if cc jump .Lzero_done;
	p1 = r1;
	r0 = 0;
	lsetup (.Lz, .Lz) lc0 = p1;
.Lz:	[p0++] = r0;
.Lzero_done:
	rts;
	.size __start, . - __start

/* Exception (EVT3). Uses no stack: the kernel may have left SP anywhere. Inside a kernel call:
 * record the fault against the call and resume the monitor at _bvb_call_abandon. Elsewhere it is
 * the firmware's own fault: record it in the window header for the host and stop.
 * The handlers run from SDRAM (cached, under the locked CPLBs above, so their fetches never
 * fault): they are never timed, and L1 instruction SRAM is kept for the kernels. */
	.text
	.align 4
	.global _bvb_exception
	.type _bvb_exception, STT_FUNC
_bvb_exception:
	p0.l = _bvb_call_state; p0.h = _bvb_call_state;
	r0 = [p0 + ST_IN_CALL];
	cc = r0 == 0;
	if cc jump .Lfatal;
	r0 = 0;
	[p0 + ST_IN_CALL] = r0;	/* a second fault while abandoning is the firmware's own */
	r0 = BVB_FAULT (z);
	[p0 + ST_STATUS] = r0;
	p1 = [p0 + ST_CALL];
	r0 = seqstat;
	[p1 + CALL_SEQSTAT] = r0;
	r0 = retx;
	[p1 + CALL_PC] = r0;
	IMM32(p2, DCPLB_FAULT_ADDR);
	r0 = [p2];
	[p1 + CALL_ADDR] = r0;
	r0.l = _bvb_call_abandon; r0.h = _bvb_call_abandon;
	retx = r0;
	rtx;
.Lfatal:
	IMM32(p0, BVB_WINDOW_ADDR);
	r0 = seqstat;
	[p0 + 52] = r0;		/* bvb_header.fatal_seqstat */
	r0 = retx;
	[p0 + 56] = r0;		/* bvb_header.fatal_pc */
	IMM32(p1, DCPLB_FAULT_ADDR);
	r0 = [p1];
	[p0 + 60] = r0;		/* bvb_header.fatal_addr */
	abort;
	.size _bvb_exception, . - _bvb_exception

/* Core timer (the watchdog) and hardware errors. The timer is armed only around a call, but an
 * interrupt latched just as the call ended can arrive after it: then nothing is abandoned, and
 * the interrupted code must get R0, P0 and ASTAT back (saved without the stack, which inside a
 * kernel may be anywhere). */
	.align 4
	.global _bvb_interrupt
	.type _bvb_interrupt, STT_FUNC
_bvb_interrupt:
	usp = p0;
	p0.l = _bvb_call_state; p0.h = _bvb_call_state;
	[p0 + ST_SAVE_R0] = r0;
	r0 = astat;
	[p0 + ST_SAVE_ASTAT] = r0;
	IMM32(p0, TCNTL);
	r0 = TMPWR (z);
	[p0] = r0;		/* stop the timer, clear its interrupt */
	p0.l = _bvb_call_state; p0.h = _bvb_call_state;
	r0 = [p0 + ST_IN_CALL];
	cc = r0 == 0;
	if cc jump .Lnot_in_call;
	r0 = 0;
	[p0 + ST_IN_CALL] = r0;
	p1 = [p0 + ST_CALL];
	r0 = seqstat;
	[p1 + CALL_SEQSTAT] = r0;
	r0 = reti;
	[p1 + CALL_PC] = r0;
	/* HWERRCAUSE (SEQSTAT bits 14-18) tells a hardware error from the watchdog. */
	r0 = seqstat;
	r0 >>= 14;
	r1 = 0x1f;
	r0 = r0 & r1;
	cc = r0 == 0;
	r0 = BVB_HANG (z);
	r1 = BVB_FAULT (z);
	if !cc r0 = r1;
	[p0 + ST_STATUS] = r0;
	r0.l = _bvb_call_abandon; r0.h = _bvb_call_abandon;
	reti = r0;
	rti;
.Lnot_in_call:
	r0 = [p0 + ST_SAVE_ASTAT];
	astat = r0;
	r0 = [p0 + ST_SAVE_R0];
	p0 = usp;
	rti;
	.size _bvb_interrupt, . - _bvb_interrupt

	.align 4
	.global _bvb_unexpected
	.type _bvb_unexpected, STT_FUNC
_bvb_unexpected:
	IMM32(p0, BVB_WINDOW_ADDR);
	r0 = seqstat;
	[p0 + 52] = r0;
	r0 = reti;
	[p0 + 56] = r0;
	abort;
	.size _bvb_unexpected, . - _bvb_unexpected
