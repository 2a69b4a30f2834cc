/* Horn-Schunck optical flow in Blackfin assembly (bvb/hornschunck.h: definitions, Q formats,
 * rounding): bvb_hs_iterate_asm, bvb_hs_iterate_n_asm, bvb_hs_prepare_asm and
 * bvb_hornschunck_asm, bit-exact with the C reference, which is written one Blackfin operation
 * per helper so that these instruction sequences reproduce it.
 *
 * FUSED ITERATIONS (bvb_hs_iterate_n_asm; bvb/hornschunck.h says how): modelled cycles, N = 10
 *   iterations in one call, c/px per pixel per iteration; coefficients and flow in SDRAM, the
 *   flow rows' scratch in L1 bank B, the coefficient rows' in bank A (bfbench bench):
 *                    160x120               320x240               640x480
 *   hs_iterate_n   2,199,204  (11.45)    8,204,149  (10.68)    44,626,089  (14.53)
 *   bound            (10.00: 5 + 5 levels) (10.00: 5 + 5)        (14.00: 5 x 2, bus-bound)
 *   The simulator's own counts are 2,151,319 and 8,109,604 (32,263,525 at 640: bus-bound, the
 *   model waits for the transfers there, 1.04x its bus bound): the model adds 1.2-2.2% (waiting
 *   for DMA where a pass fills and drains, the DMA registers' accesses), so the transfers hide
 *   under the compute. Where the 320x240 call's cycles go (bfbench profile hs_iterate_n): the
 *   row routine's interior loop 7,632,000 (9.94 per pixel an iteration, at its issue bound of
 *   30 cycles per 3 pixels); the level loop's per-row work (pointers, clamps, the slot
 *   rotation) 186,300 (76 a row, 2,400 rows); the DMA waits 65,400 (the first two steps of a
 *   pass bring rows with nothing to compute, the last ones send rows with less); the rest,
 *   320,000: each row's first and last pixel and its call (about 50 a row) and the per-step
 *   job (three slots re-addressed and started, about 400 a step, 494 steps). Against the bound
 *   1.07x at 320; 1.15x at 160 (the same per-row cost over half the pixels a row).
 *
 * CYCLES (bfbench bench, per call, empty-call overhead subtracted; c/px per frame pixel; C = the
 *   reference built with bfin-elf-gcc -O2). Modelled BF537 cycles (--timing bf537), frames,
 *   coefficients and flow in SDRAM through the data cache, as the bench places them:
 *                    160x120               320x240
 *   hs_iterate       616,456  (32.11)    2,307,931  (30.05)    bound 28 (the bus; compute 10)
 *   hs_prepare       378,006  (19.69)    1,410,741  (18.37)    bound 17 (bus 16)
 *   hornschunck    2,577,927 (134.3)     9,615,769 (125.2)     bound 117, N = 10
 *   hs_iterate with its two L1 scratches is bvb_hs_iterate_n_asm's one level (bus-bound: 1.07x
 *   at 320x240, 1.15x at 160, the per-row cost over half the pixels); before, through the data
 *   cache, 1,195,196 (62.25) and 4,669,482 (60.80). (Its direct path: 2,250 to 2,850 cycles an
 *   iteration more than before its rows became calls of the shared row routine, ROWS below: the
 *   call and return, 10 cycles a row, and at 160 wide the entry's two jumps; the simulator's
 *   counts below are those of before.) hornschunck is
 *   prepare streamed through its flow-row scratch (L1 bank B) and one bvb_hs_iterate_n_asm
 *   from a zero row read with stride 0: 1.07x its bound of 17 + 10 N at 320x240, 1.15x at 160
 *   (hs_iterate_n's per-row cost over half the pixels, prepare's 19.7); before, the iterations
 *   were N bvb_hs_iterate_asm calls through the data cache and a zeroed frame of start flow:
 *   13,226,105 and 52,997,199.
 *   hs_prepare streams its rows through L1 (the scratch in L1 bank B; STREAMED PATH below):
 *   640x480 5,608,612 (18.26). Target 18.5 c/px at 320x240 (1,420,800). Its simulator counts
 *   are 359,865 and 1,389,435. Where the 320x240 call's 1,410,741 go (bfbench profile
 *   hs_prepare), against the bound's 1,305,600: the three passes 1,333,278 (5,560 a row against
 *   the bound's 5,440: each pass at its issue bound, about 120 a row of set-up, pass A's
 *   alignment most of it); the stream's per-band work 47,600 (bvb_stream_next building and
 *   starting each job, 80 bands of 3 rows: some 590 cycles a band); waiting for DMA 15,500
 *   (band 0 with the table and row 0, 3,776 bytes, before anything can start, and the last
 *   band's and row h-1's output at the end: the bus's 16 c/px are just under the compute, so
 *   what is left to send after the last row cannot hide); frame 2's row 0 through the data
 *   cache 2,100; the rest the band loop, the calls and the MMR accesses. No sub-bank
 *   collisions are left in the loops (the layout, STREAMED PATH); 398 in pass A's first two
 *   dual loads of a row, of the two frames' band rows (one sub-bank when they are close).
 *   Before this layout (in-place sums, bands of 2, the table through the cache): 1,505,044, of
 *   which 48,440 collisions and 10,859 line fills.
 *   Before the stream (frames through the data cache): 1,169,693 (60.92) and 4,635,194
 *   (60.35); where those went (the same calls with one charge of the model turned off):
 *   hs_prepare at 160x120: 343,133 issued (the simulator's own count), 607 address-register
 *   stalls (the first pair and the tail of each row), 1,795 sub-bank collisions (two cached
 *   rows loaded in one issue in passes A and B), 824,158 SDRAM line fills and write-backs
 *   through the cache; hs_iterate: 195,564 issued, no stalls, 107 collisions (first and last
 *   pixels), 997,274 SDRAM; hornschunck: 2,318,656 issued, 607 stalls, 2,912 collisions, 10.88M
 *   SDRAM. So the model's cost is the memory, which streaming row bands into L1 by DMA (MEMORY
 *   below) hides. The simulator's own counts (data as if in L1):
 *                    160x120               320x240               640x480
 *   hs_iterate       195,564  (10.19)      775,045  (10.09)      3,086,004  (10.05)   C ~304 c/px
 *   hs_prepare       343,133  (17.87)    1,339,013  (17.44)      5,289,173  (17.22)   C ~345 c/px
 *   hornschunck    2,318,656 (120.76)    9,167,186 (119.36)     36,457,814 (118.68)   N = 10,
 *                                                                          C ~3380 c/px
 * LOWER BOUNDS. One issue per cycle: one 32-bit ALU/MAC instruction with up to two loads, or one
 *   load and one store; 16-bit instructions (pointer moves, lone loads/stores) issue alone.
 *   Iteration, 10 per pixel: ALU/MAC instructions 2 saturating dual adds (cr = T + B, e1 = ML + MR;
 *     cl and c0 are earlier pixels' cr), 4 dual MACs (the 1/12 and 1/6 weighted sums for u and v
 *     at once; the last extracts ubar, vbar), 1 dual S2RND multiply (gx' ubar, gy' vbar), 2
 *     saturating adds (+ each other, + gt'), 1 dual integer MAC (acc - e g', extracted: u', v').
 *     Memory: 6 loads (T, B, M(x-1), M(x+1), (gy':gx'), gt') and 1 store, 3.5 issues, ride along.
 *     Measured 10.05-10.19: the rest is per row (first and last pixel, pointers, ~30 cycles).
 *   Prepare, 17 per pixel, in three passes per row y (the intermediates live in the row's own
 *     6-byte-per-pixel coefficient area, overwritten in place):
 *     A  1: r = I2 + I1 and n = I2 - I1 of row y+1 of both frames, BYTEOP16P/M: 2 instructions
 *        but 4 word stores per 4 columns (store bound; the source words slide with the (R)
 *        option so that each group loads 2 words).
 *     B  2: s = r(y) + r(y+1) and p = r(y+1) - r(y) (one quad add/subtract per 2 columns),
 *        q = n(y) + n(y+1), C = (p:s) by PACK: 8 ALU instructions per 4 columns.
 *     C 14: per pixel 10 ALU/MAC (G = C(x+1) +|- C(x); half of (gt1:gt0) = q +|+ q shifted;
 *        D = alpha2 + gx^2 + gy^2 in 3 (two integer MACs and A0 += A1); SIGNBITS; the index
 *        shift D >> (20 - 2k); G <<= k (V); gt shifted by k - 5; the S2RND multiply of G and half
 *        of the one of (gt1:gt0)) + 4 pointer instructions that cannot issue in parallel:
 *        P0 = SIGNBITS, P0 = counts + 4 P0 (a 12-entry table gives k, k - 5 and 2k - 20 for
 *        three loads riding along, cheaper than computing them), P1 = index,
 *        P1 = rsqrt table + 2 P1. Each pointer is used in the address stage four cycles after
 *        its move from a data register (GCC's bfin_adjust_cost, the model: 4 cycles), taken by
 *        the other pixel's work (the phase-2 pipeline below); back to back, the two moves per
 *        pixel would stall 8 cycles a pixel.
 *     Measured 17.22-17.87: ~138 cycles per row of set-up, branches and the border pixels.
 *   Full kernel: 1 (zeroing the start flow, a store per pixel) + 17 + 10 N: 118 at N = 10;
 *     measured 118.68-120.76.
 *   Each is at least 19x faster than the C (prepare 19.3x, iteration 29.8x, full 28.0x at
 *   160x120).
 *
 * STREAMED PATH (bvb_hs_prepare_asm with a scratch in L1 and a frame or the coefficients in
 *   SDRAM): the row-band stream (bvb/stream.h) brings rows 1..h-1 of both frames into L1 and
 *   sends coefficient rows 0..h-2 out, band by band, while the band before is computed: output
 *   row y needs frame rows y and y+1, so each band row is the lower row of its output row.
 *   Pass A of every frame row goes to one of two sum rows, alternately, and pass B reads both
 *   and writes the output row in the band; phase 2 works in place there. The scratch's layout
 *   (bvb/hornschunck.h, BVB_HS_PREPARE_SCRATCH_BYTES) keeps the accesses each loop issues
 *   together in different 4 KB sub-banks when the scratch starts at a 4 KB boundary (as the
 *   bench places it): the sum rows each in a sub-bank of their own (pass B's dual loads of
 *   both, pass A's stores against its frame loads, pass B's stores against its loads), the
 *   stream's bands in the sub-banks after them, the count table in bank A. The bands are as
 *   many rows as fit L1 bank B beside the stack (3 at 320 wide: 80 bands; bvb_stream_open_rows).
 *   The rsqrt table and frame 1's row 0 come in by DMA on band 0's job (frame 2's row 0 is
 *   read where it is). After the last band the kernel sends that band's output itself and
 *   makes row h-1 in the other output buffer meanwhile, then sends it. Where the stream
 *   refuses (the scratch not in DMA-reachable L1, every buffer in L1), the direct path below.
 *
 * MEMORY. The kernels work wherever the caller puts the buffers. At the robot's sizes frames,
 *   coefficients and flow live in SDRAM (working set 14 bytes per pixel: 263 KB at 160x120, past
 *   the 64 KB of L1 data); the bench places them there. The simulator's own counts are those of
 *   data in L1; the modelled ones of bvb_hs_iterate_asm pay SDRAM through the cache (one
 *   iteration alone is bus-bound: 28 cycles a pixel for its 14 bytes); bvb_hs_iterate_n_asm
 *   fuses the iterations over L1 rings (FUSED ITERATIONS above), and bvb_hornschunck_asm calls
 *   it with the two L1 scratches it is given. The count table is in L1 data bank A; the rsqrt
 *   table is the C reference's (.rodata), read there by the direct path and copied into the
 *   scratch by the streamed one.
 *
 * ROWS. One routine makes an output row (HS_PIX0, then the loop of HS_PIX, then the last pixel)
 *   for both iteration kernels: L1 instruction memory has no room for a copy per kernel.
 *
 * READS stay inside the buffers: frame rows are read as aligned words only up to the word that
 *   holds the row's last pixel; the coefficient rows only inside their width; the flow rows
 *   inside their width but for one word after the row above each output row (row 0 for row 0;
 *   the iteration's load ahead, unused; the next row of uv_in follows it).
 */
#include "bvb/asm.h"

/* ---------------------------------------------------------------------------------------------
 * bvb_hs_iterate_asm(coef, uv_in, in_stride, uv_out, out_stride, width, height, flow_scratch,
 *                    coef_scratch): with the scratches, bvb_hs_iterate_n_asm's one iteration
 * (streamed); without, the direct path below on the buffers where they are.
 * --------------------------------------------------------------------------------------------- */

/* One interior pixel. Column sums cl = ra, c0 = rb (carried), cr = rc (computed here); on entry
 * R0 = G and R3.L = e of the previous pixel, A1:A0 its exact sums, R2 = T(x+1), I2 at M(x-1).
 * One memory access an issue (T(x+2) loaded a pixel ahead, the output stored in the sixth):
 * two in one issue cost a cycle whenever they meet in one L1 or data-cache sub-bank, as the
 * rows of one flow buffer do. The last pixel's T(x+2) is one word past the row (row y-1, or
 * row 0 for y = 0): inside uv_in, row y follows; it is not used. */
.macro HS_PIX ra, rb, rc
	R3.H = (A1 -= R3.L * R0.H), R3.L = (A0 -= R3.L * R0.L) (IH) || R1 = [I1++];
	\rc = R2 +|+ R1 (S) || R0 = [I2 ++ M0];
	A1 = \ra\().H * R7.L, A0 = \ra\().L * R7.L || R1 = [I2 ++ M1];
	R2 = R0 +|+ R1 (S) || R1 = W[P0++] (X);
	A1 += \rc\().H * R7.L, A0 += \rc\().L * R7.L || R0 = [I3++];
	A1 += R2.H * R7.H, A0 += R2.L * R7.H || [P1++] = R3;
	R3.H = (A1 += \rb\().H * R7.H), R3.L = (A0 += \rb\().L * R7.H) || R2 = [I0++];
	R3.H = R3.H * R0.H, R3.L = R3.L * R0.L (S2RND);
	R3.L = R3.L + R3.H (S);
.endm

/* The rows of one call, for (width - 2) mod 3 == m: each row is the row routine HS_ROW1 m
 * (below; one copy of the row code serves this kernel and bvb_hs_iterate_n_asm). */
.macro HS_ROWS m
	lsetup (.Lit_row\m, .Lit_row_end\m) lc1;
.Lit_row\m:
	i0 = b2;
	r0 = p3;
	r1 = b0;
	r0 = r0 + r1;
	r1 = b3;
	r0 = min (r0, r1);
	i1 = r0;
	i2 = p3;
	i3 = p4;
	p0 = p4 + fp;
	p1 = p5;
	call .Lrow1_\m;
	/* Next row: top = this row, then advance the three row pointers. */
	b2 = p3;
	r0 = p3;
	r1 = b0;
	r0 = r0 + r1;
	p3 = r0;
	r0 = p4;
	r1 = m3;
	r0 = r0 + r1;
	p4 = r0;
	r0 = p5;
	r1 = b1;
	r0 = r0 + r1;
.Lit_row_end\m:
	p5 = r0;
.endm

/* One output row, as a subroutine (for HS_ROWS and bvb_hs_iterate_n_asm): I0 = row above (T),
 * I1 = row below (B), I2 = the row (M), I3 = its (gy':gx') words, P0 = its gt' halves, P1 = the
 * output row, P2 = (width - 2) / 3, R7 = (W6:W12), M0 = 8, M1 = -4, M2 = 4; entry .Lrow1_m for
 * m = (width - 2) mod 3. Clobbers R0-R6, A0, A1, I0-I3, P0, P1, LC0, ASTAT. T is read one word
 * past its row (unused): the callers' layouts put another row there. The three entries differ
 * in pixel 0's registers and the m pixels before the loop: entry 2's state after its first
 * pixel is entry 1's after pixel 0, and entry 1's after its pixel entry 0's, so they chain. */
.macro HS_PIX0 x0, x1
	mnop || r0 = [i0++] || r1 = [i1++];
	\x0 = r0 +|+ r1 (s) || r0 = [i0++] || r1 = [i1++];
	\x1 = r0 +|+ r1 (s) || r0 = [i2 ++ m2];
	a1 = \x0\().h * r7.l, a0 = \x0\().l * r7.l || r1 = [i2 ++ m1];
	r2 = r0 +|+ r1 (s) || r1 = w[p0++] (x) || r0 = [i3++];
	a1 += \x1\().h * r7.l, a0 += \x1\().l * r7.l;
	a1 += r2.h * r7.h, a0 += r2.l * r7.h;
	r3.h = (a1 += \x0\().h * r7.h), r3.l = (a0 += \x0\().l * r7.h);
	r3.h = r3.h * r0.h, r3.l = r3.l * r0.l (s2rnd);
	r3.l = r3.l + r3.h (s);
	r3.l = r3.l + r1.l (s) || r2 = [i0++];
.endm

	.section .l1.text, "ax"
.Lrow1_2:
	HS_PIX0 r5, r6
	HS_PIX r5, r6, r4
	r3.l = r3.l + r1.l (s);
	jump.s .Lr1_m1;
.Lrow1_1:
	HS_PIX0 r6, r4
.Lr1_m1:
	HS_PIX r6, r4, r5
	r3.l = r3.l + r1.l (s);
	jump.s .Lr1_m0;
.Lrow1_0:
	HS_PIX0 r4, r5
.Lr1_m0:
	cc = p2 == 0;
	if cc jump .Lr1_last0;
	lsetup (.Lr1_pix0, .Lr1_pix_end0) lc0 = p2;
.Lr1_pix0:
	HS_PIX r4, r5, r6
	r3.l = r3.l + r1.l (s);
	HS_PIX r5, r6, r4
	r3.l = r3.l + r1.l (s);
	HS_PIX r6, r4, r5
.Lr1_pix_end0:
	r3.l = r3.l + r1.l (s);
.Lr1_last0:
.Lr1_tail:
	/* Pixel width-1: cl = R4, c0 = R5 and cr = c0. */
	r3.h = (a1 -= r3.l * r0.h), r3.l = (a0 -= r3.l * r0.l) (ih) || r0 = [i2 ++ m2];
	a1 = r4.h * r7.l, a0 = r4.l * r7.l || [p1++] = r3 || r1 = [i2];
	r2 = r0 +|+ r1 (s) || r1 = w[p0++] (x) || r0 = [i3++];
	a1 += r5.h * r7.l, a0 += r5.l * r7.l;
	a1 += r2.h * r7.h, a0 += r2.l * r7.h;
	r3.h = (a1 += r5.h * r7.h), r3.l = (a0 += r5.l * r7.h);
	r3.h = r3.h * r0.h, r3.l = r3.l * r0.l (s2rnd);
	r3.l = r3.l + r3.h (s);
	r3.l = r3.l + r1.l (s);
	r3.h = (a1 -= r3.l * r0.h), r3.l = (a0 -= r3.l * r0.l) (ih);
	[p1] = r3;
	rts;


BVB_FUNC bvb_hs_iterate_asm
	/* With the two scratches (arguments 8 and 9), one iteration of bvb_hs_iterate_n_asm: its
	 * rows by DMA through them where it reaches. Arguments 4-9 at SP + 12..32 on entry. */
	r3 = [sp + 28];
	cc = r3 == 0;
	if cc jump .Lit_direct;
	[--sp] = rets;
	sp += -40;
	r3 = [sp + 56];                  /* uv_out */
	[sp + 12] = r3;
	r3 = [sp + 60];                  /* out_stride */
	[sp + 16] = r3;
	r3 = [sp + 64];                  /* width */
	[sp + 20] = r3;
	r3 = [sp + 68];                  /* height */
	[sp + 24] = r3;
	r3 = 1;                          /* one iteration */
	[sp + 28] = r3;
	r3 = [sp + 72];                  /* flow_scratch */
	[sp + 32] = r3;
	r3 = [sp + 76];                  /* coef_scratch */
	[sp + 36] = r3;
	call _bvb_hs_iterate_n_asm;
	sp += 40;
	rets = [sp++];
	rts;
.Lit_direct:
	[--sp] = (r7:4, p5:3);
	[--sp] = fp;
	[--sp] = rets;                  /* the rows are calls */
	/* Arguments 4-7 sit 36 bytes further up after the saves. */
	p4 = r0;
	p3 = r1;
	b0 = r2;
	b2 = r1;
	p5 = [sp + 48];
	r0 = [sp + 52];
	b1 = r0;
	r6 = [sp + 56];
	r5 = [sp + 60];
	lc1 = r5;
	r0 = r5;
	r0 += -1;
	r0 *= r2;
	r0 = r0 + r1;
	b3 = r0;
	r0 = r6 << 2;
	fp = r0;
	r1 = r6 << 1;
	r0 = r0 + r1;
	r1 = 1;
	r1 = r1 & r6;
	r1 = r1 << 1;
	r0 = r0 + r1;
	m3 = r0;
	/* n = (width - 2) / 3 rotations of the loop, m = (width - 2) mod 3 pixels before it. */
	r0 = r6;
	r0 += -2;
	r1 = 0xaaab (z);
	r2 = r0;
	r2 *= r1;
	r2 >>= 17;
	p2 = r2;
	r1 = r2 << 1;
	r1 = r1 + r2;
	r0 = r0 - r1;
	r1 = 8;
	m0 = r1;
	r1 = -4;
	m1 = r1;
	r1 = 4;
	m2 = r1;
	r7.l = 2731;
	r7.h = 5461;
	cc = r0 == 0;
	if cc jump .Lit_m0;
	cc = r0 == 1;
	if cc jump .Lit_m1;
	HS_ROWS 2
	jump .Lit_done;
.Lit_m1:
	HS_ROWS 1
	jump .Lit_done;
.Lit_m0:
	HS_ROWS 0
.Lit_done:
	rets = [sp++];
	fp = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;
BVB_ENDFUNC bvb_hs_iterate_asm

#include "bvb/dma.h"

/* ---------------------------------------------------------------------------------------------
 * bvb_hs_iterate_n_asm(coef, uv_in, in_stride, uv_out, out_stride, width, height, iterations,
 *                      flow_scratch, coef_scratch): the iterations fused, L levels a pass
 *                      (bvb/hornschunck.h: FUSED ITERATIONS)
 * --------------------------------------------------------------------------------------------- */


/* Stack frame of bvb_hs_iterate_n_asm (FP-relative locals; arguments 4-10 at FP + 48). */
#define N_COEF  -4    /* the coefficients (a frame) */
#define N_SRC   -8    /* this pass's input field: uv_in, then uv_out in place */
#define N_SS    -12   /* and its stride */
#define N_W4    -16   /* flow row bytes, 4 width */
#define N_CP    -20   /* coefficient row bytes */
#define N_ROT   -24   /* (width - 2) / 3 */
#define N_FN    -28   /* the row routine for (width - 2) mod 3 */
#define N_LMAX  -32   /* levels the scratch holds */
#define N_LEFT  -36   /* iterations left */
#define N_L     -40   /* levels of this pass */
#define N_T     -44   /* the step */
#define N_DMA   -48   /* 1: the rows move by DMA, 0: by the core */
#define N_R0    -52   /* level 0's ring (4 rows) */
#define N_RK    -56   /* level 1's ring (3 rows); level k's at N_RK + 12 width (k - 1) */
#define N_RO    -60   /* the output's ring (2 rows) */
#define N_CR    -64   /* the coefficient ring (L + 1 rows) */
#define N_S3    -68   /* t mod 3 */
#define N_F4    -72   /* level 0's slot of the row arriving, (t + 2) mod 4 */
#define N_CF    -76   /* the coefficient slot of the row arriving, (t + 1) mod (L + 1) */
#define N_K     -80   /* the level */
#define N_R     -84   /* the row it makes, t - k + 1 */
#define N_CPTR  -88   /* its coefficient row */
#define N_CWRAP -92   /* the coefficient ring's bytes */
#define N_IN    -96   /* the level's input ring */
#define N_OUT   -100  /* the level's output ring (k < L) */
#define N_W12   -104  /* 12 width: a ring of 3 rows */
#define N_TEND  -108  /* the last step, height - 1 + L */
#define N_JOBP  -112  /* the addresses of N_JOB and N_X0 */
#define N_X0P   -116
#define N_OLAST -120  /* level L's output row */
#define N_OM    -124  /* the slots of the level's row in a 3-row ring: the row */
#define N_OT    -128  /* above */
#define N_OB    -132  /* below */
#define N_IM    -136  /* the slots the level reads (level 1: in level 0's 4-row ring) */
#define N_IT    -140
#define N_IB    -144
#define N_X0    -168  /* struct bvb_dma_xfer: level 0's row in (N_X1, N_X2 24 bytes below) */
#define N_X1    -192  /* the coefficient row in */
#define N_X2    -216  /* the output row out */
#define N_JOB   -328  /* the DMA job (BVB_DMA_JOB_BYTES) */
#define N_FRAME 340   /* locals at FP-328..-1, the C calls' 12 bytes of arguments below */


BVB_FUNC bvb_hs_iterate_n_asm
	[--sp] = (r7:4, p5:3);
	link N_FRAME;
	[fp + N_COEF] = r0;
	[fp + N_SRC] = r1;
	[fp + N_SS] = r2;
	r0 = 8;
	m0 = r0;                        /* the row routine's modifiers (the DMA calls keep them) */
	r0 = -4;
	m1 = r0;
	r0 = 4;
	m2 = r0;
	r1 = fp;
	r3 = N_JOB (x);
	r3 = r3 + r1;
	[fp + N_JOBP] = r3;
	r3 = N_X0 (x);
	r3 = r3 + r1;
	[fp + N_X0P] = r3;
	r0 = [fp + 64];                 /* iterations */
	cc = r0 <= 0;
	if cc jump .Ln_ret;
	[fp + N_LEFT] = r0;
	r6 = [fp + 56];                 /* width */
	r0 = r6 << 2;
	[fp + N_W4] = r0;
	r1 = r0 + r0;
	r1 = r1 + r0;
	[fp + N_W12] = r1;
	r1 = r6 << 1;
	r0 = r0 + r1;
	r1 = 1;
	r1 = r1 & r6;
	r1 = r1 << 1;
	r0 = r0 + r1;
	[fp + N_CP] = r0;               /* 2 BVB_HS_COEF_PITCH */
	r0 = r6;
	r0 += -2;
	r1 = 0xaaab (z);
	r2 = r0;
	r2 *= r1;
	r2 >>= 17;
	[fp + N_ROT] = r2;
	r1 = r2 << 1;
	r1 = r1 + r2;
	r0 = r0 - r1;
	p0.l = .Lrow1_0;
	p0.h = .Lrow1_0;
	p1.l = .Lrow1_1;
	p1.h = .Lrow1_1;
	cc = r0 == 1;
	if cc p0 = p1;
	p1.l = .Lrow1_2;
	p1.h = .Lrow1_2;
	cc = r0 == 2;
	if cc p0 = p1;
	[fp + N_FN] = p0;
	/* the most levels whose flow rows, 12 width (L + 1) bytes, fit BVB_HS_ITER_L1_BUDGET */
	r0 = 8;
	r1 = [fp + N_W12];
	r2 = 23040 (x);
.Ln_lmax:
	cc = r0 == 1;
	if cc jump .Ln_lmax_done;
	r3 = r0;
	r3 += 1;
	r3 *= r1;
	cc = r3 <= r2;
	if cc jump .Ln_lmax_done;
	r0 += -1;
	jump .Ln_lmax;
.Ln_lmax_done:
	[fp + N_LMAX] = r0;

.Ln_pass:
	/* passes = ceil(left / lmax), L = ceil(left / passes) */
	r0 = [fp + N_LEFT];
	r1 = [fp + N_LMAX];
	r2 = 1;
	r3 = r1;
.Ln_pp:
	cc = r0 <= r3;
	if cc jump .Ln_pp_done;
	r2 += 1;
	r3 = r3 + r1;
	jump .Ln_pp;
.Ln_pp_done:
	r4 = 1;
	r5 = r2;
.Ln_ll:
	cc = r0 <= r5;
	if cc jump .Ln_ll_done;
	r4 += 1;
	r5 = r5 + r2;
	jump .Ln_ll;
.Ln_ll_done:
	[fp + N_L] = r4;
	/* the rings: level 0 (4 rows), levels 1..L-1 (3 each), the output (2); coefficients L+1 */
	r0 = [fp + 68];
	[fp + N_R0] = r0;
	r1 = [fp + N_W4];
	r1 <<= 2;
	r0 = r0 + r1;
	[fp + N_RK] = r0;
	r1 = [fp + N_W12];
	r2 = r4;
	r2 += -1;
	r2 *= r1;
	r0 = r0 + r2;
	[fp + N_RO] = r0;
	r0 = [fp + 72];
	[fp + N_CR] = r0;
	r0 = r4;
	r0 += 1;
	r1 = [fp + N_CP];
	r0 *= r1;
	[fp + N_CWRAP] = r0;
	r0 = [fp + 60];
	r0 += -1;
	r0 = r0 + r4;
	[fp + N_TEND] = r0;
	/* the step counters at t = -2 */
	r0 = -2;
	[fp + N_T] = r0;
	r0 = 1;
	[fp + N_S3] = r0;
	r0 = 0;
	[fp + N_F4] = r0;
	[fp + N_CF] = r4;
	/* the three transfers: their shapes, and the addresses of step -2 */
	/* (a one-row transfer never uses its source stride; bvb_dma_prepare refuses one below the
	 * width, so in_stride 0, one row for every row, is given as the width) */
	r0 = [fp + N_SS];
	r1 = [fp + N_W4];
	r0 = max (r0, r1);
	[fp + N_X0 + DMAX_SS] = r0;
	r0 = [fp + N_W4];
	[fp + N_X0 + DMAX_DS] = r0;
	[fp + N_X0 + DMAX_W] = r0;
	r1 = 1;
	[fp + N_X0 + DMAX_ROWS] = r1;
	[fp + N_X2 + DMAX_SS] = r0;
	[fp + N_X2 + DMAX_W] = r0;
	[fp + N_X2 + DMAX_ROWS] = r1;
	[fp + N_X1 + DMAX_ROWS] = r1;
	r0 = [fp + 52];
	[fp + N_X2 + DMAX_DS] = r0;
	r0 = [fp + N_CP];
	[fp + N_X1 + DMAX_SS] = r0;
	[fp + N_X1 + DMAX_DS] = r0;
	[fp + N_X1 + DMAX_W] = r0;
	call .Ln_addr;
	/* DMA when it takes all three (every buffer where it reaches), else the core copies */
	r6 = 0;
	r5 = [fp + N_X0P];
.Ln_prep:
	r0 = [fp + N_JOBP];
	r1 = r6;
	r2 = r5;
	call _bvb_dma_prepare;
	r7 = 0;
	cc = r0 == 0;
	if !cc jump .Ln_mode;
	r5 += -24;
	r6 += 1;
	r7 = 1;
	cc = r6 < 3;
	if cc jump .Ln_prep;
.Ln_mode:
	[fp + N_DMA] = r7;

.Ln_step:
	/* wait for the job of the step before */
	r0 = [fp + N_T];
	cc = r0 < -1;
	if cc jump .Ln_nowait;
	r1 = [fp + N_DMA];
	cc = r1 == 0;
	if cc jump .Ln_nowait;
	call _bvb_dma_wait;
.Ln_nowait:
	call .Ln_addr;
	call .Ln_job;

	/* the levels: level k makes row t - k + 1 where that is a row */
	r0 = [fp + N_T];
	cc = r0 < 0;
	if cc jump .Ln_next;
	r1 = [fp + N_TEND];
	cc = r0 == r1;
	if cc jump .Ln_next;
	[fp + N_R] = r0;
	r7.l = 2731;
	r7.h = 5461;
	p2 = [fp + N_ROT];
	p3 = [fp + N_FN];
	r3 = [fp + N_W4];
	/* level L's output row, in the output ring */
	r1 = 1;
	r1 = r0 & r1;
	r1 *= r3;
	r2 = [fp + N_RO];
	r1 = r1 + r2;
	[fp + N_OLAST] = r1;
	/* row t's slots in a 3-row ring (offsets: the row, above, below); each level after
	 * the first reads its row's and writes its own into the same slots of its rings, and the
	 * next level's row is the slot above: the three rotate */
	r4 = [fp + N_S3];
	r0 = r4;
	r0 += -1;
	cc = r0 < 0;
	r1 = 2;
	if cc r0 = r1;
	r2 = r4;
	r2 += 1;
	cc = r2 == 3;
	r1 = 0;
	if cc r2 = r1;
	r4 *= r3;
	[fp + N_OM] = r4;
	r0 *= r3;
	[fp + N_OT] = r0;
	r2 *= r3;
	[fp + N_OB] = r2;
	/* row t's coefficient row */
	r0 = [fp + N_CF];
	r0 += -1;
	cc = r0 < 0;
	r1 = [fp + N_L];
	if cc r0 = r1;
	r1 = [fp + N_CP];
	r0 *= r1;
	r1 = [fp + N_CR];
	r0 = r0 + r1;
	[fp + N_CPTR] = r0;
	/* level 1 reads level 0's 4-row ring: row t, above, below */
	r4 = [fp + N_F4];
	r4 += 2;
	r0 = 3;
	r4 = r4 & r0;
	r5 = r4;
	r5 += 3;
	r5 = r5 & r0;
	r6 = r4;
	r6 += 1;
	r6 = r6 & r0;
	r4 *= r3;
	[fp + N_IM] = r4;
	r5 *= r3;
	[fp + N_IT] = r5;
	r6 *= r3;
	[fp + N_IB] = r6;
	r0 = [fp + N_R0];
	[fp + N_IN] = r0;
	r0 = [fp + N_RK];
	[fp + N_OUT] = r0;
	r0 = 1;
	[fp + N_K] = r0;
.Ln_level:
	r1 = [fp + N_R];
	cc = r1 < 0;
	if cc jump .Ln_lnext;
	r3 = [fp + 60];
	r3 += -1;
	cc = r3 < r1;
	if cc jump .Ln_lnext;
	r6 = [fp + N_IN];
	r4 = [fp + N_IM];
	r0 = [fp + N_IT];
	r2 = [fp + N_IB];
	cc = r1 == 0;
	if cc r0 = r4;                  /* row 0: the row above is itself */
	cc = r1 == r3;
	if cc r2 = r4;                  /* row h - 1: the row below is itself */
	r0 = r0 + r6;
	i0 = r0;
	r2 = r2 + r6;
	i1 = r2;
	r4 = r4 + r6;
	i2 = r4;
	r0 = [fp + N_CPTR];
	i3 = r0;
	r1 = [fp + N_W4];
	r0 = r0 + r1;
	p0 = r0;
	/* the output row: level L's into the output ring, the others into their own */
	r0 = [fp + N_OM];
	r1 = [fp + N_OUT];
	r0 = r0 + r1;
	r1 = [fp + N_K];
	r2 = [fp + N_L];
	cc = r1 == r2;
	r1 = [fp + N_OLAST];
	if cc r0 = r1;
	p1 = r0;
	call (p3);
.Ln_lnext:
	r0 = [fp + N_OM];
	r1 = [fp + N_OT];
	r2 = [fp + N_OB];
	[fp + N_OM] = r1;
	[fp + N_IM] = r1;
	[fp + N_OT] = r2;
	[fp + N_IT] = r2;
	[fp + N_OB] = r0;
	[fp + N_IB] = r0;
	r0 = [fp + N_CPTR];
	r1 = [fp + N_CP];
	r0 = r0 - r1;
	r1 = [fp + N_CR];
	cc = r0 < r1 (iu);
	r1 = [fp + N_CWRAP];
	r2 = r0 + r1;
	if cc r0 = r2;
	[fp + N_CPTR] = r0;
	r0 = [fp + N_OUT];
	[fp + N_IN] = r0;
	r1 = [fp + N_W12];
	r0 = r0 + r1;
	[fp + N_OUT] = r0;
	r0 = [fp + N_R];
	r0 += -1;
	[fp + N_R] = r0;
	r0 = [fp + N_K];
	r0 += 1;
	[fp + N_K] = r0;
	r1 = [fp + N_L];
	cc = r0 <= r1;
	if cc jump .Ln_level (bp);
.Ln_next:
	/* the next step: t + 1, the slots on */
	r0 = [fp + N_S3];
	r0 += 1;
	cc = r0 == 3;
	r1 = 0;
	if cc r0 = r1;
	[fp + N_S3] = r0;
	r0 = [fp + N_F4];
	r0 += 1;
	r1 = 3;
	r0 = r0 & r1;
	[fp + N_F4] = r0;
	r0 = [fp + N_CF];
	r0 += 1;
	r1 = [fp + N_L];
	cc = r1 < r0;
	r1 = 0;
	if cc r0 = r1;
	[fp + N_CF] = r0;
	r0 = [fp + N_T];
	r1 = [fp + N_TEND];
	cc = r0 == r1;
	r0 += 1;
	[fp + N_T] = r0;
	if cc jump .Ln_pass_end;
	jump.s .Ln_step;
.Ln_pass_end:
	r1 = [fp + N_DMA];
	cc = r1 == 0;
	if cc jump .Ln_waited;
	call _bvb_dma_wait;
.Ln_waited:
	/* the next pass reads uv_out and writes it in place (each input row arrives in L1 before
	 * the output row that replaces it leaves) */
	r0 = [fp + 48];
	[fp + N_SRC] = r0;
	r0 = [fp + 52];
	[fp + N_SS] = r0;
	r0 = [fp + N_LEFT];
	r1 = [fp + N_L];
	r0 = r0 - r1;
	[fp + N_LEFT] = r0;
	cc = r0 <= 0;
	if cc jump .Ln_ret;
	jump.s .Ln_pass;
.Ln_ret:
	unlink;
	(r7:4, p5:3) = [sp++];
	rts;

/* The step's job (R2 = its slots, 1 to 3): level 0's row t + 2 in (row h - 1 past the end: a slot no one reads),
   * coefficient row t + 1 in (t >= -1), output row t - L out (t >= L) */
.Ln_addr:
	r2 = [fp + 60];
	r2 += -1;
	r3 = 0;
	r0 = [fp + N_T];
	r0 += 2;
	r0 = min (r0, r2);
	r1 = [fp + N_SS];
	r0 *= r1;
	r1 = [fp + N_SRC];
	r0 = r0 + r1;
	[fp + N_X0 + DMAX_SRC] = r0;
	r0 = [fp + N_F4];
	r1 = [fp + N_W4];
	r0 *= r1;
	r1 = [fp + N_R0];
	r0 = r0 + r1;
	[fp + N_X0 + DMAX_DST] = r0;
	r0 = [fp + N_T];
	r0 += 1;
	r0 = min (r0, r2);
	r0 = max (r0, r3);
	r1 = [fp + N_CP];
	r0 *= r1;
	r1 = [fp + N_COEF];
	r0 = r0 + r1;
	[fp + N_X1 + DMAX_SRC] = r0;
	r0 = [fp + N_CF];
	r1 = [fp + N_CP];
	r0 *= r1;
	r1 = [fp + N_CR];
	r0 = r0 + r1;
	[fp + N_X1 + DMAX_DST] = r0;
	r0 = [fp + N_T];
	r0 += -1;
	r1 = 1;
	r0 = r0 & r1;
	r1 = [fp + N_W4];
	r0 *= r1;
	r1 = [fp + N_RO];
	r0 = r0 + r1;
	[fp + N_X2 + DMAX_SRC] = r0;
	r0 = [fp + N_T];
	r1 = [fp + N_L];
	r0 = r0 - r1;
	r0 = max (r0, r3);
	r1 = [fp + 52];
	r0 *= r1;
	r1 = [fp + 48];
	r0 = r0 + r1;
	[fp + N_X2 + DMAX_DST] = r0;
	r0 = [fp + N_T];
	r1 = [fp + N_L];
	r2 = 3;
	r3 = 2;
	cc = r0 < r1;
	if cc r2 = r3;
	cc = r0 < -1;
	r3 = 1;
	if cc r2 = r3;
	rts;

/* Runs slots 0 .. R2-1 of the step's job (level 0's row, the coefficient row, the output row):
 * started on the DMA (the slots re-addressed) or copied by the core at once. */
.Ln_job:
	[--sp] = rets;
	r7 = r2;
	r6 = 0;
	r5 = [fp + N_X0P];
	r0 = [fp + N_DMA];
	cc = r0 == 0;
	if cc jump .Ln_job_core;
.Ln_job_move:
	r0 = [fp + N_JOBP];
	r1 = r6;
	r2 = r5;
	call _bvb_dma_move;
	r5 += -24;
	r6 += 1;
	cc = r6 < r7;
	if cc jump .Ln_job_move;
	r0 = [fp + N_JOBP];
	r1 = r7;
	call _bvb_dma_start;
	rets = [sp++];
	rts;
.Ln_job_core:
	/* P0, P1, P2 = the transfer's source, destination, width: a word at a time */
	p2 = r5;
	p0 = [p2 + DMAX_SRC];
	p1 = [p2 + DMAX_DST];
	p2 = [p2 + DMAX_W];
	p2 = p2 >> 2;
	lsetup (.Ln_cp, .Ln_cp_end) lc0 = p2;
.Ln_cp:
	r0 = [p0++];
.Ln_cp_end:
	[p1++] = r0;
	r5 += -24;
	r6 += 1;
	cc = r6 < r7;
	if cc jump .Ln_job_core;
	rets = [sp++];
	rts;
BVB_ENDFUNC bvb_hs_iterate_n_asm

/* ---------------------------------------------------------------------------------------------
 * bvb_hs_prepare_asm(i1, i2, width, height, stride, alpha2_q4, coef)
 * --------------------------------------------------------------------------------------------- */

/* Shift counts by SIGNBITS(D), D in [2^10, 2^22) so SIGNBITS in 9..20: k = (sb - 1) >> 1 with
 * D 4^k in [2^28, 2^30); word 1 = (k - 5 : k), word 2 = 2k - 20 (the right shift giving the
 * table index D 4^k >> 20). */
	.section .l1.data.a, "aw"
	.align 4
.Lhs_counts:
	.int 0xffff0004, 0xffff0004, 0x00000005, 0x00000005, 0x00010006, 0x00010006
	.int 0x00020007, 0x00020007, 0x00030008, 0x00030008, 0x00040009, 0x00040009
	.int -12, -12, -10, -10, -8, -8, -6, -6, -4, -4, -2, -2

/* Stack frame of bvb_hs_prepare_asm (FP-relative locals). */
#define HS_PITCH   -4   /* coefficient row pitch, bytes */
#define HS_W4      -8   /* 4 * width: offset of the gt row */
#define HS_NGF     -12  /* full groups of 4 columns */
#define HS_TAIL    -16  /* width - 4 * groups */
#define HS_NMID    -20  /* phase-2 pairs with a pair after them: width / 2 - 1 */
#define HS_ODD     -24  /* width & 1 */
/* The streamed path's (bvb/stream.h) */
#define HS_ST      -28  /* the stream's state: scratch + BVB_HS_PREP_MAIN(width) */
#define HS_TOP     -32  /* the sum row with pass A of the output row's frame row */
#define HS_ROW0    -36  /* frame 1's row 0 in L1 */
#define HS_CSUM    -40  /* the two sum rows' addresses added (the other = CSUM - one) */
#define HS_N       -44  /* band 0's rows */
#define HS_ALPHA   -48  /* alpha2_q4, clamped (A1 again after each stream call) */
#define HS_F1      -52  /* the arguments in registers */
#define HS_F2      -56
#define HS_DEST    -60  /* where this row's pass A goes */
#define HS_W       -64  /* width */
#define HS_XFER    -88  /* the last row's transfer (struct bvb_dma_xfer) */
#define HS_JOB     -200 /* and its DMA job (BVB_DMA_JOB_BYTES) */
#define HS_PRE     -248 /* the table's and row 0's transfers, on band 0's job (2 x 24 bytes) */
#define HS_PREP_L1_BUDGET 24576 /* BVB_HS_PREP_L1_BUDGET (bvb/hornschunck.h is C only) */
#define HS_FRAME   264  /* locals at FP-248..-1, the C calls' 16 bytes of arguments below */

/* Pass A: per-row frame sums and differences of one row of both frames, r = I2 + I1 and
 * n = I2 - I1 per column, into the row's coefficient area: per group of 4 columns the words
 * (r1:r0) (r3:r2) (n1:n0) (n3:n2), then one word (n:r) per remaining column.
 * In: R0 = frame-1 row, R1 = frame-2 row, P0 = destination.
 * BYTEOP16P/M take 4 bytes at offset I0 & 3 (frame 2) and I1 & 3 (frame 1) from two words of
 * each frame, R1:0 and R3:2. Groups alternate: the word a group shares with the next stays, the
 * other is replaced, and the next group reads the pair reversed (R). Words are read only up to
 * the last one holding a pixel of the row: the group after the last one needs its second word
 * only when the row is misaligned (M1, M3 = 4 - that word's offset). */
.macro HS_PA_LOOP tag
	lsetup (.Lpa_two\tag, .Lpa_two_end\tag) lc0 = p3;
.Lpa_two\tag:
	(r7, r6) = byteop16m (r1:0, r3:2) || [p0++] = r4 || r0 = [i3++];
	mnop || [p0++] = r5 || r2 = [i2++];
	[p0++] = r6;
	(r5, r4) = byteop16p (r1:0, r3:2) (r) || [p0++] = r7;
	(r7, r6) = byteop16m (r1:0, r3:2) (r) || [p0++] = r4 || r1 = [i3++];
	mnop || [p0++] = r5 || r3 = [i2++];
	[p0++] = r6;
.Lpa_two_end\tag:
	(r5, r4) = byteop16p (r1:0, r3:2) || [p0++] = r7;
.endm

.macro HS_PASS_A tag
	i1 = r0;                        /* BYTEOP alignment: operand 2 = frame 1 */
	i0 = r1;                        /* operand 1 = frame 2 */
	r2 = -4;
	r3 = r0 & r2;
	i2 = r3;                        /* aligned word streams */
	r3 = r1 & r2;
	i3 = r3;
	/* 4 if the row is misaligned (a group spans two words), else 0 */
	r2 = 3;
	r3 = r0 & r2;
	r3 += 3;
	r2 = 4;
	r3 = r3 & r2;
	m0 = r3;
	r3 = r2 - r3;
	m1 = r3;
	r2 = 3;
	r3 = r1 & r2;
	r3 += 3;
	r2 = 4;
	r3 = r3 & r2;
	m2 = r3;
	r3 = r2 - r3;
	m3 = r3;
	p3 = [fp + HS_NGF];
	r2 = p3;
	r3 = r2 << 2;
	r0 = r0 + r3;
	r1 = r1 + r3;
	p1 = r0;                        /* byte pointers for the remaining columns */
	p2 = r1;
	cc = r2 <= 1;
	if cc jump .Lpa_one\tag;
	mnop || r0 = [i3++] || r2 = [i2++];
	mnop || r1 = [i3++] || r3 = [i2++];
	(r5, r4) = byteop16p (r1:0, r3:2);
	r6 = p3;
	cc = bittst (r6, 0);
	if cc jump .Lpa_odd\tag;
	/* Even count: (groups - 2) / 2 looped pairs, then a normal group and a reversed one. */
	r6 += -2;
	r6 >>= 1;
	p3 = r6;
	cc = r6 == 0;
	if cc jump .Lpa_even_end\tag;
	HS_PA_LOOP e\tag
.Lpa_even_end\tag:
	i3 -= m3;
	i2 -= m1;
	(r7, r6) = byteop16m (r1:0, r3:2) || [p0++] = r4 || r0 = [i3];
	mnop || [p0++] = r5 || r2 = [i2];
	[p0++] = r6;
	(r5, r4) = byteop16p (r1:0, r3:2) (r) || [p0++] = r7;
	(r7, r6) = byteop16m (r1:0, r3:2) (r) || [p0++] = r4;
	jump .Lpa_store3\tag;
.Lpa_odd\tag:
	/* Odd count: (groups - 3) / 2 looped pairs, a normal group, a reversed one, a normal one. */
	r6 += -3;
	r6 >>= 1;
	p3 = r6;
	cc = r6 == 0;
	if cc jump .Lpa_odd_end\tag;
	HS_PA_LOOP o\tag
.Lpa_odd_end\tag:
	(r7, r6) = byteop16m (r1:0, r3:2) || [p0++] = r4 || r0 = [i3++];
	mnop || [p0++] = r5 || r2 = [i2++];
	[p0++] = r6;
	(r5, r4) = byteop16p (r1:0, r3:2) (r) || [p0++] = r7;
	i3 -= m3;
	i2 -= m1;
	(r7, r6) = byteop16m (r1:0, r3:2) (r) || [p0++] = r4 || r1 = [i3];
	mnop || [p0++] = r5 || r3 = [i2];
	[p0++] = r6;
	(r5, r4) = byteop16p (r1:0, r3:2) || [p0++] = r7;
	(r7, r6) = byteop16m (r1:0, r3:2) || [p0++] = r4;
	jump .Lpa_store3\tag;
.Lpa_one\tag:
	/* One group (or none): both words of it, the second only if the row is misaligned. */
	cc = r2 == 0;
	if cc jump .Lpa_tail\tag;
	mnop || r0 = [i3 ++ m2] || r2 = [i2 ++ m0];
	mnop || r1 = [i3 ++ m3] || r3 = [i2 ++ m1];
	(r5, r4) = byteop16p (r1:0, r3:2);
	(r7, r6) = byteop16m (r1:0, r3:2) || [p0++] = r4;
.Lpa_store3\tag:
	[p0++] = r5;
	[p0++] = r6;
	[p0++] = r7;
.Lpa_tail\tag:
	p3 = [fp + HS_TAIL];
	cc = p3 == 0;
	if cc jump .Lpa_done\tag;
	lsetup (.Lpa_col\tag, .Lpa_col_end\tag) lc0 = p3;
.Lpa_col\tag:
	r0 = b[p1++] (z);
	r1 = b[p2++] (z);
	r2 = r1 + r0, r3 = r1 - r0;
	r2 = pack (r3.l, r2.l);
.Lpa_col_end\tag:
	[p0++] = r2;
.Lpa_done\tag:
.endm

/* Pass B: column sums s, vertical differences p and time differences q of the row pair from
 * the two rows' pass-A data (I2: this row, I3: the row below, or this row again on the last):
 * C = (p:s) per column into the row's first 4w bytes (in place), q into its gt row (P1). */
.macro HS_PASS_B tag
	p3 = [fp + HS_NGF];
	cc = p3 == 0;
	if cc jump .Lpb_tail\tag;
	p3 += -1;
	mnop || r0 = [i2++] || r2 = [i3++];
	r2 = r2 +|+ r0, r0 = r2 -|- r0 || r1 = [i2++] || r3 = [i3++];
	cc = p3 == 0;
	if cc jump .Lpb_last\tag;
	lsetup (.Lpb_grp\tag, .Lpb_grp_end\tag) lc0 = p3;
.Lpb_grp\tag:
	r3 = r3 +|+ r1, r1 = r3 -|- r1 || r4 = [i2++] || r6 = [i3++];
	r6 = r6 +|+ r4 || r5 = [i2++] || r7 = [i3++];
	r7 = r7 +|+ r5 || [p1++] = r6;
	r4 = pack (r0.l, r2.l) || [p1++] = r7;
	r5 = pack (r0.h, r2.h) || [p0++] = r4 || r0 = [i2++];
	r6 = pack (r1.l, r3.l) || [p0++] = r5 || r2 = [i3++];
	r7 = pack (r1.h, r3.h) || [p0++] = r6 || r1 = [i2++];
.Lpb_grp_end\tag:
	r2 = r2 +|+ r0, r0 = r2 -|- r0 || [p0++] = r7 || r3 = [i3++];
.Lpb_last\tag:
	r3 = r3 +|+ r1, r1 = r3 -|- r1 || r4 = [i2++] || r6 = [i3++];
	r6 = r6 +|+ r4 || r5 = [i2++] || r7 = [i3++];
	r7 = r7 +|+ r5 || [p1++] = r6;
	r4 = pack (r0.l, r2.l) || [p1++] = r7;
	r5 = pack (r0.h, r2.h) || [p0++] = r4;
	r6 = pack (r1.l, r3.l) || [p0++] = r5;
	r7 = pack (r1.h, r3.h) || [p0++] = r6;
	[p0++] = r7;
.Lpb_tail\tag:
	p3 = [fp + HS_TAIL];
	cc = p3 == 0;
	if cc jump .Lpb_done\tag;
	lsetup (.Lpb_col\tag, .Lpb_col_end\tag) lc0 = p3;
.Lpb_col\tag:
	mnop || r0 = [i2++] || r1 = [i3++];
	r2 = r1 +|+ r0, r3 = r1 -|- r0;
	r3 = pack (r3.l, r2.l);
	r2 = r2 >> 16 || [p0++] = r3;
.Lpb_col_end\tag:
	w[p1++] = r2;
.Lpb_done\tag:
.endm

/* Phase 2: from C and q (pass B) to the coefficients, in place, software-pipelined over pixel
 * pairs (A = x, B = x + 1) so that no table pointer is used in the address stage within four
 * cycles of being moved from a data register (the model's move-into-address-register stall,
 * GCC bfin_adjust_cost: 4 cycles).
 * Per pixel: G = C(x+1) +|- C(x), D = alpha2 + G.L^2 + G.H^2 (3 MAC), SB = SIGNBITS D; the
 * count table pointer P = counts + 4 SB gives c = 2k - 20 ([P+48]), k ([P]) and k - 5
 * ([P+2]); I = D lshift c; the rsqrt pointer Q = rsqrt + 2 I gives S; G = (G << k) * S
 * (S2RND); per pair gt = (q(x+1):q(x)) +|+ (q(x+2):q(x+1)), each half shifted by its k - 5 and
 * multiplied by its S. One iteration of 28 cycles holds pair j's A chain, pair j's B chain up to
 * its Q move, and pair j-1's B tail (Q, S, k and k - 5, the multiplies, its stores): the four
 * cycles after each pointer move are taken by the other pixel's work.
 *   cycle  0-5  A: G, D, SB, P0 = SB          14-19  B: G, D, SB, P2 = SB
 *          6-9  B(j-1): Q, G <<= k, * S, gt.H 20-23  A: Q, gt, G <<= k, * S
 *         10-13 A: P0, [c], I, P1 = I         24-27  B: P2, gt.L (A), I, P1 = I
 *   (11: gt * S of pair j-1)
 * Registers: R0 G(A) / C(x), R1 G(B) / C(x+2), R2 gt, R3 (S_B:S_A), R4 C(x+1) / (q(x+2):q(x+1)),
 * R5 the table values, R6 D / I, R7 (0:SB); P0, P2 the count pointers of A and B, P1 the rsqrt
 * pointer (A's and B's never overlap); I0 C loads, I1 q loads, I2 (gy':gx') stores, I3 gt'
 * stores; M0 = 8, M1 = 2.
 * bp = 1: this iteration also finishes pair j-1's B. kind: 0 a pair with a pair after it,
 * 1 the last pair before a lone last pixel (odd width), 2 the last pair (even width, its
 * C(x+2) = C(x+1), q(x+2) = q(x+1)), 3 the lone last pixel (odd width; its partner is a copy
 * of it whose results are dropped; the pad after its gt' is 0). */
.macro HS_IT bp, kind, last=
	r0 = r4 +|- r0;                                 /* G(A) */
	a0 = r0.l * r0.l (is);
	a0 += r0.h * r0.h (is);
	r6 = (a0 += a1);                                /* D(A) */
	r7.l = signbits r6;
	p0 = r7;
.if \bp
	p1 = p5 + (p1 << 1);                            /* Q of B(j-1) */
	r1 = ashift r1 by r5.l (v) || r3.h = w[p1];     /* G(B(j-1)) <<= k; S */
	r1.h = r1.h * r3.h, r1.l = r1.l * r3.h (s2rnd) || r5 = w[p2 + 2] (x);
	r2.h = ashift r2.h by r5.l || [i2++] = r1;
.else
	/* the first pair of a row: the modifiers, in the cycles P0 needs */
	r1 = 8;
	m0 = r1;
	r1 = 2;
	m1 = r1;
.endif
	p0 = p4 + (p0 << 2);
.if \bp
.if \kind == 0
	r2.h = r2.h * r3.h, r2.l = r2.l * r3.l (s2rnd) || r5 = [p0 + 48] || r1 = [i0++];
.elseif \kind == 1
	r2.h = r2.h * r3.h, r2.l = r2.l * r3.l (s2rnd) || r5 = [p0 + 48] || r1 = [i0];
.else
	r2.h = r2.h * r3.h, r2.l = r2.l * r3.l (s2rnd) || r5 = [p0 + 48];
.endif
	r6 = lshift r6 by r5.l || [i3++] = r2;          /* I(A) */
.else
.if \kind == 0
	mnop || r5 = [p0 + 48] || r1 = [i0++];
.elseif \kind == 1
	mnop || r5 = [p0 + 48] || r1 = [i0];
.else
	r5 = [p0 + 48];
.endif
	r6 = lshift r6 by r5.l;
.endif
	p1 = r6;
.if \kind <= 1
	r1 = r1 +|- r4 || r5 = w[p0] (x) || r2 = [i1++];    /* G(B); k(A); (q(x+1):q(x)) */
	a0 = r1.l * r1.l (is) || r4.h = w[i1--];
	a0 += r1.h * r1.h (is) || r4.l = w[i1++];
.elseif \kind == 2
	r1 = r4 +|- r4 || r5 = w[p0] (x) || r2 = [i1 ++ m1];
	a0 = r1.l * r1.l (is) || r4.h = w[i1];
	a0 += r1.h * r1.h (is) || r4.l = w[i1];
.else
	r1 = r4 +|- r4 || r5 = w[p0] (x) || r2.l = w[i1];
	a0 = r1.l * r1.l (is) || r4.l = w[i1];
	a0 += r1.h * r1.h (is);
.endif
	r6 = (a0 += a1);                                /* D(B) */
	r7.l = signbits r6;
	p2 = r7;
	p1 = p5 + (p1 << 1);                            /* Q(A) */
	r2 = r2 +|+ r4 || r3.l = w[p1];                 /* gt; S(A) */
.if \kind == 0
	r0 = ashift r0 by r5.l (v) || r5 = w[p0 + 2] (x) || r4 = [i0--];
.elseif \kind == 1
	r0 = ashift r0 by r5.l (v) || r5 = w[p0 + 2] (x) || r4 = [i0];
.else
	r0 = ashift r0 by r5.l (v) || r5 = w[p0 + 2] (x);
.endif
	r0.h = r0.h * r3.l, r0.l = r0.l * r3.l (s2rnd);
	p2 = p4 + (p2 << 2);
	r2.l = ashift r2.l by r5.l || r5 = [p2 + 48] || [i2++] = r0;
.if \kind == 0
	r6 = lshift r6 by r5.l || r5 = w[p2] (x) || r0 = [i0 ++ m0];
.elseif \kind == 1
	r6 = lshift r6 by r5.l || r5 = w[p2] (x) || r0 = [i0];
.else
	r6 = lshift r6 by r5.l || r5 = w[p2] (x);
.endif
.ifnb \last
\last:
.endif
	p1 = r6;                                        /* I(B) */
.endm

/* The tail of the last pair's B (single = 1: the lone pixel's gt' word only). */
.macro HS_DRAIN single
.if \single
	r2.l = r2.l * r3.l (s2rnd);
	r2 = r2.l (z);
	[i3++] = r2;
.else
	p1 = p5 + (p1 << 1);
	r1 = ashift r1 by r5.l (v) || r3.h = w[p1];
	r1.h = r1.h * r3.h, r1.l = r1.l * r3.h (s2rnd) || r5 = w[p2 + 2] (x);
	r2.h = ashift r2.h by r5.l || [i2++] = r1;
	r2.h = r2.h * r3.h, r2.l = r2.l * r3.l (s2rnd);
	[i3++] = r2;
.endif
.endm

/* Phase 2 of one row. In: P3 = row. floor(width / 2) - 1 pairs with a pair after them, then
 * the last pair (even width) or the last pair and the lone last pixel (odd width). */
.macro HS_PHASE2 tag
	i0 = p3;                        /* C loads */
	i2 = p3;                        /* (gy':gx') stores */
	r0 = p3;
	r1 = [fp + HS_W4];
	r0 = r0 + r1;
	i1 = r0;                        /* q loads */
	i3 = r0;                        /* gt' stores */
	r7 = 0;
	p3 = [fp + HS_NMID];
	r0 = [i0++];
	r4 = [i0++];
	cc = p3 == 0;
	if cc jump .Lp2_t0\tag;
	HS_IT 0, 0
	p3 += -1;
	cc = p3 == 0;
	if cc jump .Lp2_t1\tag;
	lsetup (.Lp2_pair\tag, .Lp2_pair_end\tag) lc0 = p3;
.Lp2_pair\tag:
	HS_IT 1, 0, .Lp2_pair_end\tag
.Lp2_t1\tag:
	r6 = [fp + HS_ODD];
	cc = r6 == 0;
	if !cc jump .Lp2_o1\tag;
	HS_IT 1, 2
	HS_DRAIN 0
	jump .Lp2_done\tag;
.Lp2_o1\tag:
	HS_IT 1, 1
.Lp2_single\tag:
	HS_IT 1, 3
	HS_DRAIN 1
	jump .Lp2_done\tag;
.Lp2_t0\tag:
	/* width 2 or 3 */
	r6 = [fp + HS_ODD];
	cc = r6 == 0;
	if !cc jump .Lp2_o0\tag;
	HS_IT 0, 2
	HS_DRAIN 0
	jump .Lp2_done\tag;
.Lp2_o0\tag:
	HS_IT 0, 1
	jump .Lp2_single\tag;
.Lp2_done\tag:
.endm

#include "bvb/stream.h"

BVB_FUNC bvb_hs_prepare_asm
	[--sp] = (r7:4, p5:3);
	link HS_FRAME;
	/* Arguments 4-8 at FP + 8 (RETS, FP) + 28 (saves) + 12. */
	[fp + HS_F1] = r0;
	[fp + HS_F2] = r1;
	[fp + HS_W] = r2;
	r3 = r2 << 2;
	[fp + HS_W4] = r3;
	r4 = r2 << 1;
	r4 = r4 + r3;
	r5 = 1;
	r5 = r5 & r2;
	[fp + HS_ODD] = r5;
	r6 = r5 << 1;
	r4 = r4 + r6;
	[fp + HS_PITCH] = r4;
	r3 = r2 >> 2;
	[fp + HS_NGF] = r3;
	r4 = 3;
	r4 = r4 & r2;
	[fp + HS_TAIL] = r4;
	r3 = r2 >> 1;
	r3 += -1;
	[fp + HS_NMID] = r3;
	r3 = [fp + 56];                 /* alpha2_q4, clamped to 1024..1048576 */
	r4 = 1024;
	r3 = max (r3, r4);
	r4.l = 0;
	r4.h = 0x10;
	r3 = min (r3, r4);
	[fp + HS_ALPHA] = r3;
	p4.l = .Lhs_counts - 36;
	p4.h = .Lhs_counts - 36;
	p5.l = _bvb_hs_rsqrt_table - 512;
	p5.h = _bvb_hs_rsqrt_table - 512;
	r0 = [fp + 64];                 /* scratch */
	cc = r0 == 0;
	if cc jump .Lpr_direct;
	call .Lps_stream;
	cc = r0 == 0;
	if !cc jump .Lpr_direct;
	jump.l .Lpr_ret;
.Lpr_direct:
	/* The frames and coefficients where they are. */
	r0 = [fp + HS_F1];
	b1 = r0;                        /* frame 1 row */
	r0 = [fp + HS_F2];
	b2 = r0;                        /* frame 2 row */
	r3 = [fp + 52];
	b3 = r3;                        /* stride */
	r3 = [fp + HS_ALPHA];
	a1 = r3;
	p3 = [fp + 60];
	b0 = p3;                        /* coefficient row */
	p0 = p3;
	r0 = b1;
	r1 = b2;
	HS_PASS_A 0
	r0 = [fp + 48];                 /* height */
	r0 += -1;
	lc1 = r0;
	lsetup (.Lpr_row, .Lpr_row_end) lc1;
.Lpr_row:
	r2 = b3;
	r0 = b1;
	r0 = r0 + r2;
	b1 = r0;
	r1 = b2;
	r1 = r1 + r2;
	b2 = r1;
	r2 = b0;
	r3 = [fp + HS_PITCH];
	r2 = r2 + r3;
	p0 = r2;
	HS_PASS_A 1
	p3 = b0;
	r0 = p3;
	i2 = r0;
	r1 = [fp + HS_PITCH];
	r1 = r1 + r0;
	i3 = r1;
	p0 = p3;
	r1 = [fp + HS_W4];
	r0 = r0 + r1;
	p1 = r0;
	HS_PASS_B 1
	p3 = b0;
	HS_PHASE2 1
	r0 = b0;
	r1 = [fp + HS_PITCH];
	r0 = r0 + r1;
.Lpr_row_end:
	b0 = r0;
	/* Last row: the row below is the row itself. */
	p3 = b0;
	r0 = p3;
	i2 = r0;
	i3 = r0;
	p0 = p3;
	r1 = [fp + HS_W4];
	r0 = r0 + r1;
	p1 = r0;
	HS_PASS_B 2
	p3 = b0;
	HS_PHASE2 2
.Lpr_ret:
	unlink;
	(r7:4, p5:3) = [sp++];
	rts;

/* The streamed path: R0 = 0 when done, else the stream refused and nothing was written (the
 * caller takes the direct path). Called from the kernel's frame (FP), RETS saved here.
 * The stream carries rows 1..h-1 of both frames in and coefficient rows 0..h-2 out: output row
 * y needs frame rows y and y+1, and the band with frame row y+1 is the one that makes it. Pass
 * A of each band row (frame row y+1) goes to the next output row's area in the band, or, for
 * the band's last row, to the sum row the next band starts from (TOP); pass B of output row y
 * takes TOP and that. The two sum rows alternate, so a band of one row reads one and fills the
 * other. Row h-1 (the row below it is itself) is made in the last band's output buffer once
 * the stream has sent it, and leaves by one DMA transfer. */
.Lps_stream:
	[--sp] = rets;
	/* The layout (bvb/hornschunck.h, BVB_HS_PREPARE_SCRATCH_BYTES): sum row 0 at the start,
	 * sum row 1 at the next 4 KB past it (4 width rounded up), the table and frame 1's row 0
	 * after it, the stream from the 4 KB boundary after those. */
	r0 = [fp + 64];
	r1 = [fp + HS_W4];
	[fp + HS_TOP] = r0;
	r2 = 4095;
	r3 = r1 + r2;
	r2 = ~r2;
	r3 = r3 & r2;                   /* SUM1 */
	r4 = r0 + r3;
	r5 = r0 + r4;
	[fp + HS_CSUM] = r5;
	r4 = r4 + r1;                   /* the table */
	[fp + HS_PRE + DMAX_DST] = r4;
	r5 = 1536 (x);
	r4 = r4 + r5;                   /* frame 1's row 0 */
	[fp + HS_ROW0] = r4;
	[fp + HS_PRE + 24 + DMAX_DST] = r4;
	[fp + HS_PRE + DMAX_SS] = r5;
	[fp + HS_PRE + DMAX_DS] = r5;
	[fp + HS_PRE + DMAX_W] = r5;
	r5 = 1;
	[fp + HS_PRE + DMAX_ROWS] = r5;
	[fp + HS_PRE + 24 + DMAX_ROWS] = r5;
	r5.l = _bvb_hs_rsqrt_table;
	r5.h = _bvb_hs_rsqrt_table;
	[fp + HS_PRE + DMAX_SRC] = r5;
	r5 = [fp + HS_F1];
	[fp + HS_PRE + 24 + DMAX_SRC] = r5;
	r5 = [fp + HS_W];
	[fp + HS_PRE + 24 + DMAX_SS] = r5;
	[fp + HS_PRE + 24 + DMAX_DS] = r5;
	[fp + HS_PRE + 24 + DMAX_W] = r5;
	r5 += 3;
	r2 = -4;
	r5 = r5 & r2;                   /* its bytes, rounded to words */
	r4 = r4 - r0;
	r4 = r4 + r5;
	r2 = 4095;
	r4 = r4 + r2;
	r2 = ~r2;
	r4 = r4 & r2;                   /* MAIN (the rounding of the row's 4 bytes is inside it) */
	r0 = r0 + r4;
	[fp + HS_ST] = r0;
	/* Band rows: (budget - MAIN - state - 24) / (2 (2 width + pitch)), 1 to 16. */
	r2 = HS_PREP_L1_BUDGET - BVB_STREAM_STATE_BYTES - 24 (x);
	r2 = r2 - r4;
	r5 = [fp + HS_W];
	r5 = r5 << 1;
	r3 = [fp + HS_PITCH];
	r5 = r5 + r3;
	r5 = r5 << 1;
	r6 = 0;
	r3 = r5;
	r7 = BVB_STREAM_MAX_BAND;
.Lps_fit:
	cc = r2 < r3;
	if cc jump .Lps_fitted;
	r6 += 1;
	r3 = r3 + r5;
	cc = r6 < r7;
	if cc jump .Lps_fit (bp);
.Lps_fitted:
	r7 = 1;
	r6 = max (r6, r7);
	p0 = r0;
	r2 = [fp + 52];                 /* stride */
	r1 = [fp + HS_F1];
	r1 = r1 + r2;
	[p0 + ST_SRC0] = r1;
	r1 = [fp + HS_F2];
	r1 = r1 + r2;
	[p0 + ST_SRC1] = r1;
	[p0 + ST_SS0] = r2;
	[p0 + ST_SS1] = r2;
	r1 = [fp + HS_W];
	[p0 + ST_SB0] = r1;
	[p0 + ST_SB1] = r1;
	r1 = [fp + 60];
	[p0 + ST_DST] = r1;
	r1 = [fp + HS_PITCH];
	[p0 + ST_DS] = r1;
	[p0 + ST_DB] = r1;
	r1 = [fp + 48];
	r1 += -1;
	[p0 + ST_ROWS] = r1;
	r1 = 2;
	[sp + 12] = r1;
	r1 = r6;
	r2 = fp;
	r3 = HS_PRE (x);
	r2 = r2 + r3;
	call _bvb_stream_open_rows;
	cc = r0 == 0;
	if cc jump .Lps_open;
	jump.l .Lps_ret;
.Lps_open:
	/* The table from L1 from here on (P5: its address - 512, as in the direct path). */
	r0 = [fp + HS_ROW0];
	r1 = -(1536 + 512) (x);
	r0 = r0 + r1;
	p5 = r0;
	r0 = [fp + HS_ST];
	call _bvb_stream_next;          /* band 0, the table and row 0 are in */
	[fp + HS_N] = r0;
	/* Pass A of frame row 0 (frame 1's from L1, frame 2's from where it is) into sum row 0. */
	r0 = [fp + HS_ROW0];
	r1 = [fp + HS_F2];
	p0 = [fp + HS_TOP];
	HS_PASS_A 3
	r0 = [fp + HS_N];
	jump .Lps_more;
.Lps_band:
	/* After the last band the kernel finishes the stream itself (.Lps_last). */
	p0 = [fp + HS_ST];
	r0 = [p0 + ST_FLY_N];
	cc = r0 == 0;
	if !cc jump .Lps_next;
	jump.l .Lps_last;
.Lps_next:
	r0 = p0;
	call _bvb_stream_next;
	cc = r0 == 0;
	if !cc jump .Lps_more;
	jump.l .Lps_last;
.Lps_more:
	lc1 = r0;
	p0 = [fp + HS_ST];
	r1 = [p0 + ST_IN0];
	b1 = r1;
	r1 = [p0 + ST_IN1];
	b2 = r1;
	r1 = [p0 + ST_OUT];
	b0 = r1;
	r1 = [fp + HS_ALPHA];
	a1 = r1;
	lsetup (.Lps_row, .Lps_row_end) lc1;
.Lps_row:
	/* Pass A of the band row (frame row y + 1) into the sum row TOP is not */
	r0 = [fp + HS_CSUM];
	r1 = [fp + HS_TOP];
	r0 = r0 - r1;
	[fp + HS_DEST] = r0;
	p0 = r0;
	r0 = b1;
	r1 = b2;
	HS_PASS_A 4
	/* Pass B: TOP and DEST into output row y (C, then q in its gt row); DEST is the next TOP */
	p3 = b0;
	r0 = [fp + HS_TOP];
	i2 = r0;
	r0 = [fp + HS_DEST];
	i3 = r0;
	[fp + HS_TOP] = r0;
	p0 = p3;
	r0 = p3;
	r1 = [fp + HS_W4];
	r0 = r0 + r1;
	p1 = r0;
	HS_PASS_B 3
	p3 = b0;
	HS_PHASE2 3
	r0 = b0;
	r1 = [fp + HS_PITCH];
	r0 = r0 + r1;
	b0 = r0;
	r1 = [fp + HS_W];
	r0 = b1;
	r0 = r0 + r1;
	b1 = r0;
	r0 = b2;
	r0 = r0 + r1;
.Lps_row_end:
	b2 = r0;
	jump.l .Lps_band;
.Lps_last:
	/* The last band: once the band before's output is out, its own leaves while row h-1 (pass
	 * B of TOP with itself) is made in the other output buffer, which then leaves too. */
	p0 = [fp + HS_ST];
	r0 = [p0 + ST_RUNNING];
	cc = r0 == 0;
	if cc jump .Lps_idle;
	call _bvb_dma_wait;
.Lps_idle:
	p0 = [fp + HS_ST];
	r0 = [p0 + ST_OUT];
	r1 = [p0 + ST_CUR_ROW];
	r2 = [p0 + ST_CUR_N];
	call .Lps_send;
	[fp + HS_N] = r0;
	p0 = [fp + HS_ST];
	r0 = [p0 + ST_BUF_OUT];
	r1 = [p0 + ST_BUF_OUT + 4];
	r0 = r0 + r1;
	r1 = [p0 + ST_OUT];
	r0 = r0 - r1;
	[fp + HS_DEST] = r0;
	p3 = r0;
	r0 = [fp + HS_TOP];
	i2 = r0;
	i3 = r0;
	p0 = p3;
	r0 = p3;
	r1 = [fp + HS_W4];
	r0 = r0 + r1;
	p1 = r0;
	HS_PASS_B 4
	r1 = [fp + HS_ALPHA];
	a1 = r1;
	p3 = [fp + HS_DEST];
	HS_PHASE2 4
	r0 = [fp + HS_N];
	cc = r0 == 0;
	if cc jump .Lps_sent;
	call _bvb_dma_wait;
.Lps_sent:
	r0 = [fp + HS_DEST];
	r1 = [fp + 48];
	r1 += -1;
	r2 = 1;
	call .Lps_send;
	cc = r0 == 0;
	if cc jump .Lps_ret;
	call _bvb_dma_wait;
	r0 = 0;
	jump .Lps_ret;

/* R2 rows from R0 (L1) to coefficient row R1 on, by one DMA job, started (R0 = 1: wait for it),
 * or by the core where DMA refuses (R0 = 0; none should: both blocks are where the stream's
 * were). */
.Lps_send:
	[--sp] = rets;
	[fp + HS_XFER + DMAX_SRC] = r0;
	[fp + HS_XFER + DMAX_ROWS] = r2;
	r0 = [fp + HS_PITCH];
	[fp + HS_XFER + DMAX_SS] = r0;
	[fp + HS_XFER + DMAX_DS] = r0;
	[fp + HS_XFER + DMAX_W] = r0;
	r1 *= r0;
	r0 = [fp + 60];
	r0 = r0 + r1;
	[fp + HS_XFER + DMAX_DST] = r0;
	r0 = fp;
	r1 = HS_JOB (x);
	r0 = r0 + r1;
	r1 = 0;
	r2 = fp;
	r3 = HS_XFER (x);
	r2 = r2 + r3;
	call _bvb_dma_prepare;
	cc = r0 == 0;
	if !cc jump .Lps_copy;
	r0 = fp;
	r1 = HS_JOB (x);
	r0 = r0 + r1;
	r1 = 1;
	call _bvb_dma_start;
	r0 = 1;
	rets = [sp++];
	rts;
.Lps_copy:
	p0 = [fp + HS_XFER + DMAX_SRC];
	p1 = [fp + HS_XFER + DMAX_DST];
	r0 = [fp + HS_XFER + DMAX_ROWS];
	r1 = [fp + HS_PITCH];
	r0 *= r1;
	r0 >>= 2;
	p2 = r0;
	lsetup (.Lps_cp, .Lps_cp_end) lc0 = p2;
.Lps_cp:
	r0 = [p0++];
.Lps_cp_end:
	[p1++] = r0;
	r0 = 0;
	rets = [sp++];
	rts;
.Lps_ret:
	rets = [sp++];
	rts;
BVB_ENDFUNC bvb_hs_prepare_asm

/* ---------------------------------------------------------------------------------------------
 * bvb_hornschunck_asm(i1, i2, width, height, stride, alpha2_q4, iterations, uv_out, out_stride,
 *                     scratch, flow_scratch, coef_scratch): prepare (streamed through
 * flow_scratch), then all the iterations in one bvb_hs_iterate_n_asm from zero flow: one zero
 * row after the coefficients in scratch, read with stride 0 as every row of the start field.
 * Once a call, so it runs from SDRAM (cached): L1 instruction memory is for the loops.
 * --------------------------------------------------------------------------------------------- */
BVB_FUNC bvb_hornschunck_asm, .text
	[--sp] = (r7:4, p5:3);
	link 40;                         /* the outgoing arguments 4-10 at SP + 12..39 */
	/* Arguments 4-12 at FP + 48: height, stride, alpha2_q4, iterations, uv_out, out_stride,
	 * scratch, flow_scratch, coef_scratch. */
	r4 = r0;                         /* i1 */
	r5 = r1;                         /* i2 */
	r6 = r2;                         /* width */
	r7 = [fp + 60];                  /* iterations */
	cc = r7 <= 0;
	if cc jump .Lhs_zero_out;
	/* the zero row: scratch + BVB_HS_COEF_BYTES(width, height), width + 1 words */
	r0 = r6 << 1;
	r0 = r0 + r6;
	r1 = 1;
	r1 = r1 & r6;
	r0 = r0 + r1;
	r0 <<= 1;                        /* 2 * BVB_HS_COEF_PITCH(width) */
	r1 = [fp + 48];
	r0 *= r1;
	r1 = [fp + 72];
	r0 = r0 + r1;
	p3 = r0;
	p0 = r0;
	p1 = r6;
	r2 = 0;
	[p0++] = r2;
	lsetup (.Lhs_z1, .Lhs_z1) lc0 = p1;
.Lhs_z1:
	[p0++] = r2;
	/* On the chip the row must leave the write-back data cache before the DMA reads it
	 * (bvb/dma.h: coherence): FLUSH its lines, 4 width + 4 bytes from a line start. */
	r0 = p3;
	r1 = 31;
	r1 = r0 & r1;
	r0 = r0 - r1;
	p0 = r0;
	r0 = r6 << 2;
	r0 = r0 + r1;
	r0 += 35;
	r0 >>= 5;
	p1 = r0;
	lsetup (.Lhs_fl, .Lhs_fl) lc0 = p1;
.Lhs_fl:
	flush [p0++];
	/* prepare(i1, i2, width, height, stride, alpha2_q4, coef = scratch, flow_scratch) */
	r0 = [fp + 48];
	[sp + 12] = r0;
	r0 = [fp + 52];
	[sp + 16] = r0;
	r0 = [fp + 56];
	[sp + 20] = r0;
	r0 = [fp + 72];
	[sp + 24] = r0;
	r0 = [fp + 76];
	[sp + 28] = r0;
	r0 = r4;
	r1 = r5;
	r2 = r6;
	call _bvb_hs_prepare_asm;
	/* iterate_n(coef, zero row, 0, uv_out, out_stride, width, height, iterations, flow_scratch,
	 * coef_scratch) */
	r0 = [fp + 64];
	[sp + 12] = r0;
	r0 = [fp + 68];
	[sp + 16] = r0;
	[sp + 20] = r6;
	r0 = [fp + 48];
	[sp + 24] = r0;
	[sp + 28] = r7;
	r0 = [fp + 76];
	[sp + 32] = r0;
	r0 = [fp + 80];
	[sp + 36] = r0;
	r0 = [fp + 72];
	r1 = p3;
	r2 = 0;
	call _bvb_hs_iterate_n_asm;
	jump .Lhs_done;
.Lhs_zero_out:
	/* no iterations: zero flow in uv_out, width words a row */
	p0 = [fp + 64];
	r0 = [fp + 68];
	r1 = r6 << 2;
	r0 = r0 - r1;
	m0 = r0;                         /* out_stride - 4 width */
	i0 = p0;
	r2 = 0;
	p1 = r6;
	r0 = [fp + 48];
	lc1 = r0;
	lsetup (.Lhs_zrow, .Lhs_zrow_end) lc1;
.Lhs_zrow:
	lsetup (.Lhs_zpix, .Lhs_zpix) lc0 = p1;
.Lhs_zpix:
	[i0++] = r2;
.Lhs_zrow_end:
	i0 += m0;
.Lhs_done:
	unlink;
	(r7:4, p5:3) = [sp++];
	rts;
BVB_ENDFUNC bvb_hornschunck_asm
