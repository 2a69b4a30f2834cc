/* Row bands through L1 by memory DMA: the contract and the schedule are in bvb/stream.h. In L1
 * instruction SRAM beside the kernels that call it, so a call fetches nothing from SDRAM. */
#include "bvb/stream.h"

#include <stddef.h>

#define L1TEXT __attribute__((section(".l1.text")))

/* The assembly reads these offsets (bvb/stream.h); a mismatch fails the build. */
#define AT(field, off) typedef char check_##field[offsetof(struct bvb_stream, field) == (off) ? 1 : -1]
AT(src, 0);
AT(src_stride, 8);
AT(src_bytes, 16);
AT(dst, 24);
AT(dst_stride, 28);
AT(dst_bytes, 32);
AT(rows, 36);
AT(in, 40);
AT(out, 48);
typedef char check_size[sizeof(struct bvb_stream) == BVB_STREAM_STATE_BYTES ? 1 : -1];

enum { K_OUT = 0, K_IN0 = 1, K_IN1 = 2 };

/* BVB_STREAM_BAND_ROWS(rb) without a division (libgcc's is in SDRAM). */
static L1TEXT int32_t band_rows(int32_t rb) {
  int32_t b = 1;
  while (b < BVB_STREAM_MAX_BAND && (b + 1) * rb <= BVB_STREAM_BAND_BYTES) ++b;
  return b;
}

static L1TEXT int32_t in_sdram(const void *p) { return (uintptr_t)p < 0x02000000u; }

/* The x of transfer `kind` for n rows from row r; `par` picks the L1 buffer. */
static L1TEXT void xfer(struct bvb_stream *st, int32_t kind, int32_t r, int32_t n, int32_t par) {
  struct bvb_dma_xfer *x = &st->x;
  x->rows = n;
  if (kind == K_OUT) {
    x->width = st->dst_bytes;
    x->src = st->buf_out[par];
    x->src_stride = st->dst_bytes;
    x->dst = st->dst + r * st->dst_stride;
    x->dst_stride = st->dst_stride;
  } else {
    const int32_t p = kind - K_IN0;
    x->width = st->src_bytes[p];
    x->src = st->src[p] + r * st->src_stride[p];
    x->src_stride = st->src_stride[p];
    x->dst = st->buf_in[p][par];
    x->dst_stride = st->src_bytes[p];
  }
}

/* What DMA refused, by the core (bvb/stream.h: none should be). */
static L1TEXT void core_copy(const struct bvb_dma_xfer *x) {
  const uint8_t *s = x->src;
  uint8_t *d = x->dst;
  for (int32_t r = 0; r < x->rows; ++r, s += x->src_stride, d += x->dst_stride)
    for (int32_t i = 0; i < x->width; ++i) d[i] = s[i];
}

/* Slot *slot of job j: st->x, re-addressed when the slot was last prepared for this shape. */
static L1TEXT void add(struct bvb_stream *st, int32_t j, int32_t *slot, int32_t kind) {
  const int32_t key = st->x.rows * 4 + kind;
  int32_t *k = &st->key[j][*slot];
  if (*k == key) {
    bvb_dma_move(st->job[j], *slot, &st->x);
  } else if (bvb_dma_prepare(st->job[j], *slot, &st->x) == 0) {
    *k = key;
  } else {
    *k = -1;
    core_copy(&st->x);
    return;
  }
  ++*slot;
}

static L1TEXT void run(struct bvb_stream *st, int32_t j, int32_t slots) {
  if (st->running) bvb_dma_wait();
  st->running = 0;
  if (slots) {
    bvb_dma_start(st->job[j], slots);
    st->running = 1;
  }
}

static L1TEXT int32_t stream_open(struct bvb_stream *st) {
  const int32_t nin = st->src_bytes[1] > 0 ? 2 : 1, out = st->dst_bytes > 0;
  const int32_t rb = st->src_bytes[0] + (nin > 1 ? st->src_bytes[1] : 0) + (out ? st->dst_bytes : 0);
  if (st->src_bytes[0] <= 0 || st->rows <= 0 || in_sdram(st) ||
      !bvb_dma_reachable(st, BVB_STREAM_SCRATCH_BYTES(st->src_bytes[0], nin > 1 ? st->src_bytes[1] : 0,
                                                      out ? st->dst_bytes : 0)))
    return -1;
  int32_t any_sdram = 0;
  for (int32_t p = 0; p < nin; ++p) {
    if (!bvb_dma_reachable(st->src[p], (st->rows - 1) * st->src_stride[p] + st->src_bytes[p])) return -1;
    any_sdram |= in_sdram(st->src[p]);
  }
  if (out) {
    if (!bvb_dma_reachable(st->dst, (st->rows - 1) * st->dst_stride + st->dst_bytes)) return -1;
    any_sdram |= in_sdram(st->dst);
  }
  if (!any_sdram) return -1;
  if (nin == 1) st->src_bytes[1] = 0;
  if (!out) st->dst_bytes = 0;

  const int32_t b = band_rows(rb);
  st->band_rows = b;
  uint8_t *m = (uint8_t *)(st + 1);
  for (int32_t par = 0; par < 2; ++par) {
    for (int32_t p = 0; p < 2; ++p) {
      st->buf_in[p][par] = m;
      m += BVB_STREAM_A4(b * st->src_bytes[p]);
    }
    st->buf_out[par] = m;
    m += BVB_STREAM_A4(b * st->dst_bytes);
  }
  for (int32_t j = 0; j < 2; ++j)
    for (int32_t s = 0; s < BVB_DMA_MAX_XFERS; ++s) st->key[j][s] = -1;

  /* Band 0 in, on job 1 (bvb_stream_next builds band k's job in job k & 1 while job
   * (k - 1) & 1 runs); then the output's largest shape once, on slot 0 of job 0 (prepared again
   * for band 1; later bands only shrink and move by whole rows). What DMA refuses here,
   * the direct path does instead. */
  const int32_t n0 = st->rows < b ? st->rows : b;
  int32_t slot = 0;
  for (int32_t kind = K_IN0; kind <= nin; ++kind) {
    xfer(st, kind, 0, n0, 0);
    if (bvb_dma_prepare(st->job[1], slot, &st->x) != 0) return -1;
    st->key[1][slot++] = n0 * 4 + kind;
  }
  st->running = 0;
  run(st, 1, slot);
  if (out) {
    xfer(st, K_OUT, 0, n0, 0);
    if (bvb_dma_prepare(st->job[0], 0, &st->x) != 0) {
      run(st, 1, 0); /* waits for band 0 */
      return -1;
    }
  }
  st->k = 0;
  st->cur_row = st->cur_n = 0;
  st->fly_row = 0;
  st->fly_n = n0;
  return 0;
}

/* GCC's code leaves a hardware loop counting when it leaves it early (a refusal inside the
 * plane loops can leave LC1 armed), its convention; an assembly caller, which may
 * keep its own loops across the call, should find no stale count whose loop end could fire,
 * and the checked call reports a loop left counting. Both counters are cleared on return. */
L1TEXT int32_t bvb_stream_open(struct bvb_stream *st) {
  const int32_t r = stream_open(st);
  __asm__ volatile("LC0 = %0;\n\tLC1 = %0;" : : "d"(0));
  return r;
}

L1TEXT int32_t bvb_stream_next(struct bvb_stream *st) {
  const int32_t k = st->k, j = k & 1, nin = st->src_bytes[1] > 0 ? 2 : 1;
  int32_t slot = 0;
  /* Band k-1's output out (from its buffer), band k+1's input in (into band k-1's). */
  if (st->dst_bytes && st->cur_n) {
    xfer(st, K_OUT, st->cur_row, st->cur_n, (k - 1) & 1);
    add(st, j, &slot, K_OUT);
  }
  const int32_t r1 = st->fly_row + st->fly_n, left = st->rows - r1;
  const int32_t n1 = st->fly_n == 0 ? 0 : left < st->band_rows ? left : st->band_rows;
  for (int32_t kind = K_IN0; n1 && kind <= nin; ++kind) {
    xfer(st, kind, r1, n1, (k + 1) & 1);
    add(st, j, &slot, kind);
  }
  run(st, j, slot);
  if (st->fly_n == 0) {
    if (st->running) bvb_dma_wait();
    st->running = 0;
    st->cur_n = 0;
    return 0;
  }
  st->in[0] = st->buf_in[0][k & 1];
  st->in[1] = st->buf_in[1][k & 1];
  st->out = st->buf_out[k & 1];
  st->cur_row = st->fly_row;
  st->cur_n = st->fly_n;
  st->fly_row = r1;
  st->fly_n = n1;
  st->k = k + 1;
  return st->cur_n;
}
