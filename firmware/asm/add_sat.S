/* Saturating 8-bit add, dst = min(255, a + b) (bvb/add_sat.h).
 *
 * Cycles (bfbench bench, simulator): 5 per pixel, 8 per row, 12 per call; 160x120: 96,972. Lower bound: each pixel needs two byte loads and one byte store, and one issue carries
 * at most two loads or one load and one store: 1.5 cycles per pixel with byte accesses, 0.75 with
 * word accesses and packed byte arithmetic. This kernel exists to exercise the harness, so it
 * keeps the plain byte loop and uses only scratch registers (no saves).
 *
 * Frames in SDRAM and the scratch in L1: the smallest user of the row-band stream
 * (bvb/stream.h): fill the three planes, bvb_stream_open, then per bvb_stream_next band the
 * same byte loop over the band as one row (contiguous in L1); the direct path otherwise.
 * Bound: the bus. 2 bytes in and 1 out per pixel at 0.5 byte per core cycle (bvb/dma.h) is
 * 6 cycles per pixel, above the byte loop's 5 (and the 1.5 of its loads and stores).
 * Modelled (bfbench bench, --timing bf537, frames in SDRAM, scratch in L1 bank B): 160x120
 * 130,024 (6.77 per pixel), 320x240 487,294 (6.34); the rest over 6.00 is the stream's per-job
 * cost and gaps, the last band's compute after its rows arrive, and band 0's start. Before
 * (frames through the write-back data cache): 333,740 (17.4) / 1,277,004 (16.6). */
#include "bvb/asm.h"
#include "bvb/stream.h"

/* bvb_add_sat_u8_asm(a, b, dst, width, height, src_stride, dst_stride, scratch): a, b, dst in
 * R0-R2, the rest on the stack, named here for after the prologue's 16 bytes. */
#define PUSHED 16			/* RETS, and 12 bytes of outgoing argument space */
#define ARG_WIDTH BVB_ARG(4, PUSHED)
#define ARG_HEIGHT BVB_ARG(5, PUSHED)
#define ARG_SRC_STRIDE BVB_ARG(6, PUSHED)
#define ARG_DST_STRIDE BVB_ARG(7, PUSHED)
#define ARG_SCRATCH BVB_ARG(8, PUSHED)

BVB_FUNC bvb_add_sat_u8_asm
	[--sp] = rets;
	sp += -12;		/* the C routines' outgoing argument space */
	p0 = [sp + ARG_SCRATCH];
	cc = p0 == 0;
	if cc jump .Ldirect;
	/* The stream's three planes (bvb/stream.h), all width bytes a row. */
	[p0 + ST_SRC0] = r0;
	[p0 + ST_SRC1] = r1;
	[p0 + ST_DST] = r2;
	r3 = [sp + ARG_WIDTH];
	[p0 + ST_SB0] = r3;
	[p0 + ST_SB1] = r3;
	[p0 + ST_DB] = r3;
	r3 = [sp + ARG_SRC_STRIDE];
	[p0 + ST_SS0] = r3;
	[p0 + ST_SS1] = r3;
	r3 = [sp + ARG_DST_STRIDE];
	[p0 + ST_DS] = r3;
	r3 = [sp + ARG_HEIGHT];
	[p0 + ST_ROWS] = r3;
	r0 = p0;
	call _bvb_stream_open;
	cc = r0 == 0;
	if !cc jump .Lrefused;
	/* Each band, contiguous in L1, is one row of n * width pixels. */
.Lband:
	r0 = [sp + ARG_SCRATCH];
	call _bvb_stream_next;
	cc = r0 == 0;
	if cc jump .Lret;
	p0 = [sp + ARG_SCRATCH];
	r2 = [p0 + ST_DB];
	r2 *= r0;
	r1 = [p0 + ST_IN0];
	i0 = r1;
	r1 = [p0 + ST_IN1];
	i1 = r1;
	r1 = [p0 + ST_OUT];
	i2 = r1;
	r0 = 1;
	call .Lrows;
	jump .Lband;

.Lrefused:			/* the frames where they are */
	p0 = [sp + ARG_SCRATCH];
	r0 = [p0 + ST_SRC0];
	r1 = [p0 + ST_SRC1];
	r2 = [p0 + ST_DST];
.Ldirect:
	i0 = r0;
	i1 = r1;
	i2 = r2;
	r0 = [sp + ARG_SRC_STRIDE];
	m0 = r0;
	r0 = [sp + ARG_DST_STRIDE];
	m1 = r0;
	r0 = [sp + ARG_HEIGHT];
	r2 = [sp + ARG_WIDTH];
	call .Lrows;
.Lret:
	sp += 12;
	rets = [sp++];
	rts;

	/* r0 rows of r2 pixels from I0, I1 (rows M0 apart) to I2 (M1 apart). */
.Lrows:
	lc1 = r0;
	r3 = 255;
	lsetup (.Lrow, .Lrow_end) lc1;
.Lrow:
	p0 = i0;
	p1 = i1;
	p2 = i2;
	lc0 = r2;
	lsetup (.Lpix, .Lpix_end) lc0;
.Lpix:	r0 = b[p0++] (z);
	r1 = b[p1++] (z);
	r0 = r0 + r1;
	r0 = min (r0, r3);
.Lpix_end:
	b[p2++] = r0;
	i0 += m0;
	i1 += m0;
.Lrow_end:
	i2 += m1;
	rts;
BVB_ENDFUNC bvb_add_sat_u8_asm
