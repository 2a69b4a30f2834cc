/* Seeded region growing and per-column free space (bvb/region.h).
 * (header completed below once measured) */

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

#define FS_HEIGHT 40
#define FS_MINGAP 44
#define FS_ROWS 48

	.align 4
	.global _bvb_free_space_asm
	.type _bvb_free_space_asm, STT_FUNC
_bvb_free_space_asm:
	[--sp] = (r7:4, p5:3);
	p5 = r1;			/* mask stride */
	r3 = [sp + FS_HEIGHT];
	p4 = [sp + FS_ROWS];
	r5 = [sp + FS_MINGAP];
	/* open every column: S = height - 1 */
	r6 = r1;
	r1 = r3;
	r1 += -1;
	p1 = r1;			/* y, from the bottom row */
	p0 = p4;
	p2 = r2;
	lsetup (.Lfs_init, .Lfs_init) lc0 = p2;
.Lfs_init:
	w[p0++] = r1;
	/* bottom row: mask + (height - 1) * stride */
	r1 *= r6;
	r0 = r0 + r1;
	p3 = r0;
	/* G = min(min_gap - 1, 32767) */
	r5 += -1;
	r1 = 32767 (x);
	r5 = min (r5, r1);
	m0 = r5;
	/* pairs - 1 in m2, the odd column flag in m1 */
	r0 = 1;
	r1 = r2 & r0;
	m1 = r1;
	r2 >>= 1;
	m3 = r2;			/* pairs */
	r2 += -1;
	m2 = r2;
	r7.l = 0x7fff;
	r7.h = 0x7fff;
	r4.l = 0x8000;
	r4.h = 0x8000;

.Lfs_row:
	/* per-row constants: y - 1 and the threshold minus one, in both lanes */
	r0 = p1;
	r1 = r0;
	r1 += -1;
	r6 = pack (r1.l, r1.l);
	r2 = m0;
	r2 = r2 + r1;
	r1 = 32767 (x);
	r2 = min (r2, r1);
	cc = r0 == 0;
	r1 = -1;
	if cc r2 = r1;
	r5 = pack (r2.l, r2.l);
	r3 = r4;
	i0 = p4;
	i1 = p4;
	p0 = p3;
	r0 = m3;
	cc = r0 == 0;
	if cc jump .Lfs_odd;
	/* first pair's loads; the loop loads one pair ahead */
	r1 = b[p0++] (z);
	r0 = b[p0++] (z);
	r2.l = w[i0++];
	r0 = pack (r0.l, r1.l);
	p2 = m2;
	cc = p2 == 0;
	if cc jump .Lfs_last;
	lsetup (.Lfs_pair, .Lfs_pair_end) lc0 = p2;
.Lfs_pair:
	r0 = r0 << 15 (v, s) || r1 = b[p0++] (z) || r2.h = w[i0++];
	r0 = r7 -|- r0;
	r0 = r6 +|+ r0 (s);
	r2 = min (r2, r0) (v);
	r0 = r5 -|- r2 (s);
	r0 = r0 & r4;
	r2 = r2 ^ r0;
	r3 = max (r3, r2) (v) || r0 = b[p0++] (z) || w[i1++] = r2.l;
.Lfs_pair_end:
	r0 = pack (r0.l, r1.l) || w[i1++] = r2.h || r2.l = w[i0++];
.Lfs_last:
	r0 = r0 << 15 (v, s) || r2.h = w[i0++];
	r0 = r7 -|- r0;
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
	if cc jump .Lfs_row_end;
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
.Lfs_row_end:
	/* every column decided (both lanes of the running max negative): stop early */
	r0 = r3 & r4;
	cc = r0 == r4;
	if cc jump .Lfs_decode;
	p3 -= p5;
	p1 += -1;
	cc = p1 < 0;
	if !cc jump .Lfs_row (bp);

.Lfs_decode:
	r2.l = 0x8000;
	r2.h = 0xffff;
	p0 = p4;
	r0 = m3;
	r1 = m1;
	r0 = r0 << 1;
	r0 = r0 + r1;
	p2 = r0;
	lsetup (.Lfs_dec, .Lfs_dec_end) lc0 = p2;
.Lfs_dec:
	r0 = w[p0] (x);
	cc = r0 == -1;
	r1 = r0 ^ r2;
	if !cc r0 = r1;
.Lfs_dec_end:
	w[p0++] = r0;
	(r7:4, p5:3) = [sp++];
	rts;
	.size _bvb_free_space_asm, . - _bvb_free_space_asm
