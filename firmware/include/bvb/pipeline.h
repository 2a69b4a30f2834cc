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
 *                           first frame do not matter.
 *   working buffers         caller-owned, contents irrelevant between frames; their sizes are
 *                           given below with where the harness puts them (L1 when they fit).
 *   Frames: 8-bit grey (the Y plane), width x height, `stride` bytes between rows, in SDRAM
 *   (where the camera's DMA puts them). Every buffer 4-byte aligned. Returns the decision.
 *
 * PROFILING. info->stages = k > 0 stops the frame after its first k stages (numbered per
 *   pipeline below): result->decision is then BVB_PIPE_STOP and diag[0] says how many stages
 *   ran. Each stage updates the part of the state it owns as it goes, so a scene run with
 *   stages = k does the same work in stages 1..k on every frame as a full run, as long as no
 *   decision of a later stage changes what those stages do (open-loop scenes; for flow_avoid,
 *   turn_frames = 1). Cycles with k stages minus cycles with k - 1 give stage k's cost
 *   (bfbench pipeline NAME --scene DIR --param stages=k).
 *
 * ============================================================================================
 * SEGMENTATION-BASED OBSTACLE AVOIDANCE (seg_avoid; the seed paper's section 2.1.1)
 *   The floor is looked for only below the horizon row (p->horizon, from the camera's tilt: the
 *   floor cannot appear above it): the band of rows horizon .. height-1, `rows` rows.
 *   Stage 1, the light and the seed. F = the band's mean intensity (sum / pixels, rounded
 *     down), F' the previous frame's. The light L (state, Q8, 256 = the first frame's light)
 *     scales the tolerances: t = tol * L / 256 and ct = change_tol * L / 256 (rounded half up,
 *     at most 255). A change of the light multiplies every intensity, the floor texture's
 *     spread and the floor-to-wall contrast alike (the boxes arena's walls in shadow are about
 *     30 levels brighter than the floor; dimmed to 0.7 that is 21, below an unscaled tol of 30).
 *     L is measured only at a jump of the light, never from the ground region, so a region
 *     grown up a wall cannot raise the tolerance that let it grow: when
 *     256 |F - F'| > light_jump_q8 F' (more than 1/8 at the harness's default 32; the robot's
 *     own step moves F by at most about 7% in the bundled arenas), the light changed:
 *     L = L * F / F' (rounded, limited to [BVB_SEG_LIGHT_MIN_Q8, BVB_SEG_LIGHT_MAX_Q8]), the
 *     ground G is predicted at the new light, G = G * F / F' (Q8, rounded), and the frame is
 *     flagged BVB_SEG_FLAG_CHANGE. Frame 0 takes L = 256. Smaller changes of the light (and a
 *     flicker) leave L as it was and are followed by G alone (stage 3).
 *     The ground region is seeded on the bottom row, in the middle column. The ground
 *     intensity G is tracked from frame to frame (state, Q8). From frame 1 on, the seed is the
 *     first pixel of the bottom row within t of G (rounded) going outwards from the middle
 *     (x = w/2, w/2-1, w/2+1, w/2-2, ...), at most seed_search pixels away; when there is none
 *     the ground is missing at the robot's feet (see stage 3) and the middle pixel is used.
 *   Stage 2, region growing (bvb_region_grow: 4-connected, tolerance t against the region's
 *     running mean) over the band, into `mask` (255 floor).
 *   Stage 3, ground tracking. m = the region's mean intensity (sum / count). The ground is
 *     - re-seeded at a jump of the light (stage 1) when the seed was found and the region has
 *       at least min_region pixels: G = m, the new ground is trusted at once, the frame is
 *       decided as usual;
 *     - as expected when the seed was found, the region has at least min_region pixels and
 *       |m - G| <= ct: G += (m - G) >> avg_shift (a running average; arithmetic shift);
 *     - changed by the light when the seed was found, the region is large enough, and the
 *       whole band moved with it: F - F' has the sign of m - G and at least half its size
 *       (a smaller change of the light than stage 1's jump). G is re-seeded: G = m, and the
 *       frame is decided as usual (flag BVB_SEG_FLAG_CHANGE); L is kept;
 *     - lost otherwise: no bottom-row pixel near G, a small region, or a region whose mean moved
 *       while the rest of the band did not (a region grown over the white wall the robot's nose
 *       is at). The frame is decided as blocked (a turn), G (as predicted at a jump) is kept
 *       (flag BVB_SEG_FLAG_LOST); after lost_frames lost frames in a row the ground is
 *       re-seeded from the middle pixel's region (G = m): the robot does not turn for ever if
 *       the floor itself has changed.
 *     Frame 0 takes G = m.
 *   Stage 4, obstacle map dilation: the region mask is eroded 3x3 (bvb_erode3x3_u8) into
 *     `map`: the obstacle map (its complement) is dilated, obstacles grow by one pixel and
 *     one-pixel floor leaks along an obstacle's edge do not open a path.
 *   Stage 5, free space per column (bvb_free_space with min_gap): each column filled upward
 *     from the bottom to the obstacle boundary, a run of fewer than min_gap non-floor pixels
 *     (the floor texture's darkest patches that the region growing left out: up to about 9 rows
 *     near the camera at 160x120, after the dilation) not stopping it. free(x) = rows - 1 -
 *     boundary(x) is the column's free-space height in pixels (rows when free to the horizon).
 *   Stage 6, decision, the 30-pixel rule with left and right clearance:
 *     ahead = min free(x) over the centre columns [centre_lo, centre_hi);
 *     forward when ahead > go_rows and no side column is short (below) and the ground is not
 *       lost, and ahead < rows. ahead = rows says every centre column is floor up to the
 *       horizon row, which sees the floor only at infinity (the harness's horizon is the row
 *       at or just below the true horizon: its floor lies hundreds of inches away, beyond any
 *       arena wall), so the region grew up a wall: the wall ahead is as bright as the tracked
 *       ground, which followed the region up the wall's shading by steps each within ct
 *       (flag BVB_SEG_FLAG_HORIZON; the robot turns as it does when blocked). go_rows is 30
 *       at 120 rows; the harness scales it with the height (30 * height / 120, the same floor
 *       distance at every resolution). With the scenes' camera (4 in high,
 *       tilted 10 deg down, 59.5 deg wide) the 30th row from the bottom sees the floor 10 in
 *       ahead of the camera, 7 in ahead of the robot's front; the scenes' truth calls the path
 *       blocked from 12 in, so between 12 and 7 in the rule still goes forward.
 *     The centre columns are those that see the robot's 6 in wide path at that distance
 *       (with 0.5 in to spare: 20% to 80% of the width). Nearer than that the path spreads
 *       over the side columns, so a side column x must have free(x) >= needed(x), going down
 *       linearly from go_rows at the centre band's edge to 0 at the image's edge (a
 *       conservative outline of the path; flag BVB_SEG_FLAG_SIDE when one is short): the robot
 *       does not brush a wall or a box corner that passes beside the centre columns.
 *     Otherwise turn toward the side with more clearance: left = sum of free(x) over
 *       x < width/2, right = sum over x >= width/2; left when left > right, else right. While
 *       the robot stays blocked the direction is latched (state), so it does not swing back
 *       and forth in front of an obstacle; the first forward decision releases the latch.
 *     A stall: the robot can push against what it cannot see. The camera sees 30 deg either
 *       side of the heading, and the robot's front corners lie some 45 deg off it, so a wall
 *       that a turn in place swept out of the view's edge can be right beside the robot's nose;
 *       driving on, it touches the wall and, still seeing open floor, keeps going forward
 *       (the encoders tick even when the robot is blocked). What it does see is that the view
 *       no longer changes. S = the band's sum, S' the previous frame's: a frame is still when
 *       |S - S'| <= (stall_q8 * w * rows) >> 8 (a band mean that moved by at most stall_q8 / 256
 *       of a grey level; the harness's default 0, an identical sum: on the scenes' floor one
 *       0.5 in step forward can move the mean by less than 1/8 of a level, so a bound of 1/8 took
 *       open floor for a stall (boxes, texture_seed=2, frame 11), and the sensor noise
 *       (noise=3 moves the mean by some 0.04 levels) hides a stall from it). A frame that would go
 *       forward, whose previous frame went forward and which is still, counts a still step (any
 *       other frame resets the count); at stall_frames still steps in a row the robot turns for
 *       stall_turn frames (flag BVB_SEG_FLAG_STALL on each), whatever the view says, in the
 *       direction of its last turn (the side with more clearance when it never turned): what it
 *       last turned away from left the view on the other side, and it is what the robot now pushes
 *       against. The turn latches that direction as any turn does.
 *   diag: [0] stages run, [1] ahead (px), [2] left clearance sum, [3] right clearance sum,
 *     [4] region pixels, [5] region mean m, [6] ground average G (Q8), [7] BVB_SEG_FLAG_* bits.
 *   Buffers: mask and map, width x rows bytes each (L1 data banks A and B at 160x120: 13.6 KB
 *     each; SDRAM at 320x240); work, BVB_SEG_AVOID_WORK_BYTES(w, queue_cap): the region
 *     growing queue (the breadth-first front of a region grown in a w x h frame stays near
 *     w + h pixels; the harness gives 2 (w + h) entries, and diag reports an overflow), the
 *     column rows (int16) and the erosion's scratch (bvb/morph.h): 10.0 KB at 160x120, 22.2 KB at
 *     320x240, L1 bank B (at 320x240 the erosion streams mask and map through it by DMA).
 *
 * ============================================================================================
 * OPTICAL-FLOW OBSTACLE AVOIDANCE (flow_avoid; the seed paper's section 2.1.2)
 *   Stage 1, the band. Rows [band_top, band_top + band_rows) of the frame, averaged over
 *     scale x scale blocks (rounded half up; scale 1 copies), into the state's slot for the
 *     current frame: ws x rs pixels, ws = width / scale, rs = band_rows / scale. The two slots
 *     take turns as previous and current band, so nothing is copied from frame to frame. Also
 *     here: what the robot did since the previous frame. The harness's defaults at 160x120:
 *     rows 0..63, those above the row where the floor is 20 in ahead (with nothing within
 *     20 in, everything there is far and moves little), and scale 4, a 40 x 16 band (in
 *     general the largest of 1, 2, 4, 8 that leaves the band at least 40 pixels wide). At the
 *     scenes' 0.5 in per frame a near obstacle moves several pixels per frame at full
 *     resolution, beyond what Horn-Schunck without a pyramid follows; its flow is then
 *     underestimated, the more the nearer it is.
 *   Stage 2, the light, then Horn-Schunck prepare (bvb/hornschunck.h) on the previous and the
 *     current band. A global change of the light's gain between the two frames (flicker, a
 *     step) breaks the brightness constancy the flow rests on: every pixel changes by
 *     (gain - 1)(I - black), which Horn-Schunck reads as motion, most where the band is bright
 *     and least textured. The bands' levels, mean - black (Q4, at least 1/16; black = the
 *     camera's black level, 16 for BT.601 studio-range Y), give the gain
 *     g = (level_cur << 12) / level_prev (Q12, limited to 1/4..8), and with light_gain = 1
 *     (the harness's default) the previous band is scaled in place to
 *     I' = black + ((I - black) g + 2048 >> 12), clamped to 0..255 (nothing when g = 1; its
 *     slot becomes the next frame's current slot, so nothing is lost). The current band is not
 *     touched: what is left is the flow at the current frame's light. The mean also moves when
 *     the view does (a box growing in one half), and that part is taken for a gain too: on the
 *     bundled boxes_approach (no change of the light) 3 of its 7 blocked frames then see L <= R
 *     by 1..11 Q9 where they saw L > R without the compensation. A change of the contrast
 *     itself (a lasting step to a dimmer light) is not undone: Horn-Schunck's alpha then weighs
 *     more against the weaker gradients and the flow of the same motion comes out smaller.
 *   Stage 3, `iterations` (10) Jacobi iterations from zero flow, ping-ponging flow_a/flow_b.
 *   Stage 4, the balance rule. A pixel's flow magnitude is |u| + |v| (Q9 px of the scaled band,
 *     limited to 8 px so that sums fit 32 bits at every size); L and R are its means over the
 *     band's left and right halves (columns < ws/2 and >= ws/2; integer division). The side
 *     with more flow has the nearer obstacles (a translating camera sees a point move in
 *     proportion to 1 / depth):
 *       forward when L <= thresh_q9 and R <= thresh_q9 (80 = 0.16 px per frame, both halves);
 *       otherwise turn toward the smaller side (left when L <= R, else right), committed for
 *       turn_frames frames (10: 30 deg at the scenes' 3 deg per frame).
 *     Stalled: both halves at or below thresh_q9 and the expansion
 *     E = (mean u over the right half) - (mean u over the left half) (u limited to +-8 px,
 *     integer divisions) within +-stall_q9 (thresh_q9 / 16 = 5): the wheels turned but the
 *     view did not move, the robot is pushing against something it did not see. A step
 *     forward moves every point away from the image centre column (u >= 0 right of it, <= 0
 *     left of it), so E > 0 whenever anything in the band moved with the robot; E < 0 is
 *     something moving on its own (a mover crossing), not a stall. Sensor noise makes a flow of
 *     its own (L, R 10..16 on the stalls of the bundled arenas with noise=3, against 20..40 for
 *     distant walls seen while moving), but of either sign, and it cancels in E (|E| <= 3 on
 *     those stalls; a test on L and R would need a noise floor). A stall is decided as a
 *     turn (mode BVB_FLOW_MODE_STALL), committed for stall_turn_frames frames (40: 120 deg):
 *     whatever the robot touches blocks every heading within 90 deg of the direction it ran
 *     into it, more when it met it at an angle, so a 30 deg turn would probe into it again.
 *     While the robot is in an avoidance manoeuvre (turned, probed, still above threshold) the
 *     turn direction is latched; a forward decision of the flow releases it.
 *   The robot's own rotation. A turn in place moves the whole image by about fx * 3 deg (7 px
 *   at 160x120) per frame and carries no depth information. So the flow is computed only when
 *   the step from the previous frame was a pure translation, read from the wheel encoders:
 *   both wheels advanced and |dleft - dright| <= rot_ticks. The frames of a committed turn
 *   compute no flow (mode TURN); the first frame after a turn (or a stop, or frame 0) takes
 *   one step forward without a flow decision (mode PROBE), and the flow of that step decides
 *   the next frame. A large change of the light between the two frames (the bands' mean
 *   intensity moved by more than light_tol grey levels, 8) is not trusted to the gain
 *   compensation of stage 2 (clipped pixels, a change that is not a gain): that frame decides
 *   nothing either and steps forward (mode LIGHT).
 *   Known limits (2,000-frame closed loops of the bundled arenas): a near wall filling the band
 *   moves more than a pixel of the scaled band per frame and its flow is underestimated, the
 *   more after a lasting drop of the light (see stage 2), so a head-on approach may stay below
 *   the threshold to contact; the probe step after a turn is blind, and a turn begun against an
 *   obstacle may step into it once before the stall turns the robot away; a mover that runs
 *   into the robot from the side is not in view before it touches.
 *   diag: BVB_FLOW_DIAG_*.
 *   Buffers (at the defaults they are small; at scale 1 frame-sized, hence SDRAM): coef,
 *     BVB_FLOW_AVOID_COEF_BYTES; flow_a, flow_b, BVB_FLOW_AVOID_FLOW_BYTES each; state,
 *     BVB_FLOW_AVOID_STATE_BYTES (two band slots). All in SDRAM in the harness.
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
  int32_t light_jump_q8; /* a band mean that moved by more than this / 256 of itself: the light */
  int32_t stall_q8;      /* a band mean that moved by at most this / 256 grey levels: no motion */
  int32_t stall_frames;  /* that many forward frames in a row without motion: a stall */
  int32_t stall_turn;    /* frames of the turn after a stall */
};

struct bvb_seg_avoid_state {
  int32_t ground_q8; /* G */
  int32_t latch;     /* 0, or the latched turn decision */
  int32_t frames;    /* frames seen */
  int32_t changes;   /* sudden ground changes seen */
  int32_t lost;      /* consecutive frames without the ground */
  int32_t frame_mean; /* the previous frame's mean below the horizon */
  int32_t light_q8;  /* the light relative to the first frame's, Q8 (256: the same) */
  int32_t frame_sum; /* the previous frame's sum below the horizon */
  int32_t stall;     /* forward frames in a row that left the view as it was */
  int32_t commit;    /* frames left of a turn after a stall */
  int32_t last_turn; /* the last turn decision (0: none yet) */
};

#define BVB_SEG_AVOID_STATE_BYTES ((int32_t)sizeof(struct bvb_seg_avoid_state))
#define BVB_SEG_AVOID_ROWS_BYTES(w) (2 * (((w) + 1) & ~1))
/* work: the region growing queue (queue_cap int32), the column rows, the erosion's scratch */
#define BVB_SEG_AVOID_WORK_BYTES(w, queue_cap) \
  (4 * (queue_cap) + BVB_SEG_AVOID_ROWS_BYTES(w) + BVB_MORPH3X3_SCRATCH_BYTES(w))
#define BVB_SEG_AVOID_STAGES 6
/* The light estimate's range, Q8: 1/8 to 4 times the first frame's light. */
#define BVB_SEG_LIGHT_MIN_Q8 32
#define BVB_SEG_LIGHT_MAX_Q8 1024

#define BVB_SEG_FLAG_CHANGE 1
#define BVB_SEG_FLAG_SEED_MOVED 2
#define BVB_SEG_FLAG_DROPPED 4
#define BVB_SEG_FLAG_LOST 8
#define BVB_SEG_FLAG_SIDE 16
#define BVB_SEG_FLAG_STALL 32
#define BVB_SEG_FLAG_HORIZON 64

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
  int32_t stall_q9;    /* below the threshold and the expansion E at or below this: stalled */
  int32_t turn_frames; /* a turn decision is kept this many frames (>= 1) */
  int32_t stall_turn_frames; /* ... and this many after a stall (>= 1) */
  int32_t rot_ticks;   /* an encoder difference above this is a rotation */
  int32_t light_tol;   /* a band mean that moved more than this (grey levels): the light changed */
  int32_t black;       /* the camera's black level (grey levels): a gain of the light scales
                        * intensity - black */
  int32_t light_gain;  /* 1: the previous band is brought to the current one's level (stage 2) */
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
  int32_t level_q4;    /* the previous band's mean above black, Q4 (before any gain) */
  int32_t pad[2];
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
#define BVB_FLOW_AVOID_GAIN_MIN 1024  /* the light compensation's gain, Q12: 1/4 .. 8 */
#define BVB_FLOW_AVOID_GAIN_MAX 32768

/* diag of flow_avoid */
#define BVB_FLOW_DIAG_STAGES 0
#define BVB_FLOW_DIAG_LEFT 1      /* L: mean magnitude over the left half, Q9 px (-1: no flow) */
#define BVB_FLOW_DIAG_RIGHT 2     /* R likewise */
#define BVB_FLOW_DIAG_MODE 3      /* see enum bvb_flow_mode */
#define BVB_FLOW_DIAG_DLEFT 4     /* encoder increments since the previous frame */
#define BVB_FLOW_DIAG_DRIGHT 5
#define BVB_FLOW_DIAG_LATCH 6
#define BVB_FLOW_DIAG_EXPANSION 7 /* E: mean u right half - mean u left half, Q9 px (0: no flow) */

enum bvb_flow_mode {
  BVB_FLOW_MODE_FLOW = 0,  /* the decision came from the flow */
  BVB_FLOW_MODE_PROBE = 1, /* no usable flow (first frame, after a turn or a stop): forward */
  BVB_FLOW_MODE_TURN = 2,  /* inside a committed turn */
  BVB_FLOW_MODE_LIGHT = 3, /* the light changed between the frames: no flow decision, forward */
  BVB_FLOW_MODE_STALL = 4  /* the wheels moved, the view did not: blocked, turn */
};

struct bvb_flow_avoid_kernels {
  void (*hs_prepare)(const uint8_t *i1, const uint8_t *i2, int32_t width, int32_t height, int32_t stride,
                     int32_t alpha2_q4, int16_t *coef, void *scratch);
  void (*hs_iterate)(const int16_t *coef, const int16_t *uv_in, int32_t in_stride, int16_t *uv_out,
                     int32_t out_stride, int32_t width, int32_t height, void *flow_scratch,
                     void *coef_scratch);
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
