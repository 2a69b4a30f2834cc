/* Memory DMA jobs on MDMA stream 0: the contract, the costs and the registers used are in
 * bvb/dma.h. Register offsets and CONFIG bits: ADSP-BF537 hardware reference, chapter 5 (DMA
 * registers, descriptor-based DMA); names as in ADI's defBF537.h. In L1 instruction SRAM
 * beside the kernels that call it, so a call fetches nothing from SDRAM. */
#include "bvb/dma.h"

#define MDMA_D0 0xFFC00F00	/* MDMA_S0 is MDMA_D0 + 0x40 */
#define D_CONFIG 0x08
#define D_CURR_DESC 0x20
#define D_IRQ 0x28
#define S_CONFIG (0x40 + 0x08)
#define S_CURR_DESC (0x40 + 0x20)
#define S_IRQ (0x40 + 0x28)

#define DMAEN 0x0001
#define WNR 0x0002
#define WDSIZE_16 0x0004
#define DMA2D 0x0010
#define DI_EN 0x0080
#define NDSIZE_7 0x0700
#define FLOW_ARRAY 0x4000
#define DMA_DONE 0x1
#define DMA_ERR 0x2

/* Descriptor-array layout (halfwords): start address low, high, CONFIG, X_COUNT, X_MODIFY,
 * Y_COUNT, Y_MODIFY. */
#define DS_SAL 0
#define DS_SAH 2
#define DS_CFG 4
#define DS_XC 6
#define DS_XM 8
#define DS_YC 10
#define DS_YM 12
#define DS_BYTES 14
#define DST_SLOTS (BVB_DMA_MAX_XFERS * DS_BYTES)

	.section .l1.text, "ax"

	/* r0 = p, r1 = bytes: 1 when [p, p + bytes) lies in SDRAM (0 .. 32 MB), L1 data bank A's
	 * SRAM (its lower 16 KB; the upper is data cache) or bank B, else 0. Clobbers R0-R2. */
	.align 4
	.global _bvb_dma_reachable
	.type _bvb_dma_reachable, STT_FUNC
_bvb_dma_reachable:
	cc = r1 <= 0;
	if cc jump .Lr_no;
	r1 += -1;
	r1 = r0 + r1;			/* the last byte */
	cc = r1 < r0 (iu);
	if cc jump .Lr_no;		/* wrapped round */
	r2.l = 0x0000;
	r2.h = 0x0200;
	cc = r1 < r2 (iu);
	if cc jump .Lr_yes;		/* SDRAM */
	r2.h = 0xff80;
	cc = r0 < r2 (iu);
	if cc jump .Lr_no;
	r2.l = 0x4000;
	cc = r1 < r2 (iu);
	if cc jump .Lr_yes;		/* bank A SRAM */
	r2.l = 0x0000;
	r2.h = 0xff90;
	cc = r0 < r2 (iu);
	if cc jump .Lr_no;
	r2.l = 0x8000;
	cc = r1 < r2 (iu);
	if cc jump .Lr_yes;		/* bank B */
.Lr_no:
	r0 = 0;
	rts;
.Lr_yes:
	r0 = 1;
	rts;
	.size _bvb_dma_reachable, . - _bvb_dma_reachable

	/* r0 = job, r1 = slot k, r2 = struct bvb_dma_xfer *: the slot's source and destination
	 * descriptors; 0, or -1 when DMA cannot do it. Saves R4-R7, P3-P5 and RETS on the stack. */
	.align 4
	.global _bvb_dma_prepare
	.type _bvb_dma_prepare, STT_FUNC
_bvb_dma_prepare:
	[--sp] = (r7:4, p5:3);
	[--sp] = rets;
	p4 = r2;
	r2 = r1 << 4;
	r1 <<= 1;
	r2 = r2 - r1;			/* 14 k */
	r0 = r0 + r2;
	p3 = r0;			/* the source descriptor */
	r4 = [p4 + DMAX_W];
	r5 = [p4 + DMAX_ROWS];
	cc = r4 <= 0;
	if cc jump .Lp_no;
	cc = r5 <= 0;
	if cc jump .Lp_no;
	/* 16-bit elements when every address, stride and the width are even. */
	r0 = [p4 + DMAX_SRC];
	r1 = [p4 + DMAX_SS];
	r6 = r0 | r1;
	r0 = [p4 + DMAX_DST];
	r1 = [p4 + DMAX_DS];
	r6 = r6 | r0;
	r6 = r6 | r1;
	r6 = r6 | r4;
	cc = bittst (r6, 0);
	r6 = 2;
	r7 = DMAEN | WDSIZE_16 (z);
	if !cc jump .Lp_e;
	r6 = 1;
	r7 = DMAEN (z);
.Lp_e:
	r0 = [p4 + DMAX_SRC];
	r1 = [p4 + DMAX_SS];
	p5 = p3;
	call .Lside;
	cc = r0 < 0;
	if cc jump .Lp_no;
	r0 = [p4 + DMAX_DST];
	r1 = [p4 + DMAX_DS];
	p5 = DST_SLOTS;
	p5 = p3 + p5;
	bitset (r7, 1);			/* WNR */
	call .Lside;
	cc = r0 < 0;
	if cc jump .Lp_no;
	r0 = 0;
.Lp_x:
	rets = [sp++];
	(r7:4, p5:3) = [sp++];
	rts;
.Lp_no:
	r0 = -1;
	jump .Lp_x;

	/* One side: r0 address, r1 stride, r4 width, r5 rows, r6 element bytes, r7 CONFIG,
	 * P5 the descriptor. r0 = 0 or -1. Clobbers R0-R3, P0, P1. */
.Lside:
	cc = r1 < r4;
	if cc jump .Ls_no;		/* rows would overlap */
	p0 = r1;			/* the stride */
	p1 = r0;			/* the address */
	r2 = r5;
	r2 += -1;
	r2 *= r1;
	r1 = r2 + r4;			/* the block's extent */
	[--sp] = rets;
	call _bvb_dma_reachable;	/* clobbers R0-R2 */
	rets = [sp++];
	cc = r0 == 0;
	if cc jump .Ls_no;
	r3 = r4;			/* elements per row */
	cc = r6 == 1;
	if cc jump .Ls_c;
	r3 >>= 1;
.Ls_c:
	r0.l = 0xffff;
	r0.h = 0;
	cc = r0 < r3 (iu);
	if cc jump .Ls_no;		/* X_COUNT beyond 16 bits */
	w[p5 + DS_XM] = r6;
	r1 = p0;
	cc = r1 == r4;
	if !cc jump .Ls_2d;
	/* contiguous rows: one row of rows x width when the count fits */
	r2 = r5;
	r2 *= r3;
	cc = r0 < r2 (iu);
	if cc jump .Ls_2d;
	w[p5 + DS_XC] = r2;
	r2 = 0;
	w[p5 + DS_YC] = r2;
	w[p5 + DS_YM] = r2;
	w[p5 + DS_CFG] = r7;
	jump .Ls_addr;
.Ls_2d:
	cc = r0 < r5 (iu);
	if cc jump .Ls_no;		/* Y_COUNT beyond 16 bits */
	/* Y_MODIFY: from the last element of a row to the first of the next */
	r2 = r1 - r4;
	r2 = r2 + r6;
	r0.l = 0x7fff;
	cc = r0 < r2 (iu);
	if cc jump .Ls_no;		/* beyond 16 bits, signed */
	w[p5 + DS_XC] = r3;
	w[p5 + DS_YC] = r5;
	w[p5 + DS_YM] = r2;
	r2 = r7;
	bitset (r2, 4);			/* DMA2D */
	w[p5 + DS_CFG] = r2;
.Ls_addr:
	r3 = p1;
	w[p5 + DS_SAL] = r3;
	r3 >>= 16;
	w[p5 + DS_SAH] = r3;
	r0 = 0;
	rts;
.Ls_no:
	r0 = -1;
	rts;
	.size _bvb_dma_prepare, . - _bvb_dma_prepare

	/* r0 = job, r1 = slot k, r2 = struct bvb_dma_xfer *: moves slot k to x->src and x->dst,
	 * keeping everything else it was prepared with. Clobbers R0-R2, P0, P1. */
	.align 4
	.global _bvb_dma_move
	.type _bvb_dma_move, STT_FUNC
_bvb_dma_move:
	p0 = r2;
	r2 = r1 << 4;
	r1 <<= 1;
	r2 = r2 - r1;			/* 14 k */
	r0 = r0 + r2;
	p1 = r0;
	r1 = [p0 + DMAX_SRC];
	r2 = [p0 + DMAX_DST];
	w[p1 + DS_SAL] = r1;
	r1 >>= 16;
	w[p1 + DS_SAH] = r1;
	w[p1 + (DST_SLOTS + DS_SAL)] = r2;
	r2 >>= 16;
	w[p1 + (DST_SLOTS + DS_SAH)] = r2;
	rts;
	.size _bvb_dma_move, . - _bvb_dma_move

	/* r0 = job, r1 = n: runs slots 0 .. n-1. Clobbers R0-R3, P0-P2. */
	.align 4
	.global _bvb_dma_start
	.type _bvb_dma_start, STT_FUNC
_bvb_dma_start:
	p0 = r0;			/* source descriptors */
	r3 = r0;
	p1 = DST_SLOTS;
	p1 = p0 + p1;			/* destination descriptors */
	p2 = r1;
	r2 = FLOW_ARRAY | NDSIZE_7 (z);
	/* every slot: FLOW array, DI_EN off; then the last: stop, and DI_EN on the destination */
.Lst_l:
	r0 = w[p0 + DS_CFG] (z);
	r1 = w[p1 + DS_CFG] (z);
	r0 = r0.b (z);
	r1 = r1.b (z);
	bitclr (r0, 7);
	bitclr (r1, 7);
	r0 = r0 | r2;
	r1 = r1 | r2;
	w[p0 + DS_CFG] = r0;
	w[p1 + DS_CFG] = r1;
	p0 += DS_BYTES;
	p1 += DS_BYTES;
	p2 += -1;
	cc = p2 == 0;
	if !cc jump .Lst_l (bp);
	r0 = r0.b (z);
	r1 = r1.b (z);
	bitset (r1, 7);			/* DI_EN */
	w[p0 + (DS_CFG - DS_BYTES)] = r0;
	w[p1 + (DS_CFG - DS_BYTES)] = r1;
	p2.l = MDMA_D0 & 0xffff;
	p2.h = MDMA_D0 >> 16;
	r0 = DMA_DONE | DMA_ERR;
	w[p2 + D_IRQ] = r0;		/* write-1-to-clear */
	[p2 + S_CURR_DESC] = r3;
	r0 = DMAEN | FLOW_ARRAY | NDSIZE_7 (z);
	w[p2 + S_CONFIG] = r0;
	r1 = DST_SLOTS;
	r3 = r3 + r1;
	[p2 + D_CURR_DESC] = r3;
	bitset (r0, 1);			/* WNR: the destination starts the transfer */
	w[p2 + D_CONFIG] = r0;
	rts;
	.size _bvb_dma_start, . - _bvb_dma_start

	/* 0 when the job's last transfer is done, -1 on a DMA error. Clobbers R0, P2. */
	.align 4
	.global _bvb_dma_wait
	.type _bvb_dma_wait, STT_FUNC
_bvb_dma_wait:
	p2.l = MDMA_D0 & 0xffff;
	p2.h = MDMA_D0 >> 16;
.Lw_l:
	r0 = w[p2 + D_IRQ] (z);
	cc = bittst (r0, 0);
	if cc jump .Lw_done (bp);
	cc = bittst (r0, 1);
	if !cc jump .Lw_l (bp);
	r0 = -1;
	rts;
.Lw_done:
	r0 = 0;
	rts;
	.size _bvb_dma_wait, . - _bvb_dma_wait

	/* Stops both channels of stream 0 and clears their status. Clobbers R0, P2. */
	.align 4
	.global _bvb_dma_reset
	.type _bvb_dma_reset, STT_FUNC
_bvb_dma_reset:
	p2.l = MDMA_D0 & 0xffff;
	p2.h = MDMA_D0 >> 16;
	r0 = 0;
	w[p2 + D_CONFIG] = r0;
	w[p2 + S_CONFIG] = r0;
	r0 = DMA_DONE | DMA_ERR;
	w[p2 + D_IRQ] = r0;
	w[p2 + S_IRQ] = r0;
	rts;
	.size _bvb_dma_reset, . - _bvb_dma_reset
