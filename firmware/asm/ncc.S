/* NCC matching (bvb/ncc.h) for the BF537.
 *
 * Cycles (bfbench bench: 32 points on a grid, r = 5 (11x11), s = 8 (289 candidates each), frame 2
 * = frame 1 (uniform noise) moved by (3, -2) plus noise; frames in SDRAM, scratch in L1 bank A).
 * Modelled BF537 cycles (--timing bf537) per call:
 *   160x120: 736,779 = 79.7 per candidate; 320x240: 736,586 = 79.7; 640x480: 737,094 (bound
 *   60.5, 1.32x; the issue's target is 80, 739,840); 737,195, 737,002, 737,510 before pass 1
 *   cleared its S register in a parallel slot of a tail store (13 cycles a point). Where the
 *   320x240 call goes per point (bfbench profile, by routine): MAC pass 17,798 (bound 17,484),
 *   pass 1 1,642, pass 2 795, selection 753 (with its calls and the seed's exact v), template
 *   285, copy program set-up 253, isqrt 252, DMA helpers and bookkeeping ~510, exact v 163,
 *   division 101, score 76, the rest ~400. Before the template of the memory DMA copy was
 *   done by SAA and an unrolled pass (_ncc_template, ncc_template5.inc: ~350 cycles a point
 *   fewer): 748,491, 748,298, 748,806; before the grouped selection sweep (below) and the
 *   radius-5-first MAC dispatch: 752,531, 752,728, 753,238; before memory DMA: 789,535 =
 *   85.4 and 837,089 = 90.5. The per-cause split that follows was measured before the sweep
 *   and template changes: the sweep now tests 4 pairs in 10 single-load issues (was 3 issues
 *   and a sub-bank collision per pair), so its collisions are gone; the template saves
 *   ~350 a point (11,296 in all); the DMA bookkeeping remains.
 *   With memory DMA (below) no point's pixels are read through the data cache, so the count no
 *   longer depends on the frame size. Where the 752,531 went at 160x120 (from the model's
 *   per-cause totals, --timing-report, of the bench's run with this code against the one
 *   before memory DMA, which also count the harness's own work: the split is an estimate
 *   where marked ~): ~725,000 issued for the work itself (as before, 78.4 per candidate),
 *   ~12,500 issued for memory DMA (~390 a point: the DMA helper's move, start and wait, ~150,
 *   and the job bookkeeping here, finding the point after next and the owners of the two
 *   sets, ~240 with calls, returns and taken branches at 5 cycles each), ~3,500 waiting for
 *   the first point's job (850 bytes at 8-bit elements; every later job is over before it is
 *   waited for),
 *   6,678 sub-bank collisions (most of them the selection sweep, 145 a point: it loads both
 *   numerators of a pair, one 8-byte record, in one issue), ~190 system MMR accesses at 8
 *   cycles (DMA start and wait), ~2,000 address-register stalls (per point set-up), and what
 *   still goes through the cache (the points and results arrays). With the banked scratch
 *   layout (bvb/ncc.h) the MAC pass, passes 1 and 2 and the copy program make no same-sub-bank
 *   dual access (in one sub-bank, T' against the search area's copies costs a cycle every
 *   other MAC). What is left above the bound, per point (~19.2 cycles a candidate, ~5,550 a
 *   point): the last column's MACs at 67 a candidate, passes 1 and 2, the DMA bookkeeping
 *   (fewer calls: inline the owner look-up and the job's sources), the sweep and the score.
 * Memory DMA (r = 5, 5 <= s <= 8, both frames in SDRAM, the scratch where DMA reaches; else the
 *   frames are read in place through the cache as before): a job of two transfers per point
 *   (bvb/dma.h) brings its L x L search area of frame 2 and its w x w template of frame 1 into
 *   one of two sets of byte buffers in the scratch's fourth sub-bank. The job for the point
 *   after next is started just before this point's MAC pass (which copies the next point's
 *   bytes, already in L1, into the spare He, Ho), into the set the next point does not use,
 *   and waited for before the next MAC pass: ~3,500 cycles of DMA under ~18,000 of MACs. The
 *   first point's job is waited for at once, the second's runs during the first's passes.
 * Simulator cycles per call (--timing none): 728,644 at 160x120, 728,449 at 320x240, 728,957 at
 *   640x480 (729,060 at 160x120 before the pass 1 change above, 739,940 before the template
 *   change, 738,970 before the sweep change; where the sweep's extra issues go has not been
 *   profiled) (the simulator's untimed DMA
 *   is waited for by polling; before memory DMA 725,345 = 78.4 per candidate); C at -O2:
 *   14,228,829 = 1538.6 per candidate.
 * Lower bound: a candidate is 121 multiply-accumulates and the two MAC units do two a cycle, so
 * 60.5 cycles per candidate (its loads, 121 data words and 61 template words per pair of
 * candidates, fit in the same cycles). The MAC pass runs at that bound for the candidate pairs
 * (121 cycles per pair) and at 67 cycles for each candidate of the last column: 61.2 cycles per
 * candidate on average. The other 17 go to, per point (r = 5, s = 8): pass 1 ~1650 cycles,
 * pass 2 ~790, template ~610 (~350 fewer on the memory DMA path: 31 SAA issues and 218 unrolled),
 * selection sweep ~570, exact v, score and threshold (isqrt,
 * divisions) ~620, the copy program ~200, calls and taken branches ~500 (the sweep's ~570
 * before it was grouped: now ~420 with no collisions).
 * Data dependence: the selection's threshold rejects almost every pair of candidates in three
 * cycles on textured scenes. On smooth real scenes many windows correlate well with the
 * template at many offsets, and each of those costs an exact comparison (~200 cycles): on the
 * Middlebury pairs (RubberWhale, Grove2, Urban2, Dimetrodon, Hydrangea; 48 points, r = 5, s = 8)
 * 256 to 391 cycles per candidate, 4 to 6 times faster than the C reference there.
 * ncc_scoremap (one point, every candidate scored exactly): 166,992 modelled cycles at 160x120
 * (578 per score), 179,685 at 320x240 (622; 13 fewer than before the pass 1 change); 140,537 issued, 23,906 multi-cycle (calls, returns
 * and taken branches: five calls a score), ~400 address-register stalls (one a candidate in
 * _ncc_exactv), no collisions, the rest SDRAM line fills (2,183 at 160x120, 14,876 at
 * 320x240, where the frames are larger than the data cache). Where they go at 320x240
 * (bfbench profile ncc_scoremap --size 320x240, by routine; 289 scores): _ncc_exactv 38,726
 * (134 a score: the window's exact sums of I and I^2 from pass 1's column sums), _ncc_isqrt
 * 29,478 (102: one bit per 5-cycle iteration), _ncc_udiv 27,645 (96: likewise, 17 bits),
 * _ncc_score 21,964 (76) and _ncc_mul64 5,491 (19), the MAC pass 17,730 (61.3 a score, at its
 * bound), the per-score loop 12,201 (42: context loads and stores, the calls), _ncc_build
 * 11,377 (mostly the line fills of the search area), _ncc_num 8,058 (28), the template 4,891,
 * pass 1 1,655. The bench's bound of 60.5 is the MAC pass's alone: an exact score also needs
 * its window's v (a few ops from running sums), a square root and a division (on the order
 * of one cycle a bit each with DIVQ and a two-op root step, some 50 a score), so about 120
 * cycles a score is the bound this method could approach; the step there is a scoring path
 * of its own (running window sums, DIVQ, no calls a score), for which L1 code memory had no
 * room (48 KB; the passes of radii 1 to 4 now run from SDRAM, which frees 2.7 KB). It reads its one point through the cache:
 * memory DMA would wait ~3,500 cycles for it against ~2,300 of line fills at 160x120 (~15,000 at
 * 320x240: the matcher's DMA path, _ncc_dlayout/_ncc_dstart, would save ~11,000 there, at
 * some 60 bytes of code).
 * Working set: the scratch buffer, 14.9 KB for r = 5, s = 8 (L1 data bank A in the bench, frames
 * in SDRAM, read once per point by DMA: a byte per pixel of the search area and of the
 * template). The copy program's P-register loads are used as addresses 6 cycles later (no stall).
 *
 * Per point the work is split into passes over the scratch buffer:
 *   template   T' = N*T - ST (16-bit), flat and with padded rows; vt = N*STT - ST^2
 *   build      the (2s+2r+1)^2 search area of frame 2 as 16-bit pixels, twice: He holds the
 *              pairs (I[2m], I[2m+1]) and Ho the pairs (I[2m+1], I[2m+2]), so that every pair of
 *              horizontally adjacent pixels is one aligned 32-bit load. For r = 5, 5 <= s <= 10
 *              the previous point's MAC pass has already copied it (see the copy program)
 *   pass 1     column sums of the 2r x 2r sub-windows at even coordinates (I, n*I^2)
 *   pass 2     a lower bound of the smallest window variance from those sub-windows
 *   MAC pass   num for every candidate: two horizontally adjacent candidates per dual MAC
 *              (A0 += T'*I[c], A1 += T'*I[c+1] with one 32-bit load of (I[c], I[c+1])), the
 *              last column alone with both MACs on one candidate
 *   select     the exact comparison of bvb/ncc.h, but only where it can matter: a lower bound
 *              tau of num that any candidate must reach to tie or beat the best so far
 *              (tau = num_b * sqrt(vmin / v_b), rounded down) filters pairs of candidates in
 *              three cycles; the best starts as the candidate at the previous point's offset
 *   score      the reported Q15 score of the winner (isqrt and division, once per point).
 * The result is the unique maximum of the total order of bvb/ncc.h, so it does not depend on
 * the order candidates are visited in or on the filter, which only skips exact comparisons
 * that cannot change the best.
 * Two rules of the machine this code keeps: the two halves of a dual MAC share their two source
 * registers, and no parallel store reads a register its own instruction writes (the simulator
 * stores the new value). */
#define CTX_FRAME1 0
#define CTX_FRAME2 4
#define CTX_STRIDE 8
#define CTX_W 12
#define CTX_H 16
#define CTX_R 20
#define CTX_S 24
#define CTX_WT 28     /* w = 2r+1 */
#define CTX_N 32      /* w*w */
#define CTX_L 36      /* side of the search area, 2s+2r+1 */
#define CTX_HEROW 40  /* bytes per row of He and Ho: (L+1)*2 */
#define CTX_HE 44
#define CTX_HO 48     /* word m of row k: (I[2m+1], I[2m+2]) */
#define CTX_TF 52     /* T' flat, N halfwords and a zero */
#define CTX_TP 56     /* T' rows as (0, T'0, ..., T'2r): r+1 words each */
#define CTX_CS2 60    /* 2r-row column sums of I at rows 2k: column c at CS2 + c*KSB, halfword k */
#define CTX_NQ2 64    /* the same for 2*n*sum I^2 (32-bit, exact), n = 4r^2: column c at NQ2 + 2c*KSB */
#define CTX_NP 72     /* num of candidate pairs: (p*(2s+1) + d)*8, lanes e = 2p, 2p+1 */
#define CTX_NS 76     /* num of the last column, e = 2s: word d */
#define CTX_KSB 80    /* 2*KS, KS = s+2 rounded up to even (row k = s+1 repeats k = s) */
#define CTX_NSUB 84   /* n = 4r^2 */
#define CTX_DSH 88    /* 2n = 2^DSH * odd: the shift and */
#define CTX_DINV 156  /* the inverse of odd mod 2^32, to divide exact multiples of 2n */
#define CTX_X 92
#define CTX_Y 96
#define CTX_VT 100
#define CTX_VMIN 104
#define CTX_QMIN 108  /* isqrt(vmin) */
#define CTX_BN 112    /* best so far: num, v, tie key, e, d */
#define CTX_BV 116
#define CTX_BKEY 120
#define CTX_BE 124
#define CTX_BD 128
#define CTX_TAU 132
#define CTX_SEEDX 136 /* the previous point's offset */
#define CTX_SEEDY 140
#define CTX_PTS 144
#define CTX_RES 148
#define CTX_NLEFT 152
#define CTX_T0 160    /* temporaries */
#define CTX_T1 164
#define CTX_T2 168
#define CTX_T3 172
#define CTX_T4 176
#define CTX_T5 180
#define CTX_T6 184
#define CTX_T7 188
#define CTX_T8 192
#define CTX_T9 196
#define CTX_T10 200
#define CTX_T11 204
#define CTX_T12 208
#define CTX_T13 212
#define CTX_T14 216
#define CTX_T15 220
#define CTX_T16 224
#define CTX_T17 228
#define CTX_T18 232
#define CTX_T19 236
#define CTX_HE2 240   /* the spare He, Ho: the next point's search area, copied during this MAC pass */
#define CTX_HO2 244
#define CTX_TAB 248   /* copy program: (source, He destination, Ho destination) per pair of candidates */
#define CTX_PIPE 252  /* 1 when the MAC pass copies the next point's search area (r = 5, 5 <= s <= 10) */
#define CTX_NB 256    /* column pairs whose MAC loop copies */
#define CTX_PRE 260   /* 1 when the spare holds the next point's search area */
#define CTX_RECIP 264 /* ceil(2^16 / (2s+1)) */
#define CTX_NCH 268   /* chunks of the copy program that are real */
#define CTX_DUMMY 272 /* 36 bytes: where the program's idle chunks write (unbanked layout) */
#define CTX_DUMMYP 312 /* the dummy area's address */
#define CTX_SEGB 320  /* the selection sweep's pairs before the seed's column pair */
#define CTX_DMAP 316  /* the DMA area (below), or 0: no memory DMA */
#define CTX_TSRC 324  /* this point's template in L1 (w x w bytes), or 0: read frame 1 */
#define CTX_BSRC 328  /* this point's search area in L1 (L x L bytes), or 0: read frame 2 */
#define CTX_CUR 332   /* this point's entry in the points array */
#define CTX_SIZE 336
#define CHUNK 18      /* pixels per chunk of the copy program */

/* The DMA area (banked layout, after NQ2 in sub-bank 3; bvb/ncc.h BVB_NCC_DMA_BYTES): the job,
 * one transfer description, the state, and two sets of (search area, template) bytes, each
 * owned by the point whose copy it holds (its entry in the points array), filled by memory DMA
 * one point ahead of its use. */
#define D_JOB 0       /* BVB_DMA_JOB_BYTES: slot 0 the search area, slot 1 the template */
#define D_X 112       /* struct bvb_dma_xfer */
#define D_FLY 136     /* the point whose job is in flight, or 0 */
#define D_FLYSET 140  /* its set, times 4 */
#define D_OWN0 144    /* the point whose bytes set 0 holds (complete), or 0 */
#define D_OWN1 148    /* set 1 */
#define D_WANT 152    /* temporaries */
#define D_WSET 156
#define D_AFTER 160   /* the next point inside the frame after this entry is */
#define D_NEXT 164    /* this one (0: none), */
#define D_NLEFT 168   /* with this many points left from it on */
#define D_SET0 176    /* the search area (L x L bytes, L <= 27), then the template at +D_TPL */
#define D_SET1 1032
#define D_TPL 732
#define D_BYTES 1888  /* = BVB_NCC_DMA_BYTES */

#define MAX_RADIUS 5
#define MAX_SEARCH 16

#include "bvb/asm.h"
#include "bvb/dma.h"

	.section .l1.text, "ax"

/* ------------------------------------------------------------------------------------------- */
BVB_FUNC bvb_ncc_match_asm
	[--sp] = rets;
	[--sp] = (r7:4, p5:3);
	/* 32 bytes pushed: width at [sp+44], height +48, points +52, npoints +56, radius +60,
	 * search +64, results +68, scratch +72 */
	r3 = [sp + 60];
	r4 = [sp + 64];
	p4 = [sp + 52];
	p3 = [sp + 68];
	r5 = [sp + 56];
	r6 = 1;
	cc = r3 < r6;
	if cc jump .Lm_bad;
	r6 = MAX_RADIUS;
	cc = r6 < r3;
	if cc jump .Lm_bad;
	r6 = 1;
	cc = r4 < r6;
	if cc jump .Lm_bad;
	r6 = MAX_SEARCH;
	cc = r6 < r4;
	if cc jump .Lm_bad;
	p5 = [sp + 72];
	[p5 + CTX_FRAME1] = r0;
	[p5 + CTX_FRAME2] = r1;
	[p5 + CTX_STRIDE] = r2;
	r0 = [sp + 44];
	[p5 + CTX_W] = r0;
	r0 = [sp + 48];
	[p5 + CTX_H] = r0;
	[p5 + CTX_R] = r3;
	[p5 + CTX_S] = r4;
	[p5 + CTX_PTS] = p4;
	[p5 + CTX_RES] = p3;
	[p5 + CTX_NLEFT] = r5;
	r0 = 0;
	[p5 + CTX_SEEDX] = r0;
	[p5 + CTX_SEEDY] = r0;
	call _ncc_layout;
	call _ncc_dlayout;
	/* with memory DMA: the first point's bytes now (waited for), and the next point's job
	 * during the first point's passes */
	p4 = [p5 + CTX_DMAP];
	r5 = [p5 + CTX_NLEFT];
	p0 = [p5 + CTX_PTS];
	r0 = p4;
	cc = r0 == 0;
	if cc jump .Lm_point;
	call _ncc_nextin;
	cc = r0 == 0;
	if cc jump .Lm_point;
	[p5 + CTX_T17] = r0;
	[p5 + CTX_T18] = r5;
	r1 = 0;
	call _ncc_dstart;
	call _ncc_dwait;
	r0 = [p5 + CTX_DMAP];
	cc = r0 == 0;
	if cc jump .Lm_point;
	p0 = [p5 + CTX_T17];
	p0 += 4;
	r5 = [p5 + CTX_T18];
	r5 += -1;
	call _ncc_nextin;
	cc = r0 == 0;
	if cc jump .Lm_point;
	r1 = 1;
	call _ncc_dstart;
.Lm_point:
	r5 = [p5 + CTX_NLEFT];
	cc = r5 <= 0;
	if cc jump .Lm_done;
	r5 += -1;
	[p5 + CTX_NLEFT] = r5;
	p4 = [p5 + CTX_PTS];
	[p5 + CTX_CUR] = p4;
	r0 = w[p4++] (x);
	r1 = w[p4++] (x);
	[p5 + CTX_PTS] = p4;
	[p5 + CTX_X] = r0;
	[p5 + CTX_Y] = r1;
	r2 = [p5 + CTX_R];
	r3 = [p5 + CTX_S];
	r2 = r2 + r3;
	r3 = r0 - r2;
	cc = r3 < 0;
	if cc jump .Lm_border;
	r3 = r1 - r2;
	cc = r3 < 0;
	if cc jump .Lm_border;
	r3 = r0 + r2;
	r4 = [p5 + CTX_W];
	cc = r3 < r4;
	if !cc jump .Lm_border;
	r3 = r1 + r2;
	r4 = [p5 + CTX_H];
	cc = r3 < r4;
	if !cc jump .Lm_border;
	/* this point's bytes in L1, if a job brought them (waiting for it if it is in flight) */
	r0 = 0;
	[p5 + CTX_TSRC] = r0;
	[p5 + CTX_BSRC] = r0;
	p4 = [p5 + CTX_DMAP];
	r0 = [p5 + CTX_CUR];
	r1 = p4;
	cc = r1 == 0;
	if cc jump .Lm_tpl;
	call _ncc_dfind;
	cc = r0 == 0;
	if cc jump .Lm_tpl;
	[p5 + CTX_BSRC] = r0;
	r1 = D_TPL (x);
	r0 = r0 + r1;
	[p5 + CTX_TSRC] = r0;
.Lm_tpl:
	call _ncc_template;
	cc = r0 == 0;
	if cc jump .Lm_flat;
	r0 = [p5 + CTX_PRE];
	cc = r0 == 0;
	if cc jump .Lm_build;
	/* the last MAC pass copied this point's search area into the spare buffers */
	r0 = [p5 + CTX_HE];
	r1 = [p5 + CTX_HE2];
	[p5 + CTX_HE] = r1;
	[p5 + CTX_HE2] = r0;
	r0 = [p5 + CTX_HO];
	r1 = [p5 + CTX_HO2];
	[p5 + CTX_HO] = r1;
	[p5 + CTX_HO2] = r0;
	jump .Lm_built;
.Lm_build:
	call _ncc_build;
.Lm_built:
	call _ncc_pass1;
	call _ncc_pass2;
	r0 = 0;
	[p5 + CTX_PRE] = r0;
	r0 = [p5 + CTX_PIPE];
	cc = r0 == 0;
	if cc jump .Lm_mac;
	call _ncc_prebuild;
.Lm_mac:
	call _ncc_macpass;
	call _ncc_select;
	r0 = [p5 + CTX_BN];
	r1 = [p5 + CTX_VT];
	r2 = [p5 + CTX_BV];
	call _ncc_score;
	r3 = [p5 + CTX_S];
	r1 = [p5 + CTX_BE];
	r2 = [p5 + CTX_BD];
	r1 = r1 - r3;
	r2 = r2 - r3;
	[p5 + CTX_SEEDX] = r1;
	[p5 + CTX_SEEDY] = r2;
	p3 = [p5 + CTX_RES];
	w[p3++] = r1;
	w[p3++] = r2;
	w[p3++] = r0;
	r0 = 0;
	w[p3++] = r0;
	[p5 + CTX_RES] = p3;
	jump .Lm_point;
.Lm_border:
	r1 = 1;
	jump .Lm_status;
.Lm_flat:
	r0 = 0;
	[p5 + CTX_PRE] = r0;
	r1 = 2;
.Lm_status:
	p3 = [p5 + CTX_RES];
	r0 = 0;
	w[p3++] = r0;
	w[p3++] = r0;
	w[p3++] = r0;
	w[p3++] = r1;
	[p5 + CTX_RES] = p3;
	jump .Lm_point;
.Lm_bad:
	/* parameters out of range: every point gets BVB_NCC_BAD_PARAMS, the scratch is not used */
	cc = r5 <= 0;
	if cc jump .Lm_ret;
	r0 = 0;
	r1 = 3;
.Lm_bad1:
	w[p3++] = r0;
	w[p3++] = r0;
	w[p3++] = r0;
	w[p3++] = r1;
	r5 += -1;
	cc = r5 <= 0;
	if !cc jump .Lm_bad1;
	jump .Lm_ret;
.Lm_done:
	/* every job started is waited for by the point it serves; this only makes sure */
	p4 = [p5 + CTX_DMAP];
	nop;
	nop;
	r0 = p4;
	cc = r0 == 0;
	if cc jump .Lm_ret;
	call _ncc_dwait;
.Lm_ret:
	(r7:4, p5:3) = [sp++];
	rets = [sp++];
	rts;
BVB_ENDFUNC bvb_ncc_match_asm

/* ------------------------------------------------------------------------------------------- */
/* Derived sizes and the scratch layout (bvb/ncc.h BVB_NCC_SCRATCH_SIZE). P5 = context. */
	.align 4
_ncc_layout:
	r3 = [p5 + CTX_R];
	r4 = [p5 + CTX_S];
	r0 = r3 << 1;
	r0 += 1;
	[p5 + CTX_WT] = r0;
	r1 = r0;
	r1 *= r0;
	[p5 + CTX_N] = r1;
	r2 = r4 + r3;
	r2 = r2 << 1;
	r2 += 1;
	[p5 + CTX_L] = r2;
	r5 = r3 << 1;
	r5 *= r5;
	[p5 + CTX_NSUB] = r5;
	r5 = r2;
	r5 += 1;
	r5 = r5 << 1;
	[p5 + CTX_HEROW] = r5;
	r6 = r2;
	r6 *= r5;            /* L * HEROW */
	r7 = p5;
	r5 = CTX_SIZE;
	r7 = r7 + r5;
	[p5 + CTX_HE] = r7;
	r7 = r7 + r6;
	r7 += 4;
	[p5 + CTX_HO] = r7;
	r7 = r7 + r6;
	[p5 + CTX_TF] = r7;
	r5 = r1;
	r5 += 1;
	r5 = r5 >> 1;
	r5 = r5 << 2;
	r7 = r7 + r5;
	[p5 + CTX_TP] = r7;
	r5 = r3;
	r5 += 1;
	r5 *= r0;
	r5 = r5 << 2;
	r7 = r7 + r5;
	[p5 + CTX_CS2] = r7;
	r5 = r4;
	r5 += 3;
	r5 >>= 1;
	r5 = r5 << 2;        /* KSB = 2 * KS, KS = s+2 rounded up to even */
	[p5 + CTX_KSB] = r5;
	r6 = r2;
	r6 += 1;
	r6 *= r5;            /* L+1 columns */
	r7 = r7 + r6;
	[p5 + CTX_NQ2] = r7;
	r7 = r7 + r6;
	r7 = r7 + r6;
	r7 += 8;             /* two words for the pipeline's first (empty) stores */
	/* 2n = 8r^2 = 2^(3 + 2*trailing zeros of r) * odd^2: the shift, and the odd part's inverse
	 * mod 2^32 by Newton (x <- x*(2 - a*x) doubles the correct low bits; a*a = 1 mod 8) */
	r0 = [p5 + CTX_R];
	r1 = 3;
	cc = bittst(r0, 0);
	if cc jump .Ll_odd;
	r0 >>= 1;            /* r = 2 or 4 */
	r1 = 5;
	cc = bittst(r0, 0);
	if cc jump .Ll_odd;
	r0 >>= 1;
	r1 = 7;
.Ll_odd:
	[p5 + CTX_DSH] = r1;
	r0 *= r0;            /* the odd part */
	r1 = r0;             /* x */
	p0 = 4;
	lsetup (.Ll_n0, .Ll_n1) lc0 = p0;
.Ll_n0:
	r2 = r0;
	r2 *= r1;
	r3 = 2;
	r3 = r3 - r2;
.Ll_n1:
	r1 *= r3;
	[p5 + CTX_DINV] = r1;
	[p5 + CTX_NP] = r7;
	r6 = r4 << 1;
	r6 += 1;
	r6 *= r4;
	r6 = r6 << 3;
	r7 = r7 + r6;
	[p5 + CTX_NS] = r7;  /* right after NP: the selection sweeps both as one array */
	r7 += 4;
	r6 = r4 << 1;
	r6 += 2;
	r6 = r6 << 2;
	r7 = r7 + r6;        /* end of the numerators */

	/* ceil(2^16 / (2s+1)) */
	r0 = r4 << 1;
	r0 += 1;
	r6.l = 0;
	r6.h = 1;
	r6 = r6 + r0;
	r6 += -1;
	[p5 + CTX_T0] = r7;
	r1 = r0;
	r0 = r6;
	[--sp] = rets;
	call _ncc_udiv;
	rets = [sp++];
	[p5 + CTX_RECIP] = r0;
	r7 = [p5 + CTX_T0];
	/* the copy program (r = 5, 5 <= s <= 10): a spare He, Ho and the program itself */
	r0 = p5;
	r1 = CTX_DUMMY;
	r0 = r0 + r1;
	[p5 + CTX_DUMMYP] = r0;
	r0 = 0;
	[p5 + CTX_PIPE] = r0;
	[p5 + CTX_PRE] = r0;
	[p5 + CTX_DMAP] = r0;
	[p5 + CTX_TSRC] = r0;
	[p5 + CTX_BSRC] = r0;
	r3 = [p5 + CTX_R];
	r4 = [p5 + CTX_S];
	r0 = 5;
	cc = r3 == r0;
	if !cc jump .Ll_out;
	cc = r4 < r0;
	if cc jump .Ll_out;
	r0 = 10;
	cc = r0 < r4;
	if cc jump .Ll_out;
	r0 = 1;
	[p5 + CTX_PIPE] = r0;
	r2 = [p5 + CTX_L];
	r5 = [p5 + CTX_HEROW];
	r6 = r2;
	r6 *= r5;            /* L * HEROW */
	r0 = 8;
	cc = r0 < r4;
	if cc jump .Ll_flat;
	/* s <= 8: the banked layout (bvb/ncc.h). Each 4 KB sub-bank of the scratch holds what is
	 * never accessed in one cycle with the others': 0 the context, He, Ho; 1 the spare He, Ho;
	 * 2 T' (TF, TP), the numerators, the copy program, CS2, the idle chunks' dummy area;
	 * 3 NQ2. The MAC pass loads He or Ho with T' (or stores numerators, loads the program,
	 * stores into the other pair), pass 1 loads He with CS2 or NQ2 stores, pass 2 loads CS2
	 * with NQ2: never two in one sub-bank. */
	r1 = p5;
	r0 = 4096 (x);
	r0 = r0 + r1;
	[p5 + CTX_HE2] = r0;
	r0 = r0 + r6;
	r0 += 4;
	[p5 + CTX_HO2] = r0;
	r0 = 12288 (x);
	r0 = r0 + r1;
	[p5 + CTX_NQ2] = r0;
	r7 = 8192 (x);
	r7 = r7 + r1;
	[p5 + CTX_TF] = r7;
	r0 = 4 * 61;         /* (N + 1) / 2 words, r = 5 */
	r7 = r7 + r0;
	[p5 + CTX_TP] = r7;
	r0 = 4 * 66 + 8;     /* w (r + 1) words, then the two words of the first (empty) stores */
	r7 = r7 + r0;
	[p5 + CTX_NP] = r7;
	r0 = r4 << 1;
	r0 += 1;
	r0 *= r4;
	r0 = r0 << 3;
	r7 = r7 + r0;
	[p5 + CTX_NS] = r7;
	r7 += 4;
	r0 = r4 << 1;
	r0 += 2;
	r0 = r0 << 2;
	r7 = r7 + r0;
	[p5 + CTX_TAB] = r7;
	r0 = r2 << 2;
	r1 = r4 << 1;
	r0 = r0 + r1;
	r0 += 1;
	r1 = 12;
	r0 *= r1;            /* 4L + 2s + 1 chunks */
	r7 = r7 + r0;
	[p5 + CTX_CS2] = r7;
	r0 = r2;
	r0 += 1;
	r1 = [p5 + CTX_KSB];
	r0 *= r1;
	r7 = r7 + r0;
	[p5 + CTX_DUMMYP] = r7;
	jump .Ll_tab;
.Ll_flat:
	[p5 + CTX_HE2] = r7;
	r7 = r7 + r6;
	r7 += 4;
	[p5 + CTX_HO2] = r7;
	r7 = r7 + r6;
	[p5 + CTX_TAB] = r7;
.Ll_tab:
	r0 = r2 << 1;        /* 2L chunks: [0, 18) and [L-18, L) of each row */
	[p5 + CTX_NCH] = r0;
	r1 = r4 << 1;
	r1 += 1;             /* pairs per column pair */
	r0 = r0 + r1;
	r0 += -1;
	[p5 + CTX_T0] = r1;
	[--sp] = rets;
	call _ncc_udiv;      /* column pairs that copy */
	rets = [sp++];
	[p5 + CTX_NB] = r0;
	r1 = [p5 + CTX_T0];
	r0 *= r1;            /* chunks in the program */
	/* every chunk idle until _ncc_prebuild fills the first NCH: read the frame's first bytes,
	 * write the dummy area */
	p0 = r0;
	p1 = [p5 + CTX_TAB];
	r0 = [p5 + CTX_FRAME2];
	r1 = [p5 + CTX_DUMMYP];
	lsetup (.Ll_d0, .Ll_d1) lc0 = p0;
.Ll_d0:
	[p1++] = r0;
	[p1++] = r1;
.Ll_d1:
	[p1++] = r1;
.Ll_out:
	rts;


/* ------------------------------------------------------------------------------------------- */
/* The first of the R5 points from entry P0 on whose search area lies in the frame: R0 = its
 * entry, or 0. Clobbers R0-R3, R5-R7, P0. */
	.align 4
_ncc_nextin:
	r0 = 0;
	cc = r5 <= 0;
	if cc jump .Lni_out;
	r2 = [p5 + CTX_R];
	r3 = [p5 + CTX_S];
	r2 = r2 + r3;        /* r + s */
	r6 = [p5 + CTX_W];
	r7 = [p5 + CTX_H];
.Lni_scan:
	r0 = w[p0++] (x);
	r1 = w[p0++] (x);
	r3 = r0 - r2;
	cc = r3 < 0;
	if cc jump .Lni_next;
	r3 = r1 - r2;
	cc = r3 < 0;
	if cc jump .Lni_next;
	r3 = r0 + r2;
	cc = r3 < r6;
	if !cc jump .Lni_next;
	r3 = r1 + r2;
	cc = r3 < r7;
	if !cc jump .Lni_next;
	r0 = p0;
	r0 += -4;
	rts;
.Lni_next:
	r5 += -1;
	cc = r5 <= 0;
	if !cc jump .Lni_scan (bp);
	r0 = 0;
.Lni_out:
	rts;

/* ------------------------------------------------------------------------------------------- */
/* The copy program for the next point that is inside the frame, if any: two chunks of CHUNK
 * pixels per row of its search area ([0, CHUNK) and [L - CHUNK, L), overlapping), each a
 * (source, He destination, Ho destination) triple for the spare buffers. Sets CTX_PRE.
 * With memory DMA the source is that point's copy in L1 (its job, started during the last MAC
 * pass, is waited for here), and the job for the in-frame point after it starts here, into the
 * other set, so that it runs during this MAC pass. */
	.align 4
_ncc_prebuild:
	[--sp] = rets;
	p4 = [p5 + CTX_DMAP];
	r5 = [p5 + CTX_NLEFT];
	p0 = [p5 + CTX_PTS];
	r0 = p4;
	cc = r0 == 0;
	if cc jump .Lpb_scan;
	/* the next point: the last prebuild found it if it ran for the point before */
	r0 = [p4 + D_AFTER];
	r1 = [p5 + CTX_CUR];
	cc = r0 == r1;
	if !cc jump .Lpb_scan;
	r0 = [p4 + D_NEXT];
	r5 = [p4 + D_NLEFT];
	jump .Lpb_have;
.Lpb_scan:
	call _ncc_nextin;
.Lpb_have:
	cc = r0 == 0;
	if cc jump .Lpb_none;
	[p5 + CTX_T17] = r0; /* the next point */
	[p5 + CTX_T18] = r5; /* points left from it on */
	r1 = 0;
	[p5 + CTX_T19] = r1; /* its search area in L1, or 0 */
	r1 = [p5 + CTX_DMAP];
	cc = r1 == 0;
	if cc jump .Lpb_prog;
	call _ncc_dfind;
	[p5 + CTX_T19] = r0;
	r1 = [p5 + CTX_DMAP];
	cc = r1 == 0;
	if cc jump .Lpb_prog;
	r2 = D_SET0;
	r1 = r1 + r2;
	cc = r0 == r1;
	r0 = cc;             /* the set the next point does not use */
	[p5 + CTX_T16] = r0;
	p0 = [p5 + CTX_T17];
	r5 = [p5 + CTX_T18];
	r5 += -1;
	p0 += 4;
	call _ncc_nextin;
	r1 = [p5 + CTX_T17];
	[p4 + D_AFTER] = r1;
	[p4 + D_NEXT] = r0;
	[p4 + D_NLEFT] = r5;
	cc = r0 == 0;
	if cc jump .Lpb_prog;
	r1 = [p5 + CTX_T16];
	call _ncc_dstart;
.Lpb_prog:
	p0 = [p5 + CTX_T17];
	r2 = [p5 + CTX_R];
	r3 = [p5 + CTX_S];
	r2 = r2 + r3;        /* r + s */
	r0 = w[p0] (x);
	r1 = w[p0 + 2] (x);
	/* six running pointers (source, He, Ho for both chunks), one store and one add a cycle */
	r3 = [p5 + CTX_T19];
	cc = r3 == 0;
	if cc jump .Lpb_frame;
	r0 = r3;             /* rows of L bytes */
	r3 = [p5 + CTX_L];
.Lpb_go:
	r1 = [p5 + CTX_HE2];
	r2 = [p5 + CTX_HO2];
	r2 += -2;            /* pixel c of a row at +2c in both */
	r4 = [p5 + CTX_L];
	p1 = r4;
	r4 += -CHUNK;        /* the second chunk's first pixel */
	r7 = r0 + r4;
	r4 = r4 << 1;
	r5 = r1 + r4;
	r4 = r2 + r4;
	r6 = [p5 + CTX_HEROW];
	r4 = r4 - r6;        /* the last pointer advances first */
	p0 = [p5 + CTX_TAB];
	lsetup (.Lpb_0, .Lpb_1) lc0 = p1;
.Lpb_0:
	r4 = r4 + r6 (ns) || [p0++] = r0 || nop;
	r0 = r0 + r3 (ns) || [p0++] = r1 || nop;
	r1 = r1 + r6 (ns) || [p0++] = r2 || nop;
	r2 = r2 + r6 (ns) || [p0++] = r7 || nop;
	r7 = r7 + r3 (ns) || [p0++] = r5 || nop;
.Lpb_1:
	r5 = r5 + r6 (ns) || [p0++] = r4 || nop;
	r0 = 1;
	[p5 + CTX_PRE] = r0;
.Lpb_none:
	rets = [sp++];
	rts;
.Lpb_frame:
	r1 = r1 - r2;
	r3 = [p5 + CTX_STRIDE];
	r1 *= r3;
	r0 = r0 - r2;
	r0 = r0 + r1;
	r1 = [p5 + CTX_FRAME2];
	r0 = r0 + r1;        /* source, row 0 */
	jump .Lpb_go;

/* ------------------------------------------------------------------------------------------- */
/* Memory DMA (bvb/dma.h) of each point's search area and template into L1, one point ahead.
 * _ncc_dlayout: on for the banked layout with both frames wholly in SDRAM and the DMA area
 * reachable by DMA (not the scratchpad), and both slots prepared (8-bit elements: L and w are
 * odd, so every later move keeps the shape); else CTX_DMAP stays 0 and the frames are read
 * through the cache as before. Clobbers R0-R7, P0-P2, P4. */
	.align 4
_ncc_dlayout:
	[--sp] = rets;
	r0 = [p5 + CTX_R];
	r1 = 5;
	cc = r0 == r1;
	if !cc jump .Ldl_out;
	r0 = [p5 + CTX_S];
	cc = r0 < r1;
	if cc jump .Ldl_out;
	r1 = 8;
	cc = r1 < r0;
	if cc jump .Ldl_out;
	r4 = [p5 + CTX_H];
	r5 = [p5 + CTX_W];
	r1 = 1;
	cc = r4 < r1;
	if cc jump .Ldl_out;
	cc = r5 < r1;
	if cc jump .Ldl_out;
	r4 += -1;
	r0 = [p5 + CTX_STRIDE];
	r4 *= r0;
	r4 = r4 + r5;        /* a frame's extent */
	r6.l = 0;
	r6.h = 0x0200;       /* the end of SDRAM */
	r0 = [p5 + CTX_FRAME1];
	r1 = r0 + r4;
	cc = r1 < r0 (iu);
	if cc jump .Ldl_out;
	cc = r6 < r1 (iu);
	if cc jump .Ldl_out;
	r0 = [p5 + CTX_FRAME2];
	r1 = r0 + r4;
	cc = r1 < r0 (iu);
	if cc jump .Ldl_out;
	cc = r6 < r1 (iu);
	if cc jump .Ldl_out;
	/* the area: after NQ2's (L+1) columns of 2*KSB bytes and its two spare words */
	r0 = [p5 + CTX_L];
	r0 += 1;
	r1 = [p5 + CTX_KSB];
	r0 *= r1;
	r0 = r0 << 1;
	r1 = [p5 + CTX_NQ2];
	r0 = r0 + r1;
	r0 += 8;
	r7 = r0;
	r1 = D_BYTES (x);
	call _bvb_dma_reachable;
	cc = r0 == 0;
	if cc jump .Ldl_out;
	p4 = r7;
	r0 = 0;
	[p4 + D_FLY] = r0;
	[p4 + D_FLYSET] = r0;
	[p4 + D_OWN0] = r0;
	[p4 + D_OWN1] = r0;
	[p4 + D_AFTER] = r0;
	/* slot 0: L rows of L bytes of frame 2 into a set; slot 1: w rows of w bytes of frame 1 */
	r0 = [p5 + CTX_FRAME2];
	[p4 + D_X + DMAX_SRC] = r0;
	r0 = [p5 + CTX_STRIDE];
	[p4 + D_X + DMAX_SS] = r0;
	r1 = D_SET0;
	r0 = r7 + r1;
	[p4 + D_X + DMAX_DST] = r0;
	r0 = [p5 + CTX_L];
	[p4 + D_X + DMAX_DS] = r0;
	[p4 + D_X + DMAX_W] = r0;
	[p4 + D_X + DMAX_ROWS] = r0;
	r0 = r7;
	r1 = 0;
	r2 = D_X;
	r2 = r2 + r7;
	call _bvb_dma_prepare;
	cc = r0 < 0;
	if cc jump .Ldl_out;
	r0 = [p5 + CTX_FRAME1];
	[p4 + D_X + DMAX_SRC] = r0;
	r1 = D_SET0 + D_TPL (x);
	r0 = r7 + r1;
	[p4 + D_X + DMAX_DST] = r0;
	r0 = [p5 + CTX_WT];
	[p4 + D_X + DMAX_DS] = r0;
	[p4 + D_X + DMAX_W] = r0;
	[p4 + D_X + DMAX_ROWS] = r0;
	r0 = r7;
	r1 = 1;
	r2 = D_X;
	r2 = r2 + r7;
	call _bvb_dma_prepare;
	cc = r0 < 0;
	if cc jump .Ldl_out;
	[p5 + CTX_DMAP] = r7;
.Ldl_out:
	rets = [sp++];
	rts;

/* _ncc_dwait: waits for the job in flight, if any, and records its set as holding its point's
 * bytes; on a DMA error memory DMA is off for the rest of the call (CTX_DMAP = 0). P4 =
 * CTX_DMAP (not 0). Clobbers R0-R3, P0-P2. */
	.align 4
_ncc_dwait:
	r0 = [p4 + D_FLY];
	cc = r0 == 0;
	if cc jump .Ldw_out;
	[--sp] = rets;
	call _bvb_dma_wait;
	rets = [sp++];
	r1 = [p4 + D_FLY];
	r2 = 0;
	[p4 + D_FLY] = r2;
	cc = r0 == 0;
	if !cc jump .Ldw_err;
	r0 = [p4 + D_FLYSET];
	r2 = [p4 + D_OWN0];
	r3 = [p4 + D_OWN1];
	cc = r0 == 0;
	if cc r2 = r1;
	if !cc r3 = r1;
	[p4 + D_OWN0] = r2;
	[p4 + D_OWN1] = r3;
.Ldw_out:
	rts;
.Ldw_err:
	[p5 + CTX_DMAP] = r2;
	rts;

/* _ncc_dfind: R0 = a point's entry; R0 = the start of the set holding its bytes (search area,
 * template at +D_TPL), or 0. Waits for its job if that is in flight. P4 = CTX_DMAP (not 0).
 * Clobbers R0-R3, P0-P2. */
	.align 4
_ncc_dfind:
	r1 = [p4 + D_FLY];
	cc = r0 == r1;
	if !cc jump .Ldf_look;
	[p4 + D_WANT] = r0;
	[--sp] = rets;
	call _ncc_dwait;
	rets = [sp++];
	r1 = [p5 + CTX_DMAP];
	cc = r1 == 0;
	if cc jump .Ldf_none;
	r0 = [p4 + D_WANT];
.Ldf_look:
	/* without branches (a taken one costs 9 cycles unhinted): the set's offset, or 0 */
	r1 = [p4 + D_OWN0];
	r2 = [p4 + D_OWN1];
	cc = r0 == r2;
	r2 = D_SET1 (x);
	r3 = 0;
	if cc r3 = r2;
	cc = r0 == r1;
	r2 = D_SET0;
	if cc r3 = r2;
	r0 = p4;
	r0 = r0 + r3;
	cc = r3 == 0;
	if cc r0 = r3;
	rts;
.Ldf_none:
	r0 = 0;
	rts;

/* _ncc_dstart: R0 = a point's entry (inside the frame), R1 = a set (0, 1): starts the job that
 * copies its search area and template into that set (after the job in flight, if any). P4 =
 * CTX_DMAP (not 0). Clobbers R0-R3, P0-P2. */
	.align 4
_ncc_dstart:
	[--sp] = rets;
	[--sp] = r0;
	r1 = r1 << 2;
	[p4 + D_WSET] = r1;
	r0 = [p4 + D_FLY];
	cc = r0 == 0;
	if !cc jump .Lds_busy;
.Lds_idle:
	r0 = [sp];
	[p4 + D_WANT] = r0;
	/* the set's bytes are about to change: no owner */
	r1 = [p4 + D_WSET];
	r0 = 0;
	r2 = [p4 + D_OWN0];
	r3 = [p4 + D_OWN1];
	cc = r1 == 0;
	if cc r2 = r0;
	if !cc r3 = r0;
	[p4 + D_OWN0] = r2;
	[p4 + D_OWN1] = r3;
	r2 = D_SET0;
	r3 = D_SET1 (x);
	if !cc r2 = r3;
	r0 = p4;
	r2 = r2 + r0;        /* the set */
	r0 = r2;
	r1 = D_TPL (x);
	r0 = r0 + r1;
	[p4 + D_X + DMAX_DST] = r0;
	[--sp] = r2;
	/* the template: frame 1 at (x - r, y - r) */
	p0 = [p4 + D_WANT];
	r0 = w[p0] (x);
	r1 = w[p0 + 2] (x);
	r2 = [p5 + CTX_R];
	r0 = r0 - r2;
	r1 = r1 - r2;
	r2 = [p5 + CTX_STRIDE];
	r1 *= r2;
	r0 = r0 + r1;
	r1 = [p5 + CTX_FRAME1];
	r1 = r1 + r0;
	[p4 + D_X + DMAX_SRC] = r1;
	r1 = [p5 + CTX_S];
	r2 *= r1;
	r0 = r0 - r1;
	r0 = r0 - r2;        /* (x - r - s, y - r - s) */
	r1 = [p5 + CTX_FRAME2];
	r0 = r0 + r1;
	[p4 + D_WANT] = r0;  /* the search area's source */
	r0 = p4;
	r1 = 1;
	r2 = p4;
	r3 = D_X;
	r2 = r2 + r3;
	call _bvb_dma_move;
	r0 = [p4 + D_WANT];
	[p4 + D_X + DMAX_SRC] = r0;
	r0 = [sp++];
	[p4 + D_X + DMAX_DST] = r0;
	r0 = p4;
	r1 = 0;
	r2 = p4;
	r3 = D_X;
	r2 = r2 + r3;
	call _bvb_dma_move;
	r0 = p4;
	r1 = 2;
	call _bvb_dma_start;
	r0 = [p4 + D_WSET];
	[p4 + D_FLYSET] = r0;
	r0 = [sp];
	[p4 + D_FLY] = r0;
.Lds_out:
	r0 = [sp++];
	rets = [sp++];
	rts;
.Lds_busy:
	call _ncc_dwait;
	r0 = [p5 + CTX_DMAP];
	cc = r0 == 0;
	if !cc jump .Lds_idle;
	jump .Lds_out;

/* ------------------------------------------------------------------------------------------- */
/* Template: ST and STT, then T' = N*T - ST into TF (flat, then a zero) and TP (each row led by
 * a zero). Returns vt in R0 (also in the context). From the memory DMA copy (contiguous, r = 5)
 * about 2 cycles a pixel in all (below); in place (.Lt_gen), ST (ALU) and STT (MAC) in two
 * cycles per pixel (one dual MAC cannot do both: its halves share their two source registers),
 * then T' in two more. The in-place loops read one pixel past each row of the template: still
 * inside the frame, since s >= 1. */
	.align 4
.Lt_far:
	jump.l .Lt_gen;      /* the fast path below is beyond a conditional jump's reach */
_ncc_template:
	r1 = [p5 + CTX_TSRC];
	cc = r1 == 0;
	if cc jump .Lt_far;
	/* The template's memory DMA copy (only in the banked layout, so r = 5): 121 contiguous
	 * bytes on a word boundary (D_SET0 + D_TPL and D_SET1 + D_TPL are multiples of 4 from the
	 * area, which is word-aligned). ST by SAA against zero, four pixels an issue, in the four
	 * 16-bit lanes of A1:0 (at most 31 * 255 each); then STT and T' in one unrolled pass of 7
	 * issues per four pixels (ncc_template5.inc). I0, I1 stay word-aligned: SAA's and
	 * BYTEUNPACK's byte offsets are 0, so each reads the word it names. */
	i0 = r1;
	p2 = r1;             /* the SAA pass's words */
	p0 = r1;             /* the unrolled pass's words */
	r0 = [p5 + CTX_TF];
	i1 = r0;             /* word-aligned too */
	r0 = [p5 + CTX_TP];
	i2 = r0;
	p1 = 14;
	r2 = 0;
	r3 = 0;
	a1 = a0 = 0 || r0 = [p2++] || nop;
	r1 = [p2++];
	lsetup (.Lt5_s0, .Lt5_s1) lc0 = p1;
.Lt5_s0:
	saa (r1:0, r3:2) || r0 = [p2++] || nop;
.Lt5_s1:
	saa (r1:0, r3:2) (r) || r1 = [p2++] || nop;
	saa (r1:0, r3:2) || r0 = [p2++] || nop;  /* word 28; word 30 in */
	saa (r1:0, r3:2) (r);                    /* word 29 */
	r0 = r0.b (z);                           /* pixel 120 alone */
	saa (r1:0, r3:2);
	r1 = a1.l + a1.h, r0 = a0.l + a0.h;
	r2 = r0 + r1;
	r2 = pack (r2.l, r2.l);                  /* (ST, ST) */
	r7 = [p5 + CTX_N];
	r1 = 0;
	a1 = a0 = 0 || r0 = [p0++] || nop;
#include "ncc_template5.inc"
	r3 = (a0 += a1);     /* STT */
	r3 *= r7;
	r6 = r2.l * r2.l (is);
	r3 = r3 - r6;
	[p5 + CTX_VT] = r3;
	r0 = r3;
	rts;
.Lt_gen:
	r0 = [p5 + CTX_Y];
	r1 = [p5 + CTX_R];
	r0 = r0 - r1;
	r2 = [p5 + CTX_STRIDE];
	r0 *= r2;
	r3 = [p5 + CTX_X];
	r3 = r3 - r1;
	r0 = r0 + r3;
	p0 = [p5 + CTX_FRAME1];
	p1 = r0;
	p0 = p0 + p1;        /* top left of the template */
	r1 = [p5 + CTX_TSRC];
	cc = r1 == 0;
	if cc jump .Lt_src;
	p0 = r1;             /* its copy in L1, rows of w bytes */
	r2 = [p5 + CTX_WT];
.Lt_src:
	p2 = p0;
	r4 = [p5 + CTX_WT];
	p3 = r4;
	r0 = r2 - r4;
	r0 += -1;
	p1 = r0;             /* stride - w - 1 */
	r2 = 0;
	a1 = a0 = 0;
	lsetup (.Lt_a0, .Lt_a1) lc1 = p3;
.Lt_a0:
	r5 = b[p2++] (z);
	lsetup (.Lt_a2, .Lt_a3) lc0 = p3;
.Lt_a2:
	a1 += r5.l * r5.l (is);
.Lt_a3:
	r2 = r2 + r5 (ns) || r5 = b[p2++] (z) || nop;
.Lt_a1:
	p2 = p2 + p1;
	r3 = a1 (is);        /* STT; ST in R2 */
	r7 = [p5 + CTX_N];
	r3 *= r7;
	r6 = r2.l * r2.l (is);
	r3 = r3 - r6;
	[p5 + CTX_VT] = r3;
	cc = r3 == 0;
	if cc jump .Lt_out;
	p2 = [p5 + CTX_TF];
	i1 = p2;
	p2 = [p5 + CTX_TP];
	i2 = p2;
	p2 = p0;
	r6 = 0;
	r0 = [p5 + CTX_R];
	p4 = r0;             /* r pairs of pixels after the first */
	lsetup (.Lt_b0, .Lt_b1) lc1 = p3;
.Lt_b0:
	mnop || r5 = b[p2++] (z) || w[i2++] = r6.l;          /* T[0]; the row's leading zero */
	r0.l = r5.l * r7.l (is) || r5 = b[p2++] (z) || nop;  /* N*T[0]; T[1] */
	r4.l = r0.l - r2.l (ns);                             /* T'[0] */
	/* two pixels per iteration, T' alternating between R4 and R1 so that no store reads a
	 * register its own instruction writes */
	lsetup (.Lt_b2, .Lt_b3) lc0 = p4;
.Lt_b2:
	r0.l = r5.l * r7.l (is) || r5 = b[p2++] (z) || w[i1++] = r4.l;
	r1.l = r0.l - r2.l (ns) || w[i2++] = r4.l || nop;
	r0.l = r5.l * r7.l (is) || r5 = b[p2++] (z) || w[i1++] = r1.l;
.Lt_b3:
	r4.l = r0.l - r2.l (ns) || w[i2++] = r1.l || nop;
	w[i1++] = r4.l;
	w[i2++] = r4.l;
.Lt_b1:
	p2 = p2 + p1;
	w[i1++] = r6.l;      /* TF[N] = 0 */
.Lt_out:
	r0 = r3;
	rts;

/* ------------------------------------------------------------------------------------------- */
/* The search area of frame 2 as 16-bit pixels: He word m of row k = (I[2m], I[2m+1]) (the last
 * word's high half repeats I[L-1]), Ho word m = (I[2m+1], I[2m+2]). One pixel per cycle: a byte
 * load, a PACK and a store. Ho's stores trail by one word; the first of each row lands in the
 * unused last word of the previous Ho row (or the word before Ho). */
	.align 4
_ncc_build:
	r0 = [p5 + CTX_Y];
	r1 = [p5 + CTX_R];
	r2 = [p5 + CTX_S];
	r1 = r1 + r2;
	r0 = r0 - r1;
	r3 = [p5 + CTX_STRIDE];
	r0 *= r3;
	r4 = [p5 + CTX_X];
	r4 = r4 - r1;
	r0 = r0 + r4;
	p0 = [p5 + CTX_FRAME2];
	p1 = r0;
	p0 = p0 + p1;
	r5 = [p5 + CTX_L];
	r0 = [p5 + CTX_BSRC];
	cc = r0 == 0;
	if cc jump .Lb_src;
	p0 = r0;             /* its copy in L1, rows of L bytes */
	r3 = r5;
.Lb_src:
	r0 = r3 - r5;
	p1 = r0;             /* stride - L */
	p2 = [p5 + CTX_HE];
	i1 = p2;
	p2 = [p5 + CTX_HO];
	i2 = p2;
	i2 -= 4;
	r0 = r5;
	r0 += -3;
	r0 >>= 1;
	p2 = r0;             /* (L-3)/2 */
	r0 = r5;
	r0 += -1;
	p3 = r0;             /* every row but the last */
	r4 = b[p0++] (z);
	r5 = b[p0++] (z);
	lsetup (.Lb_r0, .Lb_r1) lc1 = p3;
.Lb_r0:
	lsetup (.Lb_p0, .Lb_p1) lc0 = p2;
.Lb_p0:
	r6 = pack(r5.l, r4.l) || r4 = b[p0++] (z) || [i2++] = r7;
.Lb_p1:
	r7 = pack(r4.l, r5.l) || r5 = b[p0++] (z) || [i1++] = r6;
	r6 = pack(r5.l, r4.l) || r4 = b[p0++] (z) || [i2++] = r7;
	r7 = pack(r4.l, r5.l) || [i1++] = r6 || nop;
	p0 = p0 + p1;
	r6 = pack(r4.l, r4.l) || r4 = b[p0++] (z) || [i2++] = r7;
.Lb_r1:
	mnop || r5 = b[p0++] (z) || [i1++] = r6;
	lsetup (.Lb_q0, .Lb_q1) lc0 = p2;
.Lb_q0:
	r6 = pack(r5.l, r4.l) || r4 = b[p0++] (z) || [i2++] = r7;
.Lb_q1:
	r7 = pack(r4.l, r5.l) || r5 = b[p0++] (z) || [i1++] = r6;
	r6 = pack(r5.l, r4.l) || r4 = b[p0++] (z) || [i2++] = r7;
	r7 = pack(r4.l, r5.l) || [i1++] = r6 || nop;
	r6 = pack(r4.l, r4.l) || [i2++] = r7 || nop;
	[i1++] = r6;
	rts;

/* ------------------------------------------------------------------------------------------- */
/* Pass 1, for the selection's filter. Every (2r+1)^2 window contains a 2r x 2r sub-window at even
 * coordinates of the search area, and for such a sub-window (n = 4r^2 pixels)
 *     u = n*sum I^2 - (sum I)^2 = n*sum (I - Isub)^2  <=  n*sum over the window (I - I)^2  <=  v,
 * so the smallest u bounds the smallest v from below. Pass 1 makes the sub-windows' column sums:
 * for each pair of columns (2m, 2m+1) of He, sums over 2r rows starting at the even rows 2k
 * (k = 0..s), sliding down two rows a step: I in 16-bit lanes into CS2, n*I^2 (fractional MACs:
 * 2*n*sum I^2, exact) into NQ2, both column-major (rows k, k+1 adjacent). Pass 2 reads the high
 * halves of NQ2, floor(n*sum I^2 / 2^15); the exact sums serve _ncc_exactv. Eight cycles a step: for each of the two rows, the sum and
 * difference of the entering and leaving pixels, n*difference, the MAC of it by the sum
 * (= n*(new^2 - old^2)), and the I sums. */
	.align 4
_ncc_pass1:
	r7 = [p5 + CTX_NSUB];
	r0 = [p5 + CTX_HEROW];
	m0 = r0;
	r1 = [p5 + CTX_S];
	p4 = r1;             /* s steps */
	r1 = r1 << 1;
	r1 += 1;
	r1 *= r0;
	r1 += -4;
	m2 = r1;             /* I0 back from row 2s+1 to the next column pair's row 0 */
	r0 = [p5 + CTX_S];
	r0 += 2;
	r0 = r0 << 1;        /* 2*(s+2) bytes written a CS column (twice that a NQ column) */
	r1 = [p5 + CTX_KSB];
	r1 = r1 << 1;
	r1 = r1 - r0;
	m1 = r1;             /* from the end of what was written to column 2m+2 (NQ: twice) */
	p3 = r1;
	r0 = [p5 + CTX_R];
	r0 = r0 << 1;
	p0 = r0;             /* 2r rows */
	p1 = [p5 + CTX_CS2];
	p2 = [p5 + CTX_NQ2];
	r0 = p1;
	r1 = [p5 + CTX_KSB];
	r0 = r0 + r1;
	i2 = r0;
	r0 = p2;
	r0 = r0 + r1;
	r0 = r0 + r1;
	i3 = r0;
	r0 = [p5 + CTX_HE];
	i0 = r0;
	r0 = [p5 + CTX_L];
	r0 += 1;
	r0 >>= 1;
	lc1 = r0;            /* (L+1)/2 column pairs */
	r6 = 0;
	lsetup (.Lp1_c0, .Lp1_c1) lc1;
.Lp1_c0:
	i1 = i0;
	a1 = a0 = 0 || r1 = [i1 ++ m0] || nop;
	lsetup (.Lp1_i0, .Lp1_i1) lc0 = p0;
.Lp1_i0:
	r6 = r6 +|+ r1;
	r2.h = r1.h * r7.l, r2.l = r1.l * r7.l (is);
.Lp1_i1:
	r3 = (a1 += r2.h * r1.h), r2 = (a0 += r2.l * r1.l) || r1 = [i1 ++ m0] || nop;
	r0 = [i0 ++ m0];
	lsetup (.Lp1_s0, .Lp1_s1) lc0 = p4;
.Lp1_s0:
	r4 = r1 +|+ r0, r5 = r1 -|- r0 || r0 = [i0 ++ m0] || [p2++] = r2;
	r2.h = r5.h * r7.l, r2.l = r5.l * r7.l (is) || r1 = [i1 ++ m0] || w[p1++] = r6;
	a1 += r2.h * r4.h, a0 += r2.l * r4.l || w[i2++] = r6.h || nop;
	r6 = r6 +|+ r5 || [i3++] = r3 || nop;
	r4 = r1 +|+ r0, r5 = r1 -|- r0 || r0 = [i0 ++ m0] || nop;
	r2.h = r5.h * r7.l, r2.l = r5.l * r7.l (is) || r1 = [i1 ++ m0] || nop;
	r6 = r6 +|+ r5;
.Lp1_s1:
	r3 = (a1 += r2.h * r4.h), r2 = (a0 += r2.l * r4.l);
	/* row k = s, and k = s+1 repeating it (read when s is even), then the next column pair */
	[p2++] = r2;
	i0 -= m2;
	w[p1++] = r6;
	w[i2++] = r6.h;
	[i3++] = r3;
	[p2++] = r2;
	w[p1++] = r6;
	w[i2++] = r6.h;
	r6 = r6 -|- r6 || [i3++] = r3 || nop;  /* the next column pair's S = 0 */
	p1 = p1 + p3;
	p2 = p2 + p3;
	p2 = p2 + p3;
	i2 += m1;
	i3 += m1;
.Lp1_c1:
	i3 += m1;
	rts;

/* ------------------------------------------------------------------------------------------- */
/* Pass 2: the smallest u of the 2r x 2r sub-windows at even coordinates, from below, in units of
 * 2^15: rows k, k+1 (sub-windows starting at rows 2k, 2k+2) as the two 16-bit lanes, sliding two
 * columns a step; S = sum I (exact), Q = sum floor(n*I^2 column sums / 2^15), and
 *     u / 2^15 >= Q - round(S^2 / 2^15) - 1        (S^2 / 2^15 by a fractional dual multiply).
 * Eleven cycles per two sub-windows. vmin >= u_min >= 2^15 * max(0, min over lanes - 1). */
	.align 4
_ncc_pass2:
	r0 = [p5 + CTX_KSB];
	m0 = r0;
	r0 = r0 << 1;
	p4 = r0;             /* NQ2 column stride */
	r7.l = 0x7fff;
	r7.h = 0x7fff;
	r0 = [p5 + CTX_R];
	r0 = r0 << 1;
	[p5 + CTX_T1] = r0;  /* 2r columns */
	r0 = [p5 + CTX_S];
	r1 = r0;
	r1 += 1;
	[p5 + CTX_T3] = r1;  /* s+1 sub-windows a row */
	r0 += 2;
	r0 >>= 1;
	lc1 = r0;            /* pairs of rows (2j, 2j+1); with s even the last is (s, s+1 = s) */
	r0 = [p5 + CTX_CS2];
	[p5 + CTX_T0] = r0;
	r0 = [p5 + CTX_NQ2];
	r0 += 2;             /* high halves */
	[p5 + CTX_T2] = r0;
	lsetup (.Lp2_0, .Lp2_1) lc1;
.Lp2_0:
	r0 = [p5 + CTX_T0];
	i0 = r0;
	i1 = r0;
	r0 += 4;
	[p5 + CTX_T0] = r0;
	r0 = [p5 + CTX_T2];
	p0 = r0;             /* entering column, row k */
	p2 = r0;             /* leaving column, row k */
	r1 = r0;
	r1 += 4;
	p1 = r1;             /* row k+1 */
	p3 = r1;
	r0 += 8;
	[p5 + CTX_T2] = r0;
	r4 = 0;
	r5 = 0;
	r0 = [p5 + CTX_T1];
	lc0 = r0;
	lsetup (.Lp2_i0, .Lp2_i1) lc0;
.Lp2_i0:
	mnop || r1.l = w[p0 ++ p4] || r0 = [i1 ++ m0];
	r4 = r4 +|+ r0 || r1.h = w[p1 ++ p4] || nop;
.Lp2_i1:
	r5 = r5 +|+ r1;
	r6 = [p5 + CTX_T3];
	lc0 = r6;
	lsetup (.Lp2_s0, .Lp2_s1) lc0;
.Lp2_s0:
	r3.h = r4.h * r4.h, r3.l = r4.l * r4.l || r0 = [i1 ++ m0] || r1.l = w[p0 ++ p4];
	r3 = r5 -|- r3 || r2 = [i1 ++ m0] || r1.h = w[p1 ++ p4];
	r7 = min(r7, r3) (v) || r6.l = w[p0 ++ p4] || nop;
	r0 = r0 +|+ r2 || r3 = [i0 ++ m0] || r6.h = w[p1 ++ p4];
	r0 = r0 -|- r3 || r2 = [i0 ++ m0] || r3.l = w[p2 ++ p4];
	r0 = r0 -|- r2 || r3.h = w[p3 ++ p4] || nop;
	r4 = r4 +|+ r0 || r2.l = w[p2 ++ p4] || nop;
	r1 = r1 +|+ r6 || r2.h = w[p3 ++ p4] || nop;
	r1 = r1 -|- r3;
	r1 = r1 -|- r2;
.Lp2_s1:
	r5 = r5 +|+ r1;
.Lp2_1:
	nop;
	r0 = r7.l (x);
	r1 = r7 >>> 16;
	r0 = min(r0, r1);
	r0 += -1;
	r1 = 0;
	r0 = max(r0, r1);
	r0 = r0 << 15;
	[p5 + CTX_VMIN] = r0;
	rts;

/* ------------------------------------------------------------------------------------------- */
/* The MAC pass. Two horizontally adjacent candidates (e = 2p, 2p+1) at once: for template
 * element t = i*w + j, one 32-bit load brings (I[2p+j], I[2p+j+1]) of row d+i (from He when j is
 * even, Ho when odd) and
 *     A1 += T'[t] * I[2p+j+1],  A0 += T'[t] * I[2p+j]
 * is one dual MAC. T' comes from TF two elements per load (a circular buffer of (N+1)/2 words),
 * so every other cycle has a free slot; two of them store the previous pair's results. The N
 * issues of a pair are unrolled (gas macros below, one copy per radius); each loads the data of
 * the next element, jumping to the next row (M1, M2) or to the next pair (M3, M0) with the
 * post-modify of the row's last load, so consecutive pairs run back to back in a zero-overhead
 * loop: N cycles for two candidates.
 * The last column (e = 2s) has no partner: there both MACs work on one candidate, A0 on the even
 * and A1 on the odd elements of a row, with T' from TP (rows (0, T'0, .., T'2r)) against Ho words
 * (I[2s-1+2q], I[2s+2q]): w*(r+1) + 1 cycles for that candidate.
 * Registers: R0 template pair, R1 He data, R2 Ho data, R7:R6 the results. */
	.macro EMIT3 mac, ld, s2
	\mac || \ld || \s2;
	.endm

	.macro PAIR_S2 mac, ld
	.if ((tt % 2) == 1) || (tt == pn - 1)
	EMIT3 "\mac", "\ld", "r0 = [i0++]"
	.elseif tt == 0
	EMIT3 "\mac", "\ld", "[i3++] = r6"
	.elseif tt == 2
	EMIT3 "\mac", "\ld", "[i3++] = r7"
	.elseif pbuild == 0
	EMIT3 "\mac", "\ld", "nop"
	/* the copy program: load the chunk's pointers, then per pixel a byte load and two
	 * halfword stores (one P-register access per cycle: the free slot of even cycles) */
	.elseif tt == 4
	EMIT3 "\mac", "\ld", "p0 = [p3++]"
	.elseif tt == 6
	EMIT3 "\mac", "\ld", "p1 = [p3++]"
	.elseif tt == 8
	EMIT3 "\mac", "\ld", "p2 = [p3++]"
	.elseif (tt >= 10) && (tt < 10 + 6 * CHUNK) && (((tt - 10) % 6) == 0)
	EMIT3 "\mac", "\ld", "r3 = b[p0++] (z)"
	.elseif (tt >= 12) && (tt < 12 + 6 * CHUNK) && (((tt - 12) % 6) == 0)
	EMIT3 "\mac", "\ld", "w[p1++] = r3"
	.elseif (tt >= 14) && (tt < 14 + 6 * CHUNK) && (((tt - 14) % 6) == 0)
	EMIT3 "\mac", "\ld", "w[p2++] = r3"
	.else
	EMIT3 "\mac", "\ld", "nop"
	.endif
	.endm

	.macro PAIR_LD mac
	.if tt == pn - 1
	PAIR_S2 "\mac", "r1 = [i1++]"
	.else
	.set nj, (tt + 1) % pw
	.set ni, (tt + 1) / pw
	.if (nj % 2) == 0
	.if nj == 2 * pr
	.if ni == 2 * pr
	PAIR_S2 "\mac", "r1 = [i1 ++ m3]"
	.else
	PAIR_S2 "\mac", "r1 = [i1 ++ m1]"
	.endif
	.else
	PAIR_S2 "\mac", "r1 = [i1++]"
	.endif
	.else
	.if nj == 2 * pr - 1
	.if ni == 2 * pr
	PAIR_S2 "\mac", "r2 = [i2 ++ m0]"
	.else
	PAIR_S2 "\mac", "r2 = [i2 ++ m2]"
	.endif
	.else
	PAIR_S2 "\mac", "r2 = [i2++]"
	.endif
	.endif
	.endif
	.endm

	.macro PAIR_MAC
	.set cj, tt % pw
	.if (tt % 2) == 0
	.if (cj % 2) == 0
	.if tt == 0
	PAIR_LD "a1 = r0.l * r1.h, a0 = r0.l * r1.l (is)"
	.elseif tt == pn - 1
	PAIR_LD "r7 = (a1 += r0.l * r1.h), r6 = (a0 += r0.l * r1.l) (is)"
	.else
	PAIR_LD "a1 += r0.l * r1.h, a0 += r0.l * r1.l (is)"
	.endif
	.else
	PAIR_LD "a1 += r0.l * r2.h, a0 += r0.l * r2.l (is)"
	.endif
	.else
	.if (cj % 2) == 0
	PAIR_LD "a1 += r0.h * r1.h, a0 += r0.h * r1.l (is)"
	.else
	PAIR_LD "a1 += r0.h * r2.h, a0 += r0.h * r2.l (is)"
	.endif
	.endif
	.endm

	/* N issues; the label goes on the last one (the loop end) */
	.macro PAIR_BODY r, last
	.set pr, \r
	.set pw, 2 * \r + 1
	.set pn, pw * pw
	.set tt, 0
	.rept pn
	.if tt == pn - 1
\last:
	.endif
	PAIR_MAC
	.set tt, tt + 1
	.endr
	.endm

	.macro SINGLE_LD mac
	.if gg == pg - 1
	EMIT3 "\mac", "[i3++] = r6", "nop"
	.else
	.set nq, (gg + 1) % (pr + 1)
	.set ni, (gg + 1) / (pr + 1)
	.if nq == pr
	.if ni == 2 * pr
	EMIT3 "\mac", "r1 = [i1 ++ m3]", "r0 = [i0++]"
	.else
	EMIT3 "\mac", "r1 = [i1 ++ m1]", "r0 = [i0++]"
	.endif
	.else
	EMIT3 "\mac", "r1 = [i1++]", "r0 = [i0++]"
	.endif
	.endif
	.endm

	/* w*(r+1) issues (the last stores the previous candidate's num), then num = A0 + A1 while
	 * loading the next candidate's first operands */
	.macro SINGLE_BODY r, last
	.set pr, \r
	.set pw, 2 * \r + 1
	.set pg, pw * (\r + 1)
	.set gg, 0
	.rept pg
	.if gg == 0
	SINGLE_LD "a1 = r0.h * r1.h, a0 = r0.l * r1.l (is)"
	.else
	SINGLE_LD "a1 += r0.h * r1.h, a0 += r0.l * r1.l (is)"
	.endif
	.set gg, gg + 1
	.endr
\last:
	r6 = (a0 += a1) || r1 = [i1++] || r0 = [i0++];
	.endm

	/* one column pair: 2s+1 pairs of candidates (LC0 = P4), then the next column's pointers */
	.macro MAC_COLUMNS r, lab, b
	.set pbuild, \b
	lsetup (\lab\()_c0, \lab\()_c1) lc1;
\lab\()_c0:
	lsetup (\lab\()_d0, \lab\()_d1) lc0 = p4;
\lab\()_d0:
	PAIR_BODY \r, \lab\()_d1
	i1 = r4;
	i2 = r5;
	r4 += 4;
	r5 += 4;
\lab\()_c1:
	r1 = [i1++];
	.endm

	.macro MACPASS r
	.align 4
_ncc_mac\r:
	r0 = [p5 + CTX_TF];
	i0 = r0;
	b0 = r0;
	r0 = ((2 * \r + 1) * (2 * \r + 1) + 1) / 2 * 4;
	l0 = r0;
	r1 = [p5 + CTX_HEROW];
	r2 = r1;
	r0 = 2 * \r;
	r2 *= r0;            /* 2r rows */
	r0 = r1;
	r0 += -4 * \r;
	m1 = r0;             /* He: to the next row */
	r0 = r0 - r2;
	m3 = r0;             /* He: from the last row to the next pair's first */
	r0 = r1;
	r0 += -4 * (\r - 1);
	m2 = r0;             /* Ho: to the next row */
	r0 = r0 - r2;
	m0 = r0;             /* Ho: to the next pair */
	r0 = [p5 + CTX_NP];
	r0 += -8;
	i3 = r0;
	r6 = [p5 + CTX_S];
	r7 = r6 << 1;
	r7 += 1;
	p4 = r7;             /* 2s+1 rows of candidates */
	r4 = [p5 + CTX_HE];
	r5 = [p5 + CTX_HO];
	i1 = r4;
	i2 = r5;
	r4 += 4;
	r5 += 4;
	r1 = [i1++];
	r0 = [i0++];
	.if \r == 5
	r7 = [p5 + CTX_PIPE];
	cc = r7 == 0;
	if cc jump .Lmc\r\()_plain;
	/* the first NB column pairs also run the copy program */
	p3 = [p5 + CTX_TAB];
	r7 = [p5 + CTX_NB];
	r6 = r6 - r7;
	[p5 + CTX_T1] = r6;  /* the other column pairs (R6, R7 become results) */
	lc1 = r7;
	MAC_COLUMNS \r, .Lmb\r, 1
	r3 = [p5 + CTX_T1];  /* (R0, R1 hold the next pair's first operands) */
	cc = r3 == 0;
	if cc jump .Lmc\r\()_last;
	lc1 = r3;
	jump .Lmc\r\()_cols;
	.endif
.Lmc\r\()_plain:
	lc1 = r6;
.Lmc\r\()_cols:
	MAC_COLUMNS \r, .Lmc\r, 0
.Lmc\r\()_last:
	/* the last pair's A1 result (R7) is stored after the last column, whose first (empty)
	 * store lands in its place: so NS follows NP with no gap */
	[i3++] = r6;
	p0 = [p5 + CTX_NS];
	/* the last column */
	r0 = [p5 + CTX_TP];
	i0 = r0;
	b0 = r0;
	r0 = (2 * \r + 1) * (\r + 1) * 4;
	l0 = r0;
	r0 = [p5 + CTX_S];
	r0 += -1;
	r0 = r0 << 2;
	r1 = [p5 + CTX_HO];
	r0 = r0 + r1;
	i1 = r0;
	r1 = [i1++];
	r0 = [i0++];
	lsetup (.Lms\r\()_0, .Lms\r\()_1) lc0 = p4;
.Lms\r\()_0:
	SINGLE_BODY \r, .Lms\r\()_1
	[i3++] = r6;
	[i3++] = r6;         /* d = 2s+1 repeats 2s */
	[p0 + -4] = r7;
	l0 = 0;
	rts;
	.endm

	/* The passes of radii 1 to 4 (2.7 KB) run from SDRAM through the instruction cache: the
	 * robot and the benches use radius 5, and L1 instruction SRAM is full with the kernels'
	 * hot code. Their first call in a run pays the cache's line fills. */
	.text
	MACPASS 1
	MACPASS 2
	MACPASS 3
	MACPASS 4
	.section .l1.text, "ax"
	MACPASS 5

	.align 4
_ncc_macpass:
	r0 = [p5 + CTX_R];
	r1 = 5;
	cc = r0 == r1;
	if !cc jump 1f;      /* the robot's radius first: a taken branch costs 9 cycles unhinted */
	jump.l _ncc_mac5;
1:	r1 = 1;
	cc = r0 == r1;
	if !cc jump 2f;
	jump.l _ncc_mac1;
2:	r1 = 2;
	cc = r0 == r1;
	if !cc jump 3f;
	jump.l _ncc_mac2;
3:	r1 = 3;
	cc = r0 == r1;
	if !cc jump 4f;
	jump.l _ncc_mac3;
4:	r1 = 4;
	cc = r0 == r1;
	if !cc jump 5f;
	jump.l _ncc_mac4;
5:	jump.l _ncc_mac5;

/* ------------------------------------------------------------------------------------------- */
/* Helpers. MUL64: R1:R0 = R0 * R1 (unsigned 32 x 32 -> 64); clobbers R2-R5. */
	.macro MUL64
	r3 = r0.h * r1.h, r2 = r0.l * r1.l (fu);
	r5 = r0.h * r1.l, r4 = r0.l * r1.h (fu);
	r4 = r4 + r5 (ns);
	cc = ac0;
	r5 = cc;
	r5 = r5 << 16;
	r3 = r3 + r5;
	r5 = r4 << 16;
	r4 = r4 >> 16;
	r3 = r3 + r4;
	r0 = r2 + r5 (ns);
	cc = ac0;
	r5 = cc;
	r1 = r3 + r5;
	.endm

	.align 4
_ncc_mul64:
	MUL64
	rts;

/* _ncc_isqrt: R0 = floor(sqrt(R0)), bit by bit from the top: y + b is kept when (y + b)^2 <= x.
 * Clobbers R1-R5, LC1. */
	.align 4
_ncc_isqrt:
	cc = r0 == 0;
	if cc jump .Lq_out;
	r1.l = signbits r0;  /* bit length of x = 31 - R1 (x < 2^31) or 32 (x >= 2^31) */
	r1 = r1.l (x);
	r2 = 30;
	r1 = r2 - r1;        /* bit length - 1 */
	cc = r0 < 0;
	r3 = 31;
	if cc r1 = r3;
	r1 >>= 1;            /* the root's top bit */
	r2 = 1;
	r2 <<= r1;
	r1 += 1;
	lc1 = r1;
	r1 = 0;              /* y */
	lsetup (.Lq0, .Lq1) lc1;
.Lq0:
	r3 = r1 + r2;
	r4 = r3.l * r3.l (fu);
	cc = r4 <= r0 (iu);
	if cc r1 = r3;
.Lq1:
	r2 >>= 1;
	r0 = r1;
.Lq_out:
	rts;

/* _ncc_udiv: R0 = R0 / R1 (unsigned, truncating) for R1 < 2^16 and a quotient < 2^17; the
 * quotient bits enter R3 through CC. Clobbers R1-R4, LC1. */
	.align 4
_ncc_udiv:
	r2 = r1 << 16;
	r3 = 0;
	p0 = 17;
	lsetup (.Lv0, .Lv1) lc1 = p0;
.Lv0:
	cc = r2 <= r0 (iu);
	r4 = r0 - r2;
	if cc r0 = r4;
	r3 = rot r3 by 1;
.Lv1:
	r2 >>= 1;
	r0 = r3;
	rts;

/* _ncc_compare: R0 = sign(score_a - score_b) for R0 = num_a, R1 = v_a, R2 = num_b, R3 = v_b:
 * signs first, then num_a^2 * v_b against num_b^2 * v_a as 96-bit products. */
	.align 4
_ncc_compare:
	[--sp] = rets;
	r4 = r0 >>> 31;
	r5 = -r0;
	r5 >>= 31;
	r4 = r4 + r5;        /* sign(num_a) */
	r6 = r2 >>> 31;
	r5 = -r2;
	r5 >>= 31;
	r6 = r6 + r5;        /* sign(num_b) */
	cc = r4 == r6;
	if cc jump .Lc_same;
	r0 = 1;
	cc = r6 < r4;
	if cc jump .Lc_out;
	r0 = -1;
	jump .Lc_out;
.Lc_same:
	cc = r4 == 0;
	if !cc jump .Lc_nz;
	r0 = 0;
	jump .Lc_out;
.Lc_nz:
	[p5 + CTX_T5] = r4;
	r0 = abs r0;
	r2 = abs r2;
	[p5 + CTX_T0] = r1;  /* v_a */
	[p5 + CTX_T1] = r3;  /* v_b */
	[p5 + CTX_T2] = r2;  /* |num_b| */
	r1 = r0;
	MUL64                /* num_a^2 */
	r3 = [p5 + CTX_T1];
	call .Lc_times;      /* (R2, R1, R0) = R1:R0 * R3 */
	[p5 + CTX_T6] = r0;
	[p5 + CTX_T7] = r1;
	[p5 + CTX_T8] = r2;
	r0 = [p5 + CTX_T2];
	r1 = r0;
	MUL64
	r3 = [p5 + CTX_T0];
	call .Lc_times;
	r3 = [p5 + CTX_T8];
	r4 = [p5 + CTX_T7];
	r5 = [p5 + CTX_T6];
	/* left (R3, R4, R5) against right (R2, R1, R0), most significant first */
	r6 = 1;
	cc = r2 < r3 (iu);
	if cc jump .Lc_sign;
	r6 = -1;
	cc = r3 < r2 (iu);
	if cc jump .Lc_sign;
	r6 = 1;
	cc = r1 < r4 (iu);
	if cc jump .Lc_sign;
	r6 = -1;
	cc = r4 < r1 (iu);
	if cc jump .Lc_sign;
	r6 = 1;
	cc = r0 < r5 (iu);
	if cc jump .Lc_sign;
	r6 = -1;
	cc = r5 < r0 (iu);
	if cc jump .Lc_sign;
	r6 = 0;
.Lc_sign:
	r4 = [p5 + CTX_T5];
	r0 = r6;
	cc = r4 < 0;
	if !cc jump .Lc_out;
	r0 = -r6;
.Lc_out:
	rets = [sp++];
	rts;
/* (R2, R1, R0) = (R1:R0) * R3, a 64 x 32 -> 96-bit product */
.Lc_times:
	[--sp] = rets;
	[p5 + CTX_T3] = r1;
	[p5 + CTX_T4] = r3;
	r1 = r3;
	MUL64                /* lo * v */
	[p5 + CTX_T9] = r0;
	[p5 + CTX_T10] = r1;
	r0 = [p5 + CTX_T3];
	r1 = [p5 + CTX_T4];
	MUL64                /* hi * v */
	r2 = [p5 + CTX_T10];
	r0 = r0 + r2 (ns);
	cc = ac0;
	r2 = cc;
	r2 = r1 + r2;
	r1 = r0;
	r0 = [p5 + CTX_T9];
	rets = [sp++];
	rts;

/* _ncc_tau: the filter threshold for the best so far (BN, BV): any candidate that ties or beats
 * it has num >= num_b * sqrt(v / v_b) >= num_b * sqrt(vmin / v_b) >= tau, with
 * tau = floor(num_b * f / 2^15), f = floor(2^15 * isqrt(vmin) / ceil(sqrt(v_b))) (<= 32767).
 * A best with num_b = 0 can be tied by num = 0 (tau = 0); one with num_b < 0 by anything. */
	.align 4
_ncc_tau:
	[--sp] = rets;
	r0 = [p5 + CTX_BN];
	r1 = 0;
	cc = r0 == 0;
	if cc jump .Lu_set;
	r1.l = 0;
	r1.h = 0x8000;
	cc = r0 < 0;
	if cc jump .Lu_set;
	r0 = [p5 + CTX_BV];
	call _ncc_isqrt;
	r1 = r0.l * r0.l (is);
	r2 = [p5 + CTX_BV];
	cc = r1 < r2 (iu);
	r3 = r0;
	r3 += 1;
	if cc r0 = r3;       /* ceil(sqrt(v_b)) */
	r1 = r0;
	r0 = [p5 + CTX_QMIN];
	r2 = 32767;
	cc = r0 < r1;
	if !cc jump .Lu_f;   /* vmin and v_b share their ceiling root: f = 32767 */
	r0 = r0 << 16;       /* (qmin << 15), doubled for DIVS/DIVQ */
	divs (r0, r1);
	p0 = 15;
	lsetup (.Lu_d, .Lu_d) lc1 = p0;
.Lu_d:
	divq (r0, r1);
	r2 = r0.l (z);
.Lu_f:
	r0 = r2;
	r2 = [p5 + CTX_BN];
	r3 = r2 >> 15;
	r3 = r3.l * r0.l (is);
	r2 = r2 << 17;
	r2 = r2 >> 17;
	r2 = r2.l * r0.l (is);
	r2 = r2 >> 15;
	r1 = r3 + r2;
.Lu_set:
	[p5 + CTX_TAU] = r1;
	rets = [sp++];
	rts;

/* _ncc_consider: R0 = e, R1 = d, R2 = num of candidate (e, d): make it the best if it beats the
 * best so far (exact comparison), or ties it and comes first in the tie order. */
	.align 4
_ncc_consider:
	r3 = [p5 + CTX_TAU];
	cc = r2 < r3;
	if cc jump .Lk_ret;
	r3 = [p5 + CTX_BE];
	cc = r0 == r3;
	if !cc jump .Lk_go;
	r3 = [p5 + CTX_BD];
	cc = r1 == r3;
	if cc jump .Lk_ret;  /* the best itself */
.Lk_go:
	[--sp] = rets;
	[p5 + CTX_T11] = r0;
	[p5 + CTX_T12] = r1;
	[p5 + CTX_T13] = r2;
	call _ncc_exactv;
	r1 = r0;             /* v */
	[p5 + CTX_T14] = r1;
	r2 = [p5 + CTX_T13];
	r0 = r2;
	r2 = [p5 + CTX_BN];
	r3 = [p5 + CTX_BV];
	call _ncc_compare;
	cc = r0 < 0;
	if cc jump .Lk_out;
	/* tie key: (|dx| + |dy|) << 16 | d << 8 | e */
	r4 = [p5 + CTX_S];
	r1 = [p5 + CTX_T11];
	r2 = [p5 + CTX_T12];
	r5 = r1 - r4;
	r5 = abs r5;
	r6 = r2 - r4;
	r6 = abs r6;
	r5 = r5 + r6;
	r5 = r5 << 16;
	r6 = r2 << 8;
	r5 = r5 + r6;
	r5 = r5 + r1;
	cc = r0 == 0;
	if !cc jump .Lk_take;
	r6 = [p5 + CTX_BKEY];
	cc = r5 < r6;
	if !cc jump .Lk_out;
.Lk_take:
	[p5 + CTX_BKEY] = r5;
	[p5 + CTX_BE] = r1;
	[p5 + CTX_BD] = r2;
	r0 = [p5 + CTX_T13];
	[p5 + CTX_BN] = r0;
	r0 = [p5 + CTX_T14];
	[p5 + CTX_BV] = r0;
	call _ncc_tau;
.Lk_out:
	rets = [sp++];
.Lk_ret:
	rts;

/* _ncc_exactv: R0 = v = N*SII - SI^2 of candidate (e = R0, d = R1), exactly: its rows d..d+2r are
 * the 2r-row block starting at the even row 2k in {d, d+1} (CS2, NQ2 over its 2r+1 columns) and
 * one more row (d+2r or d), read from the 16-bit pixels (r full words of He or Ho and the low
 * half of one more). NQ2 holds 2n*SII; 2n = 2^DSH * odd divides it exactly (shift, then multiply
 * by odd's inverse mod 2^32). Clobbers R1-R7, P0-P2, A0-A1, LC1. */
	.align 4
_ncc_exactv:
	[p5 + CTX_T5] = r0;
	[p5 + CTX_T6] = r1;
	r2 = r1;
	r2 += 1;
	r2 >>= 1;            /* k */
	r3 = [p5 + CTX_KSB];
	r4 = r3;
	r4 *= r0;            /* e columns of CS2 */
	r5 = r2 << 1;
	r5 = r5 + r4;
	r6 = [p5 + CTX_CS2];
	r5 = r5 + r6;
	p0 = r5;
	r4 = r4 << 1;        /* of NQ2 */
	r5 = r2 << 2;
	r5 = r5 + r4;
	r6 = [p5 + CTX_NQ2];
	r5 = r5 + r6;
	p1 = r5;
	p2 = r3;             /* CS2 column stride; NQ2's is twice */
	r4 = 0;
	r5 = 0;
	r6 = [p5 + CTX_WT];
	lc1 = r6;
	lsetup (.Lx_c0, .Lx_c1) lc1;
.Lx_c0:
	r6 = w[p0 ++ p2] (z);
	r7 = [p1 ++ p2];
	r4 = r4 + r6;
.Lx_c1:
	r5 = r5 + r7 (ns) || r7 = [p1 ++ p2] || nop;  /* (the second half of NQ2's stride) */
	/* the extra row: d + 2r if d is even, else d */
	r1 = [p5 + CTX_T6];
	r0 = [p5 + CTX_T5];
	r6 = [p5 + CTX_R];
	r6 = r6 << 1;
	cc = bittst(r1, 0);
	r7 = 0;
	if cc r6 = r7;
	r1 = r1 + r6;        /* its row */
	r2 = [p5 + CTX_HEROW];
	r2 *= r1;
	r3 = r0 << 1;
	r2 = r2 + r3;
	r3 = [p5 + CTX_HE];
	r6 = [p5 + CTX_HO];
	r6 += -2;
	cc = bittst(r0, 0);
	if cc r3 = r6;
	r2 = r2 + r3;
	p0 = r2;
	r6 = 0;
	a1 = a0 = 0;
	p1 = [p5 + CTX_R];
	r1 = [p0++];
	lsetup (.Lx_q0, .Lx_q1) lc1 = p1;
.Lx_q0:
	r6 = r6 +|+ r1;
.Lx_q1:
	a1 += r1.h * r1.h, a0 += r1.l * r1.l (is) || r1 = [p0++] || nop;
	r1 = r1.l (z);
	r6 = r6 +|+ r1;
	a0 += r1.l * r1.l (is);
	r3 = a1 + a0, r2 = a1 - a0;  /* SII of the row */
	r0 = r6.l (z);
	r1 = r6 >> 16;
	r0 = r0 + r1;
	r4 = r4 + r0;        /* SI */
	r0 = [p5 + CTX_DSH];
	r5 >>= r0;
	r0 = [p5 + CTX_DINV];
	r5 *= r0;            /* SII of the block */
	r5 = r5 + r3;
	r0 = [p5 + CTX_N];
	r5 *= r0;
	r4 = r4.l * r4.l (is);
	r0 = r5 - r4;
	rts;

/* _ncc_num: R2 = num of candidate (e = R0, d = R1); clobbers R3, R4, P0. */
	.align 4
_ncc_num:
	r3 = [p5 + CTX_S];
	r3 = r3 << 1;
	cc = r0 == r3;
	if cc jump .Ln_single;
	r3 += 1;
	r4 = r0 >> 1;
	r3 *= r4;
	r3 = r3 + r1;
	r3 = r3 << 3;
	r4 = r0 << 31;
	r4 = r4 >> 29;       /* (e & 1) * 4 */
	r3 = r3 + r4;
	r4 = [p5 + CTX_NP];
	r3 = r3 + r4;
	p0 = r3;
	jump .Ln_load;       /* (its cycles cover P0's move) */
.Ln_single:
	r3 = r1 << 2;
	r4 = [p5 + CTX_NS];
	r3 = r3 + r4;
	p0 = r3;
.Ln_load:
	r2 = [p0];
	rts;

/* ------------------------------------------------------------------------------------------- */
/* Selection. The best starts as the candidate at the previous point's offset (features of one
 * frame tend to move alike); then every group of four pairs of candidates is tested against
 * tau in ten cycles, and only a candidate that reaches it gets the exact comparison
 * (_ncc_consider). */
	.align 4
_ncc_select:
	[--sp] = rets;
	r0 = [p5 + CTX_VMIN];
	r0 >>= 15;           /* vmin = m * 2^15: isqrt(vmin) >= 181 * isqrt(m) */
	call _ncc_isqrt;
	r1 = 181;
	r0 *= r1;
	[p5 + CTX_QMIN] = r0;
	/* the seed */
	r4 = [p5 + CTX_S];
	r5 = -r4;
	r0 = [p5 + CTX_SEEDX];
	r0 = max(r0, r5);
	r0 = min(r0, r4);
	r0 = r0 + r4;
	r1 = [p5 + CTX_SEEDY];
	r1 = max(r1, r5);
	r1 = min(r1, r4);
	r1 = r1 + r4;
	[p5 + CTX_BE] = r0;
	[p5 + CTX_BD] = r1;
	call _ncc_num;
	[p5 + CTX_BN] = r2;
	r0 = [p5 + CTX_BE];
	r1 = [p5 + CTX_BD];
	call _ncc_exactv;
	[p5 + CTX_BV] = r0;
	r0 = [p5 + CTX_BE];
	r1 = [p5 + CTX_BD];
	r4 = [p5 + CTX_S];
	r5 = r0 - r4;
	r5 = abs r5;
	r6 = r1 - r4;
	r6 = abs r6;
	r5 = r5 + r6;
	r5 = r5 << 16;
	r6 = r1 << 8;
	r5 = r5 + r6;
	r5 = r5 + r0;
	[p5 + CTX_BKEY] = r5;
	call _ncc_tau;
	/* every numerator, NP's pairs then NS's singles as one array of words (NS follows NP), in
	 * two segments: first from the seed's column pair to the end, then from the start to
	 * there (a good best early keeps tau high) */
	r2 = [p5 + CTX_S];
	r1 = r2 << 1;
	r1 += 1;             /* 2s+1 */
	r6 = r1;
	r6 *= r2;
	r6 = r6 << 1;        /* words of the pairs, 2s(2s+1) */
	[p5 + CTX_T16] = r6;
	r7 = r2 << 1;
	r7 += 2;
	r7 = r7 + r6;        /* all words: then NS's 2s+2 */
	r4 = [p5 + CTX_BE];
	r4 >>= 1;
	r5 = r2;
	r5 += -1;
	r4 = min(r4, r5);
	r4 *= r1;
	r4 = r4 << 1;        /* the seed's column pair's first word */
	r5 = r7 - r4;
	r3 = 7;
	r5 = r5 & r3;
	r4 = r4 + r5;        /* moved on so that the first segment is whole groups of 8 words */
	[p5 + CTX_SEGB] = r4;
	r0 = r4;
	r1 = r7 - r4;
	call .Ls_sweep;
	r0 = 0;
	r1 = [p5 + CTX_SEGB];
	call .Ls_sweep;
	rets = [sp++];
	rts;

/* .Ls_sweep: R0 = the first word, R1 = words: groups of 8 words (4 pairs) against tau in ten
 * issues, one load each (the words of a pair share a sub-bank: a dual load would cost the same
 * cycle again), then the last words one at a time in three. A group or word that reaches tau
 * is looked at word by word (.Ls_group, .Ls_word); the flagged group is twelve words behind
 * the loads, the flagged word one. */
.Ls_sweep:
	[--sp] = rets;
	r2 = [p5 + CTX_NP];
	r0 = r0 << 2;
	r0 = r0 + r2;        /* the first word's address */
	i0 = r0;
	r2 = 7;
	r2 = r2 & r1;
	[p5 + CTX_T17] = r2; /* words after the groups */
	r1 >>= 3;
	r2 = r1 << 5;
	r0 = r0 + r2;
	[p5 + CTX_T18] = r0; /* their address */
	p1 = r1;
	r3 = [p5 + CTX_TAU];
	cc = r1 == 0;
	if cc jump .Lsw_rest;
	r0 = [i0++];
	r1 = [i0++];
	r4 = [i0++];
	r5 = [i0++];
	cc = r3 < r3;
	lsetup (.Lsw_g0, .Lsw_g1) lc0 = p1;
.Lsw_g0:
	if cc jump .Lsw_gslow;
.Lsw_gback:
	r2 = max(r0, r1) || r0 = [i0++] || nop;
	r6 = max(r4, r5) || r1 = [i0++] || nop;
	r2 = max(r2, r6) || r4 = [i0++] || nop;
	r6 = max(r0, r1) || r5 = [i0++] || nop;
	r2 = max(r2, r6) || r0 = [i0++] || nop;
	r6 = max(r4, r5) || r1 = [i0++] || nop;
	r2 = max(r2, r6) || r4 = [i0++] || nop;
	mnop || r5 = [i0++] || nop;
.Lsw_g1:
	cc = r3 <= r2;
	if !cc jump .Lsw_rest (bp);
	call .Ls_group;
.Lsw_rest:
	r0 = [p5 + CTX_T17];
	p1 = r0;
	cc = r0 == 0;
	if cc jump .Lsw_out;
	r0 = [p5 + CTX_T18];
	i0 = r0;
	cc = r3 < r3;
	lsetup (.Lsw_w0, .Lsw_w1) lc0 = p1;
.Lsw_w0:
	if cc jump .Lsw_wslow;
.Lsw_wback:
	r2 = [i0++];
.Lsw_w1:
	cc = r3 <= r2;
	if !cc jump .Lsw_out (bp);
	call .Ls_oneword;
.Lsw_out:
	rets = [sp++];
	rts;
.Lsw_gslow:
	call .Ls_group;
	jump .Lsw_gback;
.Lsw_wslow:
	call .Ls_oneword;
	jump .Lsw_wback;

/* The flagged group (I0 - 48), two words at a time. Keeps R0, R1, R4, R5 (the next group's
 * first words), I0 and the sweep's loop registers; returns R3 = tau. */
.Ls_group:
	[--sp] = rets;
	[--sp] = r0;
	[--sp] = r1;
	[--sp] = r4;
	[--sp] = r5;
	r0 = i0;
	r0 += -48;
	p3 = r0;
	r0 += 32;
	p4 = r0;             /* the group's end (P3, P4 survive _ncc_consider) */
.Lgr_l:
	r0 = [p3++];
	r1 = [p3++];
	r2 = max(r0, r1);
	cc = r3 <= r2;
	if !cc jump .Lgr_n (bp);
	cc = r3 <= r0;
	if !cc jump .Lgr_b;
	[--sp] = r1;
	r2 = r0;
	r0 = p3;
	r0 += -8;
	call .Ls_word;
	r1 = [sp++];
.Lgr_b:
	cc = r3 <= r1;
	if !cc jump .Lgr_n;
	r2 = r1;
	r0 = p3;
	r0 += -4;
	call .Ls_word;
.Lgr_n:
	cc = p3 < p4 (iu);
	if cc jump .Lgr_l (bp);
	r5 = [sp++];
	r4 = [sp++];
	r1 = [sp++];
	r0 = [sp++];
	rets = [sp++];
	rts;

/* The flagged word (I0 - 4, its num in R2). Returns R3 = tau. */
.Ls_oneword:
	r0 = i0;
	r0 += -4;
/* .Ls_word: R0 = a word's address, R2 = its num: the exact comparison for its candidate. Word
 * q < 2s(2s+1) is lane q & 1 of pair q >> 1 = p*(2s+1) + d (e = 2p + lane); word 2s(2s+1) + d
 * is (2s, d), where d = 2s+1 only repeats 2s. Returns R3 = tau. */
.Ls_word:
	[--sp] = rets;
	r1 = [p5 + CTX_NP];
	r0 = r0 - r1;
	r0 >>= 2;            /* the word's index */
	r1 = [p5 + CTX_T16];
	cc = r0 < r1;
	if !cc jump .Lwd_single;
	r4 = r0 >> 1;        /* the pair */
	r5 = [p5 + CTX_RECIP];
	r5 = r4.l * r5.l (is);
	r5 >>= 16;           /* p = pair / (2s+1), exact for pair < 2^16 / (2s+1) */
	r6 = [p5 + CTX_S];
	r6 = r6 << 1;
	r6 += 1;
	r6 *= r5;
	r1 = r4 - r6;        /* d */
	r5 = r5 << 1;
	cc = bittst(r0, 0);
	r0 = cc;
	r0 = r0 + r5;        /* e */
	call _ncc_consider;
	jump .Lwd_out;
.Lwd_single:
	r1 = r0 - r1;        /* d */
	r0 = [p5 + CTX_S];
	r0 = r0 << 1;        /* e = 2s */
	cc = r0 < r1;
	if cc jump .Lwd_out;
	call _ncc_consider;
.Lwd_out:
	r3 = [p5 + CTX_TAU];
	rets = [sp++];
	rts;

/* ------------------------------------------------------------------------------------------- */
/* _ncc_score: R0 = the Q15 score of bvb/ncc.h for R0 = num, R1 = vt, R2 = v. */
	.align 4
_ncc_score:
	[--sp] = rets;
	cc = r0 == 0;
	if cc jump .Lsc_zero;
	[p5 + CTX_T0] = r0;
	r0 = r1;
	r1 = r2;
	call _ncc_mul64;     /* P = vt * v */
	cc = r1 == 0;
	if !cc jump .Lsc_hi (bp);
	cc = r0 == 0;
	if cc jump .Lsc_zero;
	r2 = 32;
	cc = r0 < 0;
	if cc jump .Lsc_b;
	r2.l = signbits r0;
	r2 = r2.l (x);
	r3 = 31;
	r2 = r3 - r2;
	jump .Lsc_b;
.Lsc_hi:
	r2.l = signbits r1;
	r2 = r2.l (x);
	r3 = 63;
	r2 = r3 - r2;
.Lsc_b:
	r2 += -31;           /* b - 31 */
	r2 >>>= 1;
	r2 = r2 << 1;        /* e */
	cc = r2 < 0;
	if cc jump .Lsc_neg;
	cc = r2 == 0;
	if cc jump .Lsc_p;
	r0 >>= r2;
	r3 = 32;
	r3 = r3 - r2;
	r1 <<= r3;
	r0 = r0 | r1;
	jump .Lsc_p;
.Lsc_neg:
	r3 = -r2;
	r0 <<= r3;
.Lsc_p:
	[p5 + CTX_T1] = r2;
	call _ncc_isqrt;
	[p5 + CTX_T2] = r0;
	r1 = [p5 + CTX_T0];
	r1 = abs r1;
	r2 = [p5 + CTX_T1];
	r2 >>>= 1;
	cc = r2 < 0;
	if cc jump .Lsc_up;
	r1 >>= r2;
	jump .Lsc_div;
.Lsc_up:
	r3 = -r2;
	r1 <<= r3;
.Lsc_div:
	r0 = r1 << 15;
	r1 = [p5 + CTX_T2];
	call _ncc_udiv;
	r1 = 32767;
	r0 = min(r0, r1);
	r1 = [p5 + CTX_T0];
	r2 = -r0;
	cc = r1 < 0;
	if cc r0 = r2;
	rets = [sp++];
	rts;
.Lsc_zero:
	r0 = 0;
	rets = [sp++];
	rts;

/* ------------------------------------------------------------------------------------------- */
BVB_FUNC bvb_ncc_scoremap_asm
	[--sp] = rets;
	[--sp] = (r7:4, p5:3);
	/* width [sp+44], height +48, x +52, y +56, radius +60, search +64, map +68, scratch +72 */
	r3 = [sp + 60];
	r4 = [sp + 64];
	p3 = [sp + 68];
	r6 = 1;
	cc = r3 < r6;
	if cc jump .Lsm_bad;
	r6 = MAX_RADIUS;
	cc = r6 < r3;
	if cc jump .Lsm_bad;
	r6 = 1;
	cc = r4 < r6;
	if cc jump .Lsm_bad;
	r6 = MAX_SEARCH;
	cc = r6 < r4;
	if cc jump .Lsm_bad;
	p5 = [sp + 72];
	[p5 + CTX_FRAME1] = r0;
	[p5 + CTX_FRAME2] = r1;
	[p5 + CTX_STRIDE] = r2;
	r0 = [sp + 44];
	[p5 + CTX_W] = r0;
	r0 = [sp + 48];
	[p5 + CTX_H] = r0;
	[p5 + CTX_R] = r3;
	[p5 + CTX_S] = r4;
	[p5 + CTX_RES] = p3;
	r0 = [sp + 52];
	[p5 + CTX_X] = r0;
	r1 = [sp + 56];
	[p5 + CTX_Y] = r1;
	call _ncc_layout;
	r0 = 0;
	[p5 + CTX_PIPE] = r0;    /* one point: nothing to copy ahead */
	r0 = [p5 + CTX_X];
	r1 = [p5 + CTX_Y];
	r2 = [p5 + CTX_R];
	r3 = [p5 + CTX_S];
	r2 = r2 + r3;
	r7 = 1;              /* status */
	r3 = r0 - r2;
	cc = r3 < 0;
	if cc jump .Lsm_zero;
	r3 = r1 - r2;
	cc = r3 < 0;
	if cc jump .Lsm_zero;
	r3 = r0 + r2;
	r4 = [p5 + CTX_W];
	cc = r3 < r4;
	if !cc jump .Lsm_zero;
	r3 = r1 + r2;
	r4 = [p5 + CTX_H];
	cc = r3 < r4;
	if !cc jump .Lsm_zero;
	call _ncc_template;
	r7 = 2;
	cc = r0 == 0;
	if cc jump .Lsm_zero;
	call _ncc_build;
	call _ncc_pass1;     /* the column sums _ncc_exactv reads */
	call _ncc_macpass;
	r0 = 0;
	[p5 + CTX_T16] = r0;  /* d */
.Lsm_row:
	r0 = 0;
	[p5 + CTX_T15] = r0;  /* e */
.Lsm_col:
	r0 = [p5 + CTX_T15];
	r1 = [p5 + CTX_T16];
	call _ncc_num;
	[p5 + CTX_T17] = r2;
	r0 = [p5 + CTX_T15];
	r1 = [p5 + CTX_T16];
	call _ncc_exactv;
	r2 = r0;
	r0 = [p5 + CTX_T17];
	r1 = [p5 + CTX_VT];
	p3 = [p5 + CTX_RES];  /* (_ncc_score keeps P3) */
	call _ncc_score;
	w[p3++] = r0;
	[p5 + CTX_RES] = p3;
	r1 = [p5 + CTX_S];
	r1 = r1 << 1;
	r0 = [p5 + CTX_T15];
	r0 += 1;
	[p5 + CTX_T15] = r0;
	cc = r1 < r0;
	if !cc jump .Lsm_col;
	r0 = [p5 + CTX_T16];
	r0 += 1;
	[p5 + CTX_T16] = r0;
	cc = r1 < r0;
	if !cc jump .Lsm_row;
	r0 = 0;
	w[p3++] = r0;
	jump .Lsm_done;
.Lsm_zero:
	/* border or flat template: all zero, then the status */
	r0 = [p5 + CTX_S];
	r0 = r0 << 1;
	r0 += 1;
	r0 *= r0;
	p0 = r0;
	r0 = 0;
	p3 = [p5 + CTX_RES];
	lsetup (.Lsm_z0, .Lsm_z0) lc0 = p0;
.Lsm_z0:
	w[p3++] = r0;
	w[p3++] = r7;
	jump .Lsm_done;
.Lsm_bad:
	r0 = 3;
	w[p3] = r0;
.Lsm_done:
	(r7:4, p5:3) = [sp++];
	rets = [sp++];
	rts;
BVB_ENDFUNC bvb_ncc_scoremap_asm

