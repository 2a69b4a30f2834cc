/* Segmentation-based obstacle avoidance (bvb/pipeline.h): region growing from the bottom middle,
 * ground intensity tracking, obstacle map dilation, free space per column, the 30-pixel rule. */
#include "bvb/pipeline.h"

static int32_t iabs(int32_t v) { return v < 0 ? -v : v; }

/* The first pixel of the bottom row, going outwards from the middle, within tol of the ground
 * average and at most `search` pixels from the middle; -1 when there is none. */
static int32_t pick_seed(const uint8_t *row, int32_t width, int32_t ground, int32_t tol, int32_t search) {
  const int32_t mid = width / 2;
  for (int32_t d = 0; d <= search; ++d) {
    const int32_t a = mid - d, b = mid + d;
    if (a >= 0 && iabs((int32_t)row[a] - ground) <= tol) return a;
    if (d > 0 && b < width && iabs((int32_t)row[b] - ground) <= tol) return b;
  }
  return -1;
}

/* v * light_q8 / 256, rounded, at most 255 (the region growing's limit). */
static int32_t scale_q8(int32_t v, int32_t light_q8) {
  const int32_t r = (v * light_q8 + 128) >> 8;
  return r > 255 ? 255 : r;
}

/* The sum of the band's intensities. */
static int32_t band_sum(const uint8_t *band, int32_t width, int32_t rows, int32_t stride) {
  /* Packed rows (the camera's frames) are summed as one run: no per-row loop overhead. */
  const int32_t run = stride == width ? width * rows : width, runs = stride == width ? 1 : rows;
  int32_t sum = 0;
  for (int32_t y = 0; y < runs; ++y) {
    const uint8_t *r = band + y * stride;
    for (int32_t x = 0; x < run; ++x) sum += r[x];
  }
  return sum;
}

/* The free space a column needs for the robot to go on: go_rows in the centre columns, falling
 * linearly to 0 at the image's edges, where the robot's path leaves the view. */
static int32_t needed(int32_t x, int32_t width, const struct bvb_seg_avoid_params *p) {
  if (x >= p->centre_lo && x < p->centre_hi) return p->go_rows;
  if (x < p->centre_lo) return p->go_rows * x / p->centre_lo;
  return p->go_rows * (width - 1 - x) / (width - p->centre_hi);
}

int32_t bvb_pipe_seg_avoid_run(const struct bvb_seg_avoid_kernels *k, const uint8_t *frame,
                               int32_t width, int32_t height, int32_t stride,
                               const struct bvb_pipe_frame *info, const struct bvb_seg_avoid_params *p,
                               struct bvb_seg_avoid_state *state, struct bvb_pipe_result *out,
                               uint8_t *mask, uint8_t *map, void *work) {
  const int32_t limit = info->stages > 0 ? info->stages : BVB_SEG_AVOID_STAGES;
  const int32_t first = info->index == 0;
  const int32_t rows = height - p->horizon;
  const uint8_t *band = frame + p->horizon * stride;
  int32_t *queue = (int32_t *)work;
  int16_t *col = (int16_t *)(queue + p->queue_cap);
  void *morph_scratch = (uint8_t *)col + BVB_SEG_AVOID_ROWS_BYTES(width);
  int32_t stage = 0, flags = 0;

  out->decision = BVB_PIPE_STOP;
  out->has_pose = 0;
  out->x_q16 = out->y_q16 = out->heading_q16 = 0;
  for (int32_t i = 0; i < BVB_PIPE_DIAG; ++i) out->diag[i] = 0;

  /* 1: the light and the seed */
  /* A change of the light scales every intensity at once; the robot's own step changes the
   * band's mean brightness much less (the scenes: at most about 7% from one frame to the next).
   * A jump of more than light_jump_q8 / 256 is taken for the light, measured by the ratio of
   * the two frames' band means (the two bands see nearly the same things). The light, relative
   * to the first frame's, scales the tolerances: the floor texture's spread and the
   * floor-to-wall contrast scale with it. It is measured only at such a jump, never from the
   * region, so a region grown up a wall cannot feed back into the tolerance. */
  const int32_t fsum = band_sum(band, width, rows, stride), fmean = fsum / (width * rows);
  const int32_t prev = state->frame_mean;
  int32_t light = first ? 256 : state->light_q8, ground_q8 = state->ground_q8, jump = 0;
  if (!first && prev > 0 && 256 * iabs(fmean - prev) > p->light_jump_q8 * prev) {
    jump = 1;
    light = (light * fmean + prev / 2) / prev; /* both products fit 32 bits: L <= 1024, G <= 255 << 8 */
    if (light < BVB_SEG_LIGHT_MIN_Q8) light = BVB_SEG_LIGHT_MIN_Q8;
    if (light > BVB_SEG_LIGHT_MAX_Q8) light = BVB_SEG_LIGHT_MAX_Q8;
    /* the ground as the new light shows it */
    ground_q8 = (ground_q8 * fmean + prev / 2) / prev;
    flags |= BVB_SEG_FLAG_CHANGE;
  }
  const int32_t tol = scale_q8(p->tol, light), change_tol = scale_q8(p->change_tol, light);
  const int32_t ground = (ground_q8 + 128) >> 8;
  int32_t seed_x = width / 2, found = 1;
  if (!first) {
    const int32_t s = pick_seed(band + (rows - 1) * stride, width, ground, tol, p->seed_search);
    found = s >= 0;
    if (found) seed_x = s;
    if (seed_x != width / 2) flags |= BVB_SEG_FLAG_SEED_MOVED;
  }
  if (++stage >= limit) goto stopped;

  /* 2: the ground region */
  struct bvb_region_params rp;
  struct bvb_region_stats st;
  rp.seed_x = seed_x;
  rp.seed_y = rows - 1;
  rp.tol = tol;
  rp.connectivity = 4;
  k->region_grow(band, stride, mask, width, width, rows, &rp, queue, p->queue_cap, &st);
  if (st.dropped) flags |= BVB_SEG_FLAG_DROPPED;
  if (++stage >= limit) goto stopped;

  /* 3: ground tracking */
  const int32_t mean = st.count > 0 ? st.sum / st.count : 0;
  int32_t lost = 0;
  if (first || (jump && found && st.count >= p->min_region)) {
    ground_q8 = mean << 8;
  } else if (!found || st.count < p->min_region || iabs(mean - ground) > change_tol) {
    /* A change of the light moves the whole frame with the ground; a region grown over
     * something else leaves the rest of the frame as it was. */
    const int32_t dm = mean - ground, df = fmean - prev;
    if (found && st.count >= p->min_region && (dm > 0) == (df > 0) && 2 * iabs(df) >= iabs(dm)) {
      flags |= BVB_SEG_FLAG_CHANGE;
      ground_q8 = mean << 8;
    } else {
      flags |= BVB_SEG_FLAG_LOST;
      lost = state->lost + 1;
      if (lost >= p->lost_frames) {
        flags |= BVB_SEG_FLAG_CHANGE;
        ground_q8 = mean << 8;
        lost = 0;
      }
    }
  } else {
    ground_q8 += ((mean << 8) - ground_q8) >> p->avg_shift;
  }
  state->ground_q8 = ground_q8;
  state->light_q8 = light;
  state->lost = lost;
  state->frame_mean = fmean;
  /* The view did not change since the previous frame (see stage 6). */
  const int32_t dsum = fsum - state->frame_sum;
  const int32_t still = !first && iabs(dsum) <= (p->stall_q8 * width * rows) >> 8;
  state->frame_sum = fsum;
  state->changes = (first ? 0 : state->changes) + ((flags & BVB_SEG_FLAG_CHANGE) != 0);
  state->frames = first ? 1 : state->frames + 1;
  if (++stage >= limit) goto stopped;

  /* 4: dilate the obstacle map (erode the floor) */
  k->erode(mask, map, width, rows, width, width, morph_scratch);
  if (++stage >= limit) goto stopped;

  /* 5: free space per column */
  k->free_space(map, width, width, rows, p->min_gap, col);
  if (++stage >= limit) goto stopped;

  /* 6: the 30-pixel rule over the robot's path, and the clearance on either side */
  int32_t ahead = rows, left = 0, right = 0;
  for (int32_t x = 0; x < width; ++x) {
    const int32_t free = rows - 1 - col[x];
    if (x < width / 2) left += free;
    else right += free;
    if (x >= p->centre_lo && x < p->centre_hi) {
      if (free < ahead) ahead = free;
    } else if (free < needed(x, width, p)) {
      flags |= BVB_SEG_FLAG_SIDE;
    }
  }
  /* The horizon row sees the floor only at infinity, beyond any wall: a region that reaches it
   * in every centre column grew up a wall, and the path ahead is not known to be floor. */
  if (ahead >= rows) flags |= BVB_SEG_FLAG_HORIZON;
  int32_t decision;
  if (first) state->stall = state->commit = state->last_turn = 0;
  if (ahead > p->go_rows && !(flags & (BVB_SEG_FLAG_SIDE | BVB_SEG_FLAG_LOST | BVB_SEG_FLAG_HORIZON))) {
    decision = BVB_PIPE_FORWARD;
  } else {
    if (first || !state->latch) state->latch = left > right ? BVB_PIPE_LEFT : BVB_PIPE_RIGHT;
    decision = state->latch;
  }
  /* A stall: forward steps that left the view as it was. The robot is pushing against
   * something it cannot see (a wall beside its nose, outside the view). It turns for
   * stall_turn frames, whatever the view says, on in the direction of its last turn: what it
   * last turned away from left the view on the other side and is what it now touches. */
  if (state->commit > 0) {
    --state->commit;
    decision = state->latch;
    flags |= BVB_SEG_FLAG_STALL;
  } else if (decision == BVB_PIPE_FORWARD) {
    state->stall = !first && state->latch == 0 && still ? state->stall + 1 : 0;
    if (state->stall >= p->stall_frames) {
      state->stall = 0;
      state->commit = p->stall_turn - 1;
      decision = state->last_turn ? state->last_turn : left > right ? BVB_PIPE_LEFT : BVB_PIPE_RIGHT;
      flags |= BVB_SEG_FLAG_STALL;
    }
  } else {
    state->stall = 0;
  }
  if (decision == BVB_PIPE_FORWARD) {
    state->latch = 0;
  } else {
    state->latch = state->last_turn = decision;
  }
  ++stage;
  out->decision = decision;
  out->diag[1] = ahead;
  out->diag[2] = left;
  out->diag[3] = right;
  out->diag[4] = st.count;
  out->diag[5] = mean;
  out->diag[6] = ground_q8;

stopped:
  out->diag[0] = stage > limit ? limit : stage;
  out->diag[7] = flags;
  return out->decision;
}

static const struct bvb_seg_avoid_kernels c_kernels = {bvb_region_grow_c, bvb_erode3x3_u8_c, bvb_free_space_c};

int32_t bvb_pipe_seg_avoid_c(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                             const struct bvb_pipe_frame *info, const struct bvb_seg_avoid_params *p,
                             struct bvb_seg_avoid_state *state, struct bvb_pipe_result *out,
                             uint8_t *mask, uint8_t *map, void *work) {
  return bvb_pipe_seg_avoid_run(&c_kernels, frame, width, height, stride, info, p, state, out, mask, map,
                                work);
}
