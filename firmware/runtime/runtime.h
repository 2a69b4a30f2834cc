/* Firmware runtime internals shared by the C monitor and the assembly start-up and trampoline. */
#ifndef BVB_RUNTIME_H
#define BVB_RUNTIME_H

/* Byte offsets into struct bvb_call and struct bvb_call_state, for the assembly. */
#define CALL_FN 0
#define CALL_ARGS 4
#define CALL_CYCLES 52
#define CALL_RET 56
#define CALL_ABI 60
#define CALL_SEQSTAT 64
#define CALL_PC 68
#define CALL_ADDR 72
#define CALL_LIMIT 76

#define ST_CALL 0
#define ST_MONITOR_SP 4
#define ST_EXPECT_SP 8
#define ST_SPARE 12 /* unused; the state keeps its size, so L1 bank A's arena stays put */
#define ST_IN_CALL 16
#define ST_STATUS 20
#define ST_SAVE_R0 24
#define ST_SAVE_ASTAT 28

/* The trampoline's frame (call.S), from the SP the kernel gets: the outgoing arguments, then
 * CYCLES before the call, the junk the caller-saved registers get (xorshift32 from the call's
 * junk seed: R3, P2, P0, I0-I3, M0-M3, B0-B3, A0.W, A0.X, A1.W, A1.X, LC0, LT0, LB0, LC1, LT1,
 * LB1), and the canaries of the callee-saved registers (from the canary seed, each made odd:
 * R4-R7, P3-P5, FP). The kernel may use its incoming argument slots; what lies above them is
 * its caller's. */
#define FR_T0 48
#define FR_JUNK 52
#define FR_J_R3 52
#define FR_J_P2 56
#define FR_J_P0 60
#define FR_J_I0 64
#define FR_J_M0 80
#define FR_J_B0 96
#define FR_J_A0W 112
#define FR_J_A0X 116
#define FR_J_A1W 120
#define FR_J_A1X 124
#define FR_J_LC0 128
#define FR_J_LT0 132
#define FR_J_LB0 136
#define FR_J_LC1 140
#define FR_J_LT1 144
#define FR_J_LB1 148
#define FR_JUNK_WORDS 25
#define FR_CANARY 152
#define FR_CANARY_WORDS 8
#define FR_SIZE 184
/* The canary seed when the host gives none (bench, runs, pipelines): any fixed odd value. */
#define CANARY_SEED_DEFAULT 0x5EED0441
/* Junk loop addresses lie in reserved address space (0x40000000-0x4FFFFFFE, nothing mapped on
 * the BF537), so a loop the caller left counting never fires inside a correct kernel. */
#define JUNK_LOOP_MASK 0x0FFFFFFE
#define JUNK_LOOP_BASE 0x40000000

/* L1 instruction SRAM (link.ld L1_CODE): the runtime and the hand-written kernels. */
#define L1_CODE_START 0xFFA00000u
/* BF537 core MMRs */
/* System MMRs the start-up programs as the SRV-1 board does (ADSP-BF537 hardware reference:
 * PLL chapter, EBIU SDRAM controller). */
#define PLL_DIV 0xFFC00004
#define EBIU_SDGCTL 0xFFC00A10
#define EBIU_SDBCTL 0xFFC00A14
#define EBIU_SDRRC 0xFFC00A18
/* The SRV-1: 22.118 MHz crystal x 22 = 486 MHz CCLK, SCLK = VCO / 4 = 121.6 MHz (its firmware's
 * config: VCO_MULTIPLIER 22, SCLK_DIVIDER 4); 32 MB SDRAM, CAS latency 3, tRAS 6, tRP 3,
 * tRCD 3, tWR 2 (EBIU_SDGCTL 0x0091998D), 32 MB bank with 9-bit columns (EBIU_SDBCTL 0x0013),
 * refresh for 121 MHz (EBIU_SDRRC 0x0817). The timing model reads these registers. */
#define SRV1_PLL_DIV 0x0004
#define SRV1_EBIU_SDGCTL 0x0091998D
#define SRV1_EBIU_SDBCTL 0x0013
#define SRV1_EBIU_SDRRC 0x0817
/* Caches and CPLBs (Blackfin Processor Programming Reference, memory chapter; bit names as in
 * ADI's def_LPBlackfin.h). */
#define DMEM_CONTROL 0xFFE00004
#define DCPLB_ADDR0 0xFFE00100
#define DCPLB_DATA0 0xFFE00200
#define IMEM_CONTROL 0xFFE01004
#define ICPLB_ADDR0 0xFFE01100
#define ICPLB_DATA0 0xFFE01200
#define ENCPLB 0x2            /* ENICPLB / ENDCPLB */
#define IMC 0x4               /* IMEM_CONTROL: the upper 16 KB of L1 code is instruction cache */
#define DMC_ACACHE_BSRAM 0x8  /* DMEM_CONTROL DMC = 10: bank A's upper 16 KB is data cache */
#define CPLB_VALID 0x1
#define CPLB_LOCK 0x2
#define CPLB_USER_RD 0x4
#define CPLB_USER_WR 0x8
#define CPLB_SUPV_WR 0x10
#define CPLB_DIRTY 0x80
#define CPLB_L1_CHBL 0x1000
#define PAGE_SIZE_4MB 0x30000
/* SDRAM: code cached in the instruction cache, data cached write-back (dirty set up front: the
 * page is written from the start, and a clean write-back page would fault on its first write). */
#define ICPLB_SDRAM (CPLB_VALID | CPLB_LOCK | CPLB_USER_RD | CPLB_L1_CHBL | PAGE_SIZE_4MB)
#define DCPLB_SDRAM (CPLB_VALID | CPLB_LOCK | CPLB_USER_RD | CPLB_USER_WR | CPLB_SUPV_WR | \
                     CPLB_DIRTY | CPLB_L1_CHBL | PAGE_SIZE_4MB)
/* The window, the host's channel: uncached, so what the firmware writes is there at once. */
#define DCPLB_WINDOW (CPLB_VALID | CPLB_LOCK | CPLB_USER_RD | CPLB_USER_WR | CPLB_SUPV_WR | \
                      CPLB_DIRTY | PAGE_SIZE_4MB)
#define EVT0 0xFFE02000
#define IMASK_MMR 0xFFE02104
#define TCNTL 0xFFE03000
#define TPERIOD 0xFFE03004
#define TSCALE 0xFFE03008
#define TCOUNT 0xFFE0300C
#define DCPLB_FAULT_ADDR 0xFFE0000C /* 0xFFE00008 is DCPLB_STATUS */
#define TMPWR 1
#define TMREN 2

#ifndef __ASSEMBLER__
#include <stdint.h>

struct bvb_call {
  void (*fn)(void);
  uint32_t args[12];
  uint32_t cycles;  /* raw: CYCLES after minus CYCLES before, call overhead included */
  uint32_t ret;
  uint32_t abi_bad;
  uint32_t seqstat;
  uint32_t pc;
  uint32_t addr;
  uint32_t limit;   /* watchdog cycles */
};

/* Calls c->fn with c->args under the ABI check and the watchdog, the caller-saved registers
 * holding junk from junk_seed (0: zero) and the callee-saved ones canaries from canary_seed
 * (0: CANARY_SEED_DEFAULT). Returns BVB_OK when the function returned, BVB_FAULT or BVB_HANG
 * when it was abandoned. */
uint32_t bvb_call(struct bvb_call *c, uint32_t junk_seed, uint32_t canary_seed);
void bvb_null(void);

void *memcpy(void *dst, const void *src, unsigned n);
void *memset(void *dst, int c, unsigned n);
#endif

#endif
