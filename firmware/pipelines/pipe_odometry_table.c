/* The odometry pipeline's assembly build: the orchestration of bvb_pipe_odometry_c over the
 * hand-written kernels (every kernel it calls has one but the Harris selection, C in both).
 * Firmware only: the host has no assembly kernels. */
#include "bvb/harris.h"
#include "bvb/lk.h"
#include "bvb/ncc.h"
#include "bvb/pipe_odometry.h"
#include "bvb/scanline.h"

static const struct bvb_odo_kernels odo_asm = {
    bvb_scanline_profile_u8_asm, bvb_scanline_shift_u8_asm, bvb_harris_response_asm, bvb_harris_nms_asm,
    bvb_lk_pyramid_asm,          bvb_lk_track_asm,          bvb_ncc_match_asm,       bvb_ncc_scoremap_asm};

int32_t bvb_pipe_odometry_asm(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                              const struct bvb_pipe_frame *info, const struct bvb_odo_params *p,
                              uint8_t *state, struct bvb_pipe_result *out, void *work) {
  return bvb_pipe_odometry_run(&odo_asm, frame, width, height, stride, info, p, state, out, work);
}
