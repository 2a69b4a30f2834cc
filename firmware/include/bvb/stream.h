/* Row bands through L1: the band streaming that a kernel reading whole frames from SDRAM needs,
 * built on the memory DMA helper (bvb/dma.h), double-buffered, in one place.
 *
 * A stream has up to two input planes and one output plane of the same number of rows (a
 * plane: its first row in SDRAM or L1, its stride, its bytes per row). Its state and band
 * buffers live in the kernel's L1 scratch, BVB_STREAM_SCRATCH_BYTES(in0, in1, out) bytes from
 * a 4-byte aligned `st`. The kernel fills the plane fields, calls bvb_stream_open, then
 * computes band after band:
 *
 *     st->src[0] = src; st->src_stride[0] = ss; st->src_bytes[0] = row bytes; ... st->rows = h;
 *     if (bvb_stream_open(st) == 0)
 *       while ((n = bvb_stream_next(st)) > 0)
 *         compute n rows from st->in[0] (and st->in[1]) into st->out;
 *     else
 *       the direct path (the frames read and written where they are);
 *
 * In L1 a band's rows are contiguous (st->in[p] rows src_bytes[p] apart, st->out rows
 * dst_bytes apart), so a kernel whose rows are independent can take a band as one long row.
 *
 * Schedule. bvb_stream_next returning band k has waited for the job that brought band k in
 * (and sent band k-2's output out) and started the next: band k-1's output rows out, then
 * band k+1's input rows in (into the buffers band k-1 has left), on MDMA stream 0, while the
 * kernel computes band k. When no band is left it waits, sends the last band's output, waits
 * for that and returns 0. The next job is built in the other of two job areas before the wait,
 * and a slot whose shape (rows, direction) is what it was two bands ago is only re-addressed
 * (bvb_dma_move), so the stream idles only between the wait and the start.
 *
 * Bands of BVB_STREAM_BAND_ROWS(row bytes of all planes) rows: as many as fit
 * BVB_STREAM_BAND_BYTES (6 KB: two bands, 12 KB, leave room in a 16 KB bank), at most
 * BVB_STREAM_MAX_BAND (16; a longer band gains little: the stream's per-job cost, some 50 SCLK
 * at 3 transfers, against a band's transfer time), at least 1.
 *
 * bvb_stream_open returns -1 (and the kernel takes its direct path) when the scratch is not in
 * DMA-reachable L1 (bank A's SRAM or bank B; not SDRAM, not the scratchpad), when a plane is
 * not wholly where DMA reaches (SDRAM or that L1), when every plane is already in L1 (nothing
 * to gain), or when a band's transfer does not fit DMA's counts (bvb_dma_prepare refuses it).
 * A later transfer DMA refuses (none should: bands only shrink and move by whole rows) is done
 * by the core.
 *
 * Costs (bvb/dma.h): the stream moves 2 bytes per SCLK (0.5 byte per core cycle at CCLK:SCLK
 * = 4), 1 byte per SCLK when an address, stride or row length is odd; per job 10 SCLK to start
 * and 7 per descriptor (2 per transfer). The core's per band, in bvb_stream_next: building the
 * job (moves), the wait, the start: a few hundred cycles, hidden when the kernel is bus-bound.
 *
 * Loop registers: every hardware loop of the stream's routines runs to its end, so none is left
 * armed (LC0, LC1 are as a finished loop leaves them); bvb_stream_open's band-row search tries
 * every count for that, where leaving its loop early returned with LC1 non-zero.
 *
 * Calling from assembly: C ABI (the routines are C, in L1 instruction SRAM, firmware/runtime/stream.c):
 * R0-R3, P0-P2, I0-I3, M0-M3, B0-B3, L0-L3 (which must be 0 at the call), A0, A1, LC0/1,
 * LT0/1, LB0/1 and ASTAT may change; R4-R7, P3-P5, FP are kept. Coherence: as bvb/dma.h. */
#ifndef BVB_STREAM_H
#define BVB_STREAM_H

#include "bvb/dma.h"

#define BVB_STREAM_BAND_BYTES 6144
#define BVB_STREAM_MAX_BAND 16
#define BVB_STREAM_STATE_BYTES 384
#define BVB_STREAM_A4(n) ((((n) + 3) / 4) * 4)
/* Rows per band for rb bytes of rows of all planes together. */
#define BVB_STREAM_BAND_ROWS(rb)                                                            \
  ((rb) * BVB_STREAM_MAX_BAND <= BVB_STREAM_BAND_BYTES ? BVB_STREAM_MAX_BAND               \
   : (rb) >= BVB_STREAM_BAND_BYTES                     ? 1                                 \
                                                       : BVB_STREAM_BAND_BYTES / (rb))
/* The scratch of a stream of bands of b rows whose planes have b0, b1 (0: none) and bd (0: none)
 * bytes a row (bvb_stream_open_rows), and of one with the default bands (bvb_stream_open). */
#define BVB_STREAM_SCRATCH_BYTES_B(b, b0, b1, bd)                                           \
  (BVB_STREAM_STATE_BYTES +                                                                 \
   2 * (BVB_STREAM_A4((b) * (b0)) + BVB_STREAM_A4((b) * (b1)) + BVB_STREAM_A4((b) * (bd))))
#define BVB_STREAM_SCRATCH_BYTES(b0, b1, bd)                                                \
  BVB_STREAM_SCRATCH_BYTES_B(BVB_STREAM_BAND_ROWS((b0) + (b1) + (bd)), b0, b1, bd)

#ifndef __ASSEMBLER__
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

struct bvb_stream {
  /* The planes, set by the kernel before bvb_stream_open. src_bytes[1] = 0: one input plane;
   * dst_bytes = 0: no output plane. */
  const uint8_t *src[2];
  int32_t src_stride[2];
  int32_t src_bytes[2];
  uint8_t *dst;
  int32_t dst_stride;
  int32_t dst_bytes;
  int32_t rows;
  /* The band bvb_stream_next returned, in L1. */
  const uint8_t *in[2];
  uint8_t *out;
  /* The stream's own. */
  int32_t band_rows;
  int32_t k;                 /* the band bvb_stream_next returns next */
  int32_t cur_row, cur_n;    /* band k-1 (its output not yet sent) */
  int32_t fly_row, fly_n;    /* band k, on its way in (fly_n = 0: none) */
  int32_t running;           /* a job is on the stream */
  uint8_t *buf_in[2][2];
  uint8_t *buf_out[2];
  int32_t key[2][BVB_DMA_MAX_XFERS];
  struct bvb_dma_xfer x;
  uint8_t job[2][BVB_DMA_JOB_BYTES];
};

int32_t bvb_stream_open(struct bvb_stream *st);
/* bvb_stream_open with bands of `rows` rows (1 .. BVB_STREAM_MAX_BAND; the scratch then is
 * BVB_STREAM_SCRATCH_BYTES_B(rows, ...)), for a kernel whose L1 budget is not the default's,
 * and npre (0 .. 2) transfers of the caller's own (tables, a first row) run on band 0's job
 * before its rows, so that they share its wait: when bvb_stream_next first returns they are
 * in. -1 as bvb_stream_open, and when DMA refuses one of them (nothing was started). */
int32_t bvb_stream_open_rows(struct bvb_stream *st, int32_t rows, const struct bvb_dma_xfer *pre,
                             int32_t npre);
int32_t bvb_stream_next(struct bvb_stream *st);

#ifdef __cplusplus
}
#endif
#else
/* Offsets into struct bvb_stream, for assembly. */
#define ST_SRC0 0
#define ST_SRC1 4
#define ST_SS0 8
#define ST_SS1 12
#define ST_SB0 16
#define ST_SB1 20
#define ST_DST 24
#define ST_DS 28
#define ST_DB 32
#define ST_ROWS 36
#define ST_IN0 40
#define ST_IN1 44
#define ST_OUT 48
/* the stream's own, for a kernel that sends its last band itself */
#define ST_CUR_ROW 60
#define ST_CUR_N 64
#define ST_FLY_N 72
#define ST_RUNNING 76
#define ST_BUF_OUT 96
#endif

#endif
