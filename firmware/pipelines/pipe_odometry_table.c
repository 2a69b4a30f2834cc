/* The odometry pipeline's assembly build: the orchestration of bvb_pipe_odometry_c over the
 * hand-written kernels (every kernel it calls has one but the Harris selection, C in both).
 * Firmware only: the host has no assembly kernels. */
#include "bvb/dma.h"
#include "bvb/harris.h"
#include "bvb/lk.h"
#include "bvb/ncc.h"
#include "bvb/pipe_odometry.h"
#include "bvb/scanline.h"

/* The state update's copies (the frame and its pyramid, SDRAM to SDRAM) by memory DMA: rows
 * of 4 KB and the rest as one more row, while the core waits (nothing is left to overlap at the
 * end of a frame). The bus moves 2 bytes per SCLK once, where the core's copy through the
 * write-back data cache reads each line in, fills each destination line on its write miss and
 * writes it back. In the simulator the caches are timing-only; on the chip the destination's
 * lines would be invalidated first (the core read the previous frame through the cache). A
 * copy DMA refuses goes through the core. */
#define COPY_ROW 4096
static void dma_copy(uint8_t *dst, const uint8_t *src, uint32_t n) {
  uint32_t job[BVB_DMA_JOB_BYTES / 4]; /* on the stack: L1 data bank B */
  const uint32_t rows = n / COPY_ROW, tail = n % COPY_ROW;
  int32_t k = 0;
  struct bvb_dma_xfer x;
  if (rows) {
    x.src = src;
    x.dst = dst;
    x.src_stride = x.dst_stride = x.width = COPY_ROW;
    x.rows = (int32_t)rows;
    if (rows > 65535 || bvb_dma_prepare(job, k++, &x) != 0) k = -1;
  }
  if (k >= 0 && tail) {
    x.src = src + rows * COPY_ROW;
    x.dst = dst + rows * COPY_ROW;
    x.src_stride = x.dst_stride = x.width = (int32_t)tail;
    x.rows = 1;
    if (bvb_dma_prepare(job, k++, &x) != 0) k = -1;
  }
  if (k > 0) {
    bvb_dma_start(job, k);
    if (bvb_dma_wait() == 0) return;
  }
  for (uint32_t i = 0; i < n; ++i) dst[i] = src[i];
}

static const struct bvb_odo_kernels odo_asm = {
    bvb_scanline_profile_u8_asm, bvb_scanline_shift_u8_asm, bvb_harris_response_asm, bvb_harris_nms_asm,
    bvb_lk_pyramid_asm,          bvb_lk_track_asm,          bvb_ncc_match_asm,       bvb_ncc_scoremap_asm,
    dma_copy};

int32_t bvb_pipe_odometry_asm(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                              const struct bvb_pipe_frame *info, const struct bvb_odo_params *p,
                              uint8_t *state, struct bvb_pipe_result *out, void *work, void *fast) {
  return bvb_pipe_odometry_run(&odo_asm, frame, width, height, stride, info, p, state, out, work, fast);
}
