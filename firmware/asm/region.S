/* Seeded region growing and per-column free space (bvb/region.h).
 *
 * Measured (bfbench bench: the robot's view of the boxes arena, pose 0; region_grow seeded at
 * the bottom middle, tol 20, 4-connected, queue_cap = width * height; free_space on that floor
 * mask, min_gap 3). "Per grown pixel" divides by the region's pixel count (11,371 at 160x120,
 * 44,672 at 320x240, 175,695 at 640x480); each is taken from the queue once.
 *
 *   region_grow   C cycles      asm cycles   speed-up  per grown pixel C / asm   per frame pixel
 *   160x120        2,277,208      579,018      3.9x         200.3 / 50.9            30.2
 *   320x240        8,951,463    2,440,578      3.7x         200.4 / 54.6            31.8
 *   640x480       35,162,669    9,439,278      3.7x         200.1 / 53.7            30.7
 *   Modelled BF537 cycles (--timing bf537; image, mask and queue in SDRAM as the bench places
 *   them): 1,126,115 at 160x120 (58.7 per frame pixel, 99.0 per grown pixel), 10,973,997 at
 *   320x240 (142.9, 245.7). At 160x120: 579,016 issued (the simulator's count above), 28
 *   address-register stalls, no sub-bank collisions, 547,071 SDRAM line fills and write-backs of
 *   the image, mask and queue through the 16 KB data cache (more of them per pixel at 320x240,
 *   77 KB of image and of mask). Each pixel's pointers are moved into P0/P1 once, five
 *   cycles before their first use; the constant 1 read beside a stack local lives in bank A.
 *   Lower bound: 20 cycles per grown pixel (four neighbour byte tests, compare + branch each;
 *   the tolerance test, multiply / subtract / abs / compare / branch; the count, sum,
 *   tol * count, bounding-box and sum_x/sum_y updates; queue bookkeeping and the loop branch;
 *   every load and store in a parallel slot, no branch penalty). The common case here costs 41
 *   issues (12 to take the pixel from the queue and find its image and mask bytes, 10 to test
 *   left, right and down at once, 16 for the up neighbour's test and join, 3 for the loop);
 *   the rest is the other cases (about one pixel in eight has a free left, right or down
 *   neighbour; border pixels; rejected neighbours) and clearing the mask.
 *
 *   free_space    C cycles      asm cycles   speed-up  per pixel C / asm
 *   160x120          143,720       62,224      2.3x         7.49 / 3.24
 *   320x240          437,932      238,029      1.8x         5.70 / 3.10
 *   640x480        1,479,060      600,271      2.5x         4.81 / 1.95
 *   Lower bound of the method: 9 single-issue ALU ops per two pixels (4.5 per pixel) over the
 *   rows it must scan; measured 1.07, 1.03 and 1.13 times that bound. The C walks each column
 *   only up to its boundary, the assembly walks whole rows (contiguous loads, two columns per
 *   op) and stops when every column (of a 64-column strip, in frames wider than 320) is decided.
 *   Modelled (--timing bf537, mask and rows in SDRAM as the bench places them): 160x120
 *   69,026 (1.18x the bound of 3.04 per pixel), 320x240 256,806 (1.11x of 3.00), 640x480
 *   753,936 (1.25x of 1.96). The mask's rows come from SDRAM by memory DMA (bvb/dma.h) into
 *   two band buffers on the stack (L1 bank B, at most 1 KB each: 3 rows a band at 320 wide,
 *   6 at 160, 16 of a 64-column strip), bottom band first, the band above in flight while one
 *   is scanned; a mask already in L1 is read where it is. The bus does not bind: a byte a
 *   pixel at 0.5 byte per core cycle, 2 cycles against the scan's 4.5. Where the rest goes
 *   at 320x240: 236,722 issued (the method's 9 per pair over the rows scanned, the bound),
 *   the per-band work (wait, re-address, start: some 200 cycles a band, 53 bands) and the
 *   first band's transfer before the scan starts, and the final pass. Before: 321,501, of
 *   which 39,731 were L1 sub-bank collisions (the rows[] load and store of one issue, and the
 *   mask byte beside a rows[] access; now at most one rows[] access an issue and none beside
 *   the first-column mask load) and 43,752 data-cache line fills of the mask.
 *   Coherence on the chip: the mask must be in SDRAM when the DMA reads it (made by DMA, as
 *   seg_avoid's map is, erode3x3_u8's output, or written back from the data cache first).
 *
 * In the segmentation obstacle avoidance pipeline (seg_avoid; scenes boxes_approach, boxes_turn,
 * cylinders_mover, 25 frames each) the two kernels take a frame from 2.31-2.66M cycles on average
 * (max 2.78M) to 0.61-0.68M (max 0.70M) at 160x120, and from 9.16-10.54M (max 11.00M) to
 * 2.32-2.58M (max 2.66M) at 320x240, with the same decisions and outputs in every frame.
 *
 * Working set: region_grow touches the image, the mask and the queue (4 bytes per queued pixel,
 * up to 4 * width * height; a FIFO, so in practice a band about as long as the growing front)
 * in whatever memory the caller gives; its state lives in registers and 80 bytes of stack.
 * free_space reads the mask once per scanned row and keeps its state in rows[] (L1 on hardware
 * for the per-row re-reads); 2.3 KB of stack (the band buffers, the DMA job). */

#include "bvb/asm.h"
#include "bvb/dma.h"

	.section .l1.text, "ax"

/* ---- bvb_free_space_asm ----
 * Rows from the bottom up, two columns per vector op. rows[] holds each column's state while
 * the rows are walked (int16):
 *   S >= -1   the column is still open: S is the bottom row of the zero run the current row
 *             would continue (the row below's row number minus one after a non-zero pixel);
 *   S <= -2   the column is decided: S = boundary - 32768.
 * Per pixel (row y, mask byte m):
 *   S1 = min(S, m ? y - 1 : 32767)      a floor pixel restarts the run one row higher; a
 *                                        decided column (negative) is left as it is
 *   if S1 >= y + min_gap - 1 (or y == 0): S = S1 ^ 0x8000   the run is long enough (or reaches
 *                                        row 0): decided, boundary S1
 * The threshold test is the sign of the saturated difference, masked into the flip, so no
 * branch and no CC per pixel. An open column never reaches a value that looks decided, and a
 * decided one never passes the test again. After the last row (or once every column is decided)
 * a pass turns S back into boundaries: decided -> S ^ 0x8000, open (-1) -> -1.
 * Limit: height <= 32767 (boundaries are int16). */

/* The frame: outgoing argument space, the band state, one DMA transfer and job, two band
 * buffers of at most FS_BAND_BYTES each (in L1 bank B with the stack). */
#define FS_BAND_BYTES 1024
#define F_DMA 12	/* 1: the mask's rows come in by DMA */
#define F_LEFT 16	/* rows of the current band still to scan */
#define F_Y 20		/* y across the calls */
#define F_NEXTY 24	/* rows 0 .. F_NEXTY - 1 of the strip are still to fetch */
#define F_B 28		/* rows a band */
#define F_SW 32		/* the strip's columns */
#define F_COL 36	/* the strip's column in row 0 of the mask */
#define F_STRIDE 40
#define F_PREP 44	/* the prepared transfer's shape: columns << 5 | rows (0: none) */
#define F_INFL 48	/* rows of the band in flight */
#define F_PEND 52	/* 1 while a job is outstanding */
#define F_CUR 56	/* the band buffer being scanned */
#define F_OTHER 60	/* the other */
#define F_FRETS 64	/* .Lfs_fetch's return address */
#define F_FBUF 68	/* .Lfs_fetch's buffer */
#define F_MASK 72
#define F_NRETS 212
#define F_WIDTH 76
#define F_X 80		/* struct bvb_dma_xfer, 24 bytes */
#define F_JOB 104	/* BVB_DMA_JOB_BYTES = 112 */
#define F_BUF0 216	/* F_NRETS at 212 */
#define F_BUF1 (F_BUF0 + FS_BAND_BYTES)
#define FS_LOC (F_BUF1 + FS_BAND_BYTES)
#define FS_HEIGHT (40 + 4 + FS_LOC)
#define FS_MINGAP (44 + 4 + FS_LOC)
#define FS_ROWS (48 + 4 + FS_LOC)

BVB_FUNC bvb_free_space_asm
	[--sp] = (r7:4, p5:3);
	[--sp] = rets;
	p0 = FS_LOC (z);
	sp -= p0;
	cc = r2 <= 0;
	if cc jump .Lfs_ret;
	p5 = r1;			/* mask stride */
	[sp + F_STRIDE] = r1;
	[sp + F_X + DMAX_SS] = r1;
	[sp + F_COL] = r0;
	[sp + F_MASK] = r0;
	[sp + F_WIDTH] = r2;
	/* Mask rows by DMA when the mask starts in SDRAM (through the data cache its line fills
	 * cost 16% of the call at 320x240); the first band, the bottom rows, is the one whose
	 * transfer DMA could refuse (the mask ending past SDRAM): then the direct path. */
	r3.l = 0x0000;
	r3.h = 0x0200;
	cc = r0 < r3 (iu);
	r4 = cc;
	[sp + F_DMA] = r4;
	r4 = 0;
	[sp + F_PEND] = r4;
	[sp + F_PREP] = r4;
.Lfs_restart:
	[sp + F_COL] = r0;
	p5 = r1;
	r3 = [sp + FS_HEIGHT];
	p4 = [sp + FS_ROWS];
	r5 = [sp + FS_MINGAP];
	/* open every column: S = height - 1 (no rows: -1, the answer) */
	r6 = r1;
	r1 = r3;
	r1 += -1;
	cc = r3 <= 0;
	r7 = -1;
	if cc r1 = r7;
	p1 = r1;			/* y, from the bottom row */
	p0 = p4;
	p2 = r2;
	lsetup (.Lfs_init, .Lfs_init) lc0 = p2;
.Lfs_init:
	w[p0++] = r1;
	if cc jump .Lfs_ret;
	b1 = r1;			/* height - 1 */
	/* bottom row: mask + (height - 1) * stride */
	r1 *= r6;
	r0 = r0 + r1;
	i3 = r0;			/* the strip's bottom-left pixel */
	i2 = p4;			/* rows */
	b2 = r2;			/* width */
	b3 = r2;			/* columns left for the strips */
	/* strips of 64 columns in frames wider than 320, else one strip: the per-row set-up of
	 * narrow strips costs more than the rows they skip in small frames */
	r1 = 320;
	cc = r1 < r2;
	r1 = 64;
	if !cc r1 = r2;
	m3 = r1;
	/* rows a band: as many strip rows as fit FS_BAND_BYTES, 1 to 16 */
	r0 = 1;
	r3 = r1;
	p0 = 15;
	r2 = FS_BAND_BYTES (z);
	lsetup (.Lfs_b0, .Lfs_b1) lc0 = p0;
.Lfs_b0:
	r3 = r3 + r1;
	cc = r3 <= r2;
	r6 = cc;
.Lfs_b1:
	r0 = r0 + r6;
	[sp + F_B] = r0;
	/* G = min(min_gap - 1, 32767) */
	r5 += -1;
	r1 = 32767 (x);
	r5 = min (r5, r1);
	r5 = pack (r5.l, r5.l);
	m0 = r5;
	r0.l = 1;
	r0.h = 1;
	b0 = r0;
	r7.l = 0x7fff;
	r7.h = 0x7fff;
	r4.l = 0x8000;
	r4.h = 0x8000;

	/* Strips of columns, each walked up only until its own columns are all decided. */
.Lfs_strip:
	r0 = b3;
	r1 = m3;
	r1 = min (r0, r1);
	r0 = r0 - r1;
	b3 = r0;
	/* pairs - 1 in m2 (-1: none), the odd column flag in m1 */
	r0 = 1;
	r0 = r1 & r0;
	m1 = r0;
	r1 >>= 1;
	r1 += -1;
	m2 = r1;
	p3 = i3;
	r0 = b1;
	r0 += 2;
	[sp + F_LEFT] = r0;		/* the direct path never reaches the end of a band */
	r0 = [sp + F_DMA];
	cc = r0 == 0;
	if cc jump .Lfs_rows;
	/* bands from the bottom: the first in and waited for, the second started */
	r1 = m2;			/* the strip's columns: 2 (pairs - 1 + 1) + odd */
	r1 += 1;
	r1 <<= 1;
	r0 = m1;
	r1 = r1 + r0;
	[sp + F_SW] = r1;
	[sp + F_X + DMAX_DS] = r1;
	[sp + F_X + DMAX_W] = r1;
	p5 = r1;			/* rows in L1 are the strip's width apart */
	r0 = b1;
	r0 += 1;
	[sp + F_NEXTY] = r0;
	r0 = F_BUF0 (z);
	r1 = sp;
	r0 = r0 + r1;
	[sp + F_OTHER] = r0;
	r1 = FS_BAND_BYTES (z);
	r1 = r0 + r1;
	[sp + F_CUR] = r1;
	call .Lfs_fetch;
	call .Lfs_next;
.Lfs_rows:
	p1 = b1;			/* y */
	r0 = b1;
	r6 = pack (r0.l, r0.l);
	r0 += 1;
	p2 = r0;
	lsetup (.Lfs_row, .Lfs_row_end) lc1 = p2;
.Lfs_row:
	/* per-row constants, both lanes: y - 1, and the threshold minus one, y - 1 + G saturated
	 * (row 0: y - 1 = -1, any zero decides) */
	r1 = b0;
	r6 = r6 -|- r1;
	r1 = m0;
	r5 = r6 +|+ r1 (s);
	cc = p1 == 0;
	if cc r5 = r6;
	r3 = r4;
	i0 = p4;
	i1 = p4;
	p0 = p3;
	p2 = m2;
	cc = p2 < 0;
	if cc jump .Lfs_odd;
	/* first pair's loads; the loop loads one pair ahead */
	/* At most one access of rows[] per instruction, and none beside the first-column mask
	 * load: the loads and stores of rows[] (int16, at any even address) and of the mask
	 * meet in one sub-bank as often as not (L1 sub-bank collisions, --timing bf537). */
	r1 = b[p0++] (z);
	r0 = b[p0++] (z);
	r0 = pack (r0.l, r1.l);
	cc = p2 == 0;
	if cc jump .Lfs_last;
	lsetup (.Lfs_pair, .Lfs_pair_end) lc0 = p2;
.Lfs_pair:
	r0 = r0 << 15 (v, s) || r2.l = w[i0++];
	r0 = r7 -|- r0 || r2.h = w[i0++];
	r0 = r6 +|+ r0 (s) || r1 = b[p0++] (z);
	r2 = min (r2, r0) (v);
	r0 = r5 -|- r2 (s);
	r0 = r0 & r4;
	r2 = r2 ^ r0;
	r3 = max (r3, r2) (v) || r0 = b[p0++] (z) || w[i1++] = r2.l;
.Lfs_pair_end:
	r0 = pack (r0.l, r1.l) || w[i1++] = r2.h;
.Lfs_last:
	r0 = r0 << 15 (v, s) || r2.l = w[i0++];
	r0 = r7 -|- r0 || r2.h = w[i0++];
	r0 = r6 +|+ r0 (s);
	r2 = min (r2, r0) (v);
	r0 = r5 -|- r2 (s);
	r0 = r0 & r4;
	r2 = r2 ^ r0;
	r3 = max (r3, r2) (v) || w[i1++] = r2.l;
	w[i1++] = r2.h;
.Lfs_odd:
	r0 = m1;
	cc = r0 == 0;
	if cc jump .Lfs_row_tail;
	r0 = b[p0] (z);
	r2.l = w[i0];
	r2.h = w[i0];
	r0 = pack (r0.l, r0.l);
	r0 = r0 << 15 (v, s);
	r0 = r7 -|- r0;
	r0 = r6 +|+ r0 (s);
	r2 = min (r2, r0) (v);
	r0 = r5 -|- r2 (s);
	r0 = r0 & r4;
	r2 = r2 ^ r0;
	r3 = max (r3, r2) (v) || w[i1] = r2.l;
.Lfs_row_tail:
	/* every column of the strip decided (both lanes of the running max negative): stop */
	r0 = r3 & r4;
	cc = r0 == r4;
	if cc jump .Lfs_strip_end;
	p3 -= p5;
	r0 = [sp + F_LEFT];
	r0 += -1;
	[sp + F_LEFT] = r0;
	cc = r0 == 0;
	if cc jump .Lfs_switch;
.Lfs_row_end:
	p1 += -1;
.Lfs_strip_end:
	call .Lfs_wait;			/* a band still in flight when the strip ended early */
	r0 = [sp + F_COL];
	r0 += 32;
	r0 += 32;
	[sp + F_COL] = r0;
	r0 = i3;
	r0 += 32;
	r0 += 32;
	i3 = r0;
	p4 += 32;
	p4 += 32;
	p4 += 32;
	p4 += 32;
	r0 = b3;
	cc = r0 == 0;
	if !cc jump .Lfs_strip;
	lc1 = r0;
	jump.s .Lfs_decode;

	/* The band's last row is scanned: the next band (in flight) is waited for and scanned
	 * from its last row, and the one above it is started into the buffer just left. */
.Lfs_switch:
	r0 = [sp + F_PEND];
	cc = r0 == 0;
	if cc jump .Lfs_row_end;	/* row 0 was the last */
	[sp + F_Y] = p1;
	call .Lfs_next;
	p1 = [sp + F_Y];
	jump .Lfs_row_end;

	/* Waits for the band in flight, makes it the current one (P3 at its last row, F_LEFT
	 * its rows), starts the next into the other buffer. Clobbers R0-R3, P0-P2. */
.Lfs_next:
	r0 = rets;
	[sp + F_NRETS] = r0;
	call .Lfs_wait;
	r0 = [sp + F_CUR];
	r1 = [sp + F_OTHER];
	[sp + F_CUR] = r1;
	[sp + F_OTHER] = r0;
	r0 = [sp + F_INFL];
	[sp + F_LEFT] = r0;
	r0 += -1;
	r2 = [sp + F_SW];
	r0 *= r2;
	r0 = r0 + r1;
	p3 = r0;
	r0 = [sp + F_NEXTY];
	cc = r0 == 0;
	if cc jump .Lfs_sw_done;
	r0 = [sp + F_OTHER];
	call .Lfs_fetch;
.Lfs_sw_done:
	r0 = [sp + F_NRETS];
	rets = r0;
	rts;

	/* Waits for the job in flight, if any. Clobbers R0, P2. */
.Lfs_wait:
	r0 = [sp + F_PEND];
	cc = r0 == 0;
	if cc jump .Lfs_w_ret;
	r0 = 0;
	[sp + F_PEND] = r0;
	r0 = rets;
	[sp + F_FRETS] = r0;
	call _bvb_dma_wait;
	r0 = [sp + F_FRETS];
	rets = r0;
.Lfs_w_ret:
	rts;

	/* Starts the next band up (F_B rows or what is left below F_NEXTY) into the buffer at
	 * r0: the slot only re-addressed when its shape is the one prepared. Clobbers R0-R3,
	 * P0-P2. DMA refuses none of these transfers (the whole mask was found reachable, the
	 * counts are at most the first band's); should it, the core copies the band. */
.Lfs_fetch:
	[sp + F_FBUF] = r0;
	[sp + F_X + DMAX_DST] = r0;
	r0 = rets;
	[sp + F_FRETS] = r0;
	r1 = [sp + F_NEXTY];
	r2 = [sp + F_B];
	r2 = min (r1, r2);
	[sp + F_INFL] = r2;
	[sp + F_X + DMAX_ROWS] = r2;
	r1 = r1 - r2;
	[sp + F_NEXTY] = r1;
	r3 = [sp + F_STRIDE];
	r1 *= r3;
	r3 = [sp + F_COL];
	r1 = r1 + r3;
	[sp + F_X + DMAX_SRC] = r1;
	r1 = [sp + F_SW];
	r1 <<= 5;
	r1 = r1 | r2;
	r3 = [sp + F_PREP];
	cc = r1 == r3;
	[sp + F_PREP] = r1;
	r2 = sp;
	r0 = F_JOB (z);
	r0 = r0 + r2;
	r1 = F_X (z);
	r2 = r2 + r1;
	r1 = 0;
	if cc jump .Lff_move;
	call _bvb_dma_prepare;
	cc = r0 == 0;
	if !cc jump .Lff_core;
	jump.s .Lff_start;
.Lff_move:
	call _bvb_dma_move;
.Lff_start:
	r1 = sp;
	r0 = F_JOB (z);
	r0 = r0 + r1;
	r1 = 1;
	call _bvb_dma_start;
	r0 = 1;
	[sp + F_PEND] = r0;
.Lff_ret:
	r0 = [sp + F_FRETS];
	rets = r0;
	rts;
.Lff_core:
	/* DMA refused: the whole call again on the direct path (none of the counts can grow
	 * past the first band's, so in practice only the first transfer can be refused) */
	r0 = 0;
	[sp + F_DMA] = r0;
	r0 = [sp + F_MASK];
	r1 = [sp + F_STRIDE];
	r2 = [sp + F_WIDTH];
	jump .Lfs_restart;

.Lfs_decode:
	r2.l = 0x8000;
	r2.h = 0xffff;
	p0 = i2;
	p2 = b2;
	lsetup (.Lfs_dec, .Lfs_dec_end) lc0 = p2;
.Lfs_dec:
	r0 = w[p0] (x);
	cc = r0 == -1;
	r1 = r0 ^ r2;
	if !cc r0 = r1;
.Lfs_dec_end:
	w[p0++] = r0;
.Lfs_ret:
	p0 = FS_LOC (z);
	sp = sp + p0;
	rets = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;
BVB_ENDFUNC bvb_free_space_asm

/* ---- bvb_region_grow_asm ---- */

/* Locals (below the saved registers); the first ones are within reach of the 16-bit loads and
 * stores that ride in parallel slots. */
#define L_CAP 0
#define L_TOL 4
#define L_BBMIN 8		/* (min_y << 16) | min_x */
#define L_BBMAX 12		/* (max_y << 16) | max_x */
#define L_MBASE 16
#define L_IBASE 20
#define L_FREE 24		/* unused (the constant 1 I2 reads is .Lrg_one, in bank A) */
#define L_DROP 28
#define L_W1 32			/* width - 1 */
#define L_H1 36			/* height - 1 */
#define L_K 40			/* 9 words: the packed (y << 16) | x offset of each neighbour */
#define L_STRIDES 76		/* (img_stride << 16) | mask_stride, read through I3 */
#define L_SIZE 80
/* Arguments: 32 bytes of saved registers, then the locals. */
#define RG_MSTRIDE (L_SIZE + 44)
#define RG_WIDTH (L_SIZE + 48)
#define RG_HEIGHT (L_SIZE + 52)
#define RG_PARAMS (L_SIZE + 56)
#define RG_QUEUE (L_SIZE + 60)
#define RG_QCAP (L_SIZE + 64)
#define RG_STATS (L_SIZE + 68)

/* Register use in the growing loop:
 *   R0 the pixel taken from the queue, (y << 16) | x      R4 count  R5 sum  R6 tol * count
 *   R7 (img_stride << 16) | mask_stride for the address multiply, then scratch  R1-R3 scratch
 *   P0 its image byte, P1 its mask byte, P4 -mask_stride, P5 -img_stride, P2/P3 the row above
 *   or below, FP queued entries, I0/I1 queue head/tail (circular, B0/L0, B1/L1), I2 -> the
 *   constant 1 (bank A), I3 -> the packed strides, A0/A1 sum_x/sum_y.
 * While growing, the mask marks the frame's border pixels: 1 = border, not in the region,
 * 254 = border, in the region (interior: 0 / 255). A neighbour is free when its byte is < 2, it
 * joins as ~byte (0 -> 255, 1 -> 254), and a pixel taken from the queue whose own byte is even
 * is on the border, where each neighbour is first checked against the frame. The border bytes
 * are turned back into 0 / 255 at the end. */

/* Join: R1 = the neighbour's mask byte, R3 = its intensity, R2 = its (y << 16) | x; \mark is the
 * store of ~R1 to its mask byte. Count, sum and tol * count stay in registers; the bounding box
 * (two packed min / max) in memory, its loads and stores riding with the ALU ops; sum_x and sum_y
 * accumulate in A0 / A1 (x, y < 2^15). */
.macro JOIN tag, back, mark, bb=3
	r1 = ~r1;
	\mark
	r5 = r5 + r3 (ns) || r3 = [sp + L_TOL] || r1 = [i2];
	r6 = r6 + r3 (ns) || r3 = [sp + L_BBMIN];
	a1 += r2.h * r1.l, a0 += r2.l * r1.l (is) || p3 = [sp + L_CAP];
	r4 = r4 + r1 (ns) || r1 = [sp + L_BBMAX];
	.if \bb & 1
	r3 = min (r3, r2) (v);
	.endif
	.if \bb & 2
	r1 = max (r1, r2) (v) || [sp + L_BBMIN] = r3;
	[sp + L_BBMAX] = r1;
	.else
	[sp + L_BBMIN] = r3;
	.endif
	cc = fp < p3;
	if !cc jump .Ldrop_\tag;
	[i1++] = r2;
	fp += 1;
	jump \back;
.Ldrop_\tag:
	r1 = [sp + L_DROP];
	r1 += 1;
	[sp + L_DROP] = r1;
	jump \back;
.endm

/* The up neighbour of a pixel whose left, right and down neighbours are in the region already
 * (growing upwards, the common case by far): tested and joined in line. P2 = its mask byte, R3
 * its intensity. Taking the pixel from the queue freed a slot and this is the first join since,
 * so the queue has room. */
.macro UP_INLINE tag, mul
	.if \mul
	r2 = r3.l * r4.l (fu) || r1 = b[p2] (z);
	.else
	r1 = b[p2] (z);
	r2 = r3;
	r2 *= r4;
	.endif
	r2 = r2 - r5 (ns) || r7 = [sp + L_K + 4];
	r2 = abs r2;
	cc = r1 < 2;
	if !cc jump .Lb_\tag;
	cc = r2 <= r6;
	if !cc jump .Lb_\tag;
	r2 = r0 + r7 (ns);
	r1 = ~r1;
	b[p2] = r1;
	r5 = r5 + r3 (ns) || r3 = [sp + L_BBMIN] || r1 = [i2];
	r3 = min (r3, r2) (v) || [i1++] = r2;
	a1 += r2.h * r1.l, a0 += r2.l * r1.l (is) || [sp + L_BBMIN] = r3;
	r4 = r4 + r1 (ns) || r3 = [sp + L_TOL];
	r6 = r6 + r3 (ns);
	fp += 1;
.Lb_\tag:
.endm

/* The tolerance test of a free neighbour, intensity in R3: |I * count - sum| <= tol * count.
 * \mul 1: frames of at most 65535 pixels, count < 2^16: one 16 x 16 unsigned multiply. */
.macro TOLTEST back, mul
	.if \mul
	r2 = r3.l * r4.l (fu);
	.else
	r2 = r3;
	r2 *= r4;
	.endif
	r2 = r2 - r5 (ns);
	r2 = abs r2;
	cc = r2 <= r6;
	if !cc jump \back;
.endm

/* One neighbour, at row offset \row (-1, 0, 1) and column offset \col, of the pixel in R0 (P0,
 * P1). \chk: 1 = check it against the frame first (the pixel is on the border). */
.macro NB tag, row, col, chk
	.if \chk
	  .if \col == -1
	r1 = r0.l (z);
	cc = r1 == 0;
	if cc jump .Lb_\tag;
	  .endif
	  .if \col == 1
	r1 = r0.l (z);
	r2 = [sp + L_W1];
	cc = r1 < r2;
	if !cc jump .Lb_\tag;
	  .endif
	  .if \row == -1
	r1 = r0 >> 16;
	cc = r1 == 0;
	if cc jump .Lb_\tag;
	  .endif
	  .if \row == 1
	r1 = r0 >> 16;
	r2 = [sp + L_H1];
	cc = r1 < r2;
	if !cc jump .Lb_\tag;
	  .endif
	.endif
	.if \row == 0
	r1 = b[p1 + \col\()] (z);
	.endif
	.if \row == -1
	p2 = p1 + p4;
	r1 = b[p2 + \col\()] (z);
	.endif
	.if \row == 1
	p2 = p1;
	p2 -= p4;
	r1 = b[p2 + \col\()] (z);
	.endif
	cc = r1 < 2;
	if cc jump .Lv_\tag;
.Lb_\tag:
.endm

/* The out-of-line visit of a free neighbour (P2 is still its row's mask pointer). */
.macro NBV tag, row, col, mul
.Lv_\tag:
	.if \row == 0
	r3 = b[p0 + \col\()] (z);
	.endif
	.if \row == -1
	p3 = p0 + p5;
	r3 = b[p3 + \col\()] (z);
	.endif
	.if \row == 1
	p3 = p0;
	p3 -= p5;
	r3 = b[p3 + \col\()] (z);
	.endif
	TOLTEST .Lb_\tag, \mul
	r2 = [sp + L_K + 12 * \row + 4 * \col + 16];
	r2 = r0 + r2 (ns);
	/* a join can only lower the box's minimum where it steps left or up, raise its maximum
	 * where it steps right or down */
	.set bb_\tag, 3
	.if \row + \col < 0
	.set bb_\tag, 1
	.endif
	.if \row + \col > 0
	.set bb_\tag, 2
	.endif
	.if \row == 0
	JOIN \tag, .Lb_\tag, "b[p1 + \col\()] = r1;", bb_\tag
	.else
	JOIN \tag, .Lb_\tag, "b[p2 + \col\()] = r1;", bb_\tag
	.endif
.endm

.macro NEIGHBOURS pre, conn, chk
	NB \pre\()l, 0, -1, \chk
	NB \pre\()r, 0, 1, \chk
	NB \pre\()u, -1, 0, \chk
	NB \pre\()d, 1, 0, \chk
	.if \conn == 8
	NB \pre\()ul, -1, -1, \chk
	NB \pre\()ur, -1, 1, \chk
	NB \pre\()dl, 1, -1, \chk
	NB \pre\()dr, 1, 1, \chk
	.endif
.endm

.macro NEIGHBOURS_V pre, conn, mul
	NBV \pre\()l, 0, -1, \mul
	NBV \pre\()r, 0, 1, \mul
	NBV \pre\()u, -1, 0, \mul
	NBV \pre\()d, 1, 0, \mul
	.if \conn == 8
	NBV \pre\()ul, -1, -1, \mul
	NBV \pre\()ur, -1, 1, \mul
	NBV \pre\()dl, 1, -1, \mul
	NBV \pre\()dr, 1, 1, \mul
	.endif
.endm

/* The loop over the queue, for connectivity \conn (\mul as in TOLTEST). R0 holds the next
 * entry, R7 the packed strides and P2 width * height + 1 on entry. */
.macro GROW conn, mul
.Lstart\conn\mul:
	/* a hardware loop: at most width * height pixels are ever taken from the queue (P2) */
	lsetup (.Lloop\conn\mul, .Lloop_end\conn\mul) lc0 = p2;
.Lloop\conn\mul:
	/* the bases are added in data registers, so that each pointer is moved into its P
	 * register once and used five cycles later (no move-to-address stall) */
	r3 = r0.h * r7.h, r2 = r0.h * r7.l (is) || r7 = [sp + L_MBASE];
	r1 = r0.l (z);
	r2 = r2 + r1 (ns);
	r2 = r2 + r7 (ns) || r7 = [sp + L_IBASE];
	p1 = r2;
	r3 = r3 + r1 (ns);
	r3 = r3 + r7 (ns);
	p0 = r3;
	fp += -1;
	r1 = b[p1] (z);
	cc = bittst (r1, 0);
	if !cc jump .Lto_border\conn\mul;
	/* left, right and down all in the region: only the up neighbour can join */
	p3 = p1;
	p3 -= p4;
	r1 = b[p1 + -1] (z);
	r2 = b[p1 + 1] (z);
	p2 = p1 + p4;
	r1 = min (r1, r2) (v) || r2 = b[p3] (z);
	p3 = p0 + p5;
	r1 = min (r1, r2) (v) || r3 = b[p3] (z);
	cc = bittst (r1, 7);
	if !cc jump .Lgeneral\conn\mul;
	UP_INLINE u\conn\mul, \mul
	.if \conn == 8
	NB uul\conn\mul, -1, -1, 0
	NB uur\conn\mul, -1, 1, 0
	NB udl\conn\mul, 1, -1, 0
	NB udr\conn\mul, 1, 1, 0
	.endif
.Lnext\conn\mul:
	cc = fp == 0;
	if cc jump .Lexit\conn\mul;
.Lloop_end\conn\mul:
	mnop || r7 = [i3] || r0 = [i0++];
.Lexit\conn\mul:
	jump.l .Lrg_done;
.Lto_border\conn\mul:
	jump.l .Lborder\conn\mul;
	.if \conn == 8
	NBV uul\conn\mul, -1, -1, \mul
	NBV uur\conn\mul, -1, 1, \mul
	NBV udl\conn\mul, 1, -1, \mul
	NBV udr\conn\mul, 1, 1, \mul
	.endif
.Lgeneral\conn\mul:
	NEIGHBOURS f\conn\mul, \conn, 0
	jump.l .Lnext\conn\mul;
	NEIGHBOURS_V f\conn\mul, \conn, \mul
.Lborder\conn\mul:
	NEIGHBOURS e\conn\mul, \conn, 1
	jump.l .Lnext\conn\mul;
	NEIGHBOURS_V e\conn\mul, \conn, \mul
.endm

	.section .l1.data.a, "aw"
	.align 4
.Lrg_one:
	.int 1

BVB_FUNC bvb_region_grow_asm
	[--sp] = (r7:4, p5:3);
	[--sp] = fp;
	/* The 16-bit address multiplies need strides and sizes in 0 .. 2^15 - 1: anything else
	 * (1-pixel-high or -wide frames beyond that, negative strides) and empty frames go to the
	 * C reference. */
	r3 = [sp + 44];
	r3 = r3 | r1;
	r4 = [sp + 48];
	r3 = r3 | r4;
	r5 = [sp + 52];
	r3 = r3 | r5;
	r3 >>= 15;
	r4 = min (r4, r5);
	cc = r4 == 0;
	if cc jump .Lrg_to_c;
	cc = r3 == 0;
	if cc jump .Lrg_asm;
.Lrg_to_c:
	fp = [sp++];
	(r7:4, p5:3) = [sp++];
	jump.l _bvb_region_grow_c;

.Lrg_asm:
	sp += -40;
	sp += -(L_SIZE - 40);
	[sp + L_IBASE] = r0;
	[sp + L_MBASE] = r2;
	r3 = [sp + RG_MSTRIDE];
	r7 = pack (r1.l, r3.l);
	[sp + L_STRIDES] = r7;
	r0 = -r1;
	p5 = r0;			/* -img_stride */
	r0 = -r3;
	p4 = r0;			/* -mask_stride */
	r4 = [sp + RG_WIDTH];
	r5 = [sp + RG_HEIGHT];
	r0 = r4;
	r0 += -1;
	[sp + L_W1] = r0;
	r0 = r5;
	r0 += -1;
	[sp + L_H1] = r0;
	r0 = pack (r5.l, r4.l);
	[sp + L_BBMIN] = r0;
	r0 = -1;
	[sp + L_BBMAX] = r0;
	r0 = 0;
	[sp + L_DROP] = r0;
	/* neighbour offsets, L_K + 12 * (dy + 1) + 4 * (dx + 1): dy * 0x10000 + dx */
	r0.l = 0;
	r0.h = 1;
	r1 = -1;
	r1 = r1 - r0;
	[sp + L_K] = r1;
	r1 += 1;
	[sp + L_K + 4] = r1;
	r1 += 1;
	[sp + L_K + 8] = r1;
	r1 = -1;
	[sp + L_K + 12] = r1;
	r1 = 0;
	[sp + L_K + 16] = r1;
	r1 = 1;
	[sp + L_K + 20] = r1;
	r1 = r0;
	r1 += -1;
	[sp + L_K + 24] = r1;
	r1 += 1;
	[sp + L_K + 28] = r1;
	r1 += 1;
	[sp + L_K + 32] = r1;
	/* I2 reads the constant 1 from L1 bank A: it is loaded in parallel with a local of the
	 * stack (bank B), so the two never meet in one sub-bank */
	i2.l = .Lrg_one;
	i2.h = .Lrg_one;
	r1 = sp;
	r1 += 40;
	r1 += L_STRIDES - 40;
	i3 = r1;
	p2 = [sp + RG_PARAMS];
	r0 = [p2 + 8];
	[sp + L_TOL] = r0;

	/* mask: 0 inside, 1 on the border */
	p0 = r2;
	p1 = r4;			/* width */
	p3 = r5;			/* height */
	r0 = 0;
	/* each row: bytes up to a word boundary, words, the last bytes */
	lsetup (.Lclr_row, .Lclr_row_end) lc1 = p3;
.Lclr_row:
	p2 = p0;
	r1 = p0;
	r1 = -r1;
	r6 = 3;
	r1 = r1 & r6;
	r1 = min (r1, r4);
	r6 = r4 - r1;
	p1 = r1;
	cc = r1 == 0;
	if cc jump .Lclr_words;
	lsetup (.Lclr_h, .Lclr_h) lc0 = p1;
.Lclr_h: b[p2++] = r0;
.Lclr_words:
	r1 = r6 >> 2;
	p1 = r1;
	cc = r1 == 0;
	if cc jump .Lclr_tail;
	lsetup (.Lclr_w, .Lclr_w) lc0 = p1;
.Lclr_w: [p2++] = r0;
.Lclr_tail:
	r1 = 3;
	r6 = r6 & r1;
	p1 = r6;
	cc = r6 == 0;
	if cc jump .Lclr_row_end;
	lsetup (.Lclr_t, .Lclr_t) lc0 = p1;
.Lclr_t: b[p2++] = r0;
.Lclr_row_end:
	p0 -= p4;
	p1 = r4;			/* width */
	r0 = 1;
	p0 = r2;			/* top row */
	lsetup (.Lbtop, .Lbtop) lc0 = p1;
.Lbtop:	b[p0++] = r0;
	r1 = r5;
	r1 += -1;
	r1 *= r3;
	r1 = r1 + r2;
	p0 = r1;			/* bottom row */
	lsetup (.Lbbot, .Lbbot) lc0 = p1;
.Lbbot:	b[p0++] = r0;
	p0 = r2;			/* left and right columns */
	p2 = p0 + p1;
	p2 += -1;
	lsetup (.Lbside, .Lbside_end) lc0 = p3;
.Lbside:
	b[p0] = r0;
	b[p2] = r0;
	p0 -= p4;
.Lbside_end:
	p2 -= p4;

	/* queue: I0 head, I1 tail, circular over queue_cap entries */
	r0 = [sp + RG_QUEUE];
	r1 = [sp + RG_QCAP];
	[sp + L_CAP] = r1;
	fp = 0;				/* queued */
	b0 = r0;
	i0 = r0;
	b1 = r0;
	i1 = r0;
	r1 <<= 2;
	l0 = r1;
	l1 = r1;

	r4 = 0;
	r5 = 0;
	r6 = 0;
	a1 = a0 = 0;

	/* the seed joins unconditionally if it is inside the frame */
	p2 = [sp + RG_PARAMS];
	r0 = [p2];			/* seed_x */
	r1 = [p2 + 4];			/* seed_y */
	r2 = [sp + L_W1];
	cc = r2 < r0 (iu);
	if cc jump .Lno_seed;
	r2 = [sp + L_H1];
	cc = r2 < r1 (iu);
	if !cc jump .Lseed_in;
.Lno_seed:
	jump.l .Lrg_done;
.Lseed_in:
	r0 = pack (r1.l, r0.l);
	r3 = r0.h * r7.h, r2 = r0.h * r7.l (is);
	r1 = r0.l (z);
	r2 = r2 + r1 (ns);
	r3 = r3 + r1 (ns);
	r1 = [sp + L_MBASE];
	r2 = r2 + r1;
	r1 = [sp + L_IBASE];
	r3 = r3 + r1;
	p2 = r2;
	p3 = r3;
	r1 = b[p2] (z);
	r3 = b[p3] (z);
	r2 = r0;
	JOIN seed, .Lseeded, "b[p2] = r1;"
.Lseeded:
	cc = fp == 0;
	if cc jump .Lno_seed;
	r0 = [sp + RG_WIDTH];
	r1 = [sp + RG_HEIGHT];
	r0 *= r1;
	r1.l = 0;
	r1.h = 1;
	cc = r0 < r1;			/* < 2^16 pixels: count fits the 16-bit multiply */
	r0 += 1;
	p2 = [sp + RG_PARAMS];
	r1 = [p2 + 12];
	p2 = r0;
	r0 = [i0++];
	if !cc jump .Lbig;
	r2 = 8;
	cc = r1 == r2;
	if cc jump .Lgo81;
	jump.l .Lstart41;
.Lgo81:
	jump.l .Lstart81;
.Lbig:
	r2 = 8;
	cc = r1 == r2;
	if cc jump .Lgo80;
	jump.l .Lstart40;
.Lgo80:
	jump.l .Lstart80;

	GROW 4, 1
	GROW 8, 1
	GROW 4, 0
	GROW 8, 0

.Lrg_done:
	r0 = 0;
	lc0 = r0;
	/* border bytes back to 0 / 255: -(byte >> 7) */
	p0 = [sp + L_MBASE];
	r0 = [sp + RG_WIDTH];
	p1 = r0;
	r3 = [sp + RG_HEIGHT];
	p3 = r3;
	p2 = p0;
	lsetup (.Lftop, .Lftop_end) lc0 = p1;
.Lftop:	r0 = b[p2] (z);
	r0 >>= 7;
	r0 = -r0;
.Lftop_end:
	b[p2++] = r0;
	r1 = r3;
	r1 += -1;
	r2 = p4;
	r2 = -r2;
	r1 *= r2;
	r2 = p0;
	r1 = r1 + r2;
	p2 = r1;
	lsetup (.Lfbot, .Lfbot_end) lc0 = p1;
.Lfbot:	r0 = b[p2] (z);
	r0 >>= 7;
	r0 = -r0;
.Lfbot_end:
	b[p2++] = r0;
	p2 = p0 + p1;
	p2 += -1;
	lsetup (.Lfside, .Lfside_end) lc0 = p3;
.Lfside:
	r0 = b[p0] (z);
	r0 >>= 7;
	r0 = -r0;
	b[p0] = r0;
	r0 = b[p2] (z);
	r0 >>= 7;
	r0 = -r0;
	b[p2] = r0;
	p0 -= p4;
.Lfside_end:
	p2 -= p4;

	/* stats */
	p0 = [sp + RG_STATS];
	[p0] = r4;
	[p0 + 4] = r5;
	r0 = [sp + L_BBMIN];
	r1 = r0.l (x);
	[p0 + 8] = r1;
	r1 = r0 >>> 16;
	[p0 + 12] = r1;
	r0 = [sp + L_BBMAX];
	r1 = r0.l (x);
	[p0 + 16] = r1;
	r1 = r0 >>> 16;
	[p0 + 20] = r1;
	r0 = a0 (is);
	[p0 + 24] = r0;
	r1 = a1 (is);
	[p0 + 28] = r1;
	r0 = [sp + L_DROP];
	[p0 + 32] = r0;
	r0 = r4;
	l0 = 0;
	l1 = 0;
	sp += 40;
	sp += L_SIZE - 40;
	fp = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;
BVB_ENDFUNC bvb_region_grow_asm
