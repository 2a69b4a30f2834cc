/* The odometry pipeline's assembly build: the orchestration of bvb_pipe_odometry_c over the
 * hand-written kernels (every kernel it calls has one but the Harris selection, C in both).
 * Firmware only: the host has no assembly kernels. */
#include "bvb/dma.h"
#include "bvb/harris.h"
#include "bvb/lk.h"
#include "bvb/ncc.h"
#include "bvb/pipe_odometry.h"
#include "bvb/scanline.h"
#include "bvb/stream.h"

/* The state update's copies (the frame, SDRAM to SDRAM, and its pyramid, from L1 at 160x120)
 * by memory DMA into the state's other slot: each as rows of 4 KB and the rest as one more
 * row, one job, which runs while the core tracks the features (they read the previous slot).
 * The bus moves 2 bytes per SCLK once, where the
 * core's copy through the write-back data cache reads each line in, fills each destination
 * line on its write miss and writes it back. In the simulator the caches are timing-only; on
 * the chip the destination's lines would be invalidated first (the core read the previous
 * frame through the cache). Copies DMA refuses go through the core at once. */
#define COPY_ROW 4096
static int32_t copy_pending;

static int32_t add_copy(void *job, int32_t k, uint8_t *dst, const uint8_t *src, uint32_t n) {
  const uint32_t rows = n / COPY_ROW, tail = n % COPY_ROW;
  struct bvb_dma_xfer x;
  if (k < 0) return k;
  if (rows) {
    x.src = src;
    x.dst = dst;
    x.src_stride = x.dst_stride = x.width = COPY_ROW;
    x.rows = (int32_t)rows;
    if (rows > 65535 || bvb_dma_prepare(job, k++, &x) != 0) return -1;
  }
  if (tail) {
    x.src = src + rows * COPY_ROW;
    x.dst = dst + rows * COPY_ROW;
    x.src_stride = x.dst_stride = x.width = (int32_t)tail;
    x.rows = 1;
    if (bvb_dma_prepare(job, k++, &x) != 0) return -1;
  }
  return k;
}

static struct {
  uint8_t *dst, *dst2;
  const uint8_t *src, *src2;
  uint32_t n, n2;
} copy_job;

static void core_copy(void) {
  for (uint32_t i = 0; i < copy_job.n; ++i) copy_job.dst[i] = copy_job.src[i];
  for (uint32_t i = 0; i < copy_job.n2; ++i) copy_job.dst2[i] = copy_job.src2[i];
}

static void dma_copy(void *job, uint8_t *dst, const uint8_t *src, uint32_t n, uint8_t *dst2, const uint8_t *src2,
                     uint32_t n2) {
  const int32_t k = add_copy(job, add_copy(job, 0, dst, src, n), dst2, src2, n2);
  copy_job.dst = dst, copy_job.src = src, copy_job.n = n;
  copy_job.dst2 = dst2, copy_job.src2 = src2, copy_job.n2 = n2;
  copy_pending = 0;
  if (k > 0) {
    bvb_dma_start(job, k);
    copy_pending = 1;
  } else if (k < 0) {
    core_copy();
  }
}

/* A job that ended in a DMA error is stopped and done again by the core. */
static void dma_copy_wait(void) {
  if (copy_pending && bvb_dma_wait() != 0) {
    bvb_dma_reset();
    core_copy();
  }
  copy_pending = 0;
}

/* The pyramid with the frame's rows brought into L1 by the row-band stream (bvb/stream.h):
 * level 1 band by band (each band an even number of rows: its rows pair as in the whole
 * frame), the levels above from level 1 (the pyramid is in L1 at 160x120). Reading the frame
 * through the data cache costs a line fill per 32 bytes; the stream moves it at the bus's
 * rate. When the stream refuses (no scratch, the frame already in L1, an odd band), the kernel
 * reads the frame in place. */
static void pyramid_asm(const uint8_t *src, int32_t width, int32_t height, int32_t stride, int32_t levels,
                        uint8_t *pyr, void *scratch, uint32_t scratch_bytes) {
  struct bvb_stream *st = (struct bvb_stream *)scratch;
  const int32_t s1 = BVB_LK_LEVEL_STRIDE(width >> 1);
  if (levels < 2 || scratch_bytes < BVB_STREAM_SCRATCH_BYTES((uint32_t)width, 0, 0) ||
      (BVB_STREAM_BAND_ROWS(width) & 1) != 0) {
    bvb_lk_pyramid_asm(src, width, height, stride, levels, pyr);
    return;
  }
  st->src[0] = src;
  st->src_stride[0] = stride;
  st->src_bytes[0] = width;
  st->src_bytes[1] = 0;
  st->dst = 0;
  st->dst_stride = 0;
  st->dst_bytes = 0;
  st->rows = height & ~1;
  if (bvb_stream_open(st) != 0) {
    bvb_lk_pyramid_asm(src, width, height, stride, levels, pyr);
    return;
  }
  int32_t n, r = 0;
  while ((n = bvb_stream_next(st)) > 0) {
    bvb_lk_pyramid_asm(st->in[0], width, n, width, 2, pyr + (r >> 1) * s1);
    r += n;
  }
  if (levels > 2) bvb_lk_pyramid_asm(pyr, width >> 1, height >> 1, s1, levels - 1, pyr + s1 * (height >> 1));
}

static const struct bvb_odo_kernels odo_asm = {
    bvb_scanline_profile_u8_asm, bvb_scanline_shift_u8_asm, bvb_harris_response_asm, bvb_harris_nms_asm,
    pyramid_asm,          bvb_lk_track_asm,          bvb_ncc_match_asm,       bvb_ncc_scoremap_asm,
    dma_copy, dma_copy_wait};

int32_t bvb_pipe_odometry_asm(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                              const struct bvb_pipe_frame *info, const struct bvb_odo_params *p,
                              uint8_t *state, struct bvb_pipe_result *out, void *work, void *fast) {
  return bvb_pipe_odometry_run(&odo_asm, frame, width, height, stride, info, p, state, out, work, fast);
}
