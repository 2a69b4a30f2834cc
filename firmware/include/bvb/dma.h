/* Memory DMA for the kernels: 2D block copies between SDRAM and L1 on MDMA stream 0.
 *
 * A kernel that streams a frame brings bands of rows from SDRAM into L1 buffers and sends its
 * output rows back the same way, while it computes on the band that arrived before. A job is a
 * short chain of transfers (for a kernel: the output band just computed, then the input band
 * after the one it computes next) run one after the other on one stream: the SRV-1's SDRAM is
 * one 16-bit bus, so transfers in and out share it on the chip whatever streams they use (the
 * timing model charges two streams to or from SDRAM at once the sum of their times, as one).
 *
 * Transfers. Each is rows x width bytes from src (src_stride bytes from row to row) to dst
 * (dst_stride); strides may differ, so a band of a strided frame lands contiguous in L1 and
 * back. bvb_dma_prepare writes the transfer's two descriptors (source and destination channel,
 * the hardware's 7-halfword descriptor-array layout: start address, CONFIG, X_COUNT, X_MODIFY,
 * Y_COUNT, Y_MODIFY) into slot k of a job: 16-bit elements when every address, stride and the
 * width are even, else bytes (twice the bus time); a side whose rows are contiguous is one
 * row (1D) when the count fits 16 bits, else 2D with Y_MODIFY = stride - width + element.
 * It refuses (returns -1; the slot must then not be started) a transfer DMA cannot do: a
 * block not wholly in SDRAM (0 .. 32 MB) or L1 data SRAM (bank A's lower 16 KB, bank B), so
 * never the L1 scratchpad (0xFFB00000, no DMA path on the BF537: the simulator ends such a
 * transfer in DMA_ERR, as the chip does) nor the window; a stride below the width; no
 * rows or no width; counts or modifies beyond 16 bits. The caller then takes another path.
 *
 * Jobs. bvb_dma_start(job, n) runs slots 0 .. n-1 (n >= 1) in order: it sets each
 * descriptor's FLOW (array for all but the last, stop for the last, which also interrupts,
 * DI_EN, so that DMA_DONE is set: the model sets it only then), clears the destination's
 * DMA_DONE (write-1-to-clear; a stale one would end the next wait at once) and starts the
 * source, then the destination channel. bvb_dma_wait() polls the destination's IRQ_STATUS
 * until DMA_DONE (returns 0) or DMA_ERR (returns -1). One job at a time: start the next one
 * only after waiting for the last. bvb_dma_reset() stops both channels (the monitor calls it
 * after a call that was abandoned mid-transfer).
 *
 * Coherence. In the simulator the caches are timing-only and the host writes frames straight
 * into memory, so nothing needs flushing. Real firmware with the write-back data cache on for
 * SDRAM would have to write back (FLUSH) the lines of a source block the core wrote through
 * the cache before the DMA reads it, and invalidate (FLUSHINV) the lines of a destination
 * block before the DMA writes it, so that no stale or dirty line overwrites it later; frames
 * the camera's DMA put in SDRAM and output only DMA reads need neither.
 *
 * Cost. On the stream (the model, --timing bf537, SCLK = CCLK / 4): 10 SCLK to start (the
 * model's assumption), 7 SCLK per descriptor fetched (2 per transfer), then 1 SCLK per 16-bit
 * element (per byte with 8-bit elements): 2 bytes per SCLK, 0.5 byte per core cycle. On the
 * core, measured with dma_copy_u8 (bfbench run, a 2x2 frame in bands of 1 row, the difference
 * of 2 and 4 jobs): a job of one transfer prepared, started and waited for, with the kernel's
 * own bookkeeping, 390 cycles in the simulator's count, 530 modelled (its 6 system MMR
 * accesses at 2 SCLK each, and the stream's 100 cycles for a 2-byte transfer); most of it is
 * bvb_dma_prepare (the checks; sobel3x3_u8 saved some 200 cycles a transfer by moving
 * prepared slots instead: 14 instructions). A kernel's per-band cost: firmware/asm/sobel.S.
 *
 * Calling from assembly: C ABI (arguments R0, R1, R2; result R0; called with CALL, so RETS is
 * the caller's to save). They clobber only R0-R3, P0-P2 and ASTAT (bvb_dma_prepare saves
 * what else it uses on the stack): the I, M, B, L registers and the loop registers are left
 * as they were, so a kernel may keep its circular buffers live across bands. */
#ifndef BVB_DMA_H
#define BVB_DMA_H

/* Transfers per job, and the job's size: the source channel's descriptors, then the
 * destination's, 14 bytes each. 4-byte aligned, anywhere DMA reaches (L1 for speed). */
#define BVB_DMA_MAX_XFERS 4
#define BVB_DMA_JOB_BYTES (2 * BVB_DMA_MAX_XFERS * 14)

#ifndef __ASSEMBLER__
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

struct bvb_dma_xfer {
  const void *src;
  int32_t src_stride;
  void *dst;
  int32_t dst_stride;
  int32_t width; /* bytes per row */
  int32_t rows;
};

int32_t bvb_dma_prepare(void *job, int32_t k, const struct bvb_dma_xfer *x);
/* Slot k again with x->src and x->dst, everything else as prepared: for the next band of the
 * same shape. No checks: the caller keeps the new block where DMA reaches and at the
 * alignment the slot was prepared for (moving by whole rows of the same frame does). */
void bvb_dma_move(void *job, int32_t k, const struct bvb_dma_xfer *x);
void bvb_dma_start(void *job, int32_t n);
int32_t bvb_dma_wait(void);
/* 1 when DMA reaches every byte of [p, p + bytes), else 0. */
int32_t bvb_dma_reachable(const void *p, int32_t bytes);
void bvb_dma_reset(void);

#ifdef __cplusplus
}
#endif
#else
/* Offsets into struct bvb_dma_xfer, for assembly. */
#define DMAX_SRC 0
#define DMAX_SS 4
#define DMAX_DST 8
#define DMAX_DS 12
#define DMAX_W 16
#define DMAX_ROWS 20
#define DMAX_BYTES 24
#endif

#endif
