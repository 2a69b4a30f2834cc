/* Optical-flow obstacle avoidance (bvb/pipeline.h): Horn-Schunck flow over a band of rows, the
 * balance of the flow magnitudes in the left and right halves, frames after a turn discarded. */
#include "bvb/pipeline.h"

static int32_t iabs(int32_t v) { return v < 0 ? -v : v; }

/* dst (w/s x rows/s, packed) = the band averaged over s x s blocks, rounded half up (s = 1
 * copies). Returns the sum of dst. */
static int32_t scale_band(const uint8_t *band, int32_t stride, int32_t width, int32_t rows, int32_t s,
                          uint8_t *dst) {
  const int32_t ws = width / s, rs = rows / s, shift = s == 8 ? 6 : s == 4 ? 4 : s == 2 ? 2 : 0;
  int32_t total = 0;
  if (s == 1) {
    for (int32_t y = 0; y < rows; ++y)
      for (int32_t x = 0; x < width; ++x) total += dst[y * width + x] = band[y * stride + x];
    return total;
  }
  for (int32_t y = 0; y < rs; ++y) {
    for (int32_t x = 0; x < ws; ++x) {
      int32_t sum = 0;
      for (int32_t j = 0; j < s; ++j)
        for (int32_t i = 0; i < s; ++i) sum += band[(y * s + j) * stride + x * s + i];
      const int32_t v = (sum + ((1 << shift) >> 1)) >> shift;
      dst[y * ws + x] = (uint8_t)v;
      total += v;
    }
  }
  return total;
}

/* The band's mean above the black level, Q4 grey levels, at least 1 (1/16 grey level). */
static int32_t level_q4(int32_t total, int32_t n, int32_t black) {
  const int32_t l = total * 16 / n - 16 * black;
  return l < 1 ? 1 : l;
}

/* The gain, Q12, that takes a band at level `from` to level `to` (Q4 each), limited to
 * BVB_FLOW_AVOID_GAIN_MIN..MAX. */
static int32_t gain_q12(int32_t to, int32_t from) {
  const int32_t g = (to << 12) / from;
  return g < BVB_FLOW_AVOID_GAIN_MIN ? BVB_FLOW_AVOID_GAIN_MIN : g > BVB_FLOW_AVOID_GAIN_MAX ? BVB_FLOW_AVOID_GAIN_MAX : g;
}


/* b = black + (b - black) gain, rounded half up, clamped to 0..255, in place. */
static void apply_gain(uint8_t *b, int32_t n, int32_t black, int32_t gain) {
  if (gain == 1 << 12) return;
  for (int32_t i = 0; i < n; ++i) {
    const int32_t v = (((b[i] - black) * gain + 2048) >> 12) + black;
    b[i] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
  }
}

/* Sum of min(|u| + |v|, BVB_FLOW_AVOID_MAX_MAG) over columns [x0, x1) of every row. */
static int32_t flow_sum(const int16_t *uv, int32_t width, int32_t rows, int32_t x0, int32_t x1) {
  int32_t sum = 0;
  for (int32_t y = 0; y < rows; ++y) {
    const int16_t *r = uv + 2 * (y * width);
    for (int32_t x = x0; x < x1; ++x) {
      int32_t m = iabs(r[2 * x]) + iabs(r[2 * x + 1]);
      if (m > BVB_FLOW_AVOID_MAX_MAG) m = BVB_FLOW_AVOID_MAX_MAG;
      sum += m;
    }
  }
  return sum;
}

/* Sum of u, limited to +-BVB_FLOW_AVOID_MAX_MAG, over columns [x0, x1) of every row. */
static int32_t u_sum(const int16_t *uv, int32_t width, int32_t rows, int32_t x0, int32_t x1) {
  int32_t sum = 0;
  for (int32_t y = 0; y < rows; ++y) {
    const int16_t *r = uv + 2 * (y * width);
    for (int32_t x = x0; x < x1; ++x) {
      const int32_t u = r[2 * x];
      sum += u > BVB_FLOW_AVOID_MAX_MAG ? BVB_FLOW_AVOID_MAX_MAG : u < -BVB_FLOW_AVOID_MAX_MAG ? -BVB_FLOW_AVOID_MAX_MAG : u;
    }
  }
  return sum;
}

int32_t bvb_pipe_flow_avoid_run(const struct bvb_flow_avoid_kernels *k, const uint8_t *frame,
                                int32_t width, int32_t height, int32_t stride,
                                const struct bvb_pipe_frame *info, const struct bvb_flow_avoid_params *p,
                                struct bvb_flow_avoid_state *state, struct bvb_pipe_result *out,
                                int16_t *coef, int16_t *flow_a, int16_t *flow_b) {
  (void)height;
  const int32_t limit = info->stages > 0 ? info->stages : BVB_FLOW_AVOID_STAGES;
  const int32_t first = info->index == 0;
  const int32_t s = p->scale, ws = width / s, rs = p->band_rows / s;
  const int32_t slot_bytes = BVB_FLOW_AVOID_SLOT_BYTES(width, p->band_rows, s);
  uint8_t *slots = (uint8_t *)(state + 1);
  const int32_t prev_slot = first ? 0 : state->slot, cur_slot = 1 - prev_slot;
  uint8_t *prev = slots + prev_slot * slot_bytes, *cur = slots + cur_slot * slot_bytes;
  int32_t stage = 0;

  out->decision = BVB_PIPE_STOP;
  out->has_pose = 0;
  out->x_q16 = out->y_q16 = out->heading_q16 = 0;
  for (int32_t i = 0; i < BVB_PIPE_DIAG; ++i) out->diag[i] = 0;

  /* 1: what the robot did since the previous frame, whether a turn is under way; the band */
  const int32_t dl = first ? 0 : info->left_ticks - state->left_ticks;
  const int32_t dr = first ? 0 : info->right_ticks - state->right_ticks;
  int32_t turn = first ? 0 : state->turn, turn_left = first ? 0 : state->turn_left;
  int32_t latch = first ? 0 : state->latch;
  const int32_t have_prev = first ? 0 : state->have_prev;
  const int32_t translated = dl > 0 && dr > 0 && iabs(dl - dr) <= p->rot_ticks;
  const int32_t total = scale_band(frame + p->band_top * stride, stride, width, p->band_rows, s, cur);
  const int32_t bright = total / (ws * rs);
  const int32_t level = level_q4(total, ws * rs, p->black);
  int32_t mode, decision = BVB_PIPE_FORWARD, mean_l = -1, mean_r = -1, expansion = 0;
  if (turn_left > 0) {
    mode = BVB_FLOW_MODE_TURN;
    decision = turn;
    --turn_left;
  } else if (!translated || !have_prev) {
    mode = BVB_FLOW_MODE_PROBE;
  } else if (iabs(bright - state->bright) > p->light_tol) {
    mode = BVB_FLOW_MODE_LIGHT;
  } else {
    mode = BVB_FLOW_MODE_FLOW;
  }
  out->diag[BVB_FLOW_DIAG_MODE] = mode;
  out->diag[BVB_FLOW_DIAG_DLEFT] = dl;
  out->diag[BVB_FLOW_DIAG_DRIGHT] = dr;
  /* What the next frame needs to know about this one, whatever the later stages decide. */
  state->left_ticks = info->left_ticks;
  state->right_ticks = info->right_ticks;
  state->have_prev = 1;
  state->slot = cur_slot;
  state->bright = bright;
  const int32_t prev_level = first ? level : state->level_q4;
  state->level_q4 = level;
  state->frames = first ? 1 : state->frames + 1;
  if (++stage >= limit) goto stopped;

  /* 2, 3: the flow from the previous band to this one */
  int16_t *uv = flow_a;
  if (mode == BVB_FLOW_MODE_FLOW) {
    /* A change of the light's gain between the frames (flicker, a step) breaks the brightness
     * constancy Horn-Schunck rests on: the previous band is brought to the current one's level.
     * Its slot is the next frame's current slot, so scaling it in place costs nothing later. */
    if (p->light_gain) apply_gain(prev, ws * rs, p->black, gain_q12(level, prev_level));
    /* The band and the coefficients are in L1 here: nothing to stream (no scratch). */
    k->hs_prepare(prev, cur, ws, rs, ws, p->alpha2_q4, coef, 0);
    if (++stage >= limit) goto stopped;
    int32_t *z = (int32_t *)flow_a;
    for (int32_t i = 0; i < ws * rs; ++i) z[i] = 0;
    for (int32_t n = 0; n < p->iterations; ++n) {
      int16_t *next = uv == flow_a ? flow_b : flow_a;
      k->hs_iterate(coef, uv, 4 * ws, next, 4 * ws, ws, rs, 0, 0); /* its buffers are in L1 */
      uv = next;
    }
    if (++stage >= limit) goto stopped;
  } else {
    stage += 2;
    if (stage >= limit) goto stopped;
  }

  /* 4: the balance rule */
  if (mode == BVB_FLOW_MODE_FLOW) {
    const int32_t half = ws / 2;
    mean_l = flow_sum(uv, ws, rs, 0, half) / (half * rs);
    mean_r = flow_sum(uv, ws, rs, half, ws) / ((ws - half) * rs);
    expansion = u_sum(uv, ws, rs, half, ws) / ((ws - half) * rs) - u_sum(uv, ws, rs, 0, half) / (half * rs);
    const int32_t below = mean_l <= p->thresh_q9 && mean_r <= p->thresh_q9;
    const int32_t stalled = below && iabs(expansion) <= p->stall_q9;
    if (below && !stalled) {
      decision = BVB_PIPE_FORWARD;
      latch = 0;
    } else {
      if (stalled) mode = BVB_FLOW_MODE_STALL;
      if (!latch) latch = mean_l <= mean_r ? BVB_PIPE_LEFT : BVB_PIPE_RIGHT;
      decision = turn = latch;
      turn_left = (stalled ? p->stall_turn_frames : p->turn_frames) - 1;
    }
  }
  out->diag[BVB_FLOW_DIAG_MODE] = mode;
  ++stage;
  state->turn = turn_left > 0 ? turn : 0;
  state->turn_left = turn_left;
  state->latch = latch;
  out->decision = decision;

stopped:
  out->diag[BVB_FLOW_DIAG_STAGES] = stage > limit ? limit : stage;
  out->diag[BVB_FLOW_DIAG_LEFT] = mean_l;
  out->diag[BVB_FLOW_DIAG_RIGHT] = mean_r;
  out->diag[BVB_FLOW_DIAG_LATCH] = latch;
  out->diag[BVB_FLOW_DIAG_EXPANSION] = expansion;
  return out->decision;
}

static const struct bvb_flow_avoid_kernels c_kernels = {bvb_hs_prepare_c, bvb_hs_iterate_c};

int32_t bvb_pipe_flow_avoid_c(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                              const struct bvb_pipe_frame *info, const struct bvb_flow_avoid_params *p,
                              struct bvb_flow_avoid_state *state, struct bvb_pipe_result *out,
                              int16_t *coef, int16_t *flow_a, int16_t *flow_b) {
  return bvb_pipe_flow_avoid_run(&c_kernels, frame, width, height, stride, info, p, state, out, coef,
                                 flow_a, flow_b);
}
