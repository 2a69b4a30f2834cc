/* The pipelines' assembly builds: the same orchestration as bvb_pipe_<name>_c over the
 * hand-written kernels where they exist, the C references elsewhere. Firmware only (the host
 * has no assembly kernels). Where an entry below is still a C reference, the pipeline's cycle
 * counts include that kernel's C cost. */
#include "bvb/pipeline.h"

static const struct bvb_seg_avoid_kernels seg_asm = {
    bvb_region_grow_asm,
    bvb_erode3x3_u8_asm,
    bvb_free_space_asm,
};

int32_t bvb_pipe_seg_avoid_asm(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                               const struct bvb_pipe_frame *info, const struct bvb_seg_avoid_params *p,
                               struct bvb_seg_avoid_state *state, struct bvb_pipe_result *out,
                               uint8_t *mask, uint8_t *map, void *work) {
  return bvb_pipe_seg_avoid_run(&seg_asm, frame, width, height, stride, info, p, state, out, mask, map,
                                work);
}

static const struct bvb_flow_avoid_kernels flow_asm = {
    bvb_hs_prepare_asm,
    bvb_hs_iterate_asm,
};

int32_t bvb_pipe_flow_avoid_asm(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                                const struct bvb_pipe_frame *info, const struct bvb_flow_avoid_params *p,
                                struct bvb_flow_avoid_state *state, struct bvb_pipe_result *out,
                                int16_t *coef, int16_t *flow_a, int16_t *flow_b) {
  return bvb_pipe_flow_avoid_run(&flow_asm, frame, width, height, stride, info, p, state, out, coef,
                                 flow_a, flow_b);
}
