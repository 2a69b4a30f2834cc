/* The robot's vision pipelines: one camera frame in, one steering decision (or pose) out, with
 * state kept from frame to frame. Each pipeline is C orchestration over a table of kernel entry
 * points: bvb_pipe_<name>_c runs it over the C references (the host build runs the same
 * source), bvb_pipe_<name>_asm over the hand-written kernels where they exist (its table lives
 * in the firmware only, firmware/pipelines/pipe_tables.c). The orchestration, and therefore
 * every decision, is the same code in both; only the kernels' speed differs.
 *
 * COMMON INTERFACE
 *   struct bvb_pipe_frame   per-frame input: frame index, cumulative wheel encoder ticks, and a
 *                           stage limit for profiling.
 *   struct bvb_pipe_result  per-frame output: decision, pose (for odometry pipelines), diag.
 *   state                   caller-owned, kept between frames (the harness keeps it in the
 *                           window); frame index 0 initialises it, so its contents before the
 *                           first frame do not matter. BVB_<NAME>_STATE_BYTES(w, h).
 *   working buffers         caller-owned, contents irrelevant between frames; their sizes are
 *                           given below with where the firmware puts them (L1 when they fit).
 *   Frames: 8-bit grey (the Y plane), width x height, `stride` bytes between rows, in SDRAM
 *   (where the camera's DMA puts them).
 *   Every buffer 4-byte aligned. Returns the decision.
 *
 * PROFILING. info->stages = k > 0 stops after the first k stages (numbered per pipeline below);
 *   result->decision is then BVB_PIPE_STOP, result->diag[0] says how many stages ran and the
 *   state is left as it was. Cycles of stages 1..k minus cycles of 1..k-1 give the cost of
 *   stage k on the same frame and state (bfbench pipeline NAME --param stages=k).
 *
 * ============================================================================================
 * SEGMENTATION-BASED OBSTACLE AVOIDANCE (seg_avoid; the seed paper's section 2.1.1)
 *   Stage 1, ground seed. The ground region is seeded at the bottom row, middle column. The
 *     ground intensity G is tracked from frame to frame (state: G in Q8, a running average
 *     G += (m - G) / 2^avg_shift over the frames, m the grown region's mean intensity). If the
 *     bottom-middle pixel differs from G by more than tol, the seed moves along the bottom row
 *     outwards from the middle (x = w/2, w/2-1, w/2+1, w/2-2, ...) to the first pixel within
 *     tol of G, at most seed_search pixels away; when none is, the bottom-middle pixel is used.
 *   Stage 2, region growing (bvb_region_grow, 4-connected, tolerance tol against the region's
 *     running mean) over rows horizon .. height-1 only: the floor cannot appear above the
 *     horizon row, so the rows above are obstacle by definition and cost nothing.
 *   Stage 3, ground tracking. m = region sum / count. A sudden change is |m - G| > change_tol
 *     (grey levels), or a region smaller than min_region pixels. On a sudden change the frame
 *     is not trusted: its decision is a turn (as if blocked: see the decision), and G is
 *     re-seeded to m, i.e. the new ground is trusted from the next frame on. A global lighting
 *     change (the floor 20 levels darker from one frame to the next) therefore costs one frame
 *     of turning in place; a region grown from something that is not floor (an obstacle at the
 *     robot's feet, whose mean is far from G) is turned away from instead of being driven
 *     into. Otherwise G += (m - G) >> avg_shift (Q8; an arithmetic shift, i.e. rounded down).
 *     Frame 0 takes G = m.
 *   Stage 4, obstacle map dilation: the region mask (255 floor, 0 obstacle) is eroded 3x3
 *     (bvb_erode3x3_u8), i.e. the obstacle map is dilated: obstacles grow by one pixel, and
 *     single floor pixels the region missed along an obstacle's edge do not open a path.
 *   Stage 5, free space per column (bvb_free_space with min_gap): the row where the floor
 *     stops going up from the bottom; a run of fewer than min_gap non-floor pixels (floor
 *     texture the region growing left out) does not stop it. free(x) = height - 1 - that row,
 *     the column's free-space height in pixels (the horizon row and above are never free, so
 *     free(x) <= height - 1 - horizon).
 *   Stage 6, decision (the 30-pixel rule with left/right clearance):
 *     ahead = min free(x) over the centre columns [centre_lo, centre_hi);
 *     forward when ahead > go_rows (30 px at 120 rows; the harness scales it with the height:
 *       30 * height / 120, i.e. the same floor distance at every resolution: about 10 in ahead
 *       of the camera with the scene's 4 in high, 10 deg tilted camera);
 *     otherwise turn toward the side with more clearance: left = sum of free(x) for
 *       x < width/2, right = sum for x >= width/2; left when left > right, else right. While
 *       the robot stays blocked the direction is latched (state), so it does not swing back
 *       and forth in front of an obstacle; the first forward decision releases the latch.
 *     A sudden ground change (stage 3) decides like a blocked frame.
 *   diag: [0] stages run, [1] ahead (px), [2] left clearance sum, [3] right clearance sum,
 *     [4] region pixels, [5] region mean (grey level), [6] ground average G (Q8),
 *     [7] flags: bit 0 sudden change, bit 1 seed moved, bit 2 region queue overflowed.
 *   Buffers: mask and map, width x (height - horizon) bytes each (L1 data banks A and B at
 *     160x120; SDRAM at 320x240); work, BVB_SEG_AVOID_WORK_BYTES(w, queue_cap): the region
 *     growing queue (the breadth-first front of a region grown in a w x h frame stays near
 *     w + h pixels; the harness gives 2 (w + h) entries and reports any overflow in diag), the
 *     column rows (int16) and the erosion's scratch: 3.9 KB at 160x120, the L1 scratchpad.
 *
 * ============================================================================================
 * OPTICAL-FLOW OBSTACLE AVOIDANCE (flow_avoid; the seed paper's section 2.1.2)
 *   The flow between the previous and the current frame (bvb_hornschunck.h: prepare, then
 *   `iterations` Jacobi iterations from zero flow) over a band of rows [band_top, band_top +
 *   band_rows): below the horizon, where the floor and the obstacles standing on it are, and
 *   above the bottom rows, whose floor moves more pixels per frame than Horn-Schunck without a
 *   pyramid can follow. The magnitude of a pixel's flow is |u| + |v| (Q9 px, each pixel's
 *   value limited to 8 px so that sums fit 32 bits at every frame size); L and R are its sums
 *   over the band's left and right halves (columns < width/2 and >= width/2).
 *   The balance rule: the side with more flow has the nearer obstacles (for a translating
 *   camera a point's flow grows with 1 / depth), so
 *     forward when L <= T and R <= T, T = thresh_q9 * (pixels in a half) (thresh_q9 is the
 *       mean magnitude per pixel, Q9 px; the harness scales it with the width);
 *     otherwise turn toward the smaller side (left when L < R, else right), committed for
 *       turn_frames frames (3 deg each in the scenes).
 *   The robot's own rotation: a turn in place moves the whole image by about fx * 3 deg
 *   (7 px at 160x120) per frame, beyond what the flow can measure and carrying no depth
 *   information anyway. So the flow is computed only when the step from the previous frame to
 *   this one was a pure translation, read from the wheel encoders: both wheels advanced and
 *   |dleft - dright| <= rot_ticks. After a turn (or a stop) the robot takes one step forward
 *   without a flow decision (a probe: the flow of that step decides the next frame), and the
 *   frames of a committed turn are not computed at all. Frame 0 probes too. While the robot is
 *   in an avoidance manoeuvre (turned, probed, still above threshold) the turn direction is
 *   latched, so it does not swing back and forth; a forward decision releases it.
 *   Stages: 1 bookkeeping (encoders, committed turn), 2 Horn-Schunck prepare, 3 the
 *     iterations, 4 sums and decision, 5 keep the current band as the next frame's previous.
 *   diag: [0] stages run, [1] L / 512 / pixels of a half ... see BVB_FLOW_DIAG_*.
 *   Buffers: coef, BVB_HS_COEF_BYTES(width, band_rows); flow_a, flow_b, 4 * width * band_rows
 *     bytes each (all SDRAM: 160 x 60 rows need 58 KB of coefficients and 38 KB per flow
 *     buffer); state: BVB_FLOW_AVOID_STATE_BYTES(stride, band_rows), the previous frame's band
 *     (SDRAM; real firmware would keep the previous camera buffer instead of copying).
 */
#ifndef BVB_PIPELINE_H
#define BVB_PIPELINE_H

#include <stdint.h>

#include "bvb/hornschunck.h"
#include "bvb/morph.h"
#include "bvb/region.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Decisions: the same order as the harness's Drive. */
enum bvb_pipe_decision { BVB_PIPE_STOP = 0, BVB_PIPE_FORWARD = 1, BVB_PIPE_LEFT = 2, BVB_PIPE_RIGHT = 3 };

#define BVB_PIPE_DIAG 8

struct bvb_pipe_frame {
  int32_t index;                   /* 0: the first frame (state initialised) */
  int32_t left_ticks, right_ticks; /* cumulative wheel encoder counts */
  int32_t stages;                  /* > 0: stop after this many stages (profiling) */
};

struct bvb_pipe_result {
  int32_t decision;                      /* enum bvb_pipe_decision */
  int32_t has_pose;                      /* 1 when x, y, heading are set (odometry pipelines) */
  int32_t x_q16, y_q16, heading_q16;     /* inches, inches, degrees (counter-clockwise), Q16 */
  int32_t diag[BVB_PIPE_DIAG];           /* pipeline-specific, see above */
};

/* ---- segmentation-based avoidance ---- */

struct bvb_seg_avoid_params {
  int32_t tol;           /* region growing tolerance, grey levels */
  int32_t seed_search;   /* how far along the bottom row the seed may move, pixels */
  int32_t horizon;       /* first row that can show floor */
  int32_t change_tol;    /* sudden ground change: |region mean - G| above this, grey levels */
  int32_t min_region;    /* a region of fewer pixels is not the ground */
  int32_t lost_frames;   /* after this many frames without the ground, trust the new one */
  int32_t avg_shift;     /* G's running average weight 1 / 2^avg_shift, 0..8 */
  int32_t min_gap;       /* free_space's obstacle run, rows */
  int32_t go_rows;       /* forward when the centre columns' free space exceeds this */
  int32_t centre_lo, centre_hi; /* the centre columns [lo, hi) */
  int32_t queue_cap;     /* entries of the region growing queue (in work) */
};

struct bvb_seg_avoid_state {
  int32_t ground_q8; /* G */
  int32_t latch;     /* 0, or the latched turn decision */
  int32_t frames;    /* frames seen */
  int32_t changes;   /* sudden ground changes seen */
  int32_t lost;      /* consecutive frames without the ground */
  int32_t frame_mean; /* the previous frame's mean below the horizon */
  int32_t pad[2];
};

#define BVB_SEG_AVOID_STATE_BYTES ((int32_t)sizeof(struct bvb_seg_avoid_state))
#define BVB_SEG_AVOID_ROWS_BYTES(w) (2 * (((w) + 1) & ~1))
/* work: the region growing queue (queue_cap int32), the column rows, the erosion's scratch */
#define BVB_SEG_AVOID_WORK_BYTES(w, queue_cap) \
  (4 * (queue_cap) + BVB_SEG_AVOID_ROWS_BYTES(w) + BVB_MORPH3X3_SCRATCH_BYTES(w))
#define BVB_SEG_AVOID_STAGES 6

#define BVB_SEG_FLAG_CHANGE 1
#define BVB_SEG_FLAG_SEED_MOVED 2
#define BVB_SEG_FLAG_DROPPED 4
#define BVB_SEG_FLAG_LOST 8
#define BVB_SEG_FLAG_SIDE 16

struct bvb_seg_avoid_kernels {
  int32_t (*region_grow)(const uint8_t *img, int32_t img_stride, uint8_t *mask, int32_t mask_stride,
                         int32_t width, int32_t height, const struct bvb_region_params *p,
                         int32_t *queue, int32_t queue_cap, struct bvb_region_stats *stats);
  void (*erode)(const uint8_t *src, uint8_t *dst, int32_t width, int32_t height, int32_t src_stride,
                int32_t dst_stride, void *scratch);
  void (*free_space)(const uint8_t *mask, int32_t mask_stride, int32_t width, int32_t height,
                     int32_t min_gap, int16_t *rows);
};

/* The orchestration over a kernel table (what _c and _asm call). */
int32_t bvb_pipe_seg_avoid_run(const struct bvb_seg_avoid_kernels *k, const uint8_t *frame,
                               int32_t width, int32_t height, int32_t stride,
                               const struct bvb_pipe_frame *info, const struct bvb_seg_avoid_params *p,
                               struct bvb_seg_avoid_state *state, struct bvb_pipe_result *out,
                               uint8_t *mask, uint8_t *map, void *work);

/* Registry entries (the harness's windows carry at most 8 buffers, hence one work buffer). */
int32_t bvb_pipe_seg_avoid_c(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                             const struct bvb_pipe_frame *info, const struct bvb_seg_avoid_params *p,
                             struct bvb_seg_avoid_state *state, struct bvb_pipe_result *out,
                             uint8_t *mask, uint8_t *map, void *work);
int32_t bvb_pipe_seg_avoid_asm(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                               const struct bvb_pipe_frame *info, const struct bvb_seg_avoid_params *p,
                               struct bvb_seg_avoid_state *state, struct bvb_pipe_result *out,
                               uint8_t *mask, uint8_t *map, void *work);

/* ---- optical-flow avoidance ---- */

struct bvb_flow_avoid_params {
  int32_t alpha2_q4;   /* Horn-Schunck smoothness, 16 alpha^2 (bvb/hornschunck.h) */
  int32_t iterations;  /* Jacobi iterations, >= 0 */
  int32_t band_top, band_rows; /* the frame rows the flow is computed and summed over */
  int32_t scale;       /* 1, 2, 4 or 8: the band is averaged over scale x scale blocks first */
  int32_t thresh_q9;   /* T: mean |u| + |v| over a half, Q9 pixels of the scaled band */
  int32_t stall_q9;    /* both halves at or below this after a step forward: stalled */
  int32_t turn_frames; /* a turn decision is kept this many frames (>= 1) */
  int32_t rot_ticks;   /* an encoder difference above this is a rotation */
  int32_t light_tol;   /* a band mean that moved more than this (grey levels): the light changed */
};

struct bvb_flow_avoid_state {
  int32_t left_ticks, right_ticks; /* at the previous frame */
  int32_t turn;        /* the committed turn's decision, 0 when none */
  int32_t turn_left;   /* frames of it still to go */
  int32_t latch;       /* the latched turn direction during a manoeuvre, 0 when none */
  int32_t have_prev;   /* the previous band is valid */
  int32_t slot;        /* which of the two band slots below holds the previous band */
  int32_t bright;      /* the previous band's mean intensity */
  int32_t frames;
  int32_t pad[3];
  /* then two slots, BVB_FLOW_AVOID_SLOT_BYTES each: the scaled bands of the previous and the
   * current frame, taking turns (no copy from frame to frame) */
};

/* The scaled band: (width / scale) x (band_rows / scale) bytes, packed. */
#define BVB_FLOW_AVOID_SLOT_BYTES(w, rows, scale) (((((w) / (scale)) * ((rows) / (scale))) + 3) & ~3)
#define BVB_FLOW_AVOID_STATE_BYTES(w, rows, scale) \
  ((int32_t)sizeof(struct bvb_flow_avoid_state) + 2 * BVB_FLOW_AVOID_SLOT_BYTES(w, rows, scale))
#define BVB_FLOW_AVOID_FLOW_BYTES(w, rows, scale) (4 * ((w) / (scale)) * ((rows) / (scale)))
#define BVB_FLOW_AVOID_COEF_BYTES(w, rows, scale) BVB_HS_COEF_BYTES((w) / (scale), (rows) / (scale))
#define BVB_FLOW_AVOID_MAX_MAG (8 << BVB_HS_UV_FRAC_BITS) /* per-pixel limit, Q9 */
#define BVB_FLOW_AVOID_STAGES 4

/* diag of flow_avoid */
#define BVB_FLOW_DIAG_STAGES 0
#define BVB_FLOW_DIAG_LEFT 1      /* L / pixels of a half: mean magnitude, Q9 px (-1: no flow) */
#define BVB_FLOW_DIAG_RIGHT 2     /* R likewise */
#define BVB_FLOW_DIAG_MODE 3      /* see enum bvb_flow_mode */
#define BVB_FLOW_DIAG_DLEFT 4     /* encoder increments since the previous frame */
#define BVB_FLOW_DIAG_DRIGHT 5
#define BVB_FLOW_DIAG_LATCH 6

enum bvb_flow_mode {
  BVB_FLOW_MODE_FLOW = 0,  /* the decision came from the flow */
  BVB_FLOW_MODE_PROBE = 1, /* no usable flow (first frame, after a turn or a stop): forward */
  BVB_FLOW_MODE_TURN = 2,  /* inside a committed turn */
  BVB_FLOW_MODE_LIGHT = 3, /* the light changed between the frames: no flow decision, forward */
  BVB_FLOW_MODE_STALL = 4  /* the wheels moved, the view did not: blocked, turn */
};

struct bvb_flow_avoid_kernels {
  void (*hs_prepare)(const uint8_t *i1, const uint8_t *i2, int32_t width, int32_t height, int32_t stride,
                     int32_t alpha2_q4, int16_t *coef);
  void (*hs_iterate)(const int16_t *coef, const int16_t *uv_in, int32_t in_stride, int16_t *uv_out,
                     int32_t out_stride, int32_t width, int32_t height);
};

int32_t bvb_pipe_flow_avoid_run(const struct bvb_flow_avoid_kernels *k, const uint8_t *frame,
                                int32_t width, int32_t height, int32_t stride,
                                const struct bvb_pipe_frame *info, const struct bvb_flow_avoid_params *p,
                                struct bvb_flow_avoid_state *state, struct bvb_pipe_result *out,
                                int16_t *coef, int16_t *flow_a, int16_t *flow_b);

int32_t bvb_pipe_flow_avoid_c(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                              const struct bvb_pipe_frame *info, const struct bvb_flow_avoid_params *p,
                              struct bvb_flow_avoid_state *state, struct bvb_pipe_result *out,
                              int16_t *coef, int16_t *flow_a, int16_t *flow_b);
int32_t bvb_pipe_flow_avoid_asm(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                                const struct bvb_pipe_frame *info, const struct bvb_flow_avoid_params *p,
                                struct bvb_flow_avoid_state *state, struct bvb_pipe_result *out,
                                int16_t *coef, int16_t *flow_a, int16_t *flow_b);

#ifdef __cplusplus
}
#endif

#endif
