/* Sobel 3x3: magnitude (bvb_sobel3x3_u8_asm) and gx/gy with an optional magnitude
 * (bvb_sobel3x3_s16_asm). Definitions, arguments and the scratch size: bvb/sobel.h.
 *
 * Method. With the 2x2 box sum B(x,y) = p(x,y) + p(x+1,y) + p(x,y+1) + p(x+1,y+1):
 *   K1 = B(x,y) - B(x-1,y-1),  K2 = B(x,y-1) - B(x-1,y),  Gx = K1 + K2,  Gy = K1 - K2,
 *   |Gx| + |Gy| = 2 max(|K1|, |K2|).
 * A row of box sums serves two output rows, and the horizontal byte-pair sums H(x) = p(x) +
 * p(x+1) of an input row serve two rows of box sums. Per group of 4 output pixels (x..x+3):
 *   H of input row y+1            1 BYTEOP16P (two byte windows, offsets from I0, I1)
 *   B of row y = H(y) + H(y+1)    2 quad add/sub (ASL: the u8 kernel keeps 2B; one half unused)
 *   K1, K2 for 4 pixels           4 dual 16-bit subtract (the x-1 neighbours come from memory:
 *                                   the new row of B is stored and read back at a 2-byte offset)
 *   u8:  max(|K1|, |K2|), clamp   4 ABS (V), 2 MAX (V), 2 MIN (V) against a per-block lane mask,
 *                                   1 BYTEPACK                                   = 16
 *   s16: gx, gy                   2 quad add/sub (K1 +|+ K2, K1 -|- K2)           = 9
 *        + magnitude              4 ABS (V), 2 add, 2 MIN (V), 1 BYTEPACK          = 18
 * The lane mask of the u8 kernel is 255 for interior pixels and 0 for x = 0 and x >= w-1, so
 * MIN writes the left and right border zeros for free.
 *
 * Memory. scratch: a ring of two rows of blocks (one block per 4 pixels: H, 2B and the two
 * lane-mask words for u8, 24 bytes; H and B for s16, 16 bytes), walked by I2 (the row above)
 * and I3 (the row being made) as circular buffers; then, on the direct paths, one input line
 * (the last input row is read from a copy, so no load leaves src) and the output row buffers
 * of the row-by-row path (56 bytes per 4 pixels for s16); on the DMA paths instead the band
 * buffers and the DMA job(s) (BVB_SOBEL3X3_SCRATCH_SIZE: 23.1 KB at widths 320 and 640, 19.4
 * KB at 160; BVB_SOBEL3X3_S16_SCRATCH_SIZE: 20.2 KB at 160 and 640, 21.5 KB at 320 -- L1
 * bank B).
 *
 * The DMA path (u8; frames in SDRAM, scratch in L1 data SRAM; .Ldplan and .Ldma_* after the
 * u8 entry). Input rows come into L1 in bands by memory DMA and output rows leave the same way
 * (bvb/dma.h, bvb/sobel.h), on one stream: the job started before the core computes band j+1
 * sends band j's output rows and then brings band j+2 into the buffer band j has left. In L1
 * the rows are P = 4 G bytes apart, so .Lseg runs each band as one stream of groups, the ring
 * continuing from band to band. Layout, for the collision rule of the model (two accesses of
 * one issue in one 4 KB sub-bank: +1 cycle): the ring's two rows on either side of a sub-bank
 * boundary (I2 and I3 always in different sub-banks: they pair in 6 of the loop's 16 issues)
 * and the band buffers from the sub-bank after the ring's second (the band loads pair with I2,
 * the output store with I3): 317 collisions in the whole simulator run of a 320x240 call
 * (--timing-report), against 114,319 with the ring at the start of the scratch (one
 * sub-bank; 439,001 cycles instead of 329,902). Bands: 2, 2, 4, 8 rows, then BVB_SOBEL3X3_BAND_ROWS (10 at width 320).
 * The core's work per band: wait for the job, re-address (bvb_dma_move) or prepare its two
 * transfers, start it (5 MMR writes), .Lseg's prologue and epilogue: about 430 cycles (below).
 * The stream's per job: 10 SCLK to start, 4 descriptors of 7 halfwords, then 2 bytes per
 * SCLK; in + out is 2 bytes a pixel, 4 core cycles at CCLK:SCLK = 4, the same as the compute:
 * neither has room for the other's overheads, so the two are balanced band by band.
 *
 * Lower bound (16 and 18 instructions per 4 pixels above, one 32-bit ALU/MAC instruction per
 * cycle): 4 cycles per interior pixel for u8, 4.5 for s16 with the magnitude. Memory does not
 * bind: per group u8 issues 18 loads, 5 stores and 2 pointer steps in 16 cycles (32 slots),
 * s16 with the magnitude 17 loads and 9 stores in 18. Why not fewer: each output needs two
 * signed 16-bit gradient values (1 dual-lane instruction per pixel), two absolute values (1 per
 * pixel), their combination and clamp (0.5 + 0.5), the pack (0.25), and a new box sum (0.5 per
 * pixel for the 16-bit add, 0.25 for the byte pair sums); only the add/sub pairs of gx and gy
 * fit the quad instruction. (ADI's dual-MAC 3x3 convolution: 4.5 cycles per pixel for one
 * mask.) Without the magnitude, s16 needs 24 memory slots per group (12 cycles); its loop
 * takes 14 (8 data registers). The loops load no address register they use at once; their
 * L1 sub-bank collisions are avoided by placement on the u8 DMA path only (above).
 *
 * The DMA path of s16 (.Ldplan16, .Lsdo16, .Ls16_db_*): the same band schedule (.Lsdband,
 * .Ldoutrows), input transfers (.Lsdin) and slot keys (.Lsd_key) as u8, bands of up to
 * BVB_SOBEL3X3_S16_BAND_ROWS rows (10 at width 160, 5 at 320, 2 at 640). A band's job holds
 * its gx, gy and mag rows out (slots 0-2; gx, gy 2 P bytes apart in L1, mag P) and the band
 * after next in (slot 3, or 2 without mag): 4 transfers, BVB_DMA_MAX_XFERS. Its bound is the
 * bus, not the core: 1 byte in and 5 out per pixel at 2 bytes per SCLK (bvb/dma.h) is 12
 * cycles per pixel at CCLK:SCLK = 4, against the loop's 4.5. So the core prepares the next
 * job in a second job area while the current one runs and starts it as soon as the current
 * one ends (.Ls16_swj swaps the two with their slots' keys); the ring is not placed by
 * sub-bank (a collision only shortens a wait). The x = 0 and x = w-1 outputs of each band
 * (which the stream of groups fills with its neighbours' sums) are zeroed in L1 before they
 * leave; rows 0 and h-1 leave from a zeroed row of an output buffer.
 *
 * Measured under the model (bfbench bench, --timing bf537, frames contiguous in SDRAM: strides
 * == width; the simulator's own count, --timing none, after it). The bound is the larger of
 * the compute's (above, per interior pixel) and the bus's (1 byte in and 1 out per pixel for
 * u8, 1 in and 5 out for s16 with mag, at 0.5 byte per core cycle: 4.00 and 12.00 per pixel),
 * as the bench's bound column states it:
 *   sobel3x3_u8    160x120      90,221 cycles  4.70 per pixel (bound 4.00, compute 3.88)   sim    83,077
 *     DMA path,    320x240     329,386         4.29           (bound 4.00, compute 3.94)   sim   318,045
 *     scratch L1B  640x480   1,294,771         4.21           (bound 4.00, compute 3.97)   sim 1,267,887
 *     (C -O2 from SDRAM: 1,768,035 / 7,123,962 / 28,567,030; 19.6x, 21.6x, 22.1x)
 *     Where the 320x240 cycles go, over the bound's 302,600 (interior pixels x 4): the same
 *     loop in place in L1 took 306,348 in the simulator's count (the 16 cycles per group on
 *     the border columns too, pass 1, the lane masks, the zero rows); the DMA path's count,
 *     318,045, adds 11,700 of core work for 27 bands (about 430 each: above) and the plan;
 *     the model adds 11,300 more: the system MMR accesses at SCLK and the waits for the
 *     stream: band 0 (2 rows) before pass 1 starts, bands 2 and 3, whose jobs carry more than
 *     their compute covers, the last band (4 rows) against the 10 of the one before, and the
 *     last 5 output rows after the compute; L1 collisions: 317. At 160x120 the fill and the
 *     end weigh twice as much per pixel, at 640x480 half as much.
 *     Before the DMA path (frames read in place from SDRAM through the data cache, scratch in
 *     SDRAM): 224,114 / 833,597 / 3,395,439 (11.67 / 10.85 / 11.05 per pixel).
 *   sobel3x3_s16   160x120     240,235 cycles 12.51 per pixel (bound 12.00, compute 4.37)   sim   104,812
 *     DMA path,    320x240     946,422        12.32           (bound 12.00, compute 4.43)   sim   385,953
 *     scratch L1B  640x480   3,797,007        12.36           (bound 12.00, compute 4.47)   sim 1,543,537
 *     (C -O2 from SDRAM: 2,363,110 / 9,390,829 / 37,764,030; 9.8x, 9.9x, 9.9x; the bus's
 *     bound, below, 12.00 per pixel at every size). With the magnitude; the core's
 *     4.5 cycles per pixel are hidden under the bus's 12 (1 byte in and 5 out per pixel), so
 *     the bus floor is 921,600 at 320x240. Over it, 24,800 (2.7%): the stream's per-job cost
 *     (10 SCLK to start and 8 descriptors of 7 SCLK: 264 core cycles, bvb/dma.h) on 51 jobs,
 *     some 13,500; band 0 (2 rows) before pass 1 can start, about 1,300 (both estimates from
 *     bvb/dma.h's stream costs, not measured apart); the rest the
 *     core's start of each job (its MMR writes at SCLK) while the stream idles, and the last
 *     job (row h-1). Before the DMA path (frames read and written in place through the data
 *     cache): 854,271 (44.49 per pixel) / 3,148,637 (41.00) / 14,196,937 (46.21); in L1,
 *     without the model: 87,422 / 347,146 / 1,384,986 (4.55 / 4.52 / 4.51 per pixel with the
 *     magnitude), without mag 68,076 / 270,076 / 1,077,276.
 *   The inner loop is 16 (u8), 14 or 18 (s16) cycles per 4 pixels, run as one stream over the
 *   frame (DMA paths: over each band); the rest is the first row of blocks (9 cycles per 4
 *   pixels), the ring's lane masks, the zero rows and, for s16, the border columns (7 cycles a
 *   row).
 *   Other layouts, on the direct paths (simulator's counts, same method, the bench's frames
 *   re-laid out; the DMA path runs every layout as the contiguous one):
 *   - rows padded, strides multiples of 4, outputs 4-byte aligned, width a multiple of 4: the
 *     loop runs on from row to row, only its pointers move (5-8 cycles a row): u8 at 160x120
 *     with 16 bytes of padding 77,279 (4.02 per pixel), s16 88,696 (4.62);
 *   - anything else goes row by row through row buffers (about 100 cycles a row, plus the
 *     copy out): u8 with strides of 162: 95,624 (4.98); dst 2 bytes off: 102,721 (5.35), one
 *     byte off: 112,161 (5.84); s16 with gx/gy 2 bytes off: 164,129 (8.55).
 *
 * Registers in the loops: R0-R3 the input words (BYTEOP16P reads R1:0 and R3:2), R4-R7 the
 * rest; P0, P1 the aligned input words, P2 (P3, P4) outputs, P5 the count; I0, I1 hold only the
 * byte offsets of the two input windows; M0-M2 the ring walk. The loops are software-pipelined
 * over two groups (prologue, kernel, epilogue below); the comment after each instruction names
 * its operations. Blocks of B are read back at 2-byte offsets with half-register loads, which
 * is what lets a single 16-cycle group keep both the x and the x-1 neighbours. */

/* The stack frame both kernels share (the helpers below read it at [sp + F_*]). */
#include "bvb/asm.h"
#include "bvb/dma.h"

#define F_C     0	/* 0x00FF00FF: the s16 loop's MIN constant, read at [SP] */
#define F_SRC   4
#define F_SS    8
#define F_W     12
#define F_H     16
#define F_SCR   20
#define F_G     24	/* groups of 4 pixels per row: ceil(w / 4) */
#define F_SAFE  28	/* the safe input line */
#define F_END   32	/* one past the last byte of src */
#define F_Y     36	/* output row of the row-by-row path */
#define F_DST   40	/* u8: dst; s16: mag (or 0) */
#define F_DS    44	/* u8: dst stride; s16: mag stride */
#define F_T     48	/* the 8-bit output row buffer */
#define F_DROW  52
#define F_GX    56
#define F_GY    60
#define F_GS    64	/* gx/gy row stride in bytes */
#define F_TGX   68
#define F_TGY   72
#define F_GXROW 76
#define F_GYROW 80
#define F_LP0   84	/* the row-to-row loops: the last row's input words, */
#define F_LP1   88
#define F_RM2   92	/* the output rows less 2, */
#define F_DIN   96	/* what the input, 8-bit output and int16 output pointers move */
#define F_DOUT  100	/* from the end of a row of groups to the next row */
#define F_DG    104
/* The DMA path of the u8 kernel (frames in SDRAM, scratch in L1): */
#define F_IN0   112	/* the L1 band buffers of band j (input, output) and of band j+1 */
#define F_IN1   116
#define F_OUT0  120
#define F_OUT1  124
#define F_JOB   128	/* the DMA job, or 0 on the other paths */
#define F_B     132	/* rows per band at most */
#define F_P     136	/* band rows' stride: 4 G */
#define F_OSRC  140	/* src and src_stride (F_SRC, F_SS then name band 0 in L1) */
#define F_OSS   144
#define F_S     148	/* band j: first input row, rows */
#define F_N     152
#define F_S1    156	/* band j+1 */
#define F_N1    160
#define F_X     164	/* a struct bvb_dma_xfer, 24 bytes */
#define F_K0    188	/* what job slots 0 and 1 were last prepared for: 2 rows + (1 in, 0 out) */
#define F_K1    192
#define LOCALS  200
/* The s16 kernel's DMA path: job slots 2 and 3, and per output slot (0 gx, 1 gy, 2 mag) a
 * record of 32 bytes: SDRAM base, SDRAM stride, L1 row stride, bytes per row, offset of its
 * rows in an output band buffer. */
#define F_K2    196
#define F_K3    200
#define F_REC   204
#define R_BASE  0
#define R_STR   4
#define R_L1S   8
#define R_W     12
#define R_OFF   16
#define F_NI    300	/* output transfers per band: 3 with mag, else 2 */
#define F_JOB2  304	/* the other job, and its slots' keys (.Ls16_swj) */
#define F_K4    308
#define LOCALS16 324	/* the s16 kernel's frame */
#define ARGS16  (LOCALS16 + 36)
#define ARGS    (LOCALS + 36)	/* [sp + ARGS + 12]: the 4th argument */

BVB_FUNC bvb_sobel3x3_u8_asm
	[--sp] = (r7:4, p5:3);
	[--sp] = fp;
	[--sp] = rets;			/* the helpers below are called */
	sp += -64;
	sp += -64;
	sp += -64;
	sp += -8;			/* LOCALS */
	[sp + F_SRC] = r0;
	[sp + F_SS] = r1;
	[sp + F_DST] = r2;
	r3 = [sp + ARGS + 12];
	[sp + F_DS] = r3;
	r4 = [sp + ARGS + 16];		/* w */
	[sp + F_W] = r4;
	r5 = [sp + ARGS + 20];		/* h */
	[sp + F_H] = r5;
	r6 = [sp + ARGS + 24];		/* scratch */
	[sp + F_SCR] = r6;
	r7 = r4;
	r7 += 3;
	r7 >>= 2;			/* G = ceil(w / 4) */
	[sp + F_G] = r7;
	r0 = r7 << 4;
	r1 = r7 << 5;
	r0 = r0 + r1;			/* 48 G: the ring */
	r0 = r0 + r6;
	[sp + F_SAFE] = r0;
	r1 = r7 << 2;
	r0 = r0 + r1;
	r0 += 16;
	[sp + F_T] = r0;
	r0 = [sp + F_SS];
	r1 = r5;
	r1 += -1;
	r0 *= r1;
	r1 = [sp + F_SRC];
	r0 = r0 + r1;
	r0 = r0 + r4;
	[sp + F_END] = r0;		/* src + (h-1) ss + w */

	/* Frames in SDRAM and the scratch in L1: the banded DMA path (.Ldma_* below). Band 0
	 * (input rows 0 and 1) is on its way while the lane masks are made. */
	call .Ldplan;
	r0 = [sp + F_JOB];
	cc = r0 == 0;
	if cc jump .Lmasks;
	r0 = 0;
	r1 = 0;
	r2 = [sp + F_IN0];
	r3 = 2;
	call .Lsdin;
	r0 = [sp + F_JOB];
	r1 = 1;
	call _bvb_dma_start;
.Lmasks:
	r4 = [sp + F_W];
	r5 = [sp + F_H];
	r6 = [sp + F_SCR];		/* the scratch, or on the DMA path the ring */
	r7 = [sp + F_G];

	/* The lane masks of the ring blocks: 255 where the output is an interior pixel, 0 on
	 * the ring (x = 0 and x >= w-1); MIN with them puts the left and right border zeros in
	 * place at no cost in the inner loop. All blocks 255 first. */
	r0.l = 0xff;
	r0.h = 0xff;
	r1 = r6;
	r1 += 16;
	i0 = r1;
	m0 = 20 (x);
	r1 = r7 << 1;
	p5 = r1;
	lsetup (.Lcfill, .Lcfill_e) lc0 = p5;
.Lcfill:
	[i0++] = r0;
.Lcfill_e:
	[i0 ++ m0] = r0;
	/* The last block of each row: r = w - 4(G-1) valid pixels, lanes i >= r-1 are 0. */
	r0 = r7 << 2;
	r0 = r4 - r0;
	r0 += 4;			/* r in 1..4 */
	r1 = 0;				/* CA */
	r2 = 0;				/* CB */
	r3 = 0xff (z);
	cc = r0 == 2;
	if cc r1 = r3;
	r3.h = 0xff;
	cc = r0 < 3;
	if !cc r1 = r3;
	r5 = 4;
	r3 = 0xff (z);
	cc = r0 == r5;
	if cc r2 = r3;
	r3 = r7;
	r3 += -1;
	r5 = r3 << 3;
	r3 <<= 4;
	r3 = r3 + r5;			/* 24 (G-1) */
	r3 = r3 + r6;
	p0 = r3;			/* the last block of row 0 */
	[p0 + 16] = r1;
	[p0 + 20] = r2;
	r3 = r7 << 3;
	r5 = r7 << 4;
	r3 = r3 + r5;			/* 24 G: the second row of blocks */
	p1 = r3;
	p0 = p0 + p1;
	[p0 + 16] = r1;
	[p0 + 20] = r2;
	/* The first block of each row: x = 0 is 0. */
	p0 = r6;
	r2.l = 0;
	r2.h = 0xffff;
	r0 = [p0 + 16];
	r0 = r0 & r2;
	[p0 + 16] = r0;
	p0 = p0 + p1;
	r0 = [p0 + 16];
	r0 = r0 & r2;
	[p0 + 16] = r0;

	r0 = [sp + F_JOB];
	cc = r0 == 0;
	if !cc jump .Ldma_pre;
	/* Rows 0 and h-1 are 0. */
	p0 = [sp + F_DST];
	p1 = r4;
	call .Lzero;
	r0 = [sp + F_DS];
	r1 = [sp + F_H];
	r1 += -1;
	r0 *= r1;
	r1 = [sp + F_DST];
	r0 = r0 + r1;
	p0 = r0;
	p1 = [sp + F_W];
	call .Lzero;

.Lpass1_go:
	/* The first row of blocks, from input rows 0 and 1: H0 into the B slots, then
	 * H1 into the H slots and 2 (H0 + H1) into the B slots. */
	r0 = [sp + F_SRC];
	call .Linrow;			/* r0: row 0 or its safe copy */
	p0 = r0;
	r1 = r0;
	r1 += 1;
	p1 = r1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r0 = [sp + F_SCR];
	r0 += 8;
	i3 = r0;
	m3 = 20 (x);
	p5 = [sp + F_G];
	p5 += -1;
	call .Lpass1;
	r0 = [sp + F_SRC];
	r1 = [sp + F_SS];
	r0 = r0 + r1;
	call .Linrow;			/* row 1 */
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r0 = [sp + F_SCR];
	i3 = r0;
	r0 += 8;
	i2 = r0;
	m3 = 20 (x);
	m2 = 12 (x);
	p5 = [sp + F_G];
	p5 += -1;
	/* prologue 0 */
	R0 = [P0++];                                                                                        /* Lw0 */
	R1 = [P0];                                                                                          /* Lw1 */
	R2 = [P1++];                                                                                        /* Lv0 */
	R3 = [P1];                                                                                          /* Lv1 */
	(R3, R2) = BYTEOP16P (R1:0, R3:2) || R0 = [I2++] || NOP;                                            /* A1 h0a */
	CC = P5 == 0;
	if CC jump .Lp2_kx;
	lsetup (.Lp2_k, .Lp2_ke) lc0 = P5;
.Lp2_k:
	R4 = R2 +|+ R0, R5 = R2 -|- R0 (ASL) || R0 = [P0++] || R1 = [I2 ++ M3];                             /* A2 Lw0 h0b */
	R5 = R3 +|+ R1, R6 = R3 -|- R1 (ASL) || R1 = [P0] || [I3++] = R2;                                   /* A3 Lw1 t1 */
	MNOP || R2 = [P1++] || [I3++] = R3;                                                                 /* Lv0 t2 */
	MNOP || R3 = [P1] || [I3++] = R4;                                                                   /* Lv1 t3 */
.Lp2_ke:
	(R3, R2) = BYTEOP16P (R1:0, R3:2) || R0 = [I2++] || [I3 ++ M2] = R5;                                /* A1 h0a t4 */
.Lp2_kx:
	/* epilogue 1 */
	R4 = R2 +|+ R0, R5 = R2 -|- R0 (ASL) || R1 = [I2 ++ M3] || NOP;                                     /* A2 h0b */
	R5 = R3 +|+ R1, R6 = R3 -|- R1 (ASL) || [I3++] = R2 || NOP;                                         /* A3 t1 */
	[I3++] = R3;                                                                                        /* t2 */
	[I3++] = R4;                                                                                        /* t3 */
	[I3 ++ M2] = R5;                                                                                    /* t4 */

	/* The ring: two rows of G blocks, walked by I2 (the row of blocks above) and I3 (the
	 * row being made), both circular so that neither needs resetting between rows. */
	r0 = [sp + F_SCR];
	r7 = [sp + F_G];
	b2 = r0;
	b3 = r0;
	r1 = r7 << 3;
	r2 = r7 << 4;
	r1 = r1 + r2;			/* 24 G */
	r2 = r1 << 1;			/* 48 G */
	l2 = r2;
	l3 = r2;
	r3 = r0 + r2;
	r3 += -10;
	i2 = r3;			/* block 0, at B(-1) */
	r3 = r0 + r1;
	r3 += -10;
	i3 = r3;			/* block G, at B(-1) */
	m0 = 8 (x);
	m1 = -6 (x);
	m2 = -4 (x);
	r0 = [sp + F_JOB];
	cc = r0 == 0;
	if !cc jump .Ldma_bands;

	/* One stream over the whole frame when rows are contiguous and dst rows aligned. */
	r4 = [sp + F_W];
	r0 = [sp + F_SS];
	cc = r0 == r4;
	if !cc jump .Lrows;
	r0 = [sp + F_DS];
	cc = r0 == r4;
	if !cc jump .Lrows;
	r0 = [sp + F_DST];
	r0 = r0 | r4;
	r1 = 3;
	r0 = r0 & r1;
	cc = r0 == 0;
	if !cc jump .Lrows;
	r0 = 8;
	cc = r4 < r0;
	if cc jump .Lrows;

	/* Rows 1 .. h-2 but the very last group: input from row 2 on. */
	r0 = [sp + F_SRC];
	r4 = [sp + F_SS];
	r0 = r0 + r4;
	r0 = r0 + r4;
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r0 = [sp + F_DST];
	r0 = r0 + r4;
	p2 = r0;
	r0 = [sp + F_H];
	r0 += -2;
	r0 *= r7;
	r0 += -2;
	p5 = r0;			/* (h-2) G - 1 iterations */
	call .Lseg;
	/* The last group reads from a copy of the last row, so nothing past the frame is read. */
	r0 = [sp + F_SS];
	r1 = [sp + F_H];
	r1 += -1;
	r0 *= r1;
	r1 = [sp + F_SRC];
	r0 = r0 + r1;
	call .Lsafe;			/* r0: the copy */
	r1 = [sp + F_G];		/* .Lseg clobbered R0-R7 */
	r1 <<= 2;
	r0 = r0 + r1;
	r0 += -4;
	r1 = r0;
	r1 += 1;
	i0 = r0;			/* the copy keeps the byte offset, but .Lsafe moved I0, I1 */
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	p5 = 0;
	call .Lseg;
	jump .Ldone;

	/* Aligned output rows, input rows all at one byte offset, width a multiple of 4: row
	 * after row without draining the loop, only the pointers move between rows. */
.Lrows:
	r4 = [sp + F_W];
	r0 = [sp + F_DST];
	r1 = [sp + F_DS];
	r0 = r0 | r1;
	r0 = r0 | r4;
	r1 = [sp + F_SS];
	r0 = r0 | r1;
	r1 = 3;
	r0 = r0 & r1;
	cc = r0 == 0;
	if !cc jump .Lrows_buf;
	r0 = 8;
	cc = r4 < r0;
	if cc jump .Lrows_buf;
	r5 = [sp + F_H];
	r0 = 4;
	cc = r5 < r0;
	if cc jump .Lrows_buf;
	r0 = r5;
	r0 += -4;
	[sp + F_RM2] = r0;		/* output rows less 2 */
	r0 = [sp + F_SS];
	r5 += -1;
	r0 *= r5;
	r1 = [sp + F_SRC];
	r0 = r0 + r1;
	call .Lsafe;			/* the last input row, copied */
	r1 = r0;
	r1 += 1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	[sp + F_LP0] = r0;
	[sp + F_LP1] = r1;
	r7 = [sp + F_G];
	r6 = r7 << 2;			/* 4 G = w */
	r4 = [sp + F_SS];
	r0 = [sp + F_SRC];
	r0 = r0 + r4;
	r0 = r0 + r4;			/* input row 2 */
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r0 = r4 - r6;
	[sp + F_DIN] = r0;
	r1 = [sp + F_DS];
	r0 = r1 - r6;
	[sp + F_DOUT] = r0;
	r0 = [sp + F_DST];
	r0 = r0 + r1;
	p2 = r0;
	p5 = r7;
	p5 += -1;
	call .Lsegr;
	jump .Ldone;

	/* Row by row: input rows read in place while that stays inside src, output rows written
	 * in place when aligned, else through the row buffer. */
.Lrows_buf:
	r0 = 1;
	[sp + F_Y] = r0;
.Lrow:
	r0 = [sp + F_Y];
	r1 = [sp + F_SS];
	r0 += 1;
	r0 *= r1;
	r1 = [sp + F_SRC];
	r0 = r0 + r1;
	call .Linrow;
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r0 = [sp + F_Y];
	r1 = [sp + F_DS];
	r0 *= r1;
	r1 = [sp + F_DST];
	r0 = r0 + r1;
	[sp + F_DROW] = r0;
	r1 = [sp + F_W];
	r1 = r1 | r0;
	r2 = 3;
	r1 = r1 & r2;
	cc = r1 == 0;
	r1 = [sp + F_T];
	if !cc r0 = r1;
	p2 = r0;
	p5 = [sp + F_G];
	p5 += -1;
	call .Lseg;
	r0 = [sp + F_T];
	r1 = p2;
	r2 = [sp + F_G];
	r2 <<= 2;
	r0 = r0 + r2;
	cc = r0 == r1;
	if !cc jump .Lrow_next;
	p0 = [sp + F_T];		/* the row went to the row buffer: copy it out */
	p1 = [sp + F_DROW];
	p2 = [sp + F_W];
	call .Lcopy;
.Lrow_next:
	r0 = [sp + F_Y];
	r0 += 1;
	[sp + F_Y] = r0;
	r1 = [sp + F_H];
	r1 += -1;
	cc = r0 < r1;
	if cc jump .Lrow;

.Ldone:
	r0 = 0;
	l0 = r0;
	l1 = r0;
	l2 = r0;
	l3 = r0;
	sp += 60;
	sp += 60;
	sp += 60;
	sp += 20;			/* LOCALS */
	rets = [sp++];
	fp = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;
BVB_ENDFUNC bvb_sobel3x3_u8_asm

	/* The banded DMA path of the u8 kernel (bvb/sobel.h, "Working set and memory").
	 *
	 * .Ldplan: F_JOB = the job when src or dst is in SDRAM, the scratch in L1 data SRAM and
	 * DMA reaches all three, else 0 (the direct paths above). It places in the scratch the
	 * ring with the boundary between its two rows on a 4 KB sub-bank boundary (I2 and I3,
	 * which load and store in the same cycles, then always work in different sub-banks), the
	 * band buffers from the sub-bank after the ring's second (so that the band loads beside
	 * I2 and the band stores beside I3 never share theirs): two input buffers of B rows, 8
	 * bytes of over-read room, two output buffers of B + 1 rows (the last band's zero row),
	 * then the job; F_SCR becomes the ring. Rows in L1 are P = 4 G bytes apart, so a band of
	 * rows is one stream of groups for .Lseg whatever the frame's strides. */
#define Q 4	/* the frame is 4 bytes further while a subroutine has RETS pushed */
.Ldplan:
	[--sp] = rets;
	r0 = 0;
	[sp + Q + F_JOB] = r0;
	r0 = -1;
	[sp + Q + F_K0] = r0;
	[sp + Q + F_K1] = r0;
	r2.l = 0;
	r2.h = 0x0200;			/* the end of SDRAM */
	r0 = [sp + Q + F_SRC];
	r1 = [sp + Q + F_DST];
	cc = r0 < r2 (iu);
	if cc jump .Ldp_f;
	cc = r1 < r2 (iu);
	if !cc jump .Ldp_x;		/* both frames in L1 (or the window): read in place */
.Ldp_f:
	r7 = [sp + Q + F_G];
	r6 = r7 << 2;			/* P */
	[sp + Q + F_P] = r6;
	r5 = 16;			/* B: BVB_SOBEL3X3_BAND_ROWS */
	r0 = 160 (x);
	r1 = 10;
	cc = r0 < r6;
	if cc r5 = r1;
	r0 = 320 (x);
	r1 = 4;
	cc = r0 < r6;
	if cc r5 = r1;
	r0 = 640 (x);
	r1 = 2;
	cc = r0 < r6;
	if cc r5 = r1;
	[sp + Q + F_B] = r5;
	r1 = r7 << 3;
	r4 = r7 << 4;
	r4 = r4 + r1;			/* 24 G: a row of the ring */
	r0 = r5 << 2;
	r0 += 2;
	r0 *= r6;
	r0 = r0 + r4;
	r1 = 8192 + 120 (x);
	r1 = r0 + r1;			/* BVB_SOBEL3X3_SCRATCH_SIZE */
	r0 = [sp + Q + F_SCR];
	r2.l = 0;
	r2.h = 0xff80;
	cc = r0 < r2 (iu);
	if cc jump .Ldp_x;		/* scratch in SDRAM: nothing to gain */
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ldp_x;
	r0 = [sp + Q + F_H];
	r0 += -1;
	r1 = [sp + Q + F_SS];
	r0 *= r1;
	r1 = [sp + Q + F_W];
	r1 = r0 + r1;
	r0 = [sp + Q + F_SRC];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ldp_x;
	r0 = [sp + Q + F_H];
	r0 += -1;
	r1 = [sp + Q + F_DS];
	r0 *= r1;
	r1 = [sp + Q + F_W];
	r1 = r0 + r1;
	r0 = [sp + Q + F_DST];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ldp_x;
	r0 = [sp + Q + F_SCR];
	r0 = r0 + r4;
	r1 = 4095 (x);
	r0 = r0 + r1;
	r1 = -4096 (x);
	r0 = r0 & r1;			/* the boundary between the ring's rows */
	r1 = r0 - r4;
	[sp + Q + F_SCR] = r1;		/* the ring */
	r1 = 4096 (x);
	r0 = r0 + r1;
	[sp + Q + F_IN0] = r0;
	r1 = r5;
	r1 *= r6;			/* B P */
	r0 = r0 + r1;
	[sp + Q + F_IN1] = r0;
	r0 = r0 + r1;
	r0 += 8;
	[sp + Q + F_OUT0] = r0;
	r0 = r0 + r1;
	r0 = r0 + r6;
	[sp + Q + F_OUT1] = r0;
	r0 = r0 + r1;
	r0 = r0 + r6;
	[sp + Q + F_JOB] = r0;
	r0 = [sp + Q + F_SRC];
	[sp + Q + F_OSRC] = r0;
	r0 = [sp + Q + F_SS];
	[sp + Q + F_OSS] = r0;
.Ldp_x:
	rets = [sp++];
	rts;

	/* Band 0 (rows 0 and 1) has arrived when pass 1 starts on it in L1; band 1 comes in
	 * meanwhile. Output row 0 (zero) goes out from slot 0 of band 0's output buffer. */
.Ldma_pre:
	p0 = [sp + F_OUT0];
	r0 = 0;
	p1 = [sp + F_G];
	lsetup (.Ldz0, .Ldz0) lc0 = p1;
.Ldz0:
	[p0++] = r0;
	call _bvb_dma_wait;
	r0 = 0;
	[sp + F_S] = r0;
	r0 = 2;
	[sp + F_N] = r0;
	[sp + F_S1] = r0;
	call .Lsdband;
	[sp + F_N1] = r0;
	r3 = r0;
	r0 = 0;
	r1 = 2;
	r2 = [sp + F_IN1];
	call .Lsdin;
	r0 = [sp + F_JOB];
	r1 = 1;
	call _bvb_dma_start;
	r0 = [sp + F_IN0];
	[sp + F_SRC] = r0;
	r0 = [sp + F_P];
	[sp + F_SS] = r0;
	r0 = -1;
	[sp + F_END] = r0;		/* .Linrow: nothing to copy */
	jump .Lpass1_go;

	/* Band j (F_S, F_N rows, buffers F_IN0, F_OUT0) computed, band j+1 (F_S1, F_N1, F_IN1,
	 * F_OUT1) in or arriving: wait for it, start the job that sends band j's output rows
	 * out and brings band j+2 into band j's input buffer, compute band j+1, and so on. */
.Ldma_bands:
	r0 = [sp + F_IN0];
	i0 = r0;			/* BYTEOP16P's byte offsets: rows in L1 are word aligned */
	r0 += 1;
	i1 = r0;
.Ldb_loop:
	r0 = [sp + F_S1];
	r1 = [sp + F_H];
	cc = r0 < r1;
	if !cc jump .Ldb_last;
	call _bvb_dma_wait;
	r1 = [sp + F_S];		/* band j's output rows (.Ldoutrows) */
	r3 = [sp + F_N];
	r1 += -1;
	cc = r1 < 0;
	if !cc jump .Ldb_o (bp);
	r1 = 0;
	r3 = 1;
.Ldb_o:
	r0 = 0;
	r2 = [sp + F_OUT0];
	call .Lsdout;
	r7 = 1;
	r0 = [sp + F_S1];
	r1 = [sp + F_N1];
	r6 = r0 + r1;			/* band j+2 */
	r1 = [sp + F_H];
	cc = r6 < r1;
	r5 = 0;
	if !cc jump .Ldb_go;
	r1 = [sp + F_B];		/* .Lsdband */
	r1 = min (r6, r1);
	r2 = 2;
	r1 = max (r1, r2);
	r2 = [sp + F_H];
	r2 = r2 - r6;
	r5 = min (r1, r2);
	r3 = r5;
	r0 = 1;
	r1 = r6;
	r2 = [sp + F_IN0];
	call .Lsdin;
	r7 = 2;
.Ldb_go:
	r0 = [sp + F_JOB];
	r1 = r7;
	call _bvb_dma_start;
	/* band j+1 becomes band j */
	r0 = [sp + F_S1];
	[sp + F_S] = r0;
	r0 = [sp + F_N1];
	[sp + F_N] = r0;
	[sp + F_S1] = r6;
	[sp + F_N1] = r5;
	r0 = [sp + F_IN0];
	r1 = [sp + F_IN1];
	[sp + F_IN0] = r1;
	[sp + F_IN1] = r0;
	r0 = [sp + F_OUT0];
	r1 = [sp + F_OUT1];
	[sp + F_OUT0] = r1;
	[sp + F_OUT1] = r0;
	p0 = [sp + F_IN0];
	p1 = p0;
	p2 = [sp + F_OUT0];
	r0 = [sp + F_N];
	r1 = [sp + F_G];
	r0 *= r1;
	r0 += -1;
	p5 = r0;
	call .Lseg;
	jump .Ldb_loop;
	/* The last band's output rows and the zero row h-1 after them. */
.Ldb_last:
	call _bvb_dma_wait;
	call .Ldoutrows;
	r0 = r3;
	r1 = [sp + F_P];
	r0 *= r1;
	r1 = [sp + F_OUT0];
	r0 = r0 + r1;
	p0 = r0;
	r0 = 0;
	p1 = [sp + F_G];
	lsetup (.Ldz1, .Ldz1) lc0 = p1;
.Ldz1:
	[p0++] = r0;
	call .Ldoutrows;
	r3 += 1;
	r0 = 0;
	r2 = [sp + F_OUT0];
	call .Lsdout;
	r0 = [sp + F_JOB];
	r1 = 1;
	call _bvb_dma_start;
	call _bvb_dma_wait;
	jump .Ldone;

	/* Band j's output rows: r1 the first, r3 how many (band 0: row 0 alone; band j: rows
	 * S-1 .. S+N-2). Clobbers R0. */
.Ldoutrows:
	r1 = [sp + F_S];
	r3 = [sp + F_N];
	r1 += -1;
	cc = r1 < 0;
	if !cc jump .Ldo_x (bp);
	r1 = 0;
	r3 = 1;
.Ldo_x:
	rts;

	/* r0 = s: the rows of the band that starts at input row s: up to B, from 2 (rows 0 and 1,
	 * pass 1) doubling (2, 2, 4, 8, ...), so that the compute starts soon. (Halving them
	 * towards the end does not pay: each job then carries more than its band's compute
	 * time covers.) Clobbers R1, R2. */
.Lsdband:
	r1 = [sp + F_B];
	r1 = min (r0, r1);
	r2 = 2;
	r1 = max (r1, r2);
	r2 = [sp + F_H];
	r2 = r2 - r0;			/* rows left */
	r0 = min (r1, r2);
	rts;

	/* Job slot r0: r3 input rows from row r1 into band buffer r2 (.Lsdin), or r3 output
	 * rows from band buffer r2 to dst's rows r1 .. (.Lsdout). r0: bvb_dma_prepare's. */
.Lsdin:
	[--sp] = rets;
	p1 = r0;			/* the slot, early: a P register moved from R waits 4 */
	p0 = 1;
	[sp + Q + F_X + DMAX_DST] = r2;
	r2 = [sp + Q + F_P];
	[sp + Q + F_X + DMAX_DS] = r2;
	r2 = [sp + Q + F_OSS];
	[sp + Q + F_X + DMAX_SS] = r2;
	r1 *= r2;
	r2 = [sp + Q + F_OSRC];
	r1 = r1 + r2;
	[sp + Q + F_X + DMAX_SRC] = r1;
	jump .Lsd_go;
.Lsdout:
	[--sp] = rets;
	p1 = r0;
	p0 = 0;
	[sp + Q + F_X + DMAX_SRC] = r2;
	r2 = [sp + Q + F_P];
	[sp + Q + F_X + DMAX_SS] = r2;
	r2 = [sp + Q + F_DS];
	[sp + Q + F_X + DMAX_DS] = r2;
	r1 *= r2;
	r2 = [sp + Q + F_DST];
	r1 = r1 + r2;
	[sp + Q + F_X + DMAX_DST] = r1;
.Lsd_go:
	[sp + Q + F_X + DMAX_ROWS] = r3;
	r2 = [sp + Q + F_W];
	[sp + Q + F_X + DMAX_W] = r2;
.Lsd_key:
	/* the slot's key, 2 rows + direction: the same as last time, only the addresses move */
	r1 = r0;
	r2 = r3 << 1;
	r0 = p0;
	r2 = r2 + r0;
	p0 = sp;
	p1 = p0 + (p1 << 2);		/* F_K0 or F_K1 */
	r0 = [p1 + Q + F_K0];
	[p1 + Q + F_K0] = r2;
	cc = r0 == r2;
	r0 = [sp + Q + F_JOB];
	r2 = sp;
	r3 = Q + F_X;
	r2 = r2 + r3;
	if cc jump .Lsd_move (bp);
	call _bvb_dma_prepare;
	rets = [sp++];
	rts;
.Lsd_move:
	call _bvb_dma_move;
	r0 = 0;
	rets = [sp++];
	rts;

	/* The banded DMA path of the s16 kernel: the u8 kernel's band schedule (.Lsdband,
	 * .Ldoutrows), its input transfers (.Lsdin) and its slot keys (.Lsd_key), with three
	 * output transfers (gx, gy and, when mag is not NULL, mag) per band instead of one.
	 *
	 * .Ldplan16: F_JOB = the job when src, gx, gy or mag is in SDRAM, the scratch in L1 data
	 * SRAM and DMA reaches all of them, else 0 (the direct paths). The scratch then holds the
	 * ring (8 P bytes), two input buffers of B rows P = 4 G bytes apart and 8 bytes of
	 * over-read room, two output buffers of B rows of gx (2 P bytes apart), B of gy and B of
	 * mag (P apart), and the job: BVB_SOBEL3X3_S16_SCRATCH_SIZE. No sub-bank placement: the
	 * bus, not the core, sets this path's pace (5 bytes out and 1 in per pixel, 12 cycles,
	 * against the loop's 4.5), so collisions in the loop only shorten the waits. */
.Ldplan16:
	[--sp] = rets;
	r0 = 0;
	[sp + Q + F_JOB] = r0;
	r0 = -1;
	[sp + Q + F_K0] = r0;
	[sp + Q + F_K1] = r0;
	[sp + Q + F_K2] = r0;
	[sp + Q + F_K3] = r0;
	[sp + Q + F_K4] = r0;
	[sp + Q + F_K4 + 4] = r0;
	[sp + Q + F_K4 + 8] = r0;
	[sp + Q + F_K4 + 12] = r0;
	r2.l = 0;
	r2.h = 0x0200;			/* the end of SDRAM */
	r0 = [sp + Q + F_SRC];
	cc = r0 < r2 (iu);
	if cc jump .Ldq_f;
	r0 = [sp + Q + F_GX];
	cc = r0 < r2 (iu);
	if cc jump .Ldq_f;
	r0 = [sp + Q + F_GY];
	cc = r0 < r2 (iu);
	if cc jump .Ldq_f;
	r0 = [sp + Q + F_DST];
	cc = r0 == 0;
	if cc jump .Ldq_x;
	cc = r0 < r2 (iu);
	if !cc jump .Ldq_x;		/* every frame in L1 (or the window): in place */
.Ldq_f:
	r7 = [sp + Q + F_G];
	r6 = r7 << 2;			/* P */
	[sp + Q + F_P] = r6;
	r5 = 10;			/* B: BVB_SOBEL3X3_S16_BAND_ROWS */
	r0 = 160 (x);
	r1 = 5;
	cc = r0 < r6;
	if cc r5 = r1;
	r0 = 320 (x);
	r1 = 2;
	cc = r0 < r6;
	if cc r5 = r1;
	[sp + Q + F_B] = r5;
	r4 = r5;
	r4 *= r6;			/* B P */
	r1 = r4 << 3;
	r0 = r4 << 2;
	r1 = r1 + r0;
	r0 = r6 << 3;
	r1 = r1 + r0;
	r0 = 232 (x);
	r1 = r1 + r0;			/* BVB_SOBEL3X3_S16_SCRATCH_SIZE: 8 P + 12 B P + 232 */
	r0 = [sp + Q + F_SCR];
	r2.l = 0;
	r2.h = 0xff80;
	cc = r0 < r2 (iu);
	if cc jump .Ldq_x;		/* scratch in SDRAM: nothing to gain */
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ldq_x;
	r0 = [sp + Q + F_H];
	r0 += -1;
	r1 = [sp + Q + F_SS];
	r0 *= r1;
	r1 = [sp + Q + F_W];
	r1 = r0 + r1;
	r0 = [sp + Q + F_SRC];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ldq_x;
	r0 = [sp + Q + F_H];
	r0 += -1;
	r1 = [sp + Q + F_GS];
	r0 *= r1;
	r1 = [sp + Q + F_W];
	r1 <<= 1;
	r1 = r0 + r1;
	r0 = [sp + Q + F_GX];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ldq_x;
	r0 = [sp + Q + F_H];
	r0 += -1;
	r1 = [sp + Q + F_GS];
	r0 *= r1;
	r1 = [sp + Q + F_W];
	r1 <<= 1;
	r1 = r0 + r1;
	r0 = [sp + Q + F_GY];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ldq_x;
	r3 = 2;				/* output transfers per band */
	r0 = [sp + Q + F_DST];
	cc = r0 == 0;
	if cc jump .Ldq_l;
	r0 = [sp + Q + F_H];
	r0 += -1;
	r1 = [sp + Q + F_DS];
	r0 *= r1;
	r1 = [sp + Q + F_W];
	r1 = r0 + r1;
	r0 = [sp + Q + F_DST];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ldq_x;
	r3 = 3;
.Ldq_l:
	[sp + Q + F_NI] = r3;
	r0 = [sp + Q + F_SCR];		/* the ring */
	r1 = r6 << 3;
	r0 = r0 + r1;
	[sp + Q + F_IN0] = r0;
	r0 = r0 + r4;
	[sp + Q + F_IN1] = r0;
	r0 = r0 + r4;
	r0 += 8;
	[sp + Q + F_OUT0] = r0;
	r1 = r4 << 2;
	r1 = r1 + r4;			/* 5 B P */
	r0 = r0 + r1;
	[sp + Q + F_OUT1] = r0;
	r0 = r0 + r1;
	[sp + Q + F_JOB] = r0;
	r0 += 56;
	r0 += 56;			/* BVB_DMA_JOB_BYTES */
	[sp + Q + F_JOB2] = r0;
	/* the output records: gx, gy (2 P apart in L1, 2 w bytes a row), mag (P, w) */
	r0 = [sp + Q + F_GS];
	r1 = r6 << 1;
	r2 = [sp + Q + F_W];
	r3 = r2 << 1;
	[sp + Q + F_REC + R_STR] = r0;
	[sp + Q + F_REC + 32 + R_STR] = r0;
	[sp + Q + F_REC + R_L1S] = r1;
	[sp + Q + F_REC + 32 + R_L1S] = r1;
	[sp + Q + F_REC + R_W] = r3;
	[sp + Q + F_REC + 32 + R_W] = r3;
	[sp + Q + F_REC + 64 + R_L1S] = r6;
	[sp + Q + F_REC + 64 + R_W] = r2;
	r0 = [sp + Q + F_GX];
	[sp + Q + F_REC + R_BASE] = r0;
	r0 = [sp + Q + F_GY];
	[sp + Q + F_REC + 32 + R_BASE] = r0;
	r0 = [sp + Q + F_DST];
	[sp + Q + F_REC + 64 + R_BASE] = r0;
	r0 = [sp + Q + F_DS];
	[sp + Q + F_REC + 64 + R_STR] = r0;
	r0 = 0;
	[sp + Q + F_REC + R_OFF] = r0;
	r0 = r4 << 1;			/* 2 B P */
	[sp + Q + F_REC + 32 + R_OFF] = r0;
	r0 <<= 1;			/* 4 B P */
	[sp + Q + F_REC + 64 + R_OFF] = r0;
	r0 = [sp + Q + F_SRC];
	[sp + Q + F_OSRC] = r0;
	r0 = [sp + Q + F_SS];
	[sp + Q + F_OSS] = r0;
.Ldq_x:
	rets = [sp++];
	rts;

	/* Job slot r0 (0 gx, 1 gy, 2 mag): r3 output rows from F_OUT0's buffer to the frame's
	 * rows r1 .. (record r0). r0: bvb_dma_prepare's. */
.Lsdo16:
	[--sp] = rets;
	p2 = r0;
	p1 = r0;
	p0 = 0;
	p2 = p2 << 2;
	p2 = p2 << 2;
	p2 = p2 << 1;
	p2 = p2 + sp;			/* the record, at [p2 + Q + F_REC] */
	[sp + Q + F_X + DMAX_ROWS] = r3;
	r2 = [p2 + Q + F_REC + R_STR];
	[sp + Q + F_X + DMAX_DS] = r2;
	r1 *= r2;
	r2 = [p2 + Q + F_REC + R_BASE];
	r1 = r1 + r2;
	[sp + Q + F_X + DMAX_DST] = r1;
	r2 = [p2 + Q + F_REC + R_L1S];
	[sp + Q + F_X + DMAX_SS] = r2;
	r2 = [p2 + Q + F_REC + R_W];
	[sp + Q + F_X + DMAX_W] = r2;
	r1 = [p2 + Q + F_REC + R_OFF];
	r2 = [sp + Q + F_OUT0];
	r1 = r1 + r2;
	[sp + Q + F_X + DMAX_SRC] = r1;
	jump .Lsd_key;

	/* Row 0 of F_OUT0's gx, gy and mag rows: 0 (output rows 0 and h-1). Clobbers R0, R1,
	 * P0-P3. */
.Ls16_z0:
	r0 = [sp + F_OUT0];
	p0 = r0;
	r1 = [sp + F_REC + 32 + R_OFF];
	r1 = r1 + r0;
	p1 = r1;
	r1 = [sp + F_REC + 64 + R_OFF];
	r1 = r1 + r0;
	p2 = r1;
	p3 = [sp + F_G];
	r0 = 0;
	lsetup (.Ls16_z0l, .Ls16_z0le) lc0 = p3;
.Ls16_z0l:
	[p0++] = r0;
	[p0++] = r0;
	[p1++] = r0;
	[p1++] = r0;
.Ls16_z0le:
	[p2++] = r0;
	rts;

	/* The two jobs change places, with their slots' keys: F_JOB is the one to prepare while
	 * the other runs. Clobbers R0, R1. */
.Ls16_swj:
	r0 = [sp + F_JOB];
	r1 = [sp + F_JOB2];
	[sp + F_JOB] = r1;
	[sp + F_JOB2] = r0;
	r0 = [sp + F_K0];
	r1 = [sp + F_K4];
	[sp + F_K0] = r1;
	[sp + F_K4] = r0;
	r0 = [sp + F_K1];
	r1 = [sp + F_K4 + 4];
	[sp + F_K1] = r1;
	[sp + F_K4 + 4] = r0;
	r0 = [sp + F_K2];
	r1 = [sp + F_K4 + 8];
	[sp + F_K2] = r1;
	[sp + F_K4 + 8] = r0;
	r0 = [sp + F_K3];
	r1 = [sp + F_K4 + 12];
	[sp + F_K3] = r1;
	[sp + F_K4 + 12] = r0;
	rts;
#undef Q

BVB_FUNC bvb_sobel3x3_s16_asm
	[--sp] = (r7:4, p5:3);
	[--sp] = fp;
	[--sp] = rets;
	sp += -64;
	sp += -64;
	sp += -64;
	sp += -64;
	sp += -64;
	sp += -4;			/* LOCALS16 */
	[sp + F_SRC] = r0;
	[sp + F_SS] = r1;
	[sp + F_GX] = r2;
	r3 = [sp + ARGS16 + 12];
	[sp + F_GY] = r3;
	r3 = [sp + ARGS16 + 16];
	r3 <<= 1;
	[sp + F_GS] = r3;
	r3 = [sp + ARGS16 + 20];
	[sp + F_DST] = r3;		/* mag, or 0 */
	r3 = [sp + ARGS16 + 24];
	[sp + F_DS] = r3;
	r4 = [sp + ARGS16 + 28];		/* w */
	[sp + F_W] = r4;
	r5 = [sp + ARGS16 + 32];		/* h */
	[sp + F_H] = r5;
	r6 = [sp + ARGS16 + 36];		/* scratch */
	[sp + F_SCR] = r6;
	r0.l = 0xff;
	r0.h = 0xff;
	[sp + F_C] = r0;
	r7 = r4;
	r7 += 3;
	r7 >>= 2;			/* G */
	[sp + F_G] = r7;
	r0 = r7 << 5;			/* 32 G: the ring */
	r0 = r0 + r6;
	[sp + F_SAFE] = r0;
	r1 = r7 << 2;
	r0 = r0 + r1;
	r0 += 16;
	[sp + F_TGX] = r0;
	r1 = r7 << 3;
	r0 = r0 + r1;
	[sp + F_TGY] = r0;
	r0 = r0 + r1;
	[sp + F_T] = r0;
	r0 = [sp + F_SS];
	r1 = r5;
	r1 += -1;
	r0 *= r1;
	r1 = [sp + F_SRC];
	r0 = r0 + r1;
	r0 = r0 + r4;
	[sp + F_END] = r0;

	/* Frames in SDRAM and the scratch in L1: the banded DMA path (.Ldplan16, .Ls16_db_*).
	 * Band 0 (input rows 0 and 1) comes in while output row 0 is zeroed in L1. */
	call .Ldplan16;
	r0 = [sp + F_JOB];
	cc = r0 == 0;
	if cc jump .Ls16_zrows;
	r0 = 0;
	r1 = 0;
	r2 = [sp + F_IN0];
	r3 = 2;
	call .Lsdin;
	r0 = [sp + F_JOB];
	r1 = 1;
	call _bvb_dma_start;
	call .Ls16_z0;
	call _bvb_dma_wait;
	r0 = 0;
	[sp + F_S] = r0;
	r0 = 2;
	[sp + F_N] = r0;
	[sp + F_S1] = r0;
	call .Lsdband;
	[sp + F_N1] = r0;
	r3 = r0;
	r0 = 0;
	r1 = 2;
	r2 = [sp + F_IN1];
	call .Lsdin;
	r0 = [sp + F_JOB];
	r1 = 1;
	call _bvb_dma_start;
	call .Ls16_swj;
	r0 = [sp + F_IN0];
	[sp + F_SRC] = r0;
	r0 = [sp + F_P];
	[sp + F_SS] = r0;
	r0 = -1;
	[sp + F_END] = r0;		/* .Linrow: nothing to copy */
	jump .Ls16_nomag0;

.Ls16_zrows:
	/* Rows 0 and h-1 are 0. */
	p0 = [sp + F_GX];
	p1 = [sp + F_W];
	call .Lzero16;
	p0 = [sp + F_GY];
	p1 = [sp + F_W];
	call .Lzero16;
	r0 = [sp + F_GS];
	r1 = [sp + F_H];
	r1 += -1;
	r0 *= r1;
	p2 = r0;
	p0 = [sp + F_GX];
	p0 = p0 + p2;
	p1 = [sp + F_W];
	call .Lzero16;
	p0 = [sp + F_GY];
	p0 = p0 + p2;
	p1 = [sp + F_W];
	call .Lzero16;
	r0 = [sp + F_DST];
	cc = r0 == 0;
	if cc jump .Ls16_nomag0;
	p0 = r0;
	p1 = [sp + F_W];
	call .Lzero;
	r0 = [sp + F_DS];
	r1 = [sp + F_H];
	r1 += -1;
	r0 *= r1;
	r1 = [sp + F_DST];
	r0 = r0 + r1;
	p0 = r0;
	p1 = [sp + F_W];
	call .Lzero;
.Ls16_nomag0:

	/* The first row of blocks (16 bytes each: H, then B unscaled). */
	r0 = [sp + F_SRC];
	call .Linrow;
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r0 = [sp + F_SCR];
	r0 += 8;
	i3 = r0;
	m3 = 12 (x);
	p5 = [sp + F_G];
	p5 += -1;
	call .Lpass1;
	r0 = [sp + F_SRC];
	r1 = [sp + F_SS];
	r0 = r0 + r1;
	call .Linrow;
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r0 = [sp + F_SCR];
	i3 = r0;
	r0 += 8;
	i2 = r0;
	m3 = 12 (x);
	m2 = 4 (x);
	p5 = [sp + F_G];
	p5 += -1;
	/* prologue 0 */
	R0 = [P0++];                                                                                        /* Lw0 */
	R1 = [P0];                                                                                          /* Lw1 */
	R2 = [P1++];                                                                                        /* Lv0 */
	R3 = [P1];                                                                                          /* Lv1 */
	(R3, R2) = BYTEOP16P (R1:0, R3:2) || R0 = [I2++] || NOP;                                            /* A1 h0a */
	CC = P5 == 0;
	if CC jump .Lp2u_kx;
	lsetup (.Lp2u_k, .Lp2u_ke) lc0 = P5;
.Lp2u_k:
	R4 = R2 +|+ R0 || R0 = [P0++] || R1 = [I2 ++ M3];                                                   /* A2 Lw0 h0b */
	R5 = R3 +|+ R1 || R1 = [P0] || [I3++] = R2;                                                         /* A3 Lw1 t1 */
	MNOP || R2 = [P1++] || [I3++] = R3;                                                                 /* Lv0 t2 */
	MNOP || R3 = [P1] || [I3++] = R4;                                                                   /* Lv1 t3 */
.Lp2u_ke:
	(R3, R2) = BYTEOP16P (R1:0, R3:2) || R0 = [I2++] || [I3 ++ M2] = R5;                                /* A1 h0a t4 */
.Lp2u_kx:
	/* epilogue 1 */
	R4 = R2 +|+ R0 || R1 = [I2 ++ M3] || NOP;                                                           /* A2 h0b */
	R5 = R3 +|+ R1 || [I3++] = R2 || NOP;                                                               /* A3 t1 */
	[I3++] = R3;                                                                                        /* t2 */
	[I3++] = R4;                                                                                        /* t3 */
	[I3 ++ M2] = R5;                                                                                    /* t4 */

	r0 = [sp + F_SCR];
	r7 = [sp + F_G];
	b2 = r0;
	b3 = r0;
	r1 = r7 << 4;			/* 16 G */
	r2 = r1 << 1;			/* 32 G */
	l2 = r2;
	l3 = r2;
	r3 = r0 + r2;
	r3 += -2;
	i2 = r3;			/* block 0, at B(-1) */
	r3 = r0 + r1;
	r3 += -2;
	i3 = r3;			/* block G, at B(-1) */
	m1 = 6 (x);
	m2 = -4 (x);
	r0 = [sp + F_JOB];
	cc = r0 == 0;
	if !cc jump .Ls16_dma_bands;

	/* One stream over the whole frame when src, gx, gy (and mag) rows are contiguous and
	 * aligned; the border columns are then zeroed afterwards. */
	r4 = [sp + F_W];
	r0 = [sp + F_SS];
	cc = r0 == r4;
	if !cc jump .Ls16_rows;
	r0 = [sp + F_GS];
	r1 = r4 << 1;
	cc = r0 == r1;
	if !cc jump .Ls16_rows;
	r0 = [sp + F_GX];
	r1 = [sp + F_GY];
	r0 = r0 | r1;
	r0 = r0 | r4;
	r1 = [sp + F_DST];
	r0 = r0 | r1;
	r1 = 3;
	r0 = r0 & r1;
	cc = r0 == 0;
	if !cc jump .Ls16_rows;
	r0 = 8;
	cc = r4 < r0;
	if cc jump .Ls16_rows;
	r0 = [sp + F_DST];
	cc = r0 == 0;
	if cc jump .Ls16_stream;
	r0 = [sp + F_DS];
	cc = r0 == r4;
	if !cc jump .Ls16_rows;
.Ls16_stream:
	r0 = [sp + F_SRC];
	r0 = r0 + r4;
	r0 = r0 + r4;			/* input row 2 */
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r1 = r4 << 1;
	r0 = [sp + F_GX];
	r0 = r0 + r1;
	p2 = r0;
	r0 = [sp + F_GY];
	r0 = r0 + r1;
	p3 = r0;
	r0 = [sp + F_DST];
	r0 = r0 + r4;
	p4 = r0;
	r0 = [sp + F_H];
	r0 += -2;
	r0 *= r7;
	r0 += -2;
	p5 = r0;			/* (h-2) G - 1 groups */
	r0 = [sp + F_DST];
	cc = r0 == 0;
	if cc jump .Ls16_sa;
	call .Lseg16m;
	jump .Ls16_sb;
.Ls16_sa:
	call .Lseg16;
.Ls16_sb:
	/* The last group from a copy of the last row. */
	r0 = [sp + F_SS];
	r1 = [sp + F_H];
	r1 += -1;
	r0 *= r1;
	r1 = [sp + F_SRC];
	r0 = r0 + r1;
	call .Lsafe;
	r1 = [sp + F_G];
	r1 <<= 2;
	r0 = r0 + r1;
	r0 += -4;
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	p5 = 0;
	r0 = [sp + F_DST];
	cc = r0 == 0;
	if cc jump .Ls16_sc;
	call .Lseg16m;
	jump .Ls16_sd;
.Ls16_sc:
	call .Lseg16;
.Ls16_sd:
	/* x = w-1 of row y and x = 0 of row y+1 are neighbours: zero both, for y = 0 .. h-2. */
	r4 = [sp + F_W];
	r0 = r4 << 1;
	p4 = r0;			/* gx/gy row */
	r0 += -2;
	r1 = [sp + F_GX];
	r1 = r1 + r0;
	p0 = r1;
	r1 = [sp + F_GY];
	r1 = r1 + r0;
	p1 = r1;
	r0 = [sp + F_DST];
	r0 = r0 + r4;
	r0 += -1;
	p2 = r0;
	p3 = r4;			/* mag row */
	p5 = [sp + F_H];
	p5 += -1;
	r0 = 0;
	r1 = [sp + F_DST];
	cc = r1 == 0;
	if cc jump .Ls16_bnm;
	lsetup (.Ls16_bl, .Ls16_ble) lc0 = p5;
.Ls16_bl:
	w[p0 + 2] = r0;
	w[p0 ++ p4] = r0.l;
	w[p1 + 2] = r0;
	w[p1 ++ p4] = r0.l;
	b[p2 + 1] = r0;
	b[p2] = r0;
.Ls16_ble:
	p2 = p2 + p3;
	jump .Ls16_done;
.Ls16_bnm:
	lsetup (.Ls16_bn, .Ls16_bne) lc0 = p5;
.Ls16_bn:
	w[p0 + 2] = r0;
	w[p0 ++ p4] = r0.l;
	w[p1 + 2] = r0;
.Ls16_bne:
	w[p1 ++ p4] = r0.l;
	jump .Ls16_done;

	/* Aligned rows (src, gx, gy, mag strides multiples of 4, outputs 4-byte aligned), width a
	 * multiple of 4: the loop runs from row to row without draining, then the border columns
	 * are zeroed. */
.Ls16_rows:
	r4 = [sp + F_W];
	r0 = [sp + F_GX];
	r1 = [sp + F_GY];
	r0 = r0 | r1;
	r1 = [sp + F_GS];
	r0 = r0 | r1;
	r1 = [sp + F_SS];
	r0 = r0 | r1;
	r1 = [sp + F_DST];
	r0 = r0 | r1;
	r0 = r0 | r4;
	r1 = [sp + F_DS];
	r2 = [sp + F_DST];
	cc = r2 == 0;
	if cc r1 = r2;
	r0 = r0 | r1;
	r1 = 3;
	r0 = r0 & r1;
	cc = r0 == 0;
	if !cc jump .Ls16_rows_buf;
	r0 = 8;
	cc = r4 < r0;
	if cc jump .Ls16_rows_buf;
	r5 = [sp + F_H];
	r0 = 4;
	cc = r5 < r0;
	if cc jump .Ls16_rows_buf;
	r0 = r5;
	r0 += -4;
	[sp + F_RM2] = r0;
	r0 = [sp + F_SS];
	r5 += -1;
	r0 *= r5;
	r1 = [sp + F_SRC];
	r0 = r0 + r1;
	call .Lsafe;			/* the last input row, copied */
	r1 = r0;
	r1 += 1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	[sp + F_LP0] = r0;
	[sp + F_LP1] = r1;
	r7 = [sp + F_G];
	r6 = r7 << 2;			/* 4 G = w */
	r4 = [sp + F_SS];
	r0 = r4 - r6;
	[sp + F_DIN] = r0;
	r1 = [sp + F_DS];
	r0 = r1 - r6;
	[sp + F_DOUT] = r0;
	r1 = [sp + F_GS];
	r6 <<= 1;
	r0 = r1 - r6;
	[sp + F_DG] = r0;
	r0 = [sp + F_SRC];
	r0 = r0 + r4;
	r0 = r0 + r4;			/* input row 2 */
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r1 = [sp + F_GS];
	r0 = [sp + F_GX];
	r0 = r0 + r1;
	p2 = r0;
	r0 = [sp + F_GY];
	r0 = r0 + r1;
	p3 = r0;
	r1 = [sp + F_DS];
	r0 = [sp + F_DST];
	r0 = r0 + r1;
	p4 = r0;
	p5 = r7;
	p5 += -1;
	r0 = [sp + F_DST];
	cc = r0 == 0;
	if cc jump .Ls16_ra;
	call .Lsegr16m;
	jump .Ls16_rb;
.Ls16_ra:
	call .Lsegr16;
.Ls16_rb:
	/* The border columns of rows 1 .. h-2. */
	r4 = [sp + F_W];
	r5 = [sp + F_GS];
	r0 = r4 << 1;
	r0 += -2;			/* x = w-1 */
	r1 = [sp + F_GX];
	r1 = r1 + r5;
	p0 = r1;
	r1 = r1 + r0;
	p1 = r1;
	r1 = [sp + F_GY];
	r1 = r1 + r5;
	p2 = r1;
	r1 = r1 + r0;
	p3 = r1;
	p4 = r5;
	p5 = [sp + F_H];
	p5 += -2;
	r0 = 0;
	lsetup (.Ls16_rbl, .Ls16_rble) lc0 = p5;
.Ls16_rbl:
	w[p0 ++ p4] = r0.l;
	w[p1 ++ p4] = r0.l;
	w[p2 ++ p4] = r0.l;
.Ls16_rble:
	w[p3 ++ p4] = r0.l;
	r1 = [sp + F_DST];
	cc = r1 == 0;
	if cc jump .Ls16_done;
	r2 = [sp + F_DS];
	r1 = r1 + r2;
	p0 = r1;
	r1 = r1 + r4;
	r1 += -1;
	p1 = r1;
	p2 = r2;
	lsetup (.Ls16_rml, .Ls16_rmle) lc0 = p5;
.Ls16_rml:
	b[p0] = r0;
	b[p1] = r0;
	p0 = p0 + p2;
.Ls16_rmle:
	p1 = p1 + p2;
	jump .Ls16_done;

.Ls16_rows_buf:
	r0 = 1;
	[sp + F_Y] = r0;
.Ls16_row:
	r0 = [sp + F_Y];
	r1 = [sp + F_SS];
	r0 += 1;
	r0 *= r1;
	r1 = [sp + F_SRC];
	r0 = r0 + r1;
	call .Linrow;
	r1 = r0;
	r1 += 1;
	i0 = r0;
	i1 = r1;
	r2 = -4;
	r0 = r0 & r2;
	r1 = r1 & r2;
	p0 = r0;
	p1 = r1;
	r0 = [sp + F_Y];
	r1 = [sp + F_GS];
	r0 *= r1;
	r1 = [sp + F_GX];
	r1 = r1 + r0;
	[sp + F_GXROW] = r1;
	r2 = [sp + F_GY];
	r2 = r2 + r0;
	[sp + F_GYROW] = r2;
	r3 = [sp + F_W];
	r3 = r3 | r1;
	r3 = r3 | r2;
	r0 = 3;
	r3 = r3 & r0;
	cc = r3 == 0;			/* gx, gy rows aligned and no partial group: in place */
	r0 = [sp + F_TGX];
	if !cc r1 = r0;
	r0 = [sp + F_TGY];
	if !cc r2 = r0;
	p2 = r1;
	p3 = r2;
	p5 = [sp + F_G];
	p5 += -1;
	r0 = [sp + F_DST];
	cc = r0 == 0;
	if cc jump .Ls16_nomag;
	r1 = [sp + F_Y];
	r2 = [sp + F_DS];
	r1 *= r2;
	r0 = r0 + r1;
	[sp + F_DROW] = r0;
	r1 = [sp + F_W];
	r1 = r1 | r0;
	r2 = 3;
	r1 = r1 & r2;
	cc = r1 == 0;
	r1 = [sp + F_T];
	if !cc r0 = r1;
	p4 = r0;
	call .Lseg16m;
	r0 = p4;
	r1 = [sp + F_DROW];
	r2 = [sp + F_G];
	r2 <<= 2;
	r1 = r1 + r2;
	cc = r0 == r1;
	if cc jump .Ls16_gxgy;
	p0 = [sp + F_T];		/* the magnitude row went to its row buffer */
	p1 = [sp + F_DROW];
	p2 = [sp + F_W];
	call .Lcopy;
	jump .Ls16_gxgy;
.Ls16_nomag:
	call .Lseg16;
.Ls16_gxgy:
	r0 = p3;
	r1 = [sp + F_GYROW];
	r2 = [sp + F_G];
	r2 <<= 3;
	r1 = r1 + r2;
	cc = r0 == r1;
	if cc jump .Ls16_border;
	p0 = [sp + F_TGX];		/* gx and gy went to their row buffers */
	p1 = [sp + F_GXROW];
	p2 = [sp + F_W];
	call .Lcopy16;
	p0 = [sp + F_TGY];
	p1 = [sp + F_GYROW];
	p2 = [sp + F_W];
	call .Lcopy16;
.Ls16_border:
	/* x = 0 and x = w-1 are 0. */
	r0 = 0;
	r1 = [sp + F_W];
	r1 += -1;
	p2 = r1;
	r1 <<= 1;
	p1 = r1;
	p0 = [sp + F_GXROW];
	w[p0] = r0;
	p0 = p0 + p1;
	w[p0] = r0;
	p0 = [sp + F_GYROW];
	w[p0] = r0;
	p0 = p0 + p1;
	w[p0] = r0;
	r1 = [sp + F_DST];
	cc = r1 == 0;
	if cc jump .Ls16_next;
	p0 = [sp + F_DROW];
	b[p0] = r0;
	p0 = p0 + p2;
	b[p0] = r0;
.Ls16_next:
	r0 = [sp + F_Y];
	r0 += 1;
	[sp + F_Y] = r0;
	r1 = [sp + F_H];
	r1 += -1;
	cc = r0 < r1;
	if cc jump .Ls16_row;

.Ls16_done:
	r0 = 0;
	l0 = r0;
	l1 = r0;
	l2 = r0;
	l3 = r0;
	sp += 60;
	sp += 60;
	sp += 60;
	sp += 60;
	sp += 60;
	sp += 24;			/* LOCALS16 */
	rets = [sp++];
	fp = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;
	/* The DMA path's bands (.Ldplan16): band j (F_S, F_N, buffers F_IN0, F_OUT0) computed,
	 * band j+1 (F_S1, F_N1, F_IN1, F_OUT1) in or arriving. Wait for it, start the job that
	 * sends band j's gx, gy (and mag) rows out and brings band j+2 into band j's input
	 * buffer (up to 4 transfers), compute band j+1, zero its border columns, and so on. */
.Ls16_dma_bands:
	r0 = [sp + F_IN0];
	i0 = r0;			/* BYTEOP16P's byte offsets: rows in L1 are word aligned */
	r0 += 1;
	i1 = r0;
.Ls16_db_loop:
	call .Ldoutrows;
	r4 = r1;
	r5 = r3;
	r0 = 0;
	call .Lsdo16;
	r0 = 1;
	r1 = r4;
	r3 = r5;
	call .Lsdo16;
	r7 = [sp + F_NI];
	cc = r7 == 2;
	if cc jump .Ls16_db_i;
	r0 = 2;
	r1 = r4;
	r3 = r5;
	call .Lsdo16;
.Ls16_db_i:
	r5 = 0;
	r0 = [sp + F_S1];
	r1 = [sp + F_N1];
	r6 = r0 + r1;			/* band j+2 */
	r1 = [sp + F_H];
	cc = r6 < r1;
	if !cc jump .Ls16_db_go;
	r0 = r6;
	call .Lsdband;
	r5 = r0;
	r3 = r0;
	r0 = r7;
	r1 = r6;
	r2 = [sp + F_IN0];
	call .Lsdin;
	r7 += 1;
.Ls16_db_go:
	call _bvb_dma_wait;
	r0 = [sp + F_JOB];
	r1 = r7;
	call _bvb_dma_start;
	call .Ls16_swj;
	r0 = [sp + F_S1];
	r1 = [sp + F_H];
	cc = r0 < r1;
	if !cc jump .Ls16_db_end;
	/* band j+1 becomes band j */
	[sp + F_S] = r0;
	r0 = [sp + F_N1];
	[sp + F_N] = r0;
	[sp + F_S1] = r6;
	[sp + F_N1] = r5;
	r0 = [sp + F_IN0];
	r1 = [sp + F_IN1];
	[sp + F_IN0] = r1;
	[sp + F_IN1] = r0;
	r0 = [sp + F_OUT0];
	r1 = [sp + F_OUT1];
	[sp + F_OUT0] = r1;
	[sp + F_OUT1] = r0;
	p0 = [sp + F_IN0];
	p1 = p0;
	p2 = r1;
	r0 = [sp + F_REC + 32 + R_OFF];
	r0 = r0 + r1;
	p3 = r0;
	r0 = [sp + F_REC + 64 + R_OFF];
	r0 = r0 + r1;
	p4 = r0;
	r0 = [sp + F_N];
	r1 = [sp + F_G];
	r0 *= r1;
	r0 += -1;
	p5 = r0;
	r0 = [sp + F_DST];
	cc = r0 == 0;
	if cc jump .Ls16_db_nm;
	call .Lseg16m;
	jump .Ls16_db_b;
.Ls16_db_nm:
	call .Lseg16;
.Ls16_db_b:
	/* x = 0 and x = w-1 of the band's output rows are 0. */
	r0 = [sp + F_OUT0];
	r1 = [sp + F_W];
	r1 += -1;
	r2 = r1 << 1;			/* x = w-1 in gx, gy */
	p0 = r0;
	r3 = r0 + r2;
	p1 = r3;
	r3 = [sp + F_REC + 32 + R_OFF];
	r3 = r3 + r0;
	p2 = r3;
	r3 = r3 + r2;
	p3 = r3;
	p4 = [sp + F_REC + R_L1S];
	p5 = [sp + F_N];
	r2 = 0;
	lsetup (.Ls16_db_bl, .Ls16_db_ble) lc0 = p5;
.Ls16_db_bl:
	w[p0 ++ p4] = r2.l;
	w[p1 ++ p4] = r2.l;
	w[p2 ++ p4] = r2.l;
.Ls16_db_ble:
	w[p3 ++ p4] = r2.l;
	r3 = [sp + F_DST];
	cc = r3 == 0;
	if cc jump .Ls16_db_loop;
	r3 = [sp + F_REC + 64 + R_OFF];
	r3 = r3 + r0;
	p0 = r3;
	r3 = r3 + r1;
	p1 = r3;
	p2 = [sp + F_P];
	lsetup (.Ls16_db_ml, .Ls16_db_mle) lc0 = p5;
.Ls16_db_ml:
	b[p0] = r2;
	b[p1] = r2;
	p0 = p0 + p2;
.Ls16_db_mle:
	p1 = p1 + p2;
	jump .Ls16_db_loop;
	/* The last band's rows are on their way: then row h-1, zero, from its output buffer. */
.Ls16_db_end:
	r0 = [sp + F_OUT0];		/* the buffer of the job that has ended */
	r1 = [sp + F_OUT1];
	[sp + F_OUT0] = r1;
	[sp + F_OUT1] = r0;
	call .Ls16_z0;
	r4 = [sp + F_H];
	r4 += -1;
	r0 = 0;
	r1 = r4;
	r3 = 1;
	call .Lsdo16;
	r0 = 1;
	r1 = r4;
	r3 = 1;
	call .Lsdo16;
	r7 = [sp + F_NI];
	cc = r7 == 2;
	if cc jump .Ls16_db_z;
	r0 = 2;
	r1 = r4;
	r3 = 1;
	call .Lsdo16;
.Ls16_db_z:
	call _bvb_dma_wait;
	r0 = [sp + F_JOB];
	r1 = r7;
	call _bvb_dma_start;
	call _bvb_dma_wait;
	jump .Ls16_done;
BVB_ENDFUNC bvb_sobel3x3_s16_asm


	/* r0 = an input row; returns it, or a copy in the safe line when the groups' reads
	 * (up to 4 G + 4 bytes past the row start) would leave src. */
.Linrow:
	r1 = [sp + F_G];
	r1 <<= 2;
	r1 = r1 + r0;
	r1 += 4;
	r2 = [sp + F_END];
	cc = r1 < r2 (iu);
	if !cc jump .Lsafe;
	rts;
.Lsafe:
	/* Copies the words holding r0 .. r0 + w - 1 to the safe line, keeping the byte offset;
	 * returns the copy's address of r0. */
	r1 = -4;
	r1 = r0 & r1;
	i0 = r1;
	r2 = r0 - r1;			/* offset in the word */
	r3 = [sp + F_SAFE];
	r0 = r3 + r2;
	i1 = r3;
	r3 = [sp + F_W];
	r3 = r3 + r2;
	r3 += -1;
	r3 >>= 2;			/* words to copy, less one */
	p0 = r3;
	r1 = [i0++];
	cc = p0 == 0;
	if cc jump .Lsafe_e;
	lsetup (.Lsafe_l, .Lsafe_l) lc0 = p0;
.Lsafe_l:
	mnop || r1 = [i0++] || [i1++] = r1;
.Lsafe_e:
	[i1++] = r1;
	rts;

	/* Zeroes p1 bytes at p0. */
.Lzero:
	r0 = 0;
	r1 = p0;
	r2 = p1;
	r1 = r1 | r2;
	r2 = 3;
	r1 = r1 & r2;
	cc = r1 == 0;
	if !cc jump .Lzero_b;
	p1 = p1 >> 2;
	lsetup (.Lzero_w, .Lzero_w) lc0 = p1;
.Lzero_w:
	[p0++] = r0;
	rts;
.Lzero_b:
	lsetup (.Lzero_bl, .Lzero_bl) lc0 = p1;
.Lzero_bl:
	b[p0++] = r0;
	rts;

	/* Copies p2 >= 3 bytes from p0 (4-byte aligned) to p1: by words when p1 is aligned, by
	 * halfwords when it is even, else a byte a cycle. Clobbers R0-R2, P0-P2, I0, LC0. */
.Lcopy:
	i0 = p0;
	r1 = p1;
	r2 = 3;
	r2 = r1 & r2;
	cc = r2 == 0;
	if cc jump .Lcopy_w;
	cc = bittst (r1, 0);
	if !cc jump .Lcopy_h;
	/* odd: a word in, four bytes out, each shift beside a store */
	r0 = [i0++];
	r2 = p2;
	r1 = 3;
	r1 = r1 & r2;			/* the bytes after the last whole word */
	p2 = p2 >> 2;
	cc = p2 == 0;
	if cc jump .Lcopy_tail;
	lsetup (.Lcopy_b, .Lcopy_be) lc0 = p2;
.Lcopy_b:
	r1 = r0 >> 8 || b[p1++] = r0 || nop;
	r0 = r1 >> 8 || b[p1++] = r1 || nop;
	r1 = r0 >> 8 || b[p1++] = r0 || nop;
.Lcopy_be:
	mnop || b[p1++] = r1 || r0 = [i0++];
	r1 = 3;
	r1 = r1 & r2;
	jump .Lcopy_tail;
.Lcopy_h:
	r0.l = w[i0++];
	r1 = p2;
	p2 = p2 >> 1;
	p2 += -1;
	cc = p2 == 0;
	if cc jump .Lcopy_he;
	lsetup (.Lcopy_hl, .Lcopy_hl) lc0 = p2;
.Lcopy_hl:
	mnop || w[p1++] = r0 || r0.l = w[i0++];
.Lcopy_he:
	w[p1++] = r0;
	cc = bittst (r1, 0);
	if !cc jump .Lcopy_x;
	r0.l = w[i0];			/* the odd last byte */
	b[p1] = r0;
.Lcopy_x:
	rts;
.Lcopy_w:
	r1 = p2;
	p2 = p2 >> 2;
	cc = p2 == 0;
	if cc jump .Lcopy_w0;
	r0 = [i0++];
	p2 += -1;
	cc = p2 == 0;
	if cc jump .Lcopy_we;
	lsetup (.Lcopy_wl, .Lcopy_wl) lc0 = p2;
.Lcopy_wl:
	mnop || [p1++] = r0 || r0 = [i0++];
.Lcopy_we:
	[p1++] = r0;
.Lcopy_w0:
	r2 = 3;
	r1 = r1 & r2;			/* 0-3 bytes left */
	r0 = [i0];
.Lcopy_tail:
	cc = r1 == 0;
	if cc jump .Lcopy_x;
	p2 = r1;
	lsetup (.Lcopy_tl, .Lcopy_te) lc0 = p2;
.Lcopy_tl:
	b[p1++] = r0;
.Lcopy_te:
	r0 >>= 8;
	rts;

	/* The inner loop: p5 + 1 groups of 4 output pixels (bvb/sobel.h for the method).
	 * In: P0, P1 the aligned words of input windows x..x+3 and x+1..x+4 (I0, I1 the
	 * same addresses unaligned: BYTEOP16P takes the byte offset from them), P2 output, I2, I3
	 * the ring (circular), M0 = 8, M1 = -6, M2 = -4. Clobbers R0-R7, P5, LC0.
	 * Software-pipelined over two groups, one instruction per cycle, 16 cycles a group.
	 * Operations: Lw0, Lw1 / Lv0, Lv1 the two words of the windows at x / x+1; A1 the pair sums
	 * H of the new input row; s1-s10 the walk over the blocks above (B(x-1) .. B(x+2) as halves
	 * into BOA, BOB; H; B(x..x+3) as words; the lane masks); A2, A3 the new 2B = 2 (H + H);
	 * t1-t8 the walk over the new blocks (store H and 2B, read B(x-1) .. B(x+2) back); K1a, K1b
	 * = 2B(new) - Bo(above); K2a, K2b = 2B(above) - Bo(new); X1-X4 ABS; M1, M2 MAX; N1, N2 MIN
	 * with the lane masks; PK BYTEPACK; SW the store. */
.Lseg:
	/* prologue 0 */
	R0 = [P0++];                                                                                        /* Lw0 */
	R1 = [P0];                                                                                          /* Lw1 */
	R2 = [P1++];                                                                                        /* Lv0 */
	MNOP || R3 = [P1] || R6.L = W[I2++];                                                                /* Lv1 s1 */
	I2 += M0;                                                                                           /* s1b */
	MNOP || R7 = [I2++] || R5.L = W[I3++];                                                              /* s2 t1 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || I3 += M0;                                       /* A1 s3 t1b */
	R0 = R3 +|+ R7, R7 = R3 -|- R7 (ASL) || R6.H = W[I2++] || [I3++] = R3;                              /* A2 s4 t2 */
	R2 = R1 +|+ R2, R7 = R1 -|- R2 (ASL) || R3.L = W[I2++] || [I3++] = R1;                              /* A3 s5 t3 */
	R1 = R0 -|- R6 || R3.H = W[I2] || [I3++] = R0;                                                      /* K1a s6 t4 */
	R3 = R2 -|- R3 || R0 = [I2 ++ M2] || [I3--] = R2;                                                   /* K1b s7 t5 */
	R1 = ABS R1 (V) || R2 = [I2 ++ M0] || R5.H = W[I3++];                                               /* X1 s8 t6 */
	R5 = R2 -|- R5 || R6.L = W[I3++] || NOP;                                                            /* K2a t7 */
	R2 = ABS R3 (V) || R6.H = W[I3++] || NOP;                                                           /* X2 t8 */
	R0 = R0 -|- R6;                                                                                     /* K2b */
	R3 = ABS R5 (V);                                                                                    /* X3 */
	CC = P5 == 0;
	if CC jump .Lu8_kx;
	lsetup (.Lu8_k, .Lu8_ke) lc0 = P5;
.Lu8_k:
	R4 = ABS R0 (V) || R0 = [P0++] || NOP;                                                              /* X4 Lw0 */
	R6 = MAX (R1, R3) (V) || R1 = [P0] || R3 = [I2++];                                                  /* M1 Lw1 s9 */
	R5 = MAX (R2, R4) (V) || R2 = [P1++] || R4 = [I2 ++ M1];                                            /* M2 Lv0 s10 */
	R7 = MIN (R6, R3) (V) || R3 = [P1] || R6.L = W[I2++];                                               /* N1 Lv1 s1 */
	R4 = MIN (R5, R4) (V) || I2 += M0 || NOP;                                                           /* N2 s1b */
	R4 = BYTEPACK (R7, R4) || R7 = [I2++] || R5.L = W[I3++];                                            /* PK s2 t1 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || I3 += M0;                                       /* A1 s3 t1b */
	R0 = R3 +|+ R7, R7 = R3 -|- R7 (ASL) || R6.H = W[I2++] || [I3++] = R3;                              /* A2 s4 t2 */
	R2 = R1 +|+ R2, R7 = R1 -|- R2 (ASL) || R3.L = W[I2++] || [I3++] = R1;                              /* A3 s5 t3 */
	R1 = R0 -|- R6 || R3.H = W[I2] || [I3++] = R0;                                                      /* K1a s6 t4 */
	R3 = R2 -|- R3 || R0 = [I2 ++ M2] || [I3--] = R2;                                                   /* K1b s7 t5 */
	R1 = ABS R1 (V) || R2 = [I2 ++ M0] || R5.H = W[I3++];                                               /* X1 s8 t6 */
	R5 = R2 -|- R5 || [P2++] = R4 || R6.L = W[I3++];                                                    /* K2a SW t7 */
	R2 = ABS R3 (V) || R6.H = W[I3++] || NOP;                                                           /* X2 t8 */
	R0 = R0 -|- R6;                                                                                     /* K2b */
.Lu8_ke:
	R3 = ABS R5 (V);                                                                                    /* X3 */
.Lu8_kx:
	/* epilogue 1 */
	R4 = ABS R0 (V);                                                                                    /* X4 */
	R6 = MAX (R1, R3) (V) || R3 = [I2++] || NOP;                                                        /* M1 s9 */
	R5 = MAX (R2, R4) (V) || R4 = [I2 ++ M1] || NOP;                                                    /* M2 s10 */
	R7 = MIN (R6, R3) (V);                                                                              /* N1 */
	R4 = MIN (R5, R4) (V);                                                                              /* N2 */
	R4 = BYTEPACK (R7, R4);                                                                             /* PK */
	[P2++] = R4;                                                                                        /* SW */
	rts;

	/* .Lseg over rows 1 .. h-2 with the pipeline kept full from row to row: P0, P1, I0, I1
	 * input row 2 (input rows all at one byte offset), P2 output row 1, P5 = G - 1 >= 1; in
	 * the frame the last row's input words (from a copy), the row count less 2 and the pointer
	 * moves F_DIN, F_DOUT. FP is used. The input pointers serve only a group's first 16 cycles
	 * and the output only its second, so the input moves before a row's first group and the
	 * output one group later: 5 cycles a row. */
.Lsegr:
	/* prologue: the first group of the first row */
	R0 = [P0++];                                                                                        /* Lw0 */
	R1 = [P0];                                                                                          /* Lw1 */
	R2 = [P1++];                                                                                        /* Lv0 */
	MNOP || R3 = [P1] || R6.L = W[I2++];                                                                /* Lv1 s1 */
	I2 += M0;                                                                                           /* s1b */
	MNOP || R7 = [I2++] || R5.L = W[I3++];                                                              /* s2 t1 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || I3 += M0;                                       /* A1 s3 t1b */
	R0 = R3 +|+ R7, R7 = R3 -|- R7 (ASL) || R6.H = W[I2++] || [I3++] = R3;                              /* A2 s4 t2 */
	R2 = R1 +|+ R2, R7 = R1 -|- R2 (ASL) || R3.L = W[I2++] || [I3++] = R1;                              /* A3 s5 t3 */
	R1 = R0 -|- R6 || R3.H = W[I2] || [I3++] = R0;                                                      /* K1a s6 t4 */
	R3 = R2 -|- R3 || R0 = [I2 ++ M2] || [I3--] = R2;                                                   /* K1b s7 t5 */
	R1 = ABS R1 (V) || R2 = [I2 ++ M0] || R5.H = W[I3++];                                               /* X1 s8 t6 */
	R5 = R2 -|- R5 || R6.L = W[I3++] || NOP;                                                            /* K2a t7 */
	R2 = ABS R3 (V) || R6.H = W[I3++] || NOP;                                                           /* X2 t8 */
	R0 = R0 -|- R6;                                                                                     /* K2b */
	R3 = ABS R5 (V);                                                                                    /* X3 */
	lsetup (.Lu8r_a, .Lu8r_ae) lc0 = p5;
.Lu8r_a:
	R4 = ABS R0 (V) || R0 = [P0++] || NOP;                                                              /* X4 Lw0 */
	R6 = MAX (R1, R3) (V) || R1 = [P0] || R3 = [I2++];                                                  /* M1 Lw1 s9 */
	R5 = MAX (R2, R4) (V) || R2 = [P1++] || R4 = [I2 ++ M1];                                            /* M2 Lv0 s10 */
	R7 = MIN (R6, R3) (V) || R3 = [P1] || R6.L = W[I2++];                                               /* N1 Lv1 s1 */
	R4 = MIN (R5, R4) (V) || I2 += M0 || NOP;                                                           /* N2 s1b */
	R4 = BYTEPACK (R7, R4) || R7 = [I2++] || R5.L = W[I3++];                                            /* PK s2 t1 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || I3 += M0;                                       /* A1 s3 t1b */
	R0 = R3 +|+ R7, R7 = R3 -|- R7 (ASL) || R6.H = W[I2++] || [I3++] = R3;                              /* A2 s4 t2 */
	R2 = R1 +|+ R2, R7 = R1 -|- R2 (ASL) || R3.L = W[I2++] || [I3++] = R1;                              /* A3 s5 t3 */
	R1 = R0 -|- R6 || R3.H = W[I2] || [I3++] = R0;                                                      /* K1a s6 t4 */
	R3 = R2 -|- R3 || R0 = [I2 ++ M2] || [I3--] = R2;                                                   /* K1b s7 t5 */
	R1 = ABS R1 (V) || R2 = [I2 ++ M0] || R5.H = W[I3++];                                               /* X1 s8 t6 */
	R5 = R2 -|- R5 || [P2++] = R4 || R6.L = W[I3++];                                                    /* K2a SW t7 */
	R2 = ABS R3 (V) || R6.H = W[I3++] || NOP;                                                           /* X2 t8 */
	R0 = R0 -|- R6;                                                                                     /* K2b */
.Lu8r_ae:
	R3 = ABS R5 (V);                                                                                    /* X3 */
	fp = [sp + F_DIN];
	p0 = p0 + fp;
	p1 = p1 + fp;
	fp = [sp + F_RM2];
	cc = fp == 0;
	if cc jump .Lu8r_bx;
	lc1 = fp;
	lsetup (.Lu8r_o, .Lu8r_oe) lc1;
.Lu8r_o:
	R4 = ABS R0 (V) || R0 = [P0++] || NOP;                                                              /* X4 Lw0 */
	R6 = MAX (R1, R3) (V) || R1 = [P0] || R3 = [I2++];                                                  /* M1 Lw1 s9 */
	R5 = MAX (R2, R4) (V) || R2 = [P1++] || R4 = [I2 ++ M1];                                            /* M2 Lv0 s10 */
	R7 = MIN (R6, R3) (V) || R3 = [P1] || R6.L = W[I2++];                                               /* N1 Lv1 s1 */
	R4 = MIN (R5, R4) (V) || I2 += M0 || NOP;                                                           /* N2 s1b */
	R4 = BYTEPACK (R7, R4) || R7 = [I2++] || R5.L = W[I3++];                                            /* PK s2 t1 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || I3 += M0;                                       /* A1 s3 t1b */
	R0 = R3 +|+ R7, R7 = R3 -|- R7 (ASL) || R6.H = W[I2++] || [I3++] = R3;                              /* A2 s4 t2 */
	R2 = R1 +|+ R2, R7 = R1 -|- R2 (ASL) || R3.L = W[I2++] || [I3++] = R1;                              /* A3 s5 t3 */
	R1 = R0 -|- R6 || R3.H = W[I2] || [I3++] = R0;                                                      /* K1a s6 t4 */
	R3 = R2 -|- R3 || R0 = [I2 ++ M2] || [I3--] = R2;                                                   /* K1b s7 t5 */
	R1 = ABS R1 (V) || R2 = [I2 ++ M0] || R5.H = W[I3++];                                               /* X1 s8 t6 */
	R5 = R2 -|- R5 || [P2++] = R4 || R6.L = W[I3++];                                                    /* K2a SW t7 */
	R2 = ABS R3 (V) || R6.H = W[I3++] || NOP;                                                           /* X2 t8 */
	R0 = R0 -|- R6;                                                                                     /* K2b */
	R3 = ABS R5 (V);                                                                                    /* X3 */
	fp = [sp + F_DOUT];
	p2 = p2 + fp;
	lsetup (.Lu8r_i, .Lu8r_ie) lc0 = p5;
.Lu8r_i:
	R4 = ABS R0 (V) || R0 = [P0++] || NOP;                                                              /* X4 Lw0 */
	R6 = MAX (R1, R3) (V) || R1 = [P0] || R3 = [I2++];                                                  /* M1 Lw1 s9 */
	R5 = MAX (R2, R4) (V) || R2 = [P1++] || R4 = [I2 ++ M1];                                            /* M2 Lv0 s10 */
	R7 = MIN (R6, R3) (V) || R3 = [P1] || R6.L = W[I2++];                                               /* N1 Lv1 s1 */
	R4 = MIN (R5, R4) (V) || I2 += M0 || NOP;                                                           /* N2 s1b */
	R4 = BYTEPACK (R7, R4) || R7 = [I2++] || R5.L = W[I3++];                                            /* PK s2 t1 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || I3 += M0;                                       /* A1 s3 t1b */
	R0 = R3 +|+ R7, R7 = R3 -|- R7 (ASL) || R6.H = W[I2++] || [I3++] = R3;                              /* A2 s4 t2 */
	R2 = R1 +|+ R2, R7 = R1 -|- R2 (ASL) || R3.L = W[I2++] || [I3++] = R1;                              /* A3 s5 t3 */
	R1 = R0 -|- R6 || R3.H = W[I2] || [I3++] = R0;                                                      /* K1a s6 t4 */
	R3 = R2 -|- R3 || R0 = [I2 ++ M2] || [I3--] = R2;                                                   /* K1b s7 t5 */
	R1 = ABS R1 (V) || R2 = [I2 ++ M0] || R5.H = W[I3++];                                               /* X1 s8 t6 */
	R5 = R2 -|- R5 || [P2++] = R4 || R6.L = W[I3++];                                                    /* K2a SW t7 */
	R2 = ABS R3 (V) || R6.H = W[I3++] || NOP;                                                           /* X2 t8 */
	R0 = R0 -|- R6;                                                                                     /* K2b */
.Lu8r_ie:
	R3 = ABS R5 (V);                                                                                    /* X3 */
	fp = [sp + F_DIN];
	p0 = p0 + fp;
.Lu8r_oe:
	p1 = p1 + fp;
.Lu8r_bx:
	p0 = [sp + F_LP0];
	p1 = [sp + F_LP1];
	R4 = ABS R0 (V) || R0 = [P0++] || NOP;                                                              /* X4 Lw0 */
	R6 = MAX (R1, R3) (V) || R1 = [P0] || R3 = [I2++];                                                  /* M1 Lw1 s9 */
	R5 = MAX (R2, R4) (V) || R2 = [P1++] || R4 = [I2 ++ M1];                                            /* M2 Lv0 s10 */
	R7 = MIN (R6, R3) (V) || R3 = [P1] || R6.L = W[I2++];                                               /* N1 Lv1 s1 */
	R4 = MIN (R5, R4) (V) || I2 += M0 || NOP;                                                           /* N2 s1b */
	R4 = BYTEPACK (R7, R4) || R7 = [I2++] || R5.L = W[I3++];                                            /* PK s2 t1 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || I3 += M0;                                       /* A1 s3 t1b */
	R0 = R3 +|+ R7, R7 = R3 -|- R7 (ASL) || R6.H = W[I2++] || [I3++] = R3;                              /* A2 s4 t2 */
	R2 = R1 +|+ R2, R7 = R1 -|- R2 (ASL) || R3.L = W[I2++] || [I3++] = R1;                              /* A3 s5 t3 */
	R1 = R0 -|- R6 || R3.H = W[I2] || [I3++] = R0;                                                      /* K1a s6 t4 */
	R3 = R2 -|- R3 || R0 = [I2 ++ M2] || [I3--] = R2;                                                   /* K1b s7 t5 */
	R1 = ABS R1 (V) || R2 = [I2 ++ M0] || R5.H = W[I3++];                                               /* X1 s8 t6 */
	R5 = R2 -|- R5 || [P2++] = R4 || R6.L = W[I3++];                                                    /* K2a SW t7 */
	R2 = ABS R3 (V) || R6.H = W[I3++] || NOP;                                                           /* X2 t8 */
	R0 = R0 -|- R6;                                                                                     /* K2b */
	R3 = ABS R5 (V);                                                                                    /* X3 */
	fp = [sp + F_DOUT];
	p2 = p2 + fp;
	lsetup (.Lu8r_l, .Lu8r_le) lc0 = p5;
.Lu8r_l:
	R4 = ABS R0 (V) || R0 = [P0++] || NOP;                                                              /* X4 Lw0 */
	R6 = MAX (R1, R3) (V) || R1 = [P0] || R3 = [I2++];                                                  /* M1 Lw1 s9 */
	R5 = MAX (R2, R4) (V) || R2 = [P1++] || R4 = [I2 ++ M1];                                            /* M2 Lv0 s10 */
	R7 = MIN (R6, R3) (V) || R3 = [P1] || R6.L = W[I2++];                                               /* N1 Lv1 s1 */
	R4 = MIN (R5, R4) (V) || I2 += M0 || NOP;                                                           /* N2 s1b */
	R4 = BYTEPACK (R7, R4) || R7 = [I2++] || R5.L = W[I3++];                                            /* PK s2 t1 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || I3 += M0;                                       /* A1 s3 t1b */
	R0 = R3 +|+ R7, R7 = R3 -|- R7 (ASL) || R6.H = W[I2++] || [I3++] = R3;                              /* A2 s4 t2 */
	R2 = R1 +|+ R2, R7 = R1 -|- R2 (ASL) || R3.L = W[I2++] || [I3++] = R1;                              /* A3 s5 t3 */
	R1 = R0 -|- R6 || R3.H = W[I2] || [I3++] = R0;                                                      /* K1a s6 t4 */
	R3 = R2 -|- R3 || R0 = [I2 ++ M2] || [I3--] = R2;                                                   /* K1b s7 t5 */
	R1 = ABS R1 (V) || R2 = [I2 ++ M0] || R5.H = W[I3++];                                               /* X1 s8 t6 */
	R5 = R2 -|- R5 || [P2++] = R4 || R6.L = W[I3++];                                                    /* K2a SW t7 */
	R2 = ABS R3 (V) || R6.H = W[I3++] || NOP;                                                           /* X2 t8 */
	R0 = R0 -|- R6;                                                                                     /* K2b */
.Lu8r_le:
	R3 = ABS R5 (V);                                                                                    /* X3 */
	/* epilogue: the last group of the last row */
	R4 = ABS R0 (V);                                                                                    /* X4 */
	R6 = MAX (R1, R3) (V) || R3 = [I2++] || NOP;                                                        /* M1 s9 */
	R5 = MAX (R2, R4) (V) || R4 = [I2 ++ M1] || NOP;                                                    /* M2 s10 */
	R7 = MIN (R6, R3) (V);                                                                              /* N1 */
	R4 = MIN (R5, R4) (V);                                                                              /* N2 */
	R4 = BYTEPACK (R7, R4);                                                                             /* PK */
	[P2++] = R4;                                                                                        /* SW */
	rts;

	/* Zeroes p1 int16 at p0. */
.Lzero16:
	r0 = 0;
	lsetup (.Lzero16_l, .Lzero16_l) lc0 = p1;
.Lzero16_l:
	w[p0++] = r0;
	rts;

	/* Copies p2 >= 3 int16 from p0 (4-byte aligned) to p1 (2-byte aligned): by words when p1
	 * is 4-byte aligned, else by halfwords. Clobbers R0, R1, P2, I0, LC0. */
.Lcopy16:
	i0 = p0;
	r1 = p2;
	r0 = p1;
	cc = bittst (r0, 1);
	if cc jump .Lcopy16_h;
	r0 = [i0++];
	p2 = p2 >> 1;
	p2 += -1;
	cc = p2 == 0;
	if cc jump .Lcopy16_we;
	lsetup (.Lcopy16_wl, .Lcopy16_wl) lc0 = p2;
.Lcopy16_wl:
	mnop || [p1++] = r0 || r0 = [i0++];
.Lcopy16_we:
	[p1++] = r0;
	cc = bittst (r1, 0);
	if !cc jump .Lcopy16_x;
	r0.l = w[i0];			/* the odd last element */
	w[p1] = r0;
.Lcopy16_x:
	rts;
.Lcopy16_h:
	r0.l = w[i0++];
	p2 += -1;
	lsetup (.Lcopy16_l, .Lcopy16_l) lc0 = p2;
.Lcopy16_l:
	mnop || w[p1++] = r0 || r0.l = w[i0++];
	w[p1++] = r0;
	rts;

	/* The first row of blocks, part 1: H of input row 0 into the B slots. P0, P1, I0, I1 the
	 * row as for the inner loops, I3 the first B slot, M3 the block size - 4, P5 = G - 1. */
.Lpass1:
	/* prologue 0 */
	R0 = [P0++];                                                                                        /* Lw0 */
	R1 = [P0];                                                                                          /* Lw1 */
	R2 = [P1++];                                                                                        /* Lv0 */
	R3 = [P1];                                                                                          /* Lv1 */
	CC = P5 == 0;
	if CC jump .Lp1_kx;
	lsetup (.Lp1_k, .Lp1_ke) lc0 = P5;
.Lp1_k:
	(R3, R2) = BYTEOP16P (R1:0, R3:2) || R0 = [P0++] || NOP;                                            /* A1 Lw0 */
	MNOP || R1 = [P0] || [I3++] = R2;                                                                   /* Lw1 t1 */
	MNOP || R2 = [P1++] || [I3 ++ M3] = R3;                                                             /* Lv0 t2 */
.Lp1_ke:
	R3 = [P1];                                                                                          /* Lv1 */
.Lp1_kx:
	/* epilogue 1 */
	(R3, R2) = BYTEOP16P (R1:0, R3:2);                                                                  /* A1 */
	[I3++] = R2;                                                                                        /* t1 */
	[I3 ++ M3] = R3;                                                                                    /* t2 */
	rts;

	/* The gx/gy inner loop: p5 + 1 groups of 4 pixels; as .Lseg, with gx to P2, gy to P3, the
	 * ring in 16-byte blocks (M1 = 6, M2 = -4) holding H and B unscaled. 14 cycles a group.
	 * Operations as in .Lseg; Q1, Q2 the quad add/sub gx = K1 + K2, gy = K1 - K2; SXA .. SYB
	 * their stores. */
.Lseg16:
	/* prologue 0 */
	R0 = [P0++];                                                                                        /* Lw0 */
	MNOP || R2 = [P1++] || R6.L = W[I2++];                                                              /* Lv0 s1 */
	MNOP || R3 = [P1] || R5.L = W[I3++];                                                                /* Lv1 t1 */
	R1 = [P0];                                                                                          /* Lw1 */
	(R0, R3) = BYTEOP16P (R1:0, R3:2) || R1 = [I2++] || NOP;                                            /* A1 s2 */
	R2 = [I2++];                                                                                        /* s3 */
	R1 = R3 +|+ R1 || R6.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R0 +|+ R2 || R2.L = W[I2++] || [I3++] = R0;                                                    /* A3 s5 t3 */
	R0 = R1 -|- R6 || R2.H = W[I2] || [I3++] = R1;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R3 = [I2 ++ M1] || R5.H = W[I3++];                                                          /* s8 t6 */
	R3 = R3 -|- R5 || R5.L = W[I3++] || NOP;                                                            /* K2a t7 */
	CC = P5 == 0;
	if CC jump .Ls16_kx;
	lsetup (.Ls16_k, .Ls16_ke) lc0 = P5;
.Ls16_k:
	R4 = R0 +|+ R3, R3 = R0 -|- R3 || R0 = [P0++] || R5.H = W[I3++];                                    /* Q1 Lw0 t8 */
	[P2++] = R4;                                                                                        /* SXA */
	R4 = R2 -|- R5 || R2 = [P1++] || R6.L = W[I2++];                                                    /* K2b Lv0 s1 */
	[P3++] = R3;                                                                                        /* SYA */
	R7 = R1 +|+ R4, R4 = R1 -|- R4 || R3 = [P1] || R5.L = W[I3++];                                      /* Q2 Lv1 t1 */
	R1 = [P0];                                                                                          /* Lw1 */
	(R0, R3) = BYTEOP16P (R1:0, R3:2) || R1 = [I2++] || NOP;                                            /* A1 s2 */
	MNOP || [P2++] = R7 || R2 = [I2++];                                                                 /* SXB s3 */
	R1 = R3 +|+ R1 || R6.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R0 +|+ R2 || R2.L = W[I2++] || [I3++] = R0;                                                    /* A3 s5 t3 */
	R0 = R1 -|- R6 || R2.H = W[I2] || [I3++] = R1;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R3 = [I2 ++ M1] || R5.H = W[I3++];                                                          /* s8 t6 */
.Ls16_ke:
	R3 = R3 -|- R5 || [P3++] = R4 || R5.L = W[I3++];                                                    /* K2a SYB t7 */
.Ls16_kx:
	/* epilogue 1 */
	R4 = R0 +|+ R3, R3 = R0 -|- R3 || R5.H = W[I3++] || NOP;                                            /* Q1 t8 */
	[P2++] = R4;                                                                                        /* SXA */
	R4 = R2 -|- R5;                                                                                     /* K2b */
	[P3++] = R3;                                                                                        /* SYA */
	R7 = R1 +|+ R4, R4 = R1 -|- R4;                                                                     /* Q2 */
	[P2++] = R7;                                                                                        /* SXB */
	[P3++] = R4;                                                                                        /* SYB */
	rts;

	/* .Lseg16 and .Lseg16m from row to row, as .Lsegr (P3 gy and P4 mag rows too, F_DG,
	 * F_DOUT their moves). */
.Lsegr16:
	/* prologue: the first group of the first row */
	R0 = [P0++];                                                                                        /* Lw0 */
	MNOP || R2 = [P1++] || R6.L = W[I2++];                                                              /* Lv0 s1 */
	MNOP || R3 = [P1] || R5.L = W[I3++];                                                                /* Lv1 t1 */
	R1 = [P0];                                                                                          /* Lw1 */
	(R0, R3) = BYTEOP16P (R1:0, R3:2) || R1 = [I2++] || NOP;                                            /* A1 s2 */
	R2 = [I2++];                                                                                        /* s3 */
	R1 = R3 +|+ R1 || R6.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R0 +|+ R2 || R2.L = W[I2++] || [I3++] = R0;                                                    /* A3 s5 t3 */
	R0 = R1 -|- R6 || R2.H = W[I2] || [I3++] = R1;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R3 = [I2 ++ M1] || R5.H = W[I3++];                                                          /* s8 t6 */
	R3 = R3 -|- R5 || R5.L = W[I3++] || NOP;                                                            /* K2a t7 */
	lsetup (.Ls16r_a, .Ls16r_ae) lc0 = p5;
.Ls16r_a:
	R4 = R0 +|+ R3, R3 = R0 -|- R3 || R0 = [P0++] || R5.H = W[I3++];                                    /* Q1 Lw0 t8 */
	[P2++] = R4;                                                                                        /* SXA */
	R4 = R2 -|- R5 || R2 = [P1++] || R6.L = W[I2++];                                                    /* K2b Lv0 s1 */
	[P3++] = R3;                                                                                        /* SYA */
	R7 = R1 +|+ R4, R4 = R1 -|- R4 || R3 = [P1] || R5.L = W[I3++];                                      /* Q2 Lv1 t1 */
	R1 = [P0];                                                                                          /* Lw1 */
	(R0, R3) = BYTEOP16P (R1:0, R3:2) || R1 = [I2++] || NOP;                                            /* A1 s2 */
	MNOP || [P2++] = R7 || R2 = [I2++];                                                                 /* SXB s3 */
	R1 = R3 +|+ R1 || R6.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R0 +|+ R2 || R2.L = W[I2++] || [I3++] = R0;                                                    /* A3 s5 t3 */
	R0 = R1 -|- R6 || R2.H = W[I2] || [I3++] = R1;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R3 = [I2 ++ M1] || R5.H = W[I3++];                                                          /* s8 t6 */
.Ls16r_ae:
	R3 = R3 -|- R5 || [P3++] = R4 || R5.L = W[I3++];                                                    /* K2a SYB t7 */
	fp = [sp + F_DIN];
	p0 = p0 + fp;
	p1 = p1 + fp;
	fp = [sp + F_RM2];
	cc = fp == 0;
	if cc jump .Ls16r_bx;
	lc1 = fp;
	lsetup (.Ls16r_o, .Ls16r_oe) lc1;
.Ls16r_o:
	R4 = R0 +|+ R3, R3 = R0 -|- R3 || R0 = [P0++] || R5.H = W[I3++];                                    /* Q1 Lw0 t8 */
	[P2++] = R4;                                                                                        /* SXA */
	R4 = R2 -|- R5 || R2 = [P1++] || R6.L = W[I2++];                                                    /* K2b Lv0 s1 */
	[P3++] = R3;                                                                                        /* SYA */
	R7 = R1 +|+ R4, R4 = R1 -|- R4 || R3 = [P1] || R5.L = W[I3++];                                      /* Q2 Lv1 t1 */
	R1 = [P0];                                                                                          /* Lw1 */
	(R0, R3) = BYTEOP16P (R1:0, R3:2) || R1 = [I2++] || NOP;                                            /* A1 s2 */
	MNOP || [P2++] = R7 || R2 = [I2++];                                                                 /* SXB s3 */
	R1 = R3 +|+ R1 || R6.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R0 +|+ R2 || R2.L = W[I2++] || [I3++] = R0;                                                    /* A3 s5 t3 */
	R0 = R1 -|- R6 || R2.H = W[I2] || [I3++] = R1;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R3 = [I2 ++ M1] || R5.H = W[I3++];                                                          /* s8 t6 */
	R3 = R3 -|- R5 || [P3++] = R4 || R5.L = W[I3++];                                                    /* K2a SYB t7 */
	fp = [sp + F_DG];
	p2 = p2 + fp;
	p3 = p3 + fp;
	lsetup (.Ls16r_i, .Ls16r_ie) lc0 = p5;
.Ls16r_i:
	R4 = R0 +|+ R3, R3 = R0 -|- R3 || R0 = [P0++] || R5.H = W[I3++];                                    /* Q1 Lw0 t8 */
	[P2++] = R4;                                                                                        /* SXA */
	R4 = R2 -|- R5 || R2 = [P1++] || R6.L = W[I2++];                                                    /* K2b Lv0 s1 */
	[P3++] = R3;                                                                                        /* SYA */
	R7 = R1 +|+ R4, R4 = R1 -|- R4 || R3 = [P1] || R5.L = W[I3++];                                      /* Q2 Lv1 t1 */
	R1 = [P0];                                                                                          /* Lw1 */
	(R0, R3) = BYTEOP16P (R1:0, R3:2) || R1 = [I2++] || NOP;                                            /* A1 s2 */
	MNOP || [P2++] = R7 || R2 = [I2++];                                                                 /* SXB s3 */
	R1 = R3 +|+ R1 || R6.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R0 +|+ R2 || R2.L = W[I2++] || [I3++] = R0;                                                    /* A3 s5 t3 */
	R0 = R1 -|- R6 || R2.H = W[I2] || [I3++] = R1;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R3 = [I2 ++ M1] || R5.H = W[I3++];                                                          /* s8 t6 */
.Ls16r_ie:
	R3 = R3 -|- R5 || [P3++] = R4 || R5.L = W[I3++];                                                    /* K2a SYB t7 */
	fp = [sp + F_DIN];
	p0 = p0 + fp;
.Ls16r_oe:
	p1 = p1 + fp;
.Ls16r_bx:
	p0 = [sp + F_LP0];
	p1 = [sp + F_LP1];
	R4 = R0 +|+ R3, R3 = R0 -|- R3 || R0 = [P0++] || R5.H = W[I3++];                                    /* Q1 Lw0 t8 */
	[P2++] = R4;                                                                                        /* SXA */
	R4 = R2 -|- R5 || R2 = [P1++] || R6.L = W[I2++];                                                    /* K2b Lv0 s1 */
	[P3++] = R3;                                                                                        /* SYA */
	R7 = R1 +|+ R4, R4 = R1 -|- R4 || R3 = [P1] || R5.L = W[I3++];                                      /* Q2 Lv1 t1 */
	R1 = [P0];                                                                                          /* Lw1 */
	(R0, R3) = BYTEOP16P (R1:0, R3:2) || R1 = [I2++] || NOP;                                            /* A1 s2 */
	MNOP || [P2++] = R7 || R2 = [I2++];                                                                 /* SXB s3 */
	R1 = R3 +|+ R1 || R6.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R0 +|+ R2 || R2.L = W[I2++] || [I3++] = R0;                                                    /* A3 s5 t3 */
	R0 = R1 -|- R6 || R2.H = W[I2] || [I3++] = R1;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R3 = [I2 ++ M1] || R5.H = W[I3++];                                                          /* s8 t6 */
	R3 = R3 -|- R5 || [P3++] = R4 || R5.L = W[I3++];                                                    /* K2a SYB t7 */
	fp = [sp + F_DG];
	p2 = p2 + fp;
	p3 = p3 + fp;
	lsetup (.Ls16r_l, .Ls16r_le) lc0 = p5;
.Ls16r_l:
	R4 = R0 +|+ R3, R3 = R0 -|- R3 || R0 = [P0++] || R5.H = W[I3++];                                    /* Q1 Lw0 t8 */
	[P2++] = R4;                                                                                        /* SXA */
	R4 = R2 -|- R5 || R2 = [P1++] || R6.L = W[I2++];                                                    /* K2b Lv0 s1 */
	[P3++] = R3;                                                                                        /* SYA */
	R7 = R1 +|+ R4, R4 = R1 -|- R4 || R3 = [P1] || R5.L = W[I3++];                                      /* Q2 Lv1 t1 */
	R1 = [P0];                                                                                          /* Lw1 */
	(R0, R3) = BYTEOP16P (R1:0, R3:2) || R1 = [I2++] || NOP;                                            /* A1 s2 */
	MNOP || [P2++] = R7 || R2 = [I2++];                                                                 /* SXB s3 */
	R1 = R3 +|+ R1 || R6.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R0 +|+ R2 || R2.L = W[I2++] || [I3++] = R0;                                                    /* A3 s5 t3 */
	R0 = R1 -|- R6 || R2.H = W[I2] || [I3++] = R1;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R3 = [I2 ++ M1] || R5.H = W[I3++];                                                          /* s8 t6 */
.Ls16r_le:
	R3 = R3 -|- R5 || [P3++] = R4 || R5.L = W[I3++];                                                    /* K2a SYB t7 */
	/* epilogue: the last group of the last row */
	R4 = R0 +|+ R3, R3 = R0 -|- R3 || R5.H = W[I3++] || NOP;                                            /* Q1 t8 */
	[P2++] = R4;                                                                                        /* SXA */
	R4 = R2 -|- R5;                                                                                     /* K2b */
	[P3++] = R3;                                                                                        /* SYA */
	R7 = R1 +|+ R4, R4 = R1 -|- R4;                                                                     /* Q2 */
	[P2++] = R7;                                                                                        /* SXB */
	[P3++] = R4;                                                                                        /* SYB */
	rts;
.Lsegr16m:
	/* prologue: the first group of the first row */
	R2 = [P1++];                                                                                        /* Lv0 */
	R4.L = W[I2++];                                                                                     /* s1 */
	R3 = [P1];                                                                                          /* Lv1 */
	R0 = [P0++];                                                                                        /* Lw0 */
	MNOP || R1 = [P0] || R7 = [I2++];                                                                   /* Lw1 s2 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || R0.L = W[I3++];                                 /* A1 s3 t1 */
	R7 = R3 +|+ R7 || R4.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R1 +|+ R2 || R2.L = W[I2++] || [I3++] = R1;                                                    /* A3 s5 t3 */
	R4 = R7 -|- R4 || R2.H = W[I2] || [I3++] = R7;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R5 = [I2 ++ M1] || R0.H = W[I3++];                                                          /* s8 t6 */
	R5 = R5 -|- R0 || R0.L = W[I3++] || NOP;                                                            /* K2a t7 */
	R5 = R4 +|+ R5, R4 = R4 -|- R5 || R0.H = W[I3++] || NOP;                                            /* Q1 t8 */
	R0 = R2 -|- R0 || [P2++] = R5 || NOP;                                                               /* K2b SXA */
	R3 = R1 +|+ R0, R0 = R1 -|- R0 || [P3++] = R4 || NOP;                                               /* Q2 SYA */
	R1 = ABS R5 (V) || [P2++] = R3 || NOP;                                                              /* XA SXB */
	lsetup (.Ls16rm_a, .Ls16rm_ae) lc0 = p5;
.Ls16rm_a:
	R4 = ABS R4 (V) || R2 = [P1++] || NOP;                                                              /* YA Lv0 */
	R1 = R1 +|+ R4 || [P3++] = R0 || R4.L = W[I2++];                                                    /* SA SYB s1 */
	R5 = ABS R3 (V) || R3 = [P1] || NOP;                                                                /* XB Lv1 */
	R0 = ABS R0 (V);                                                                                    /* YB */
	R7 = R5 +|+ R0 || R6 = [SP] || NOP;                                                                 /* SB LC */
	R5 = MIN (R1, R6) (V) || R0 = [P0++] || NOP;                                                        /* NA Lw0 */
	R6 = MIN (R7, R6) (V) || R1 = [P0] || R7 = [I2++];                                                  /* NB Lw1 s2 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || R0.L = W[I3++];                                 /* A1 s3 t1 */
	R7 = R3 +|+ R7 || R4.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R1 +|+ R2 || R2.L = W[I2++] || [I3++] = R1;                                                    /* A3 s5 t3 */
	R4 = R7 -|- R4 || R2.H = W[I2] || [I3++] = R7;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	R3 = BYTEPACK (R5, R6) || R5 = [I2 ++ M1] || R0.H = W[I3++];                                        /* PK s8 t6 */
	R5 = R5 -|- R0 || [P4++] = R3 || R0.L = W[I3++];                                                    /* K2a SM t7 */
	R5 = R4 +|+ R5, R4 = R4 -|- R5 || R0.H = W[I3++] || NOP;                                            /* Q1 t8 */
	R0 = R2 -|- R0 || [P2++] = R5 || NOP;                                                               /* K2b SXA */
	R3 = R1 +|+ R0, R0 = R1 -|- R0 || [P3++] = R4 || NOP;                                               /* Q2 SYA */
.Ls16rm_ae:
	R1 = ABS R5 (V) || [P2++] = R3 || NOP;                                                              /* XA SXB */
	fp = [sp + F_DIN];
	p0 = p0 + fp;
	p1 = p1 + fp;
	fp = [sp + F_DG];
	p2 = p2 + fp;
	fp = [sp + F_RM2];
	cc = fp == 0;
	if cc jump .Ls16rm_bx;
	lc1 = fp;
	lsetup (.Ls16rm_o, .Ls16rm_oe) lc1;
.Ls16rm_o:
	R4 = ABS R4 (V) || R2 = [P1++] || NOP;                                                              /* YA Lv0 */
	R1 = R1 +|+ R4 || [P3++] = R0 || R4.L = W[I2++];                                                    /* SA SYB s1 */
	fp = [sp + F_DG];
	p3 = p3 + fp;
	R5 = ABS R3 (V) || R3 = [P1] || NOP;                                                                /* XB Lv1 */
	R0 = ABS R0 (V);                                                                                    /* YB */
	R7 = R5 +|+ R0 || R6 = [SP] || NOP;                                                                 /* SB LC */
	R5 = MIN (R1, R6) (V) || R0 = [P0++] || NOP;                                                        /* NA Lw0 */
	R6 = MIN (R7, R6) (V) || R1 = [P0] || R7 = [I2++];                                                  /* NB Lw1 s2 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || R0.L = W[I3++];                                 /* A1 s3 t1 */
	R7 = R3 +|+ R7 || R4.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R1 +|+ R2 || R2.L = W[I2++] || [I3++] = R1;                                                    /* A3 s5 t3 */
	R4 = R7 -|- R4 || R2.H = W[I2] || [I3++] = R7;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	R3 = BYTEPACK (R5, R6) || R5 = [I2 ++ M1] || R0.H = W[I3++];                                        /* PK s8 t6 */
	R5 = R5 -|- R0 || [P4++] = R3 || R0.L = W[I3++];                                                    /* K2a SM t7 */
	R5 = R4 +|+ R5, R4 = R4 -|- R5 || R0.H = W[I3++] || NOP;                                            /* Q1 t8 */
	R0 = R2 -|- R0 || [P2++] = R5 || NOP;                                                               /* K2b SXA */
	R3 = R1 +|+ R0, R0 = R1 -|- R0 || [P3++] = R4 || NOP;                                               /* Q2 SYA */
	R1 = ABS R5 (V) || [P2++] = R3 || NOP;                                                              /* XA SXB */
	fp = [sp + F_DOUT];
	p4 = p4 + fp;
	lsetup (.Ls16rm_i, .Ls16rm_ie) lc0 = p5;
.Ls16rm_i:
	R4 = ABS R4 (V) || R2 = [P1++] || NOP;                                                              /* YA Lv0 */
	R1 = R1 +|+ R4 || [P3++] = R0 || R4.L = W[I2++];                                                    /* SA SYB s1 */
	R5 = ABS R3 (V) || R3 = [P1] || NOP;                                                                /* XB Lv1 */
	R0 = ABS R0 (V);                                                                                    /* YB */
	R7 = R5 +|+ R0 || R6 = [SP] || NOP;                                                                 /* SB LC */
	R5 = MIN (R1, R6) (V) || R0 = [P0++] || NOP;                                                        /* NA Lw0 */
	R6 = MIN (R7, R6) (V) || R1 = [P0] || R7 = [I2++];                                                  /* NB Lw1 s2 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || R0.L = W[I3++];                                 /* A1 s3 t1 */
	R7 = R3 +|+ R7 || R4.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R1 +|+ R2 || R2.L = W[I2++] || [I3++] = R1;                                                    /* A3 s5 t3 */
	R4 = R7 -|- R4 || R2.H = W[I2] || [I3++] = R7;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	R3 = BYTEPACK (R5, R6) || R5 = [I2 ++ M1] || R0.H = W[I3++];                                        /* PK s8 t6 */
	R5 = R5 -|- R0 || [P4++] = R3 || R0.L = W[I3++];                                                    /* K2a SM t7 */
	R5 = R4 +|+ R5, R4 = R4 -|- R5 || R0.H = W[I3++] || NOP;                                            /* Q1 t8 */
	R0 = R2 -|- R0 || [P2++] = R5 || NOP;                                                               /* K2b SXA */
	R3 = R1 +|+ R0, R0 = R1 -|- R0 || [P3++] = R4 || NOP;                                               /* Q2 SYA */
.Ls16rm_ie:
	R1 = ABS R5 (V) || [P2++] = R3 || NOP;                                                              /* XA SXB */
	fp = [sp + F_DIN];
	p0 = p0 + fp;
	p1 = p1 + fp;
	fp = [sp + F_DG];
.Ls16rm_oe:
	p2 = p2 + fp;
.Ls16rm_bx:
	p0 = [sp + F_LP0];
	p1 = [sp + F_LP1];
	R4 = ABS R4 (V) || R2 = [P1++] || NOP;                                                              /* YA Lv0 */
	R1 = R1 +|+ R4 || [P3++] = R0 || R4.L = W[I2++];                                                    /* SA SYB s1 */
	fp = [sp + F_DG];
	p3 = p3 + fp;
	R5 = ABS R3 (V) || R3 = [P1] || NOP;                                                                /* XB Lv1 */
	R0 = ABS R0 (V);                                                                                    /* YB */
	R7 = R5 +|+ R0 || R6 = [SP] || NOP;                                                                 /* SB LC */
	R5 = MIN (R1, R6) (V) || R0 = [P0++] || NOP;                                                        /* NA Lw0 */
	R6 = MIN (R7, R6) (V) || R1 = [P0] || R7 = [I2++];                                                  /* NB Lw1 s2 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || R0.L = W[I3++];                                 /* A1 s3 t1 */
	R7 = R3 +|+ R7 || R4.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R1 +|+ R2 || R2.L = W[I2++] || [I3++] = R1;                                                    /* A3 s5 t3 */
	R4 = R7 -|- R4 || R2.H = W[I2] || [I3++] = R7;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	R3 = BYTEPACK (R5, R6) || R5 = [I2 ++ M1] || R0.H = W[I3++];                                        /* PK s8 t6 */
	R5 = R5 -|- R0 || [P4++] = R3 || R0.L = W[I3++];                                                    /* K2a SM t7 */
	R5 = R4 +|+ R5, R4 = R4 -|- R5 || R0.H = W[I3++] || NOP;                                            /* Q1 t8 */
	R0 = R2 -|- R0 || [P2++] = R5 || NOP;                                                               /* K2b SXA */
	R3 = R1 +|+ R0, R0 = R1 -|- R0 || [P3++] = R4 || NOP;                                               /* Q2 SYA */
	R1 = ABS R5 (V) || [P2++] = R3 || NOP;                                                              /* XA SXB */
	fp = [sp + F_DOUT];
	p4 = p4 + fp;
	lsetup (.Ls16rm_l, .Ls16rm_le) lc0 = p5;
.Ls16rm_l:
	R4 = ABS R4 (V) || R2 = [P1++] || NOP;                                                              /* YA Lv0 */
	R1 = R1 +|+ R4 || [P3++] = R0 || R4.L = W[I2++];                                                    /* SA SYB s1 */
	R5 = ABS R3 (V) || R3 = [P1] || NOP;                                                                /* XB Lv1 */
	R0 = ABS R0 (V);                                                                                    /* YB */
	R7 = R5 +|+ R0 || R6 = [SP] || NOP;                                                                 /* SB LC */
	R5 = MIN (R1, R6) (V) || R0 = [P0++] || NOP;                                                        /* NA Lw0 */
	R6 = MIN (R7, R6) (V) || R1 = [P0] || R7 = [I2++];                                                  /* NB Lw1 s2 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || R0.L = W[I3++];                                 /* A1 s3 t1 */
	R7 = R3 +|+ R7 || R4.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R1 +|+ R2 || R2.L = W[I2++] || [I3++] = R1;                                                    /* A3 s5 t3 */
	R4 = R7 -|- R4 || R2.H = W[I2] || [I3++] = R7;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	R3 = BYTEPACK (R5, R6) || R5 = [I2 ++ M1] || R0.H = W[I3++];                                        /* PK s8 t6 */
	R5 = R5 -|- R0 || [P4++] = R3 || R0.L = W[I3++];                                                    /* K2a SM t7 */
	R5 = R4 +|+ R5, R4 = R4 -|- R5 || R0.H = W[I3++] || NOP;                                            /* Q1 t8 */
	R0 = R2 -|- R0 || [P2++] = R5 || NOP;                                                               /* K2b SXA */
	R3 = R1 +|+ R0, R0 = R1 -|- R0 || [P3++] = R4 || NOP;                                               /* Q2 SYA */
.Ls16rm_le:
	R1 = ABS R5 (V) || [P2++] = R3 || NOP;                                                              /* XA SXB */
	/* epilogue: the last group of the last row */
	R4 = ABS R4 (V);                                                                                    /* YA */
	R1 = R1 +|+ R4 || [P3++] = R0 || NOP;                                                               /* SA SYB */
	R5 = ABS R3 (V);                                                                                    /* XB */
	R0 = ABS R0 (V);                                                                                    /* YB */
	R7 = R5 +|+ R0 || R6 = [SP] || NOP;                                                                 /* SB LC */
	R5 = MIN (R1, R6) (V);                                                                              /* NA */
	R6 = MIN (R7, R6) (V);                                                                              /* NB */
	R3 = BYTEPACK (R5, R6);                                                                             /* PK */
	[P4++] = R3;                                                                                        /* SM */
	rts;

	/* The same with the magnitude to P4: XA .. YB ABS, SA, SB |gx| + |gy|, LC the constant
	 * 0x00FF00FF at [SP] (the caller's frame), NA, NB MIN, PK BYTEPACK, SM its store.
	 * 18 cycles a group. */
.Lseg16m:
	/* prologue 0 */
	R2 = [P1++];                                                                                        /* Lv0 */
	R4.L = W[I2++];                                                                                     /* s1 */
	R3 = [P1];                                                                                          /* Lv1 */
	R0 = [P0++];                                                                                        /* Lw0 */
	MNOP || R1 = [P0] || R7 = [I2++];                                                                   /* Lw1 s2 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || R0.L = W[I3++];                                 /* A1 s3 t1 */
	R7 = R3 +|+ R7 || R4.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R1 +|+ R2 || R2.L = W[I2++] || [I3++] = R1;                                                    /* A3 s5 t3 */
	R4 = R7 -|- R4 || R2.H = W[I2] || [I3++] = R7;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	MNOP || R5 = [I2 ++ M1] || R0.H = W[I3++];                                                          /* s8 t6 */
	R5 = R5 -|- R0 || R0.L = W[I3++] || NOP;                                                            /* K2a t7 */
	R5 = R4 +|+ R5, R4 = R4 -|- R5 || R0.H = W[I3++] || NOP;                                            /* Q1 t8 */
	R0 = R2 -|- R0 || [P2++] = R5 || NOP;                                                               /* K2b SXA */
	R3 = R1 +|+ R0, R0 = R1 -|- R0 || [P3++] = R4 || NOP;                                               /* Q2 SYA */
	R1 = ABS R5 (V) || [P2++] = R3 || NOP;                                                              /* XA SXB */
	CC = P5 == 0;
	if CC jump .Ls16m_kx;
	lsetup (.Ls16m_k, .Ls16m_ke) lc0 = P5;
.Ls16m_k:
	R4 = ABS R4 (V) || R2 = [P1++] || NOP;                                                              /* YA Lv0 */
	R1 = R1 +|+ R4 || [P3++] = R0 || R4.L = W[I2++];                                                    /* SA SYB s1 */
	R5 = ABS R3 (V) || R3 = [P1] || NOP;                                                                /* XB Lv1 */
	R0 = ABS R0 (V);                                                                                    /* YB */
	R7 = R5 +|+ R0 || R6 = [SP] || NOP;                                                                 /* SB LC */
	R5 = MIN (R1, R6) (V) || R0 = [P0++] || NOP;                                                        /* NA Lw0 */
	R6 = MIN (R7, R6) (V) || R1 = [P0] || R7 = [I2++];                                                  /* NB Lw1 s2 */
	(R1, R3) = BYTEOP16P (R1:0, R3:2) || R2 = [I2++] || R0.L = W[I3++];                                 /* A1 s3 t1 */
	R7 = R3 +|+ R7 || R4.H = W[I2++] || [I3++] = R3;                                                    /* A2 s4 t2 */
	R3 = R1 +|+ R2 || R2.L = W[I2++] || [I3++] = R1;                                                    /* A3 s5 t3 */
	R4 = R7 -|- R4 || R2.H = W[I2] || [I3++] = R7;                                                      /* K1a s6 t4 */
	R1 = R3 -|- R2 || R2 = [I2 ++ M2] || [I3--] = R3;                                                   /* K1b s7 t5 */
	R3 = BYTEPACK (R5, R6) || R5 = [I2 ++ M1] || R0.H = W[I3++];                                        /* PK s8 t6 */
	R5 = R5 -|- R0 || [P4++] = R3 || R0.L = W[I3++];                                                    /* K2a SM t7 */
	R5 = R4 +|+ R5, R4 = R4 -|- R5 || R0.H = W[I3++] || NOP;                                            /* Q1 t8 */
	R0 = R2 -|- R0 || [P2++] = R5 || NOP;                                                               /* K2b SXA */
	R3 = R1 +|+ R0, R0 = R1 -|- R0 || [P3++] = R4 || NOP;                                               /* Q2 SYA */
.Ls16m_ke:
	R1 = ABS R5 (V) || [P2++] = R3 || NOP;                                                              /* XA SXB */
.Ls16m_kx:
	/* epilogue 1 */
	R4 = ABS R4 (V);                                                                                    /* YA */
	R1 = R1 +|+ R4 || [P3++] = R0 || NOP;                                                               /* SA SYB */
	R5 = ABS R3 (V);                                                                                    /* XB */
	R0 = ABS R0 (V);                                                                                    /* YB */
	R7 = R5 +|+ R0 || R6 = [SP] || NOP;                                                                 /* SB LC */
	R5 = MIN (R1, R6) (V);                                                                              /* NA */
	R6 = MIN (R7, R6) (V);                                                                              /* NB */
	R3 = BYTEPACK (R5, R6);                                                                             /* PK */
	[P4++] = R3;                                                                                        /* SM */
	rts;
