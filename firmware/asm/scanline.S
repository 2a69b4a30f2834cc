/* Scan-line profiles and their shift (bvb/scanline.h).
 *
 * scanline_profile_u8: column sums, two rows per pass, then one normalising pass.
 *   Sum pass, per 4 columns of 2 rows: BYTEOP16P adds the 4 bytes of each row into 4 16-bit
 *   sums (the two row words loaded in parallel, through I0 and I1, whose low bits carry each
 *   row's misalignment); two vector adds fold them into the 16-bit column sums in scratch,
 *   loaded and stored in the parallel slots. 3 ops per 8 pixels: 0.375 cycles per pixel.
 *   The first pass adds to a constant word holding rows / 2 in both halves (the rounding
 *   term), an odd row is paired with a word of zeros: I2 and I1 run as 4-byte circular
 *   buffers over those words, so every pass is the same loop.
 *   Normalising pass, per 2 columns: profile = floor((S + rows / 2) * R / 2^24) with
 *   R = ceil(2^24 / rows) (a table built by the assembler), split as R = Rh * 256 + Rl:
 *   A = S * Rl (dual MAC), A >>= 8 (twice), A += S * Rh with truncating extraction of bits
 *   16..31 (exact: the bits dropped by the shift cannot reach bit 24), one shift to bring
 *   the second column down, two byte stores: 5 ops per 2 columns.
 *   Lower bound: 0.375 cycles per pixel of the band plus 2.5 per column.
 *
 * scanline_shift_u8: for each shift, SAA accumulates |p1[i] - p2[i + t]| four bytes per
 *   cycle into the accumulators' four 16-bit lanes (two loads per cycle, misalignment of
 *   either profile absorbed through I0 and I1) after the overlap's first n mod 4 bytes have
 *   been taken one by one; a lone last 4-byte chunk gets one more SAA, the lanes are summed
 *   as signed halves in one instruction while n <= 512 (each lane then holds at most 128 terms
 *   of at most 255, below 2^15) and as unsigned halves with the MACs above (the shifts with
 *   k < w - 512 of windows above 512, that code in .text), and S(t) is compared with the best by
 *   cross-multiplication (out of line: only when S(t) is below the best S, which with the
 *   overlap never growing outwards is needed for f(t) to be below the best f).
 *   p2's words are first copied onto the stack (L1 bank B; w / 4 words, 2 cycles each) when
 *   the profiles' addresses agree in bits 13:12 and neither is in bank B: the two loads of
 *   every SAA then come from different banks
 *   (profiles in SDRAM sit in bank A's data cache, where the model puts two lines in one
 *   sub-bank whenever their address bits 13:12 agree: one collision per SAA before).
 *   Lower bound: (w - |t|) / 4 cycles per shift, the SAA rate (two 4-byte loads and one SAA
 *   per cycle), 19,240 cycles at w = 320, rho = 160. Profiles not in the data cache would
 *   add their 2 w bytes from SDRAM, at most 2 w / 0.5 = 1,280 cycles at w = 320 of line fills;
 *   in the bench and in the odometry (which made them just before) they are in it.
 *
 * Measured (bfbench bench):
 *   profile, band of h / 2 rows (60, 120, 240):
 *     160x120: C 59,566, asm 5,478 (10.9x); 320x240: C 176,686, asm 18,058 (9.8x);
 *     640x480: C 583,726, asm 64,818 (9.0x); bound 4,000 / 15,200 / 59,200.
 *   shift, window = image width, rho = width / 2 (161, 321, 641 shifts):
 *     160x120: C 105,375, asm 13,056 (8.1x); 320x240: C 402,634, asm 35,448 (11.4x);
 *     640x480: C 1,573,222, asm 109,192 (14.4x); bound 4,820 / 19,240 / 76,880 (SAA rate);
 *     about 50 cycles a shift go to set-up, the 0..3 odd bytes, the lane sum and the
 *     comparison. (Before the copy of p2; now 12,190 / 33,635 / 106,378.)
 * Both kernels read their inputs only within the words that hold them (circular buffers over
 * each row or profile). Working set: the profile's 16-bit column sums (scratch, 1.3 KB at 640
 * wide; L1 on hardware); the shift search: a copy of p2 on the stack (w bytes, rounded to words)
 * when the two profiles would share a sub-bank, the rest in registers.
 *
 * Modelled (bfbench bench, --timing bf537):
 *   profile, frames in SDRAM, scratch in L1 bank B: the band's rows come in by memory DMA
 *     through the row-band stream (bvb/stream.h; 16 rows a band at widths up to 384), the sum
 *     pass runs on each band in L1. Bound: the bus, 1 byte per pixel at 0.5 byte per core
 *     cycle (bvb/dma.h), 2.0 cycles per pixel, above the sum pass's 0.375, plus the
 *     normalising pass after the last row (2.5 per column). 160x120 23,327 (bound 19,600),
 *     320x240 82,659 (bound 77,600), 640x480 319,841; the rest: band 0 before the sums start,
 *     the last band's sums after its rows arrive, the stream's per-job cost. Before (frames
 *     through the data cache): 9,038 at 160x120, with the 9.6 KB band still in the data cache
 *     from the monitor's copy into SDRAM (a camera frame never is), and 173,889 at 320x240,
 *     where two rows a pass fall in the same sets of the 2-way cache and lines were filled
 *     again and again.
 *   shift: 160x120 12,186 (2.53x the bound of 4,820), 320x240 33,631 (1.75x of 19,240),
 *     640x480 107,494 (1.40x of 76,880); --timing none 12,190, 33,635, 106,378: no
 *     collisions, no line fills (the profiles are in the data cache), at 640 some 1,100
 *     cycles of instruction-cache fills for the MAC-sum loop in .text (k < w - 512). Before
 *     the one-instruction lane sum: 12,664, 34,589, 107,489; before the copy of p2: 18,050
 *     and 55,042, of which 19,602 were sub-bank collisions of the SAA's two loads. Where the
 *     rest goes at 320x240 (bfbench profile): the SAA loops take 18,880 of the bound's
 *     19,240; each of the 321 shifts costs some 46 cycles more: the n mod 4 odd bytes one by
 *     one (5 cycles a byte and 7 to set up, about 11 a shift on average), the last lone SAA
 *     and its branch (about 5: taken one time in 2, 8 cycles when taken), the lane sum (3),
 *     pointers, loop counts and the SAA loop's set-up (about 12), the branch over the odd
 *     bytes (about 3 on average, taken 1 time in 4), the curve store and the test against
 *     the best (2); 1,976 cycles in all are branch cycles. Toward the bound: a zero-padded
 *     copy of p2 (zeros on both sides) and a running correction of p1's bytes (the bytes the
 *     rounded-up overlap takes in against zeros, one byte more per k, reset every 8 k) make
 *     every shift a whole number of SAA pairs with no odd bytes, no lone SAA and no branch
 *     but the best test: about 12 cycles a shift, 1.2x; the shifts with k < 8 then read p1
 *     past its ends and need p1 padded too, a copy that must sit in another L1 sub-bank than
 *     p2's. L1 code memory (48 KB, nearly full) is the constraint on a second path beside
 *     the present one. */

	.section .rodata
	.align 4
/* ceil(2^24 / rows) for rows = 1..256. */
.Lrecip:
	.set .Ln, 1
	.rept 256
	.long ((1 << 24) + .Ln - 1) / .Ln
	.set .Ln, .Ln + 1
	.endr

#include "bvb/asm.h"
#include "bvb/stream.h"

	.section .l1.text, "ax"

/* Circular buffer over the words holding bytes [ireg, ireg + len): base and length. */
.macro CIRC ireg, breg, lreg, len
	r0 = \ireg;
	r1 = \len;
	r2 = r0 + r1;
	r2 += -1;
	r3 = -4;
	r2 = r2 & r3;
	r3 = r0 & r3;
	r2 = r2 - r3;
	r2 += 4;
	\breg = r3;
	\lreg = r2;
.endm

/* The profile's frame: the C routines' outgoing argument space at [sp], then: */
#define F_ZERO 12	/* a zero word: the partner of an odd row */
#define F_ROUND 16	/* rows / 2 in both halves: the first pass's addend */
#define F_STARTED 20	/* 1 once a pass has written the column sums */
#define F_N 24		/* rows of the chunk being summed */
#define F_ROWS 28
#define F_W 32
#define F_ST 36		/* the stream, after the column sums in the scratch */
#define F_LOC 40
#define A_STRIDE (F_LOC + 32 + 12)	/* past RETS and 7 registers: the 4th argument on */
#define A_PROFILE (A_STRIDE + 4)
#define A_SCRATCH (A_STRIDE + 8)

/* The first pass reads the rounding word instead of column sums (L2 = 4 over it), every
 * later one the sums: I2, B2, L2 for the next pass, from the flag at [sp + F_STARTED]. */
.macro SETSUM
	r0 = [sp + F_STARTED];
	cc = r0 == 0;
	r1 = m0;
	r1 += 4;
	r2 = sp;
	r2 += F_ROUND;
	if cc r1 = r2;
	i2 = r1;
	b2 = r2;
	r3 = 4;
	r2 = 0;
	if !cc r3 = r2;
	l2 = r3;
.endm

/* The sums of r0 rows from P5 (rows P4 apart) into the column sums at M0 + 4 (width M1): an
 * odd row on its own against the zero word, then pairs. Leaves L0-L2 at 0. */
.macro CHUNK id
	[sp + F_N] = r0;
	SETSUM
	r0 = [sp + F_N];
	cc = bittst (r0, 0);
	if !cc jump .Lc_pairs_\id (bp);
	i0 = p5;
	CIRC i0, b0, l0, m1
	r0 = sp;
	r0 += F_ZERO;
	i1 = r0;
	b1 = r0;
	l1 = 4;
	i3 = m0;
	call .Lp_pass;
	p5 = p5 + p4;
	r0 = 1;
	[sp + F_STARTED] = r0;
	SETSUM
.Lc_pairs_\id:
	r0 = [sp + F_N];
	r0 >>= 1;
	cc = r0 == 0;
	if cc jump .Lc_done_\id;
	p0 = r0;
	lsetup (.Lc_row_\id, .Lc_row_end_\id) lc1 = p0;
.Lc_row_\id:
	i0 = p5;
	CIRC i0, b0, l0, m1
	p5 = p5 + p4;
	i1 = p5;
	CIRC i1, b1, l1, m1
	p5 = p5 + p4;
	i3 = m0;
	call .Lp_pass;
	r0 = m0;
	r0 += 4;
	i2 = r0;
.Lc_row_end_\id:
	l2 = 0;
	r0 = 1;
	[sp + F_STARTED] = r0;
.Lc_done_\id:
	l0 = 0;
	l1 = 0;
	l2 = 0;
.endm

/* void bvb_scanline_profile_u8_asm(src, width, rows, stride, profile, scratch) */
BVB_FUNC bvb_scanline_profile_u8_asm
	[--sp] = (r7:4, p5:3);
	[--sp] = rets;
	sp += -F_LOC;
	[sp + F_ROWS] = r2;
	[sp + F_W] = r1;
	p5 = r0;			/* next source row */
	r3 = r1;
	r3 += 7;
	r3 >>= 3;
	p3 = r3;			/* iterations of the sum pass: 8 columns each */
	r3 = r2 >> 1;			/* rows / 2 in both halves: the first pass's addend */
	r4 = r3 << 16;
	r3 = r3 | r4;
	[sp + F_ROUND] = r3;
	r4 = 0;
	[sp + F_ZERO] = r4;
	[sp + F_STARTED] = r4;
	p4 = [sp + A_STRIDE];
	/* Frames in SDRAM and the scratch in L1: the band's rows come in by DMA (bvb/stream.h),
	 * through the stream after the column sums. */
	r0 = [sp + A_SCRATCH];
	r1 <<= 1;			/* 16 ceil(w / 8) + 8 = BVB_SCANLINE_PROFILE_SUMS_BYTES */
	r1 += 15;
	r2 = -16;
	r1 = r1 & r2;
	r1 += 8;
	r0 = r0 + r1;
	[sp + F_ST] = r0;
	p0 = r0;
	[p0 + ST_SRC0] = p5;
	[p0 + ST_SS0] = p4;
	r1 = [sp + F_W];
	[p0 + ST_SB0] = r1;
	[p0 + ST_SB1] = r4;
	[p0 + ST_DB] = r4;
	r1 = [sp + F_ROWS];
	[p0 + ST_ROWS] = r1;
	call _bvb_stream_open;
	cc = r0 == 0;
	if !cc jump .Lp_direct;
.Lp_band:
	r0 = [sp + F_ST];
	call _bvb_stream_next;
	cc = r0 == 0;
	if cc jump .Lp_norm;
	p0 = [sp + F_ST];
	r1 = [sp + A_SCRATCH];
	m0 = r1;
	r1 = [sp + F_W];
	m1 = r1;
	p4 = r1;			/* the band's rows are contiguous */
	p5 = [p0 + ST_IN0];
	CHUNK b
	jump .Lp_band;
.Lp_direct:
	r0 = [sp + A_SCRATCH];
	m0 = r0;
	r0 = [sp + F_W];
	m1 = r0;
	r0 = [sp + F_ROWS];
	CHUNK d
.Lp_norm:
	r0 = [sp + A_SCRATCH];
	m0 = r0;
	r0 = [sp + F_W];
	m1 = r0;
	r0 = [sp + F_ROWS];
	m2 = r0;
	/* R = ceil(2^24 / rows) = Rh * 256 + Rl, Rh at most 0xffff, into r7 = Rh:Rl. */
	p0.l = .Lrecip;
	p0.h = .Lrecip;
	r0 = m2;
	r0 += -1;
	r0 <<= 2;
	p1 = r0;
	p0 = p0 + p1;
	r0 = [p0];
	r1 = r0 >> 8;
	r2.l = 0xffff;
	r2.h = 0;
	r1 = min (r1, r2);
	r2 = r1 << 8;
	r2 = r0 - r2;
	r7 = pack (r1.l, r2.l);
	p1 = [sp + A_PROFILE];
	r0 = m0;
	r0 += 4;
	i2 = r0;
	r0 = m1;
	r0 >>= 1;
	p2 = r0;			/* column pairs */
	r0 = [i2++];
	a1 = r0.h * r7.l, a0 = r0.l * r7.l (fu);
	cc = p2 == 0;
	if cc jump .Lp_odd;
	lsetup (.Ln0, .Ln1) lc0 = p2;
.Ln0:	a0 = a0 >> 8;
	a1 = a1 >> 8;
	r2.h = (a1 += r0.h * r7.h), r2.l = (a0 += r0.l * r7.h) (tfu) || r0 = [i2++];
	r3 = r2 >> 16 || b[p1++] = r2;
.Ln1:	a1 = r0.h * r7.l, a0 = r0.l * r7.l (fu) || b[p1++] = r3;
.Lp_odd:
	r1 = m1;
	cc = bittst (r1, 0);
	if !cc jump .Lp_done (bp);
	a0 = a0 >> 8;
	r2.l = (a0 += r0.l * r7.h) (tfu);
	b[p1++] = r2;
.Lp_done:
	sp += F_LOC;
	rets = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;

	/* One sum pass: rows at I0 and I1 (circular over their words), column sums read at I2
	 * and written at I3 (which starts one pad word early: the pipeline's first store is
	 * a don't-care), P3 iterations of 8 columns. */
.Lp_pass:
	disalgnexcpt || r0 = [i0++] || r2 = [i1++];
	disalgnexcpt || r1 = [i0++] || r3 = [i1++];
	r6 = [i2++];
	lsetup (.Lq0, .Lq1) lc0 = p3;
.Lq0:	(r5, r4) = byteop16p (r1:0, r3:2) || r0 = [i0++] || r2 = [i1++];
	r6 = r6 +|+ r4 || [i3++] = r7 || r7 = [i2++];
	r7 = r7 +|+ r5 || [i3++] = r6 || r6 = [i2++];
	(r5, r4) = byteop16p (r1:0, r3:2) (r) || r1 = [i0++] || r3 = [i1++];
	r6 = r6 +|+ r4 || [i3++] = r7 || r7 = [i2++];
.Lq1:	r7 = r7 +|+ r5 || [i3++] = r6 || r6 = [i2++];
	[i3++] = r7;
	rts;
BVB_ENDFUNC bvb_scanline_profile_u8_asm


/* S(t) for one shift: I0 -> p1[i0], I1 -> p2[i0 + t] (circular over each profile's words),
 * r4 = overlap n, p2 = n >> 3. Result in r5. Uses r0-r3, a0, a1, p0, p1, m3, lc0.
 * The n mod 4 odd bytes are taken first, one by one (I0 and I1 then step past them by the
 * circular DAG arithmetic, so that no read leaves the profiles' words); SAA does the rest.
 * For n < 4 the SAA part reads a word pair and adds nothing. */
.macro SAD_AT id, sum
	r5 = 0;
	r2 = 3;
	r2 = r2 & r4;
	cc = r2 == 0;
	if cc jump .Ls_body_\id;	/* not predicted: 3 overlaps in 4 have odd bytes */
	p0 = i0;
	p1 = i1;
	m3 = r2;
	lc0 = r2;
	lsetup (.Lt0_\id, .Lt1_\id) lc0;
.Lt0_\id:
	r0 = b[p0++] (z);
	r1 = b[p1++] (z);
	r0 = r0 - r1 (ns);
	r0 = abs r0;
.Lt1_\id:
	r5 = r5 + r0;
	i0 += m3;
	i1 += m3;
.Ls_body_\id:
	disalgnexcpt || r0 = [i0++] || r2 = [i1++];
	disalgnexcpt || r1 = [i0++] || r3 = [i1++];
	a1 = a0 = 0;
	cc = p2 == 0;
	if cc jump .Ls_chunks_done_\id;
	lsetup (.Ls0_\id, .Ls1_\id) lc0 = p2;
.Ls0_\id:
	saa (r1:0, r3:2) || r0 = [i0++] || r2 = [i1++];
.Ls1_\id:
	saa (r1:0, r3:2) (r) || r1 = [i0++] || r3 = [i1++];
.Ls_chunks_done_\id:
	cc = bittst (r4, 2);
	if !cc jump .Ls_no4_\id;
	saa (r1:0, r3:2);
.Ls_no4_\id:
	LANESUM_\sum
	r5 = r5 + r0;
.endm

/* The four SAA lanes into r0. Each lane holds at most n / 4 terms of at most 255: for
 * n <= 512 that is below 2^15, and the halves added as signed 16-bit values are exact (one
 * instruction); above, the lanes are unsigned 16-bit sums, added with the MACs. */
.macro LANESUM_fast
	r0 = a1.l + a1.h, r1 = a0.l + a0.h;
	r0 = r0 + r1;
.endm

.macro LANESUM_mac
	r1 = a1, r0 = a0 (fu);
	r2 = 1;
	a1 = r0.h * r2.l, a0 = r0.l * r2.l (fu);
	a1 += r1.h * r2.l, a0 += r1.l * r2.l (fu);
	r0 = (a0 += a1);
.endm

/* Keep shift t if S * n_best < S_best * n (f(t) below the best so far). r5 = S, r4 = n,
 * r6 = S_best, r7 = n_best, p3 = best t. The search runs outwards, so n <= n_best always:
 * S >= S_best then already means f(t) >= f(best), without the products. That is the common
 * case, so it falls through (1 cycle); the products are out of line (KEEP_BODY, after the
 * function's return). */
.macro KEEP_IF_BETTER treg, id
	cc = r5 < r6 (iu);
	if cc jump .Lk_do_\id;
.Lk_back_\id:
.endm

.macro KEEP_BODY treg, id
.Lk_do_\id:
	r0 = r5;
	r0 *= r7;
	r1 = r6;
	r1 *= r4;
	cc = r0 < r1 (iu);
	if cc r6 = r5;
	if cc r7 = r4;
	if cc p3 = \treg;
	jump .Lk_back_\id;
.endm

/* Shifts -k and +k (k = p4 after the increments). */
.macro KBODY id, sum
	p4 += 1;
	p5 += -1;
	r4 += -1;			/* n = w - k for both shifts */
	r0 = r4 >> 3;
	p2 = r0;
	m2 = p4;
	/* t = -k: p1[k..w) against p2[0..w-k). */
	i0 = m0;
	i0 += m2;
	i1 = m1;
	SAD_AT n\id, \sum
	[i2--] = r5;
	KEEP_IF_BETTER p5, n\id
	/* t = +k: p1[0..w-k) against p2[k..w). */
	i0 = m0;
	i1 = m1;
	i1 += m2;
	SAD_AT p\id, \sum
	[i3++] = r5;
	KEEP_IF_BETTER p4, p\id
.endm

/* The shift t = 0 (the first best); sum = the lane sum's kind. */
.macro SEARCH0 id, sum
	r4 = m2;			/* n = w - k, k = 0 */
	r0 = r4 >> 3;
	p2 = r0;
	i0 = m0;
	i1 = m1;
	SAD_AT z\id, \sum
	r6 = r5;
	r7 = r4;
	p3 = 0;
	[i2--] = r5;
	i3 += 4;
.endm

/* void bvb_scanline_shift_u8_asm(p1, p2, w, rho, result, curve) */
BVB_FUNC bvb_scanline_shift_u8_asm
	[--sp] = (r7:4, p5:3);
	[--sp] = fp;
	fp = sp;			/* rho at [fp + 44], result [fp + 48], curve [fp + 52] */
	m0 = r0;			/* p1 */
	m1 = r1;			/* p2 */
	m2 = r2;			/* w */
	/* p2's words onto the stack (L1 bank B), unless p1 or p2 is in bank B already or their
	 * addresses differ in bits 13:12 (the sub-bank in L1 and, the model's assumption, in
	 * the data cache): the search's
	 * dual loads then never meet in one sub-bank (through the data cache, as in SDRAM, both
	 * profiles would be in bank A's cache, often in one sub-bank: 36% of the call). */
	r3 = r0 ^ r1;
	r4 = 0x3000 (z);
	r3 = r3 & r4;
	cc = r3 == 0;
	if !cc jump .Lsh_nocopy;	/* other sub-banks (address bits 13:12) */
	r3 = r0 >> 15;
	r4 = 0x1ff2 (z);
	r4 <<= 4;			/* 0xff900000 >> 15 */
	cc = r3 == r4;
	if cc jump .Lsh_nocopy;
	r3 = r1 >> 15;
	cc = r3 == r4;
	if cc jump .Lsh_nocopy;		/* p2 in bank B already */
	r3 = -4;
	r4 = r1 & r3;
	r5 = r1 + r2;
	r5 += -1;
	r5 = r5 & r3;
	r5 = r5 - r4;
	r5 += 4;			/* bytes of the words holding p2 */
	p0 = r4;
	p1 = r5;
	sp -= p1;
	r5 >>= 2;
	p2 = r5;
	p1 = sp;
	lsetup (.Lsh_cp0, .Lsh_cp1) lc0 = p2;
.Lsh_cp0:
	r0 = [p0++];
.Lsh_cp1:
	[p1++] = r0;
	r0 = m1;
	r3 = 3;
	r0 = r0 & r3;
	r1 = sp;
	r0 = r0 + r1;
	m1 = r0;			/* p2 in its copy, at the same byte offset */
.Lsh_nocopy:
	r4 = 0;
	[--sp] = r4;			/* where the curve goes when there is none */
	i0 = m0;
	CIRC i0, b0, l0, m2
	i1 = m1;
	CIRC i1, b1, l1, m2
	r0 = [fp + 44];			/* rho */
	r1 = m2;
	r1 = r1 - r0;			/* T = w - rho */
	m3 = r1;
	r0 = [fp + 52];			/* curve */
	cc = r0 == 0;
	if !cc jump .Lsh_curve (bp);
	r0 = sp;
	b2 = r0;
	b3 = r0;
	i2 = r0;
	i3 = r0;
	l2 = 4;
	l3 = 4;
	jump.s .Lsh_zero;
.Lsh_curve:
	r1 <<= 2;
	r0 = r0 + r1;			/* &curve[T] */
	i2 = r0;
	i3 = r0;
.Lsh_zero:
	r0 = m3;
	p5 = r0;			/* T (m3 is SAD_AT's) */
	/* Windows above 512: t = 0 and the shifts whose overlap is above 512 take the MAC
	 * lane sum, in .text (SDRAM through the instruction cache); they come back for the rest. */
	r0 = m2;
	r1 = 512 (z);
	cc = r0 <= r1;
	if !cc jump .Lsh_to_big;
	SEARCH0 f, fast
	p0 = p5;			/* the k loop's count */
	p4 = 0;				/* k */
	p5 = 0;				/* -k */
	/* k from p4 + 1 on, p0 steps, r4 = w - p4, p5 = -p4. */
.Lsh_kloop:
	cc = p0 == 0;
	if cc jump .Lsh_done;
	lsetup (.Lsh_k, .Lsh_k_end) lc1 = p0;
.Lsh_k:
	KBODY kf, fast
.Lsh_k_end:
	nop;
.Lsh_done:
	r0 = [fp + 48];			/* result */
	p0 = r0;
	r0 = p3;
	[p0] = r0;
	[p0 + 4] = r6;
	[p0 + 8] = r7;
	l0 = 0;
	l1 = 0;
	l2 = 0;
	l3 = 0;
	sp = fp;
	fp = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;
	KEEP_BODY p5, nkf
	KEEP_BODY p4, pkf
.Lsh_to_big:
	p0.l = .Lsh_big;
	p0.h = .Lsh_big;
	jump (p0);
BVB_ENDFUNC bvb_scanline_shift_u8_asm

	/* w > 512: t = 0 and k = 1..min(T, w - 512), overlaps above 512, with the MAC lane sum. */
	.text
	.align 4
.Lsh_big:
	SEARCH0 m, mac
	r1 = p5;			/* T */
	r0 = m2;
	r2 = 512 (z);
	r0 = r0 - r2;
	r0 = min (r0, r1);		/* at least 1 */
	r1 = r1 - r0;
	[--sp] = r1;			/* the steps left for the fast loop */
	p0 = r0;
	p4 = 0;
	p5 = 0;
	lsetup (.Lsh_km, .Lsh_km_end) lc1 = p0;
.Lsh_km:
	KBODY km, mac
.Lsh_km_end:
	nop;
	r0 = [sp++];
	p0 = r0;
	p1.l = .Lsh_kloop;
	p1.h = .Lsh_kloop;
	jump (p1);
	KEEP_BODY p5, nkm
	KEEP_BODY p4, pkm
