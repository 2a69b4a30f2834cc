/* Harris corner response (bvb/harris.h), bit-exact with firmware/c/harris.c.
 *
 * Per output row, four passes over int16 working rows in scratch (24 * NG + 144 bytes,
 * NG = (width + 9) & ~7, so at least width + 2 columns):
 *  1. gradients of the one new image row, central differences x32, by BYTEOP16M four pixels at a
 *     time (gy from the rows above and below, gx from the row itself at offsets +1 and -1, each
 *     stream aligned by I0/I1), into one of three ring slots; a scalar tail for the last <= 14
 *     pixels so that no load leaves the row; for a word-aligned row (the DMA path's ring) gx
 *     from one load stream, both windows in one register pair (no sub-bank collision);
 *  2. column sums of gx^2, gy^2, gx*gy over the three slots, two columns per dual MAC in signed
 *     fraction mode: (32g)(32g) << 1 = 2048 g^2, truncated high half = floor(sum / 32), exactly
 *     the C's ">> 5"; 6 loads and 3 stores in the 9 issues, one an issue, so that none pays an
 *     L1 sub-bank collision whatever the layout;
 *  3. window sums over three columns, two pixels per 16-bit vector add: (c(x+1)|c(x)) +
 *     (c(x)|c(x-1)) + (c(x+2)|c(x+1)), the odd-aligned pair built by two halfword loads (no
 *     PACK: 2 ALU issues a pair); the halfword c(x+1) is loaded beside the word c(x+1)|c(x)
 *     (one 32-bit word, no collision), c(x+2) beside the W store. The working rows are laid out
 *     cxx, cyy, cxy, the three gradient slots, then Wa, Wb, so that a C plane and its W
 *     plane are 18 NG + 96 bytes apart: from 4 KB to 12 KB (another sub-bank for every x)
 *     for NG = 224 .. 672, widths 215 .. 670; narrower, a store may still collide (at 160
 *     wide, 3,120 bytes apart, every one: still no worse than the PACK's issue was);
 *  4. the response, two pixels at a time: c's window sum made here as in pass 3 (its ALU
 *     issues fill the same 7 issues as its 5 loads and 2 stores, and a pass's set-up goes),
 *     hh by the quad add with ASR, kh by a dual 16-bit multiply in (T) mode
 *     (floor(2*hh*K / 65536)), a*b - c*c - kh*hh by three dual MACs (IS).
 * Columns 0 and >= width-1 of the working rows are never cleaned: they only reach the border
 * outputs, which are written as 0 afterwards.
 *
 * The DMA path (frames in SDRAM, scratch in L1 data SRAM: .Lplan, .Ldstart, .Ldrow after the
 * kernel). Image rows come into L1 by memory DMA (bvb/dma.h) into a ring of four row slots
 * (slot r & 3 holds row r), and response rows leave from two L1 output rows: while the core
 * makes output row y (gradient row y+1 from ring rows y .. y+2), one job on the stream sends
 * output row y-1 and brings image row y+3 into the slot of row y-1. Job A brings rows 0..3
 * before anything is computed; job B brings row 4 and writes the four zero border rows (from
 * the zeroed output rows) while gradient row 2 is made. Per row the core waits, re-addresses
 * the two transfers (bvb_dma_move; an odd src_stride prepares the input again: the rows
 * alternate between byte and halfword moves) and starts the job: about 290 cycles in the
 * simulator's count. On the stream per row: width bytes in and 4 width out, 2.5 width SCLK,
 * 10 width core cycles at CCLK:SCLK = 4, under the 14 per pixel of compute. With dst in L1 (the
 * odometry's response strips, bvb_odo_harris_strips) nothing goes out by DMA (F_DOUT): the
 * core writes each response row and the four zero border rows into dst itself, and the jobs
 * carry the image rows alone; before, job B held the stream for the border rows' 16 width
 * bytes (some 5,000 cycles at 160 wide, waited for at the first row) and every call ended
 * waiting for its last row's transfer: the odometry's three strip calls at 160x120 went from
 * 293.2k to 234.4k cycles with their NMS (bfbench bench -k pipe_odometry, info.stages 5 -> 6).
 * Otherwise (a frame in L1 both ways, scratch in SDRAM, or a transfer DMA refuses) the direct
 * path reads and writes the frames in place.
 *
 * Lower bound: per pixel, the gradients (0.5 BYTEOP16M and 1 vector shift), 9 products on the
 * dual MACs (4.5), three 3-column sums at 2 vector adds per pair (3.0) and the response (hh, kh
 * and three dual MACs per pair: 2.5): 11.5 issues per pixel; every load and store fits a free
 * slot (per pair: 6 + 3 + 3 + 3 loads, 3 + 3 + 2 stores in 23 issues).
 *
 * Measured (bfbench bench -k harris_response -j 2, frames in SDRAM, scratch in L1B; modelled
 * cycles under --timing bf537, then the simulator's own count, --timing none):
 *   160x120     321,120  16.73 per pixel (bound 11.5: 1.45x)   sim   286,533
 *   320x240   1,047,494  13.64           (1.19x)                sim 1,014,493
 *   640x480   3,859,804  12.56           (1.09x)                sim 3,795,213
 *   (with the window sums' odd pairs by PACK, 3 ALU issues a pair, and slots before planes:
 *   350,484 / 1,172,856 / 4,375,324, sim 310,595 / 1,120,155 / 4,236,875;
 *   before the window sums' W store moved off the issue that loads plane C and the gy loop's
 *   two rows off one issue: 365,829 / 1,244,191 / 4,429,624; dst in SDRAM: the test of where
 *   dst is costs some 8 cycles a row.)
 *   (C -O2 from SDRAM: 3,008,346 / 12,238,913 / 49,397,617.) Before the DMA path (frames and
 *   scratch read and written in place in SDRAM through the data cache): 793,108 modelled at
 *   160x120 (41 per pixel; sim 274,911), the response's 4 bytes per pixel paying a line fill
 *   and a write-back per 8 pixels.
 *   Where the 320x240 cycles go over the bound's 883,200 (985,125 issues, bfbench profile):
 *   the passes run over NG (328) columns, not 320, and the per-row set-up of the four passes
 *   (the window sums' two planes some 10 cycles a row over their loops); the DMA
 *   bookkeeping (about 290 cycles a row, 68,000); the gx tail's extra pair on aligned rows
 *   (some 30 cycles a row); then under the model multi-cycle branches and calls 39,981, MMR
 *   accesses 16,496, L1 sub-bank collisions 948; the fill (job A, 4 rows) and the last row's
 *   transfer, which no compute covers. At 160x120 the window sums' stores add 18,096
 *   collisions (of 18,564); at 640x480 the per-row costs weigh a quarter.
 * Working set: 24 * NG + 144 bytes of working rows, then the DMA region (job, four image rows,
 * two response rows): BVB_HARRIS_SCRATCH_BYTES, 6.4 KB at 160, 23.7 KB at 640. */
#include "bvb/asm.h"
#include "bvb/dma.h"
#include "bvb/harris.h"

	.section .l1.text, "ax"
	.align 4

/* The frame (FP-relative, after LINK) */
#define F_SRC    -4    /* src */
#define F_SSTR   -8    /* src_stride */
#define F_DST    -12   /* dst row of the current output row */
#define F_DSTR   -16   /* dst_stride in bytes */
#define F_W      -20   /* width */
#define F_ROWS   -24   /* output rows left */
#define F_NG     -28   /* working row length (elements) */
#define F_N8     -32   /* 8-pixel blocks of the vector gradient loops */
#define F_NPAIR  -36   /* response pairs per row: (width - 3) >> 1 */
#define F_SLOT0  -40   /* gradient slot 0 */
#define F_SLOTS  -44   /* bytes between slots: 4 * NG + 16 */
#define F_CSUM   -48   /* cxx plane (cyy, cxy, the slots, Wa, Wb follow) */
#define F_PLANE  -52   /* bytes between planes: 2 * NG + 16 */
#define F_MID    -56   /* image row of the next gradient row */
#define F_NEXT   -60   /* slot index (0..2) the next gradient row goes to */
#define F_HALF   -64   /* 2-pair iterations of the window loop: ceil(npairs / 2) */
/* The DMA path (frames in SDRAM, scratch in L1): F_JOB is 0 on the direct path. */
#define F_JOB    -68   /* the DMA job (the DMA region's start) */
#define F_RING   -72   /* the L1 ring of four image rows, slot r & 3 holds row r */
#define F_P      -76   /* bytes between ring slots */
#define F_OUTB   -80   /* two L1 output rows, 4 * width bytes apart */
#define F_Y      -84   /* the output row being made */
#define F_DDST   -88   /* dst's row y (in SDRAM) */
#define F_NSRC   -92   /* src's row y + 3, the next one to bring */
#define F_UPP    -96   /* the gradient row's image rows above and below (.Lgrad) */
#define F_DNP    -100
#define F_MIDP   -104  /* ... and the row itself */
#define F_ODD    -108  /* src_stride odd: the input slot is prepared again for every row */
#define F_XIN    -132  /* struct bvb_dma_xfer of the input row (24 bytes) */
#define F_XOUT   -156  /* ... of the output row */
#define F_DOUT   -160  /* dst in L1: the core writes the response rows there, no output DMA */
#define F_WOFF   -164  /* bytes from a C plane to its W plane */
#define F_SIZE   164

BVB_FUNC bvb_harris_response_asm
	[--sp] = (r7:4, p5:3);
	p0 = [sp + 40];         /* height (arguments are 28 bytes further up after the push) */
	r3 = [sp + 44];         /* src_stride */
	r4 = [sp + 48];         /* dst_stride */
	r5 = [sp + 52];         /* scratch */
	link F_SIZE;
	[fp + F_SRC] = r0;
	[fp + F_SSTR] = r3;
	r4 <<= 2;
	[fp + F_DSTR] = r4;
	[fp + F_W] = r2;
	r6 = p0;
	r6 += -4;
	[fp + F_ROWS] = r6;     /* h - 4 output rows */
	r6 = 9;
	r6 = r6 + r2;
	r7 = -8;
	r6 = r6 & r7;
	[fp + F_NG] = r6;       /* NG */
	r7 = r2;
	r7 += -6;
	r7 >>>= 3;
	r0 = 0;
	r7 = max (r7, r0);
	[fp + F_N8] = r7;
	r7 = r2;
	r7 += -3;
	r7 >>= 1;
	[fp + F_NPAIR] = r7;
	r0 = r7;
	r0 += 1;
	r0 >>= 1;
	[fp + F_HALF] = r0;     /* ceil(npairs / 2) */
	/* cxx, cyy, cxy, the three gradient slots, Wa, Wb: each C plane 18 NG + 96 bytes
	 * before its W plane, which is another 4 KB sub-bank from 320 wide on */
	r5 += 8;
	[fp + F_CSUM] = r5;
	r7 = r6 << 1;
	r7 += 16;
	[fp + F_PLANE] = r7;
	r0 = r7 + r7;
	r0 = r0 + r7;
	r0 = r0 + r5;
	[fp + F_SLOT0] = r0;
	r3 = r6 << 2;
	r3 += 16;
	[fp + F_SLOTS] = r3;
	r0 = r3 + r7;
	r3 = r0 << 1;
	r0 = r0 + r3;
	[fp + F_WOFF] = r0;     /* 3 (PLANE + SLOTS) */
	r0 = 0;
	[fp + F_NEXT] = r0;

	[fp + F_DST] = r1;
	call .Lplan;
	r0 = [fp + F_JOB];
	cc = r0 == 0;
	if !cc jump .Ldstart;

	/* Rows 0 and 1 of the output are 0. */
	r1 = [fp + F_DST];
.Ldirect:
	p2 = r1;
	call .Lzero_row;
	r1 = [fp + F_DST];
	r0 = [fp + F_DSTR];
	r1 = r1 + r0;
	p2 = r1;
	call .Lzero_row;

	/* Gradient rows 1 and 2 into slots 1 and 2. */
	r0 = [fp + F_SRC];
	r1 = [fp + F_SSTR];
	r0 = r0 + r1;
	call .Lmid_direct;
	r2 = [fp + F_SLOT0];
	r3 = [fp + F_SLOTS];
	r2 = r2 + r3;
	p1 = r2;
	call .Lgrad;
	r0 = [fp + F_SRC];
	r1 = [fp + F_SSTR];
	r1 <<= 1;
	r0 = r0 + r1;
	call .Lmid_direct;
	r2 = [fp + F_SLOT0];
	r3 = [fp + F_SLOTS];
	r3 <<= 1;
	r2 = r2 + r3;
	p1 = r2;
	call .Lgrad;
	/* The next gradient row is row 3; output row 2 starts two dst rows down. */
	r0 = [fp + F_SRC];
	r1 = [fp + F_SSTR];
	r2 = r1 << 1;
	r0 = r0 + r2;
	r0 = r0 + r1;
	[fp + F_MID] = r0;
	r0 = [fp + F_DST];
	r1 = [fp + F_DSTR];
	r1 <<= 1;
	r0 = r0 + r1;
	[fp + F_DST] = r0;

.Lrow:
	r0 = [fp + F_JOB];
	cc = r0 == 0;
	if !cc jump .Ldrow;
	r0 = [fp + F_MID];
	call .Lmid_direct;
.Lrow_body:
	/* 1. the gradients of the new row into the slot of the oldest */
	r0 = [fp + F_NEXT];
	r1 = [fp + F_SLOTS];
	r1 *= r0;
	r2 = [fp + F_SLOT0];
	r1 = r1 + r2;
	p1 = r1;
	r0 += 1;
	r2 = 3;
	cc = r0 == r2;
	r2 = 0;
	if cc r0 = r2;
	[fp + F_NEXT] = r0;
	call .Lgrad;
	r0 = [fp + F_MID];
	r1 = [fp + F_SSTR];
	r0 = r0 + r1;
	[fp + F_MID] = r0;

	/* 2. column sums: slots 0, 1, 2 (the order does not matter to a sum) */
	r0 = [fp + F_SLOT0];
	r1 = [fp + F_SLOTS];
	i0 = r0;
	r0 = r0 + r1;
	i1 = r0;
	r0 = r0 + r1;
	i2 = r0;
	r0 = [fp + F_CSUM];
	r1 = [fp + F_PLANE];
	r3 = r0;
	r3 += -4;
	p0 = r3;                /* cxx, stored one pair late as cyy is */
	r0 = r0 + r1;
	r2 = r0;
	r2 += -4;               /* cyy is stored one pair late: the first store lands in the pad */
	p1 = r2;
	r0 = r0 + r1;
	p2 = r0;                /* cxy */
	r0 = [fp + F_NG];
	r0 >>= 1;
	p3 = r0;
	/* R0 gxA, R1 gyA, R2 gxB, R3 gyB, R4 gxC, R5 gyC (A, B, C the three slots); one data
	 * access an issue, so no two of them meet in a sub-bank */
	mnop || r0 = [i0++] || r2 = [i1++];
	mnop || r1 = [i0++] || r3 = [i1++];
	r4 = [i2++];
	lsetup (.Lv_s, .Lv_e) lc0 = p3;
.Lv_s:	a1 = r0.h * r1.h, a0 = r0.l * r1.l || [p1++] = r6;
	a1 += r2.h * r3.h, a0 += r2.l * r3.l || r5 = [i2++];
	r6.h = (a1 += r4.h * r5.h), r6.l = (a0 += r4.l * r5.l) (t) || [p0++] = r7;
	a1 = r0.h * r0.h, a0 = r0.l * r0.l || [p2++] = r6;
	a1 += r2.h * r2.h, a0 += r2.l * r2.l || r2 = [i1++];
	r7.h = (a1 += r4.h * r4.h), r7.l = (a0 += r4.l * r4.l) (t) || r0 = [i0++];
	a1 = r1.h * r1.h, a0 = r1.l * r1.l || r4 = [i2++];
	a1 += r3.h * r3.h, a0 += r3.l * r3.l || r1 = [i0++];
.Lv_e:	r6.h = (a1 += r5.h * r5.h), r6.l = (a0 += r5.l * r5.l) (t) || r3 = [i1++];
	[p1++] = r6;
	[p0++] = r7;

	/* 3. window sums, one plane at a time: W = (c(x)|c(x-1)) + (c(x+1)|c(x)) + (c(x+2)|c(x+1)) */
	r0 = [fp + F_CSUM];
	p4 = r0;
	p5 = [fp + F_WOFF];     /* C plane -> its W plane */
	p3 = [fp + F_HALF];
	r7 = 2;                 /* cxx and cyy: cxy's window sum is made in the response */
.Lwin:
	/* per pair n (x = 2n + 2): E = (c(x+1)|c(x)), O(n) = (c(x+2)|c(x+1)) from two halfword
	 * loads, W = E + O(n-1) + O(n); two ALU issues a pair. The halfword c(x+1) shares its word
	 * with E (one bank access); c(x+2) goes with the store. */
	i0 = p4;
	p0 = p4 + p5;
	i1 = p0;                /* the first (garbage) store goes to W[0..1], the pair for x = 2 to W[2..3] */
	r0 = p4;
	r0 += 2;
	i2 = r0;
	r1.l = w[i2++];         /* O(-1) = (c(2)|c(1)) */
	r1.h = w[i2++];
	i0 += 4;                /* E of x = 2 */
	lsetup (.Lw_s, .Lw_e) lc0 = p3;
.Lw_s:	r3 = r3 +|+ r1 || r0 = [i0++] || r5.l = w[i2++];
	r4 = r0 +|+ r1 || r5.h = w[i2++] || [i1++] = r3;
	r4 = r4 +|+ r5 || r0 = [i0++] || r1.l = w[i2++];
.Lw_e:	r3 = r0 +|+ r5 || r1.h = w[i2++] || [i1++] = r4;
	r3 = r3 +|+ r1;
	[i1++] = r3;
	r0 = [fp + F_PLANE];
	r1 = p4;
	r1 = r1 + r0;
	p4 = r1;
	r7 += -1;
	cc = r7 == 0;
	if !cc jump .Lwin (bp);

	/* 4. response, pairs x = 2, 4, ...; the first two stores (garbage) land on dst[0], dst[1] */
	r0 = [fp + F_CSUM];
	r1 = [fp + F_PLANE];
	r2 = [fp + F_WOFF];
	r0 = r0 + r2;
	r0 += 4;
	i0 = r0;                /* Wa + 2 elements */
	r0 = r0 + r1;
	i1 = r0;                /* Wb + 2 elements */
	r0 = [fp + F_CSUM];
	r1 = r1 << 1;
	r0 = r0 + r1;           /* cxy */
	r1 = r0;
	r1 += 4;
	i2 = r1;                /* E = (c(3)|c(2)) */
	r0 += 2;
	i3 = r0;
	p0 = [fp + F_DST];
	p3 = [fp + F_NPAIR];
	r3 = BVB_HARRIS_K4_Q15 (x);
	r0 = [i0++];
	r1 = [i1++];
	r2 = [i2++];
	r5.l = w[i3++];         /* O = (c(2)|c(1)) */
	r5.h = w[i3++];
	/* c = E + O(x-1) + O(x+1) as in the window sums, O in one register: its halves are loaded
	 * after the first add and before the second. One data access an issue. */
	lsetup (.Lr_s, .Lr_e) lc0 = p3;
.Lr_s:	r2 = r2 +|+ r5 || [p0++] = r6;
	a1 = r0.h * r1.h, a0 = r0.l * r1.l (is) || [p0++] = r7;
	r4 = r0 +|+ r1, r0 = r0 -|- r1 (asr) || r5.l = w[i3++];
	r6.h = r4.h * r3.l, r6.l = r4.l * r3.l (t) || r5.h = w[i3++];
	r2 = r2 +|+ r5 || r0 = [i0++];
	a1 -= r2.h * r2.h, a0 -= r2.l * r2.l (is) || r2 = [i2++];
.Lr_e:	r7 = (a1 -= r6.h * r4.h), r6 = (a0 -= r6.l * r4.l) (is) || r1 = [i1++];
	[p0++] = r6;
	[p0++] = r7;
	/* the border columns */
	p0 = [fp + F_DST];
	r0 = 0;
	[p0] = r0;
	[p0 + 4] = r0;
	r1 = [fp + F_W];
	p1 = r1;
	p0 = p0 + (p1 << 2);
	[p0 + -4] = r0;
	[p0 + -8] = r0;

	r0 = [fp + F_JOB];
	cc = r0 == 0;
	if !cc jump .Ldrow_end;
	r0 = [fp + F_DST];
	r1 = [fp + F_DSTR];
	r0 = r0 + r1;
	[fp + F_DST] = r0;
	r0 = [fp + F_ROWS];
	r0 += -1;
	[fp + F_ROWS] = r0;
	cc = r0 == 0;
	if !cc jump .Lrow;

	/* Rows h-2 and h-1 */
	p2 = [fp + F_DST];
	call .Lzero_row;
	r0 = [fp + F_DST];
	r1 = [fp + F_DSTR];
	r0 = r0 + r1;
	p2 = r0;
	call .Lzero_row;

.Lexit:
	unlink;
	(r7:4, p5:3) = [sp++];
	rts;

/* The DMA path. Output row y is made from image rows y-1 .. y+3 (gradient rows y-1 .. y+1):
 * while the core makes it, one job sends output row y-1 from its L1 row to dst and brings image
 * row y+3 into the ring slot of row y-1, which the gradient of row y+1 no longer needs. */
.Ldstart:
	r0 = [fp + F_DOUT];
	cc = r0 == 0;
	if !cc jump .Ld_zero_dst;
	p2 = [fp + F_OUTB];
	call .Lzero_row;
	call .Lzero_row;        /* both L1 output rows: the border rows' source */
	jump .Ld_job_a;
	/* dst in L1: its rows 0, 1, h-2 and h-1 zeroed by the core (a store a cycle, where their
	 * transfer would hold the stream for 2 width SCLK before the first row) */
.Ld_zero_dst:
	r5 = [fp + F_DST];
	p2 = r5;
	call .Lzero_row;
	r0 = [fp + F_DSTR];
	r5 = r5 + r0;
	p2 = r5;
	call .Lzero_row;
	r0 = [fp + F_ROWS];     /* h - 4 */
	r1 = [fp + F_DSTR];
	r0 *= r1;
	r5 = r5 + r0;
	r5 = r5 + r1;           /* row h - 2 */
	p2 = r5;
	call .Lzero_row;
	r0 = [fp + F_DSTR];
	r5 = r5 + r0;
	p2 = r5;
	call .Lzero_row;
.Ld_job_a:
	/* job A: image rows 0 .. 3 into slots 0 .. 3 */
	r0 = [fp + F_SRC];
	[fp + F_XIN + DMAX_SRC] = r0;
	r0 = [fp + F_SSTR];
	[fp + F_XIN + DMAX_SS] = r0;
	r0 = [fp + F_RING];
	[fp + F_XIN + DMAX_DST] = r0;
	r0 = [fp + F_P];
	[fp + F_XIN + DMAX_DS] = r0;
	r0 = [fp + F_W];
	[fp + F_XIN + DMAX_W] = r0;
	r0 = 4;
	[fp + F_XIN + DMAX_ROWS] = r0;
	r0 = [fp + F_JOB];
	r1 = 0;
	r2 = fp;
	r3 = F_XIN (x);
	r2 = r2 + r3;
	call _bvb_dma_prepare;
	cc = r0 < 0;
	if cc jump .Ld_refused;
	r0 = [fp + F_JOB];
	r1 = 1;
	call _bvb_dma_start;
	call _bvb_dma_wait;
	/* gradient row 1 (slot 1) from ring rows 0 .. 2: row 0's slot is free for row 4 after it */
	r0 = [fp + F_RING];
	r1 = [fp + F_P];
	[fp + F_UPP] = r0;
	r0 = r0 + r1;
	[fp + F_MIDP] = r0;
	r0 = r0 + r1;
	[fp + F_DNP] = r0;
	r2 = [fp + F_SLOT0];
	r3 = [fp + F_SLOTS];
	r2 = r2 + r3;
	p1 = r2;
	call .Lgrad;
	/* job B: image row 4 into slot 0; output rows 0, 1 and h-2, h-1 (zeros) */
	r0 = [fp + F_SRC];
	r1 = [fp + F_SSTR];
	r1 <<= 2;
	r0 = r0 + r1;
	[fp + F_XIN + DMAX_SRC] = r0;
	r0 = 1;
	[fp + F_XIN + DMAX_ROWS] = r0;
	r0 = [fp + F_JOB];
	r1 = 0;
	r2 = fp;
	r3 = F_XIN (x);
	r2 = r2 + r3;
	call _bvb_dma_prepare;
	cc = r0 < 0;
	if cc jump .Ld_refused;
	r0 = [fp + F_DOUT];
	cc = r0 == 0;
	r1 = 1;                 /* dst in L1: job B is row 4 alone */
	if !cc jump .Ld_job_b;
	r0 = [fp + F_OUTB];
	[fp + F_XOUT + DMAX_SRC] = r0;
	r0 = [fp + F_W];
	r0 <<= 2;
	[fp + F_XOUT + DMAX_SS] = r0;
	[fp + F_XOUT + DMAX_W] = r0;
	r0 = [fp + F_DST];
	[fp + F_XOUT + DMAX_DST] = r0;
	r0 = [fp + F_DSTR];
	[fp + F_XOUT + DMAX_DS] = r0;
	r0 = 2;
	[fp + F_XOUT + DMAX_ROWS] = r0;
	r0 = [fp + F_JOB];
	r1 = 1;
	r2 = fp;
	r3 = F_XOUT (x);
	r2 = r2 + r3;
	call _bvb_dma_prepare;
	cc = r0 < 0;
	if cc jump .Ld_refused;
	r0 = [fp + F_ROWS];
	r0 += 2;                /* h - 2 */
	r1 = [fp + F_DSTR];
	r0 *= r1;
	r1 = [fp + F_DST];
	r0 = r0 + r1;
	[fp + F_XOUT + DMAX_DST] = r0;
	r0 = [fp + F_JOB];
	r1 = 2;
	r2 = fp;
	r3 = F_XOUT (x);
	r2 = r2 + r3;
	call _bvb_dma_prepare;
	cc = r0 < 0;
	if cc jump .Ld_refused;
	r1 = 3;
.Ld_job_b:
	r0 = [fp + F_JOB];
	call _bvb_dma_start;
	/* gradient row 2 (slot 2) from ring rows 1 .. 3, while job B runs */
	r0 = [fp + F_MIDP];
	[fp + F_UPP] = r0;
	r0 = [fp + F_DNP];
	[fp + F_MIDP] = r0;
	r1 = [fp + F_P];
	r0 = r0 + r1;
	[fp + F_DNP] = r0;
	r2 = [fp + F_SLOT0];
	r3 = [fp + F_SLOTS];
	r3 <<= 1;
	r2 = r2 + r3;
	p1 = r2;
	call .Lgrad;
	/* output row 2 next; image row 5 the next to bring */
	r0 = 2;
	[fp + F_Y] = r0;
	r0 = [fp + F_SSTR];
	r1 = r0 << 2;
	r0 = r0 + r1;
	r1 = [fp + F_SRC];
	r0 = r0 + r1;
	[fp + F_NSRC] = r0;
	r0 = [fp + F_DSTR];
	r0 <<= 1;
	r1 = [fp + F_DST];
	r0 = r0 + r1;
	[fp + F_DDST] = r0;
	r0 = 1;
	[fp + F_XOUT + DMAX_ROWS] = r0;
	jump .Lrow;

	/* DMA refused a transfer (a stride beyond its 16-bit modify, say): the direct path; what
	 * reached L1 is not used. */
.Ld_refused:
	r0 = 0;
	[fp + F_JOB] = r0;
	r1 = [fp + F_DST];
	jump .Ldirect;

/* One output row's job and pointers (output row y = F_Y). */
.Ldrow:
	call _bvb_dma_wait;
	/* image row y+3 (in the last row, h-1 again: there is no row h) into slot (y+3) & 3 */
	r0 = [fp + F_NSRC];
	r1 = [fp + F_SSTR];
	r2 = r0 + r1;
	[fp + F_NSRC] = r2;
	r3 = r0 - r1;
	r2 = [fp + F_ROWS];
	cc = r2 == 1;
	if cc r0 = r3;
	[fp + F_XIN + DMAX_SRC] = r0;
	r0 = [fp + F_Y];
	r0 += 3;
	r1 = 3;
	r0 = r0 & r1;
	r1 = [fp + F_P];
	r0 *= r1;
	r1 = [fp + F_RING];
	r0 = r0 + r1;
	[fp + F_XIN + DMAX_DST] = r0;
	r3 = [fp + F_ODD];
	cc = r3 == 0;
	r0 = [fp + F_JOB];
	r1 = 0;
	r2 = fp;
	r3 = F_XIN (x);
	r2 = r2 + r3;
	if cc jump .Ld_mvin (bp);
	call _bvb_dma_prepare;  /* an odd stride: rows alternate between byte and halfword moves */
	jump .Ld_out;
.Ld_mvin:
	call _bvb_dma_move;
.Ld_out:
	/* output row y-1, from y = 3 on (none when the core writes dst in L1) */
	r0 = [fp + F_DOUT];
	cc = r0 == 0;
	if !cc jump .Ld_one;
	r0 = [fp + F_Y];
	r1 = 2;
	cc = r0 == r1;
	if cc jump .Ld_one;
	r0 += -1;
	r1 = 1;
	r0 = r0 & r1;
	r1 = [fp + F_W];
	r1 <<= 2;
	r0 *= r1;
	r1 = [fp + F_OUTB];
	r0 = r0 + r1;
	[fp + F_XOUT + DMAX_SRC] = r0;
	r0 = [fp + F_DDST];
	r1 = [fp + F_DSTR];
	r0 = r0 - r1;
	[fp + F_XOUT + DMAX_DST] = r0;
	r0 = [fp + F_JOB];
	r1 = 1;
	r2 = fp;
	r3 = F_XOUT (x);
	r2 = r2 + r3;
	r3 = [fp + F_Y];
	r3 += -3;
	cc = r3 == 0;
	if !cc jump .Ld_mvout (bp);
	call _bvb_dma_prepare;  /* the first: slot 1 had job B's two border rows */
	jump .Ld_two;
.Ld_mvout:
	call _bvb_dma_move;
.Ld_two:
	r0 = [fp + F_JOB];
	r1 = 2;
	call _bvb_dma_start;
	jump .Ld_ptrs;
.Ld_one:
	r0 = [fp + F_JOB];
	r1 = 1;
	call _bvb_dma_start;
.Ld_ptrs:
	/* gradient row y+1 from ring rows y, y+1, y+2; the response into L1 output row y & 1 */
	r3 = [fp + F_Y];
	r2 = 3;
	r1 = [fp + F_P];
	r4 = [fp + F_RING];
	r0 = r3 & r2;
	r0 *= r1;
	r0 = r0 + r4;
	[fp + F_UPP] = r0;
	r0 = r3;
	r0 += 1;
	r0 = r0 & r2;
	r0 *= r1;
	r0 = r0 + r4;
	[fp + F_MIDP] = r0;
	r0 = r3;
	r0 += 2;
	r0 = r0 & r2;
	r0 *= r1;
	r0 = r0 + r4;
	[fp + F_DNP] = r0;
	r0 = 1;
	r0 = r3 & r0;
	r1 = [fp + F_W];
	r1 <<= 2;
	r0 *= r1;
	r1 = [fp + F_OUTB];
	r0 = r0 + r1;
	r1 = [fp + F_DOUT];
	cc = r1 == 0;
	r1 = [fp + F_DDST];
	if !cc r0 = r1;         /* dst in L1: straight into its row y */
	[fp + F_DST] = r0;
	jump .Lrow_body;

.Ldrow_end:
	r0 = [fp + F_DDST];
	r1 = [fp + F_DSTR];
	r0 = r0 + r1;
	[fp + F_DDST] = r0;
	r0 = [fp + F_Y];
	r0 += 1;
	[fp + F_Y] = r0;
	r0 = [fp + F_ROWS];
	r0 += -1;
	[fp + F_ROWS] = r0;
	cc = r0 == 0;
	if cc jump 1f;
	jump .Lrow;             /* beyond a conditional jump's reach */
1:	/* the last output row, h-3 (y - 1 now); with dst in L1 only the last input to wait for */
	call _bvb_dma_wait;
	r0 = [fp + F_DOUT];
	cc = r0 == 0;
	if !cc jump .Lexit;
	r0 = [fp + F_Y];
	r0 += -1;
	r1 = 1;
	r0 = r0 & r1;
	r1 = [fp + F_W];
	r1 <<= 2;
	r0 *= r1;
	r1 = [fp + F_OUTB];
	r0 = r0 + r1;
	[fp + F_XOUT + DMAX_SRC] = r0;
	r0 = [fp + F_DDST];
	r1 = [fp + F_DSTR];
	r0 = r0 - r1;
	[fp + F_XOUT + DMAX_DST] = r0;
	r0 = [fp + F_JOB];
	r1 = 0;
	r2 = fp;
	r3 = F_XOUT (x);
	r2 = r2 + r3;
	call _bvb_dma_prepare;
	r0 = [fp + F_JOB];
	r1 = 1;
	call _bvb_dma_start;
	call _bvb_dma_wait;
	jump .Lexit;

/* The direct path's image rows around row R0: F_MIDP, F_UPP, F_DNP. */
.Lmid_direct:
	[fp + F_MIDP] = r0;
	r1 = [fp + F_SSTR];
	r2 = r0 - r1;
	[fp + F_UPP] = r2;
	r2 = r0 + r1;
	[fp + F_DNP] = r2;
	rts;

/* The DMA path's plan: F_JOB stays 0 (the direct path) unless the scratch is in L1 data SRAM,
 * DMA reaches both frames and one of them is in SDRAM. The DMA region follows the working rows
 * (24 * (width + 16) bytes in): the job, the ring of four image rows (P bytes apart, 8 bytes of
 * pad before and after: the vector loads reach 3 bytes beyond a row), the two output rows. */
.Lplan:
	[--sp] = rets;
	r0 = 0;
	[fp + F_JOB] = r0;
	[fp + F_DOUT] = r0;
	r0 = [fp + F_CSUM];
	r0 += -8;               /* scratch */
	r2.l = 0;
	r2.h = 0xff80;
	cc = r0 < r2 (iu);
	if cc jump .Lp_x;       /* scratch in SDRAM: nothing to gain */
	r1 = [fp + F_W];
	r2 = 36;
	r1 *= r2;
	r2 = 640;
	r1 = r1 + r2;           /* BVB_HARRIS_SCRATCH_BYTES */
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Lp_x;
	r0 = [fp + F_ROWS];
	r0 += 3;                /* h - 1 */
	r1 = [fp + F_SSTR];
	r0 *= r1;
	r1 = [fp + F_W];
	r1 = r0 + r1;
	r0 = [fp + F_SRC];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Lp_x;
	r0 = [fp + F_ROWS];
	r0 += 3;
	r1 = [fp + F_DSTR];
	r0 *= r1;
	r1 = [fp + F_W];
	r1 <<= 2;
	r1 = r0 + r1;
	r0 = [fp + F_DST];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Lp_x;
	r2.l = 0;
	r2.h = 0xff80;
	r0 = [fp + F_SRC];
	r1 = [fp + F_DST];
	cc = r0 < r2 (iu);
	if cc jump .Lp_ok;      /* src in SDRAM */
	cc = r1 < r2 (iu);
	if !cc jump .Lp_x;      /* both in L1: nothing to gain */
.Lp_ok:
	r0 = [fp + F_W];
	r1 = r0;
	r1 += 16;
	r2 = 24;
	r1 *= r2;
	r2 = [fp + F_CSUM];
	r2 += -8;
	r1 = r1 + r2;
	[fp + F_JOB] = r1;
	r2 = BVB_DMA_JOB_BYTES + 8;
	r1 = r1 + r2;
	[fp + F_RING] = r1;
	r2 = r0;
	r2 += 7;
	r3 = -8;
	r2 = r2 & r3;
	r2 += 8;
	[fp + F_P] = r2;
	r2 <<= 2;
	r1 = r1 + r2;
	r1 += 8;
	[fp + F_OUTB] = r1;
	r0 = [fp + F_SSTR];
	r1 = 1;
	r0 = r0 & r1;
	[fp + F_ODD] = r0;
	r0 = 0;
	r1 = [fp + F_DST];
	r2.l = 0;
	r2.h = 0xff80;
	cc = r1 < r2 (iu);
	r3 = 1;
	if !cc r0 = r3;         /* dst in L1 (DMA reaches it, so bank A or B) */
	[fp + F_DOUT] = r0;
.Lp_x:
	rets = [sp++];
	rts;

/* Zero a dst row: P2 = row. */
.Lzero_row:
	p1 = [fp + F_W];
	r0 = 0;
	lsetup (.Lz_s, .Lz_s) lc0 = p1;
.Lz_s:	[p2++] = r0;
	rts;

/* The gradient row of image row F_MIDP (1 <= yr <= h-2; F_UPP, F_DNP the rows above and
 * below) into the slot at P1: per pixel pair the word
 * (gx(x+1)|gx(x)) then (gy(x+1)|gy(x)), each x32. */
.Lgrad:
	p0 = [fp + F_MIDP];
	r6 = [fp + F_N8];
	r5 = p0;                /* mid */
	r4 = [fp + F_DNP];      /* dn */
	r3 = [fp + F_UPP];      /* up */
	cc = r6 == 0;
	if cc jump .Lg_tail;
	p3 = r6;
	m2 = 8;
	/* gy = dn - up, pixels 0 .. 8 n8 - 1 */
	i0 = r4;
	i1 = r3;
	r0 = r4 | r3;
	r7 = 3;
	r0 = r0 & r7;
	cc = r0 == 0;           /* both rows word-aligned (the DMA path's ring rows) */
	r0 = p1;
	r0 += -4;               /* the pipelined first store is garbage: into the pad */
	i2 = r0;
	disalgnexcpt || r0 = [i0++] || r2 = [i1++];
	disalgnexcpt || r1 = [i0++] || r3 = [i1++];
	if !cc jump .Lgy_u;
	/* aligned rows: the two rows' loads in different issues, since the ring's rows y and
	 * y+2 share a sub-bank (a dual load of them costs a cycle) */
	lsetup (.Lgya_s, .Lgya_e) lc0 = p3;
.Lgya_s: (r5, r4) = byteop16m (r1:0, r3:2) || r0 = [i0++];
	r4 = r4 << 5 (v) || [i2++m2] = r7 || r2 = [i1++];
	r5 = r5 << 5 (v) || [i2++m2] = r4;
	(r7, r6) = byteop16m (r1:0, r3:2) (r) || r1 = [i0++];
	r6 = r6 << 5 (v) || [i2++m2] = r5 || r3 = [i1++];
.Lgya_e: r7 = r7 << 5 (v) || [i2++m2] = r6;
	jump .Lgy_j;
.Lgy_u:
	lsetup (.Lgy_s, .Lgy_e) lc0 = p3;
.Lgy_s:	(r5, r4) = byteop16m (r1:0, r3:2) || r0 = [i0++] || r2 = [i1++];
	r4 = r4 << 5 (v) || [i2++m2] = r7;
	r5 = r5 << 5 (v) || [i2++m2] = r4;
	(r7, r6) = byteop16m (r1:0, r3:2) (r) || r1 = [i0++] || r3 = [i1++];
	r6 = r6 << 5 (v) || [i2++m2] = r5;
.Lgy_e:	r7 = r7 << 5 (v) || [i2++m2] = r6;
.Lgy_j:
	[i2++m2] = r7;
	/* gx = mid[x+1] - mid[x-1] */
	r5 = p0;
	r0 = 3;
	r0 = r0 & r5;
	cc = r0 == 0;
	if cc jump .Lgx_a;
	r0 = r5;
	r0 += 1;
	i0 = r0;
	r0 += -2;
	i1 = r0;
	r0 = p1;
	r0 += -8;
	i2 = r0;
	disalgnexcpt || r0 = [i0++] || r2 = [i1++];
	disalgnexcpt || r1 = [i0++] || r3 = [i1++];
	lsetup (.Lgx_s, .Lgx_e) lc0 = p3;
.Lgx_s:	(r5, r4) = byteop16m (r1:0, r3:2) || r0 = [i0++] || r2 = [i1++];
	r4 = r4 << 5 (v) || [i2++m2] = r7;
	r5 = r5 << 5 (v) || [i2++m2] = r4;
	(r7, r6) = byteop16m (r1:0, r3:2) (r) || r1 = [i0++] || r3 = [i1++];
	r6 = r6 << 5 (v) || [i2++m2] = r5;
.Lgx_e:	r7 = r7 << 5 (v) || [i2++m2] = r6;
	[i2++m2] = r7;
	r5 = p0;
	r4 = [fp + F_DNP];
	r3 = [fp + F_UPP];
.Lg_tail:
	/* x from 8 n8 to width - 2: pairs, then perhaps one pixel. R5 mid, R4 dn, R3 up. */
	r6 = [fp + F_N8];
	r6 <<= 3;               /* x */
.Lg_tail_x:
	r0 = [fp + F_W];
	r0 += -1;
	r0 = r0 - r6;           /* pixels left: width - 1 - x */
	r2 = r0;
	r0 >>= 1;               /* pairs */
	r1 = p1;
	r7 = r6 << 2;
	r1 = r1 + r7;
	i3 = r1;                /* store address: 4 x */
	r5 = r5 + r6;
	r1 = r5;
	r1 += -1;
	p0 = r1;                /* mid + x - 1 */
	r1 += 2;
	p3 = r1;                /* mid + x + 1 */
	r1 = r3 + r6;
	p1 = r1;                /* up + x */
	r1 = r4 + r6;
	p2 = r1;                /* dn + x */
	cc = r0 == 0;
	if cc jump .Lt_single;
	p5 = r0;
	lsetup (.Lt_s, .Lt_e) lc0 = p5;
.Lt_s:	r0 = b[p0++] (z);
	r1 = b[p0++] (z);
	r4 = b[p3++] (z);
	r3 = b[p3++] (z);
	r4 = r4 - r0 (ns) || r5 = b[p1++] (z);
	r4 = r4 << 5 || r6 = b[p2++] (z);
	r3 = r3 - r1 (ns) || w[i3++] = r4.l;
	r3 = r3 << 5 || r0 = b[p1++] (z);
	r6 = r6 - r5 (ns) || w[i3++] = r3.l;
	r6 = r6 << 5 || r1 = b[p2++] (z);
	r1 = r1 - r0 (ns) || w[i3++] = r6.l;
	r1 = r1 << 5;
.Lt_e:	w[i3++] = r1.l;
.Lt_single:
	cc = bittst (r2, 0);
	if !cc jump .Lg_done;
	r0 = b[p0] (z);
	r4 = b[p3] (z);
	r4 = r4 - r0;
	r4 <<= 5;
	w[i3++] = r4.l;
	r5 = b[p1] (z);
	r6 = b[p2] (z);
	r6 = r6 - r5;
	r6 <<= 5;
	i3 += 2;
	w[i3] = r6.l;
.Lg_done:
	rts;
	/* mid word-aligned (the ring's rows): one load stream, both windows from one register pair,
	 * so no two loads share an issue (the two streams' words collided in a sub-bank). Groups
	 * x = 4j - 2 .. 4j + 1: the x+1 window at byte 3 of the word at mid + 4j - 4, the x-1
	 * window at byte 1; pair x = -2 goes to the pad before the slot. */
.Lgx_a:
	r0 = r5;
	r0 += -1;
	i0 = r0;
	r0 += -2;
	i1 = r0;
	r0 = p1;
	r0 += -16;
	i2 = r0;
	disalgnexcpt || r0 = [i0++];
	disalgnexcpt || r1 = [i0++];
	lsetup (.Lgxa_s, .Lgxa_e) lc0 = p3;
.Lgxa_s: (r5, r4) = byteop16m (r1:0, r1:0) || r0 = [i0++];
	r4 = r4 << 5 (v) || [i2++m2] = r7;
	r5 = r5 << 5 (v) || [i2++m2] = r4;
	(r7, r6) = byteop16m (r1:0, r1:0) (r) || r1 = [i0++];
	r6 = r6 << 5 (v) || [i2++m2] = r5;
.Lgxa_e: r7 = r7 << 5 (v) || [i2++m2] = r6;
	[i2++m2] = r7;
	r5 = p0;
	r4 = [fp + F_DNP];
	r3 = [fp + F_UPP];
	r6 = [fp + F_N8];
	r6 <<= 3;
	r6 += -2;               /* the tail from x = 8 n8 - 2 (its gy pair again, the same values) */
	jump .Lg_tail_x;
BVB_ENDFUNC bvb_harris_response_asm

/* Harris candidates (bvb_harris_nms in bvb/harris.h), bit-exact with firmware/c/harris.c.
 *
 * Rows are taken in pairs and cut into 2x2 blocks: only the block's largest value (the first in
 * raster order among equals) can be a candidate, since its block-mates are among its neighbours.
 * The fast path tests the block's maximum against the threshold (three MAX, a compare, a branch
 * not taken: 5 issues per 4 pixels, the loads riding along, the next block loaded ahead). A
 * block above the threshold picks its winner with three compares and conditional moves and
 * gives it the full test, branch-free:
 *   max(u[x-1], u[x], u[x+1], r[x-1], max(r[x+1], d[x-1], d[x], d[x+1]) - 1) < v
 * (the raster-order tie rule in one comparison; the threshold holds already: the winner is the
 * block's maximum). Candidates of the lower row wait in scratch until the upper row is done, so
 * the list comes out in raster order as the C scan leaves it. An odd last column or row, and
 * maps narrower than 8 elements per row, take an exact per-pixel path. Values must be above
 * INT32_MIN so that "- 1" cannot wrap. The loads ahead read up to 3 elements past the end of a
 * row pair: inside the next row, which exists.
 *
 * Cycles (bfbench bench, the response of real frames, threshold 1% of the peak): 65,368 at
 * 160x120, 142,574 at 320x240, 1,041,495 at 640x480 (3.4, 1.9, 3.4 per pixel; 13%, 4% and 13% of
 * the 2x2 blocks reach the full test); the C scan takes 15-17 per pixel (4.8x, 8.2x, 4.9x).
 * Lower bound: 1 issue per pixel (each value through the one 32-bit ALU once). With the map
 * in SDRAM (the bench) the scan streams it (bvb_harris_nms_stream_asm, at the end of this file):
 * 693,069 modelled cycles at 320x240 against the bus bound of 614,400. */
#define C_W      -4
#define C_PAIRS  -8    /* row pairs left */
#define C_ROW    -12   /* the upper row of the pair, + 4 (x = 1) */
#define C_KEY    -16   /* y << 16 | 1 for that row */
#define C_NB     -20   /* 2x2 blocks per row pair: (width - 2) >> 1 */
#define C_ODDW   -24   /* (width - 2) & 1: a last column x = width - 2 outside the blocks */
#define C_ODDH   -28   /* (height - 2) & 1: a last row y = height - 2 outside the pairs */
#define C_SIZE   28
/* the caller's arguments, FP-relative after the push and LINK */
#define C_ARG_STRIDE  48
#define C_ARG_THR     52
#define C_ARG_CAND    56
#define C_ARG_COUNT   60
#define C_ARG_SCRATCH 64

/* A 2x2 block above the threshold (I0, I1 at the next block's upper and lower pair, M2 = -16,
 * M3 the stride): its upper pair's larger value in R0 (R4 its offset, 0 or 4) and the lower
 * pair's in R2 (R5 its offset, stride or stride + 4), raster-first among equals; the two
 * scans' slow paths (bvb_harris_nms_asm's and the ring's) share it. */
.macro NMS_BLOCK_WINNERS
	i0 += m2;
	i1 += m2;
	mnop || r0 = [i0++] || r2 = [i1++];     /* a, c */
	mnop || r1 = [i0++] || r3 = [i1++];     /* b, d */
	r4 = 0;
	r5 = 4;
	cc = r0 < r1;
	if cc r0 = r1;
	if cc r4 = r5;
	r5 = m3;
	r1 = r5;
	r1 += 4;
	cc = r2 < r3;
	if cc r2 = r3;
	if cc r5 = r1;
.endm

BVB_FUNC bvb_harris_nms_asm
	[--sp] = (r7:4, p5:3);
	link C_SIZE;
	[fp + C_W] = r1;
	r3 = [fp + C_ARG_STRIDE];
	r3 <<= 2;
	m3 = r3;                 /* stride in bytes */
	r2 += -2;
	r0 = r0 + r3;
	r0 += 4;
	[fp + C_ROW] = r0;
	r3 = 1;
	r0 = r2 & r3;
	[fp + C_ODDH] = r0;
	r2 >>= 1;
	[fp + C_PAIRS] = r2;
	r0 = 1;
	r0 <<= 16;
	r0 += 1;
	[fp + C_KEY] = r0;       /* y << 16 | x for y = 1, x = 1 */
	r1 += -2;
	r0 = r1 & r3;
	[fp + C_ODDW] = r0;
	r1 >>= 1;
	[fp + C_NB] = r1;
	r7 = [fp + C_ARG_THR];
	r6 = -1;
	p5 = [fp + C_ARG_CAND];
	p1 = -4;
	m1 = -4;
	m2 = -16;

	r0 = [fp + C_PAIRS];
	cc = r0 == 0;
	if cc jump .Lc_last_row;
.Lc_pair:
	r0 = [fp + C_ROW];
	b0 = r0;
	r1 = [fp + C_KEY];
	b1 = r1;
	r2 = [fp + C_ARG_SCRATCH];
	p3 = r2;                 /* the lower row's candidates wait here */
	r1 = m3;
	r2 = 32;
	cc = r1 < r2;
	if cc jump .Lc_narrow;
	p2 = [fp + C_NB];
	cc = p2 == 0;
	if cc jump .Lc_pair_end;
	i0 = r0;
	r0 = r0 + r1;
	i1 = r0;
	mnop || r0 = [i0++] || r2 = [i1++];
	mnop || r1 = [i0++] || r3 = [i1++];
	r4 = max (r0, r2) || r0 = [i0++] || r2 = [i1++];
	r5 = max (r1, r3) || r1 = [i0++] || r3 = [i1++];
	lsetup (.Lc_b_s, .Lc_b_e) lc0 = p2;
.Lc_b_s: r4 = max (r4, r5);
	cc = r4 <= r7;
	if !cc jump .Lc_slow;
.Lc_back:
	r4 = max (r0, r2) || r0 = [i0++] || r2 = [i1++];
.Lc_b_e: r5 = max (r1, r3) || r1 = [i0++] || r3 = [i1++];

.Lc_pair_end:
	/* the upper row's last column, then the lower row's waiting candidates, then its last
	 * column: raster order */
	r0 = [fp + C_ODDW];
	cc = r0 == 0;
	if cc jump 1f;
	r0 = [fp + C_NB];
	r0 <<= 3;
	r1 = b0;
	r0 = r0 + r1;
	p2 = 1;
	call .Lc_pix;
1:	r0 = [fp + C_ARG_SCRATCH];
	r1 = p3;
	r1 = r1 - r0;
	r1 >>= 2;
	cc = r1 == 0;
	if cc jump 2f;
	i2 = r0;
	p2 = r1;
	lsetup (3f, 5f) lc1 = p2;
3:	r0 = [i2++];
5:	[p5++] = r0;
2:
	r0 = [fp + C_ODDW];
	cc = r0 == 0;
	if cc jump 4f;
	r0 = b0;
	r1 = m3;
	r0 = r0 + r1;
	b0 = r0;
	r1 = b1;
	r2 = 1;
	r2 <<= 16;
	r1 = r1 + r2;
	b1 = r1;
	r1 = [fp + C_NB];
	r1 <<= 3;
	r0 = r0 + r1;
	p2 = 1;
	call .Lc_pix;
4:
.Lc_next_pair:
	r0 = [fp + C_ROW];
	r1 = m3;
	r1 <<= 1;
	r0 = r0 + r1;
	[fp + C_ROW] = r0;
	r0 = [fp + C_KEY];
	r1 = 2;
	r1 <<= 16;
	r0 = r0 + r1;
	[fp + C_KEY] = r0;
	r0 = [fp + C_PAIRS];
	r0 += -1;
	[fp + C_PAIRS] = r0;
	cc = r0 == 0;
	if !cc jump .Lc_pair;

.Lc_last_row:
	r0 = [fp + C_ODDH];
	cc = r0 == 0;
	if cc jump .Lc_done;
	r0 = [fp + C_ROW];
	b0 = r0;
	r1 = [fp + C_KEY];
	b1 = r1;
	r1 = [fp + C_W];
	r1 += -2;
	p2 = r1;
	call .Lc_pix;
.Lc_done:
	r0 = [fp + C_ARG_CAND];
	r1 = p5;
	r0 = r1 - r0;
	r0 >>= 3;
	p0 = [fp + C_ARG_COUNT];
	[p0] = r0;
	unlink;
	(r7:4, p5:3) = [sp++];
	rts;

/* Narrow maps: both rows of the pair through the per-pixel path. */
.Lc_narrow:
	r0 = b0;
	r1 = [fp + C_W];
	r1 += -2;
	p2 = r1;
	call .Lc_pix;
	r0 = b0;
	r1 = m3;
	r0 = r0 + r1;
	b0 = r0;
	r1 = b1;
	r2 = 1;
	r2 <<= 16;
	r1 = r1 + r2;
	b1 = r1;
	r1 = [fp + C_W];
	r1 += -2;
	p2 = r1;
	call .Lc_pix;
	jump .Lc_next_pair;

/* A 2x2 block above the threshold: its upper pair is 16 bytes behind I0, its lower pair 16
 * behind I1. Leaves R0-R3 holding the next block and I0, I1 after it, as the loop expects. */
.Lc_slow:
	NMS_BLOCK_WINNERS
	cc = r0 < r2;
	if cc r0 = r2;
	if cc r4 = r5;                           /* R0 its value, R4 its offset from the block */
	r1 = i0;
	r1 += -12;                               /* the block's upper-left pixel - 4 */
	r1 = r1 + r4;                            /* the winner - 4 */
	p0 = r1;
	r5 = m3;
	r2 = r1 - r5;
	i2 = r2;                                 /* the row above */
	r2 = r1 + r5;
	i3 = r2;                                 /* the row below */
	mnop || r1 = [i2++] || r2 = [i3++];      /* u0, d0 */
	mnop || r3 = [i2++] || r5 = [i3++];      /* u1, d1 */
	r1 = max (r1, r3) || r3 = [i2++];        /* u2 */
	r2 = max (r2, r5) || r5 = [i3++];        /* d2 */
	r1 = max (r1, r3) || r3 = [p0++];        /* l */
	r2 = max (r2, r5) || r5 = [p0++];        /* (v) */
	r1 = max (r1, r3) || r3 = [p0];          /* r */
	r2 = max (r2, r3);
	r2 = r2 + r6 (ns);
	r1 = max (r1, r2);
	cc = r1 < r0;
	if cc jump .Lc_found;
.Lc_resume:
	mnop || r0 = [i0++] || r2 = [i1++];      /* the next block, as the loop left it */
	mnop || r1 = [i0++] || r3 = [i1++];
	jump .Lc_back;
/* The winner is a candidate: into the list if it is in the upper row, else to wait in scratch. */
.Lc_found:
	r1 = i0;
	r1 += -8;
	r2 = b0;
	r1 = r1 - r2;
	r1 >>= 2;                                /* x0 - 1 */
	r2 = b1;
	r1 = r1 + r2;                            /* the key of the block's upper-left pixel */
	r2 = 8;
	cc = r4 < r2;
	if !cc jump 1f;
	r4 >>= 2;                                /* upper row: offset 0 or 4 */
	r1 = r1 + r4;
	[p5++] = r1;
	[p5++] = r0;
	jump .Lc_resume;
1:	r2 = m3;                                 /* lower row: offset stride or stride + 4 */
	r4 = r4 - r2;
	r4 >>= 2;
	r1 = r1 + r4;
	r2 = 1;
	r2 <<= 16;
	r1 = r1 + r2;
	[p3++] = r1;
	[p3++] = r0;
	jump .Lc_resume;

/* The exact per-pixel path: P2 pixels from the one at R0, in the row whose x = 1 is at B0 and
 * whose key is B1; appends candidates at P5. Keeps R6, R7, I0, I1, P1, P3, M1-M3, B0, B1. */
.Lc_pix:
	r1 = b0;
	r2 = r0 - r1;
	r2 >>= 2;
	r1 = b1;
	r2 = r2 + r1;
	p4 = r2;                 /* the key of the first pixel */
	r1 = m3;
	r0 += -4;
	r2 = r0 - r1;
	i2 = r2;
	r2 = r0 + r1;
	i3 = r2;
	p0 = r0;
	lsetup (.Lc_p_s, .Lc_p_e) lc1 = p2;
.Lc_p_s: mnop || r0 = [i2++] || r1 = [i3++];
	r0 = max (r0, r7) || r2 = [i2++] || r3 = [i3++];
	r0 = max (r0, r2) || r2 = [i2++m1] || r4 = [i3++m1];
	r0 = max (r0, r2) || r2 = [p0++];
	r1 = max (r1, r3) || r3 = [p0++];
	r0 = max (r0, r2) || r2 = [p0++p1];
	r1 = max (r1, r4);
	r1 = max (r1, r2);
	r1 = r1 + r6 (ns);
	r0 = max (r0, r1);
	cc = r0 < r3;
	if !cc jump .Lc_p_e (bp);
	r0 = p4;
	[p5++] = r0;
	[p5++] = r3;
.Lc_p_e: p4 += 1;
	rts;
BVB_ENDFUNC bvb_harris_nms_asm

/* bvb_harris_nms_stream_asm: bvb_harris_nms with the response map in SDRAM (the stand-alone
 * scan: kernels.def's harris_nms), its rows brought into L1 by memory DMA (bvb/dma.h) ahead of
 * the scan; the same arguments, the same candidates. The odometry keeps calling
 * bvb_harris_nms_asm: its response strips are in L1 already.
 *
 * The ring. Row pair m (map rows 2m, 2m+1) goes to slot m % 5 of two regions, the even row to
 * E, the odd row to O, O starting at the first 4 KB boundary after E's end: a pair's upper row
 * (odd) and lower row (even) are never in one L1 sub-bank, so the scan's dual loads of the two
 * never collide. Pair j (rows 2j+1, 2j+2) reads row pairs j and j+1; the rows above an upper
 * row and below a lower row are G = O - E away, the lower row Dp = E(j+1 % 5) - O(j % 5)
 * from the upper: the pair code (.Ls_do_pair) is bvb_harris_nms_asm's with those two
 * distances, the above-threshold test inline (a taken jump for the 57% of blocks below the
 * threshold at the bench's 1% of the peak, instead of two for the 43% above), the next block
 * reloaded while the winner's row pointers settle (no address-register stall), the rows
 * above and below the winner (one region) each loaded beside a load of the winner's own row
 * (no sub-bank collision), and a candidate's key made from the winner's address and a
 * per-row constant.
 *
 * The jobs. Every other pair j, one job (two job areas, built in the one no job runs from,
 * before the wait) brings row pairs j+3 and j+4 (one 2-row transfer each, E and O rows
 * G apart) and sends pairs j-2 and j-1's candidates (collected in one of two L1 sections,
 * the transfer re-addressed and its X_COUNT set: no bvb_dma_prepare per job), after waiting
 * for the job before (row pairs j+1, j+2): each job has two pairs' scans to run under, which
 * evens out pairs that outrun the bus (the map's flat parts) and pairs the bus outruns (one
 * job a pair: 731,486 at 320x240; a third band ahead with one job a pair saved nothing). The
 * first job brings row pairs 0 to 2 while the core waits; an odd last row is scanned in
 * SDRAM. Anything else (the map in L1, the scratch or cand where DMA does not reach, maps
 * narrower than 8 or lower than 4, a transfer DMA refuses) takes bvb_harris_nms_asm as it is.
 * Coherence as bvb/dma.h: on the chip with the data cache on, cand's lines would be
 * invalidated before the candidates' transfers write it.
 * The driver is once-per-call code and runs from SDRAM (.text) through the instruction cache,
 * the scan too (its 700 bytes hit in the cache; L1 instruction SRAM is full).
 *
 * Measured (bfbench bench, the integer texture's response, threshold 1% of the peak; map and
 * cand in SDRAM, scratch in L1 bank B; modelled cycles, then the simulator's own count):
 *   160x120     189,788   9.88 per pixel (bound 8: 1.24x)   sim   172,816
 *   320x240     693,069   9.02           (1.13x)            sim   650,748
 *   (640x480: the scratch, 42 KB, does not fit L1 bank B's arena: bvb_harris_nms_asm on the
 *   map in SDRAM, 5,477,247.) Before: bvb_harris_nms_asm on the map in SDRAM through the data
 *   cache, 400,418 / 1,516,068 (its line fills 800,275 of the 320x240 count). C: 539,223 /
 *   2,115,219.
 * Bound: the map's 4 bytes per pixel over the bus at 0.5 byte per core cycle, 8 per pixel
 * (614,400 at 320x240; the scan's compute bound is 1). Where the rest of 320x240 goes: the
 * bus also carries the candidates (2,083, 16.7 KB: some 33,000 cycles) and the jobs' start-up
 * and descriptors (60 jobs of 3 transfers, some 200 cycles each); the first three row pairs
 * (15,400 cycles) come in before anything is computed; the scan itself is about as long as
 * the bus's time (the block
 * loop 567,600 cycles: 5 issues a block, 8 more for the below-threshold jump, some 40 for an
 * above-threshold block's winner and its 8 neighbours, 8,230 of 18,921), so that the pairs
 * the bus waits for are not all hidden; the core waits 35,700 cycles in bvb_dma_wait in all.
 * Scratch: BVB_HARRIS_NMS_STREAM_SCRATCH_BYTES, 23.0 KB at 320 wide. */
#define S_RESP   -32   /* resp */
#define S_H      -36   /* height */
#define S_RB     -40   /* bytes per row, 4 width */
#define S_SSTR   -44   /* stride in bytes */
#define S_E      -48   /* region E (even rows), slot s at E + s RB */
#define S_O      -52   /* region O (odd rows) */
#define S_JOB    -56   /* job area 0 (area 1 follows, 128 bytes on) */
#define S_SRC    -60   /* the next band to bring, in SDRAM */
#define S_BSLOT  -64   /* its slot offset, s RB */
#define S_BLEFT  -68   /* bands left to bring */
#define S_PSLOT  -72   /* the slot offset of the current pair's upper row */
#define S_SECT   -76   /* bytes per candidate section */
#define S_SEC    -80   /* the section the last pair's candidates went to */
#define S_PREVN  -84   /* ... and their number */
#define S_CPOS   -88   /* where in cand the next section goes */
#define S_AREA   -92   /* the job area the next job is built in (0, 1) */
#define S_CKEY   -100  /* per area, the slot prepared for candidates (-1: none) */
#define S_CUR    -104  /* the area being built */
#define S_NSLOT  -108  /* its slots */
#define S_KU     -112  /* key - (the winner - 4) / 4 in the upper row */
#define S_KL     -116  /* ... in the lower row */
#define S_RING   -120  /* bytes of a ring region, 5 RB */
#define S_J      -124  /* the pair */
#define S_X      -148  /* struct bvb_dma_xfer */
#define S_SIZE   148
/* bvb/dma.h's descriptor layout: X_COUNT is halfword 3 of each 7-halfword descriptor, the
 * destination's descriptors BVB_DMA_MAX_XFERS * 14 bytes after the source's. */
#define S_DS_XC  6
#define S_DST_SLOTS (BVB_DMA_MAX_XFERS * 14)

BVB_FUNC bvb_harris_nms_stream_asm, .text
	[--sp] = (r7:4, p5:3);
	link S_SIZE;
	[fp + C_W] = r1;
	[fp + S_RESP] = r0;
	[fp + S_H] = r2;
	r4 = r1 << 2;
	[fp + S_RB] = r4;
	r3 = 8;
	cc = r1 < r3;
	if cc jump .Ls_direct;
	r3 = 4;
	cc = r2 < r3;
	if cc jump .Ls_direct;
	/* the map in SDRAM, all of it where DMA reaches */
	r3.l = 0;
	r3.h = 0x0200;
	cc = r0 < r3 (iu);
	if !cc jump .Ls_direct;
	r5 = [fp + C_ARG_STRIDE];
	r5 <<= 2;
	[fp + S_SSTR] = r5;
	r1 = r2;
	r1 += -1;
	r1 *= r5;
	r1 = r1 + r4;
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ls_direct;
	/* cand where DMA reaches: its capacity, ((w - 1) / 2) ((h - 1) / 2) pairs */
	r0 = [fp + C_W];
	r0 += -1;
	r0 >>= 1;
	r1 = [fp + S_H];
	r1 += -1;
	r1 >>= 1;
	r1 *= r0;
	r1 <<= 3;
	r0 = [fp + C_ARG_CAND];
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ls_direct;
	/* the scratch in L1 data SRAM DMA reaches */
	r0 = [fp + C_ARG_SCRATCH];
	r3.l = 0;
	r3.h = 0xff80;
	cc = r0 < r3 (iu);
	if cc jump .Ls_direct;
	r3 = [fp + C_W];
	r3 += -1;
	r3 >>= 1;
	r3 <<= 3;
	r3 += 8;                /* the waiting list, BVB_HARRIS_NMS_SCRATCH_BYTES */
	r2 = r3;
	r2 += 8;
	r2 <<= 1;
	[fp + S_SECT] = r2;     /* two pairs' candidates, at most (w - 2) / 2 + 2 each */
	r1 = [fp + C_W];
	r2 = 40;
	r1 *= r2;               /* the ten ring rows */
	r2 = r3 << 2;
	r2 = r2 + r3;
	r1 = r1 + r2;
	r2 = 4399 (z);          /* the sections' 32, two jobs (256), the gap to O's boundary (< 4096), a pad (16) */
	r1 = r1 + r2;
	r0 = [fp + C_ARG_SCRATCH];
	[fp + S_JOB] = r3;      /* (the list's size, for a moment) */
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ls_direct;
	/* the layout: list, two jobs, two sections, E (five rows), O from the next 4 KB
	 * boundary after E's end */
	r0 = [fp + C_ARG_SCRATCH];
	r3 = [fp + S_JOB];
	r0 = r0 + r3;
	[fp + S_JOB] = r0;
	r1 = 256;
	r0 = r0 + r1;
	[fp + S_SEC] = r0;      /* section 0 (section 1 follows) */
	p5 = r0;
	r1 = [fp + S_SECT];
	r1 <<= 1;
	r0 = r0 + r1;
	[fp + S_E] = r0;
	r4 = [fp + S_RB];
	r1 = r4 << 2;
	r1 = r1 + r4;
	[fp + S_RING] = r1;     /* 5 RB */
	r1 = r0 + r1;           /* E + 5 RB */
	r2 = 4095;
	r1 = r1 + r2;
	r2 = ~r2;
	r1 = r1 & r2;
	[fp + S_O] = r1;
	r1 = r1 - r0;
	m0 = r1;                /* G = O - E */

	/* job area 0: row pairs 0, 1 and 2 (when the map has them) into slots 0, 1, 2 (rows
	 * 0, 2, 4 to E, rows 1, 3, 5 to O); area 1's slots 0 and 1 prepared for the row pairs
	 * that follow */
	r0 = [fp + S_RESP];
	[fp + S_X + DMAX_SRC] = r0;
	r0 = [fp + S_SSTR];
	[fp + S_X + DMAX_SS] = r0;
	r0 = [fp + S_E];
	[fp + S_X + DMAX_DST] = r0;
	r0 = m0;
	[fp + S_X + DMAX_DS] = r0;
	r0 = [fp + S_RB];
	[fp + S_X + DMAX_W] = r0;
	r0 = 2;
	[fp + S_X + DMAX_ROWS] = r0;
	r0 = 128;
	r1 = 0;
	call .Ls_prep;
	r0 = 128;
	r1 = 1;
	call .Ls_prep;
	r0 = 0;
	r1 = 0;
	call .Ls_prep;
	call .Ls_next_rp;
	r0 = 0;
	r1 = 1;
	call .Ls_prep;
	r1 = 2;
	r0 = [fp + S_H];
	r2 = 6;
	cc = r0 < r2;
	if cc jump 1f;          /* h < 6: row pairs 0 and 1 are all */
	call .Ls_next_rp;
	r0 = 0;
	r1 = 2;
	call .Ls_prep;
	r1 = 3;
1:	r0 = [fp + S_JOB];
	call _bvb_dma_start;

	/* the scan's state, as bvb_harris_nms_asm's */
	r2 = [fp + S_H];
	r2 += -2;
	r3 = 1;
	r0 = r2 & r3;
	[fp + C_ODDH] = r0;
	r2 >>= 1;
	[fp + C_PAIRS] = r2;    /* >= 1 */
	r2 += -2;
	r0 = 0;
	r2 = max (r2, r0);
	[fp + S_BLEFT] = r2;    /* row pairs 3 .. pairs */
	r0 = 1;
	r0 <<= 16;
	r0 += 1;
	[fp + C_KEY] = r0;
	r1 = [fp + C_W];
	r1 += -2;
	r0 = r1 & r3;
	[fp + C_ODDW] = r0;
	r1 >>= 1;
	[fp + C_NB] = r1;
	r0 = [fp + S_RESP];
	r1 = [fp + S_SSTR];
	r2 = r1 << 1;
	r0 = r0 + r2;
	r1 <<= 2;
	r0 = r0 + r1;
	[fp + S_SRC] = r0;      /* row pair 3: rows 6 and 7 */
	r0 = [fp + S_RB];
	r1 = r0 << 1;
	r0 = r0 + r1;
	[fp + S_BSLOT] = r0;
	r0 = 0;
	[fp + S_PSLOT] = r0;
	[fp + S_PREVN] = r0;
	[fp + S_J] = r0;
	r0 = [fp + C_ARG_CAND];
	[fp + S_CPOS] = r0;
	r0 = 1;
	[fp + S_AREA] = r0;
	r0 = -1;
	[fp + S_CKEY] = r0;
	[fp + S_CKEY + 4] = r0;
	r7 = [fp + C_ARG_THR];
	m1 = -4;
	m2 = -16;

.Ls_pair:
	/* every other pair (j even), the next job, built in the area no job runs from: the row
	 * pairs j+3 and j+4, the candidates of pairs j-2 and j-1; then the wait for the last job
	 * (row pairs j+1 and j+2), its start. Each job has two pairs' scans to run under. */
	r0 = [fp + S_J];
	cc = bittst (r0, 0);
	if cc jump .Ls_scan;
	r0 = p5;
	r1 = [fp + S_SEC];
	r0 = r0 - r1;
	r0 >>= 3;
	[fp + S_PREVN] = r0;
	r0 = [fp + S_AREA];
	r1 = r0 << 7;
	r2 = [fp + S_JOB];
	r1 = r1 + r2;
	[fp + S_CUR] = r1;
	r0 = 0;
	[fp + S_NSLOT] = r0;
	call .Ls_band;
	call .Ls_band;
	r0 = [fp + S_PREVN];
	cc = r0 == 0;
	if cc jump .Ls_run;
	call .Ls_cand_slot;
.Ls_run:
	call _bvb_dma_wait;     /* row pairs up to j+2 are in */
	r1 = [fp + S_NSLOT];
	cc = r1 == 0;
	if cc jump 1f;
	r0 = [fp + S_CUR];
	call _bvb_dma_start;
1:	r0 = [fp + S_AREA];
	r1 = 1;
	r0 = r0 ^ r1;
	[fp + S_AREA] = r0;
	/* pairs j and j+1's candidates into the other section than the last two pairs' */
	r0 = [fp + S_JOB];
	r1 = 256;
	r0 = r0 + r1;           /* section 0 */
	r1 = [fp + S_AREA];     /* (j / 2) & 1 now */
	cc = r1 == 0;
	r2 = [fp + S_SECT];
	r1 = 0;
	if cc r2 = r1;
	r0 = r0 + r2;
	[fp + S_SEC] = r0;
	p5 = r0;
.Ls_scan:
	/* upper row 2j+1 in O at slot j % 5, lower row 2j+2 in E at slot (j+1) % 5 */
	r0 = [fp + S_PSLOT];
	r1 = [fp + S_O];
	r1 = r1 + r0;
	r1 += 4;
	b0 = r1;
	r2 = [fp + S_RB];
	r0 = r0 + r2;
	r3 = [fp + S_RING];
	cc = r0 == r3;
	r3 = 0;
	if cc r0 = r3;
	[fp + S_PSLOT] = r0;
	r2 = [fp + S_E];
	r2 = r2 + r0;
	r2 += 4;
	r2 = r2 - r1;
	m3 = r2;                /* Dp */
	r3 = [fp + C_KEY];
	b1 = r3;
	/* the keys from the winner's address - 4 (P0 in .Ls_found): x = (W - B0) / 4 + 1 */
	r3 += 1;
	r0 = r1 >> 2;
	r0 = r3 - r0;
	[fp + S_KU] = r0;
	r1 = r1 + r2;           /* the lower row's B0 */
	r1 >>= 2;
	r3 = r3 - r1;
	r1 = 1;
	r1 <<= 16;
	r3 = r3 + r1;
	[fp + S_KL] = r3;
	call .Ls_do_pair;
	r0 = [fp + S_J];
	r0 += 1;
	[fp + S_J] = r0;
	r0 = [fp + C_KEY];
	r1 = 2;
	r1 <<= 16;
	r0 = r0 + r1;
	[fp + C_KEY] = r0;
	r0 = [fp + C_PAIRS];
	r0 += -1;
	[fp + C_PAIRS] = r0;
	cc = r0 == 0;
	if !cc jump .Ls_pair;
	r0 = p5;
	r1 = [fp + S_SEC];
	r0 = r0 - r1;
	r0 >>= 3;
	[fp + S_PREVN] = r0;

	/* the last pair's candidates */
	call _bvb_dma_wait;
	r0 = [fp + S_PREVN];
	cc = r0 == 0;
	if cc jump .Ls_tail;
	r0 = [fp + S_AREA];
	r1 = r0 << 7;
	r2 = [fp + S_JOB];
	r1 = r1 + r2;
	[fp + S_CUR] = r1;
	r0 = 0;
	[fp + S_NSLOT] = r0;
	call .Ls_cand_slot;
	r0 = [fp + S_CUR];
	r1 = [fp + S_NSLOT];
	call _bvb_dma_start;
	call _bvb_dma_wait;
.Ls_tail:
	p5 = [fp + S_CPOS];
	/* an odd last row, y = h - 2, in SDRAM */
	r0 = [fp + C_ODDH];
	cc = r0 == 0;
	if cc jump .Ls_done;
	r0 = [fp + S_H];
	r0 += -2;
	r1 = [fp + S_SSTR];
	r0 *= r1;
	r2 = [fp + S_RESP];
	r0 = r0 + r2;
	r0 += 4;
	b0 = r0;
	b2 = r1;
	b3 = r1;
	r1 = [fp + C_KEY];
	b1 = r1;
	r1 = [fp + C_W];
	r1 += -2;
	p2 = r1;
	p1 = -4;
	call .Ls_pix;
.Ls_done:
	r0 = [fp + C_ARG_CAND];
	r1 = p5;
	r0 = r1 - r0;
	r0 >>= 3;
	p0 = [fp + C_ARG_COUNT];
	[p0] = r0;
	unlink;
	(r7:4, p5:3) = [sp++];
	rts;

.Ls_direct:
	r0 = [fp + S_RESP];
	r1 = [fp + C_W];
	r2 = [fp + S_H];
	unlink;
	(r7:4, p5:3) = [sp++];
	jump.l _bvb_harris_nms_asm;

/* Slot R1 of job area R0 (byte offset 0 or 128) prepared for S_X (the initial jobs); refused:
 * the direct path. */
.Ls_prep:
	[--sp] = rets;
	r2 = [fp + S_JOB];
	r0 = r0 + r2;
	r2 = fp;
	r3 = S_X (x);
	r2 = r2 + r3;
	call _bvb_dma_prepare;
	rets = [sp++];
	cc = r0 < 0;
	if cc jump 1f;
	rts;
1:	jump.l .Ls_direct;       /* (its UNLINK drops this call's return) */

/* S_X one row pair (2 rows) further down the map and the ring. */
.Ls_next_rp:
	r0 = [fp + S_X + DMAX_SRC];
	r1 = [fp + S_SSTR];
	r1 <<= 1;
	r0 = r0 + r1;
	[fp + S_X + DMAX_SRC] = r0;
	r0 = [fp + S_X + DMAX_DST];
	r1 = [fp + S_RB];
	r0 = r0 + r1;
	[fp + S_X + DMAX_DST] = r0;
	rts;

/* The next row pair to bring, when one is left, as slot S_NSLOT of the area at S_CUR. */
.Ls_band:
	r0 = [fp + S_BLEFT];
	cc = r0 == 0;
	if cc jump 1f;
	[--sp] = rets;
	r0 += -1;
	[fp + S_BLEFT] = r0;
	r0 = [fp + S_SRC];
	[fp + S_X + DMAX_SRC] = r0;
	r1 = [fp + S_SSTR];
	r1 <<= 1;
	r0 = r0 + r1;
	[fp + S_SRC] = r0;
	r0 = [fp + S_BSLOT];
	r1 = [fp + S_E];
	r1 = r1 + r0;
	[fp + S_X + DMAX_DST] = r1;
	r1 = [fp + S_RB];
	r0 = r0 + r1;
	r2 = [fp + S_RING];
	cc = r0 == r2;
	r2 = 0;
	if cc r0 = r2;
	[fp + S_BSLOT] = r0;
	r0 = [fp + S_CUR];
	r1 = [fp + S_NSLOT];
	r2 = fp;
	r3 = S_X (x);
	r2 = r2 + r3;
	call _bvb_dma_move;
	r1 = [fp + S_NSLOT];
	r1 += 1;
	[fp + S_NSLOT] = r1;
	rets = [sp++];
1:	rts;

/* The last pair's S_PREVN candidates (section S_SEC) to cand at S_CPOS, as slot S_NSLOT of
 * the area at S_CUR: re-addressed, with its X_COUNTs set, when that slot of that area is the
 * one prepared for candidates (1D, 16-bit elements: every address and length is a multiple
 * of 4), else prepared first. */
.Ls_cand_slot:
	[--sp] = rets;
	r0 = [fp + S_SEC];
	[fp + S_X + DMAX_SRC] = r0;
	r0 = [fp + S_CPOS];
	[fp + S_X + DMAX_DST] = r0;
	r1 = [fp + S_PREVN];
	r1 <<= 3;
	r0 = r0 + r1;
	[fp + S_CPOS] = r0;
	r0 = [fp + S_AREA];
	r0 <<= 2;
	r1 = fp;
	r0 = r0 + r1;
	p2 = r0;                 /* &S_CKEY[area] - S_CKEY */
	r0 = [p2 + S_CKEY];
	r1 = [fp + S_NSLOT];
	cc = r0 == r1;
	if !cc jump 1f;
	r0 = [fp + S_CUR];
	r2 = fp;
	r3 = S_X (x);
	r2 = r2 + r3;
	call _bvb_dma_move;
	jump 2f;
1:	r0 = [fp + S_SECT];
	[fp + S_X + DMAX_W] = r0;
	[fp + S_X + DMAX_SS] = r0;
	[fp + S_X + DMAX_DS] = r0;
	r0 = 1;
	[fp + S_X + DMAX_ROWS] = r0;
	r0 = [fp + S_CUR];
	r1 = [fp + S_NSLOT];
	r2 = fp;
	r3 = S_X (x);
	r2 = r2 + r3;
	call _bvb_dma_prepare;
	r1 = [fp + S_AREA];
	r1 <<= 2;
	r2 = fp;
	r1 = r1 + r2;
	p2 = r1;
	r1 = [fp + S_NSLOT];
	cc = r0 < 0;
	if cc jump 3f;
	[p2 + S_CKEY] = r1;
2:	r1 = [fp + S_NSLOT];
	r0 = r1 << 4;
	r1 <<= 1;
	r0 = r0 - r1;           /* 14 k */
	r1 = [fp + S_CUR];
	r0 = r0 + r1;
	p0 = r0;
	r0 = [fp + S_PREVN];
	r0 <<= 2;               /* 16-bit elements */
	w[p0 + S_DS_XC] = r0;
	w[p0 + (S_DST_SLOTS + S_DS_XC)] = r0;
	r1 = [fp + S_NSLOT];
	r1 += 1;
	[fp + S_NSLOT] = r1;
	rets = [sp++];
	rts;
3:	/* DMA refused it (none should): the core copies the section */
	r0 = -1;
	[p2 + S_CKEY] = r0;
	p0 = [fp + S_X + DMAX_SRC];
	p1 = [fp + S_X + DMAX_DST];
	p2 = [fp + S_PREVN];
	p2 = p2 + p2;
	lsetup (4f, 5f) lc1 = p2;
4:	r0 = [p0++];
5:	[p1++] = r0;
	rets = [sp++];
	rts;

/* One row pair from the ring: B0 its upper row (x = 1), B1 that row's key, M3 = Dp, M0 = G. */
.Ls_do_pair:
	[--sp] = rets;
	r0 = b0;
	r2 = [fp + C_ARG_SCRATCH];
	p3 = r2;                 /* the lower row's candidates wait here */
	p2 = [fp + C_NB];
	i0 = r0;
	r1 = m3;
	r0 = r0 + r1;
	i1 = r0;
	mnop || r0 = [i0++] || r2 = [i1++];
	mnop || r1 = [i0++] || r3 = [i1++];
	r4 = max (r0, r2) || r0 = [i0++] || r2 = [i1++];
	r5 = max (r1, r3) || r1 = [i0++] || r3 = [i1++];
	lsetup (.Ls_b_s, .Ls_b_e) lc0 = p2;
.Ls_b_s: r4 = max (r4, r5);
	cc = r4 <= r7;
	if cc jump .Ls_back;     /* below the threshold: the jump costs 9, a slow path entered by one 14 */
	/* above the threshold: bvb_harris_nms_asm's .Lc_slow with the ring's distances; the row
	 * above an upper winner is G before it and the row below Dp after it; above a lower
	 * winner Dp before, below G after */
	NMS_BLOCK_WINNERS
	r1 = m0;
	r3 = m3;
	cc = r0 < r2;
	if cc r0 = r2;
	if cc r4 = r5;                           /* R0 its value, R4 its offset from the block */
	r5 = r1;
	if cc r1 = r3;
	if cc r3 = r5;                           /* R1 the distance up, R3 down */
	r2 = i0;
	r2 += -12;
	r2 = r2 + r4;                            /* the winner - 4 */
	r5 = r2 - r1;
	i2 = r5;                                 /* the row above, from the winner's left */
	p0 = r2;
	r5 = r2 + r3;
	i3 = r5;                                 /* the row below */
	r4 = r0;                                 /* the winner's value */
	mnop || r0 = [i0++] || r2 = [i1++];      /* the next block, as the loop left it, while */
	mnop || r1 = [i0++] || r3 = [i1++];      /* I2, I3 and P0 become usable */
	/* the rows above and below share a region: each pairs with a load of the winner's row */
	mnop || r5 = [i2++] || r7 = [p0];        /* u0, l */
	r5 = max (r5, r7) || r6 = [i3++] || r7 = [p0 + 8];  /* d0, r */
	r6 = max (r6, r7) || r7 = [i2++];        /* u1 */
	r5 = max (r5, r7) || r7 = [i2++];        /* u2 */
	r5 = max (r5, r7) || r7 = [i3++];        /* d1 */
	r6 = max (r6, r7) || r7 = [i3++];        /* d2 */
	r6 = max (r6, r7);
	r6 += -1;                                /* after the winner: >= is enough */
	r5 = max (r5, r6) || r7 = [fp + C_ARG_THR];
	cc = r5 < r4;
	if cc jump .Ls_found;
.Ls_back:
	r4 = max (r0, r2) || r0 = [i0++] || r2 = [i1++];
.Ls_b_e: r5 = max (r1, r3) || r1 = [i0++] || r3 = [i1++];
	p1 = -4;
	r0 = [fp + C_ODDW];
	cc = r0 == 0;
	if cc jump 1f;
	r0 = [fp + C_NB];
	r0 <<= 3;
	r1 = b0;
	r0 = r0 + r1;
	b2 = m0;
	b3 = m3;
	p2 = 1;
	call .Ls_pix;
1:	r0 = [fp + C_ARG_SCRATCH];
	r1 = p3;
	r1 = r1 - r0;
	r1 >>= 2;
	cc = r1 == 0;
	if cc jump 2f;
	i2 = r0;
	p2 = r1;
	lsetup (3f, 5f) lc1 = p2;
3:	r0 = [i2++];
5:	[p5++] = r0;
2:
	r0 = [fp + C_ODDW];
	cc = r0 == 0;
	if cc jump 4f;
	r0 = b0;
	r1 = m3;
	r0 = r0 + r1;
	b0 = r0;
	r1 = b1;
	r2 = 1;
	r2 <<= 16;
	r1 = r1 + r2;
	b1 = r1;
	r1 = [fp + C_NB];
	r1 <<= 3;
	r0 = r0 + r1;
	b2 = m3;
	b3 = m0;
	p2 = 1;
	call .Ls_pix;
4:	rets = [sp++];
	rts;

/* The winner is a candidate: into the section if it is in the upper row, else to wait. */
.Ls_found:
	r5 = p0;
	r6 = [fp + S_O];
	cc = r5 < r6 (iu);                       /* the lower row (region E, before O) */
	r5 >>= 2;
	if cc jump 1f;
	r6 = [fp + S_KU];
	r5 = r5 + r6;
	[p5++] = r5;
	[p5++] = r4;
	jump .Ls_back;
1:	r6 = [fp + S_KL];
	r5 = r5 + r6;
	[p3++] = r5;
	[p3++] = r4;
	jump .Ls_back;

/* .Lc_pix with the distance to the row above in B2 and to the row below in B3. */
.Ls_pix:
	r1 = b0;
	r2 = r0 - r1;
	r2 >>= 2;
	r1 = b1;
	r2 = r2 + r1;
	p4 = r2;
	r0 += -4;
	r1 = b2;
	r2 = r0 - r1;
	i2 = r2;
	r1 = b3;
	r2 = r0 + r1;
	i3 = r2;
	p0 = r0;
	lsetup (.Ls_p_s, .Ls_p_e) lc1 = p2;
.Ls_p_s: mnop || r0 = [i2++] || r1 = [i3++];
	r0 = max (r0, r7) || r2 = [i2++] || r3 = [i3++];
	r0 = max (r0, r2) || r2 = [i2++m1] || r4 = [i3++m1];
	r0 = max (r0, r2) || r2 = [p0++];
	r1 = max (r1, r3) || r3 = [p0++];
	r0 = max (r0, r2) || r2 = [p0++p1];
	r1 = max (r1, r4);
	r1 = max (r1, r2);
	r1 += -1;
	r0 = max (r0, r1);
	cc = r0 < r3;
	if !cc jump .Ls_p_e (bp);
	r0 = p4;
	[p5++] = r0;
	[p5++] = r3;
.Ls_p_e: p4 += 1;
	rts;
BVB_ENDFUNC bvb_harris_nms_stream_asm
