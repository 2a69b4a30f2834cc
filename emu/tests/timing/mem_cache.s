# mach: bfin
# sim: --environment operating --timing bf537 --timing-ext-sync=2 --timing-wbuf=5 --timing-mmr-sclk=2 --timing-ifetch-bytes=8 --timing-cwf=1
# ld: -Ttext=0xFFA00000 -Tdata=0xFF800800 --section-start=.sdram_text=0x00010000

# BF537 timing model, caches (timing-mem.c): data cache (2-way, 32-byte lines, LRU, in the
# upper 16 KB of banks A and B, write-back and write-through pages), instruction cache
# (4-way), line fills from SDRAM critical word first, write-back of dirty lines.
#
# Clocks and SDRAM as in mem_ext_sdram.s: CCLK = 4 x SCLK; CL 3, tRP 3, tRCD 3, tWR 2;
# 1 KB rows, internal bank = address bits 24:23; 2 SCLK sync per access; 16-bit bus (a
# 32-byte line is 16 transfers).  DCPLB 0: 0-4 MB cacheable write-back; DCPLB 1: 4-8 MB
# cacheable write-through, no allocate on write; ICPLB 0: 0-4 MB cacheable.  DMEM_CONTROL
# = 0xF (DMC 11: A and B cache, DCBS 0: bank by address bit 14), IMEM_CONTROL = 0x7.
# A fill's latency before data: sync 2 + row (tRP 3 (+ tWR 2 if written) + tRCD 3 on a
# row miss) + CL 3; the word asked for comes first, then the line in order, 1 SCLK per 16
# bits.  Each window is compared with the same code on L1 (no extra cycles):
#   1. read X=0x100000, no row open: 2 + 3 + 3 = 8, + 2 transfers = 10 SCLK          = 40
#   2. read X+4: hit                                                                  = 0
#   3. read X+64 (row open: 2 + 3 = 5, + 2 = 7 SCLK = 28) then at once X+92 (offset 28:
#      5 + 14 + 2 = 21 SCLK = 84 after the fill began, asked at +29: 55)        28 + 55 = 83
#   4. X, Y=X+8K, Z=X+32K share set 0 of bank A, rows 0x400, 0x408, 0x420 of bank 0;
#      each miss: 2 + tRP 3 + tRCD 3 + CL 3 + 2 = 13 SCLK = 52:
#      Y miss 52, X hit 0, Z miss 52 (evicts Y, the least recent), X hit 0, Y miss 52
#   5. P (set 8) read and written (dirty), Q = P+8K read; then R = P+32K evicts P:
#      R: 52; P's 16 transfers go back after R's fill (fill ends at +4x(11+16) = 108,
#      write-back 2 + tRP 3 + tRCD 3 + 16 = 24 SCLK -> bus busy until 108 + 96 = 204);
#      S = P+0x40 asked at +53 waits for the bus, row 0x400 open: 2 + 3 + 2 = 7 SCLK
#      -> 204 + 28 = 232, stall 179                                          52 + 179 = 231
#   6. write-through page: store W=0x400000 (not in cache) goes to the write buffer: 0;
#      a read of W then misses (no allocate on write), row 0x1000 open: 7 SCLK     = 28
#   7. write-back page, store to V=0x100200 not cached: allocates; open row 0x1000 was
#      written: 2 + tRP 3 + tWR 2 + tRCD 3 + CL 3 + 2 = 15 SCLK = 60; read V: hit = 0
#   8. call of NOP x4; RTS at 0x10000 through the instruction cache, row 0x400 open: the
#      fill's first 64 bits: 2 + 3 + 3 + 3 + 4 = 15 SCLK = 60; NOPs 2-4 are in them; the
#      RTS's 64 bits: 11 + 4 + 4 = 19 SCLK = 76 after the fill began, asked at +64: 12 -> 72;
#      the same call again: all hits, 0
# With --timing none every difference is 0, so every non-zero check fails.

	.include "testutils.inc"

	start

	R0 = SYSCFG;
	BITSET (R0, 1);
	SYSCFG = R0;
	CSYNC;

	imm32 P2, 0xFFC00004;	/* PLL_DIV */
	R0 = 0x0004 (Z);
	W[P2] = R0;
	imm32 P0, 0xFFC00A10;	/* EBIU_SDGCTL */
	imm32 R0, 0x0011998D;
	[P0] = R0;
	imm32 P0, 0xFFC00A14;	/* EBIU_SDBCTL */
	R0 = 0x0013 (Z);
	W[P0] = R0;

	imm32 P0, 0xFFE00100;	/* DCPLB_ADDR0, 1 */
	R0 = 0;
	[P0] = R0;
	imm32 R0, 0x00400000;
	[P0 + 4] = R0;
	imm32 P0, 0xFFE00200;	/* DCPLB_DATA0: valid, rd/wr, dirty, cacheable, 4 MB, WB */
	imm32 R0, 0x0003109D;
	[P0] = R0;
	imm32 R0, 0x0003509D;	/* DCPLB_DATA1: the same, write-through */
	[P0 + 4] = R0;
	imm32 P0, 0xFFE01100;	/* ICPLB_ADDR0 */
	R0 = 0;
	[P0] = R0;
	imm32 P0, 0xFFE01200;	/* ICPLB_DATA0: valid, user rd, cacheable, 4 MB */
	imm32 R0, 0x00031005;
	[P0] = R0;
	imm32 P0, 0xFFE00004;	/* DMEM_CONTROL */
	R0 = 0xF (Z);
	[P0] = R0;
	imm32 P0, 0xFFE01004;	/* IMEM_CONTROL */
	R0 = 0x7 (Z);
	[P0] = R0;
	SSYNC;

	/* Wait long enough for any fill or write-back to finish, off the clock.  */
	.macro pad
	.rept 150
	NOP;
	.endr
	.endm
	.macro time_read
	pad
	R6 = CYCLES;
	R0 = [P1];
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm
	.macro check_read addr, expect
	imm32 P1, \addr;
	time_read
	R7 = R7 - R5;
	CHECKREG R7, \expect;
	.endm
	.macro time_store
	pad
	R6 = CYCLES;
	[P1] = R0;
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm
	.macro check_store addr, expect
	imm32 P1, \addr;
	time_store
	R7 = R7 - R4;
	CHECKREG R7, \expect;
	.endm

	/* References on L1 data (bank A, lower half: SRAM).  */
	imm32 P1, 0xFF801000;
	time_read
	R5 = R7;
	time_store
	R4 = R7;

	check_read 0x00100000, 40	/* 1 */
	check_read 0x00100004, 0	/* 2 */

	/* 3: two reads of one line, the second before the fill is done.  */
	imm32 P1, 0xFF801000;
	imm32 P0, 0xFF801000;
	pad
	R6 = CYCLES;
	R0 = [P1];
	R1 = [P0 + 28];
	R7 = CYCLES;
	R3 = R7 - R6;
	imm32 P1, 0x00100040;
	imm32 P0, 0x00100040;
	pad
	R6 = CYCLES;
	R0 = [P1];
	R1 = [P0 + 28];
	R7 = CYCLES;
	R7 = R7 - R6;
	R7 = R7 - R3;
	CHECKREG R7, 83;

	/* 4: LRU in a 2-way set.  */
	check_read 0x00102000, 52	/* Y miss */
	check_read 0x00100000, 0	/* X hit */
	check_read 0x00108000, 52	/* Z miss, evicts Y */
	check_read 0x00100000, 0	/* X hit */
	check_read 0x00102000, 52	/* Y miss */

	/* 5: a dirty victim goes back to SDRAM and delays the next fill.  */
	imm32 P1, 0x00100100;	/* P */
	R0 = [P1];
	pad
	[P1] = R0;		/* P dirty */
	pad
	imm32 P1, 0x00102100;	/* Q */
	R0 = [P1];
	imm32 P1, 0xFF801000;
	imm32 P0, 0xFF801040;
	pad
	R6 = CYCLES;
	R0 = [P1];
	R1 = [P0];
	R7 = CYCLES;
	R3 = R7 - R6;
	imm32 P1, 0x00108100;	/* R */
	imm32 P0, 0x00100140;	/* S */
	pad
	R6 = CYCLES;
	R0 = [P1];
	R1 = [P0];
	R7 = CYCLES;
	R7 = R7 - R6;
	R7 = R7 - R3;
	CHECKREG R7, 231;

	/* 6: write-through, no allocation on write.  */
	check_store 0x00400000, 0
	check_read 0x00400000, 28

	/* 7: write-back allocates on a write miss.  */
	check_store 0x00400000, 0	/* W again: hit, written through, buffered */
	check_store 0x00100200, 60
	check_read 0x00100200, 0

	/* 8: instruction cache.  */
	.macro time_call f
	pad
	R6 = CYCLES;
	CALL \f;
	R7 = CYCLES;
	R7 = R7 - R6;
	.endm
	time_call f_l1
	R4 = R7;
	time_call f_sdram
	R7 = R7 - R4;
	CHECKREG R7, 72;
	time_call f_sdram
	R7 = R7 - R4;
	CHECKREG R7, 0;

	dbg_pass

	.align 8
f_l1:
	NOP; NOP; NOP; NOP;
	RTS;

	.section .sdram_text, "ax"
	.align 32
f_sdram:
	NOP; NOP; NOP; NOP;
	RTS;
