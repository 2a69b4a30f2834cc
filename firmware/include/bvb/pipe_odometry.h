/* Visual odometry pipeline (the seed paper's section 2.2), one call per camera frame, all fixed
 * point: rotation from the scan-line intensity profile shift, translation from floor features
 * tracked by Lucas-Kanade or matched by NCC, optionally fused with the wheel encoders; the pose
 * is accumulated in the state buffer from one frame to the next.
 *
 * UNITS. Positions Q16 inches, angles Q16 degrees (65536 = 1 degree), image coordinates Q8
 * pixels unless a field says otherwise. World and camera conventions are the scene generator's
 * (harness/scene/camera.h): heading counter-clockwise from +x, left turns positive; image x
 * right, y down, pixel centres at integers; the camera on the robot's centre line cam_offset
 * ahead of the axle centre, cam_height above the floor, tilted down by tilt, no roll.
 *
 * ROTATION (equations 3 to 5 of the seed). The column profile of a band of rows around the
 * horizon (bvb/scanline.h: the mean of each column over band_rows rows from band_y0) is
 * compared with a key profile (an earlier frame's, below) by the scan-line shift search: the
 * integer shift t minimising the mean absolute difference f(t) = S(t) / (n - |t|) over
 * |t| <= T = win_w - rho; t > 0 when the scene moved right, i.e. the robot turned left.
 * Sub-pixel (shift_fit 1): a parabola through f(t-1), f(t), f(t+1) (exact quotients in Q16),
 * delta = (f(t-1) - f(t+1)) / (2 (f(t-1) - 2 f(t) + f(t+1))), |delta| <= 1/2 because f(t) is
 * the minimum; s = t + delta in Q8 (no step at the end of the search range or with zero
 * curvature). shift_fit 0: whole pixels; 2: the equiangular (V) fit, denominator 2 (max(f(t-1),
 * f(t+1)) - f(t)).
 *   From shift to angle. A turn by dtheta about the vertical axis moves the image point with
 *   normalised coordinates (xn, yn) = ((x - cx) / fx, (y - cy) / fy) horizontally by, to first
 *   order, du = fx dtheta ((1 + xn^2) cos(tilt) - yn sin(tilt)) pixels (the rotational flow of a
 *   camera turning about the axis (0, -cos tilt, -sin tilt) of its own frame). It does not
 *   depend on depth, so the band moves as a whole, but it grows towards the image sides by
 *   (1 + xn^2): one pixel at the edge of a 60 degree view is 20% less angle than at the centre,
 *   and a shift found over all columns is a texture-weighted mix of the two.
 *   rot_bins 1 (the default) therefore compares the profiles in angle bins rather than in
 *   columns: on the horizon row a point at azimuth phi (from the optical axis's vertical plane)
 *   is seen at x = cx + fx tan(phi) / cos(tilt), so bin k of width dphi = cos(tilt) / fx rad
 *   (one pixel at the image centre) is the profile linearly interpolated at that x (a table
 *   made in frame 0 with CORDIC: bins from the window's first column to its last). A turn
 *   shifts this angle profile uniformly: dtheta = s dphi, exact on the horizon row for any
 *   shift, i.e. the atan in "theta = atan(shift / fx)" is applied per column. The band's centre
 *   row yc is off the horizon; there the flow in bins is cos(tilt) (cos(tilt) - yc sin(tilt))
 *   per bin of turn at the image centre, so the bin's angle is dphi_row = dphi / that.
 *   At 160x120 (fx = 140, tilt 10 deg, band rows 21..52, window columns 8..151): 133 bins of
 *   0.4030 deg, dphi_row = 0.4039 deg, so the scenes' 3 deg turn per frame is 7.43 bins.
 *   rot_bins 0 compares columns and converts with one gain for the window:
 *     dtheta = atan(s / G),  G = fx ((1 + m2) cos(tilt) - yc sin(tilt)),
 *     m2 = ((xm - cx)^2 + (win_w^2 - 1) / 12) / fx^2 (the mean of xn^2 over the window, xm its
 *     centre column): G = 154.1 px/rad at 160x120. For an untilted camera and a one-column
 *     window this is atan(s / fx); the small-angle form s * HFOV / width uses the mean angle of
 *     a pixel across the whole width instead.
 *   Key profiles. Comparing each frame with the previous one adds one sub-pixel error per frame
 *   (the parabola is pulled towards whole pixels); comparing with a key profile adds one per
 *   key. The key is renewed (after this frame's comparison) when the whole-bin shift reaches
 *   key_shift (so the next frame's shift stays inside the search range), when it changed by
 *   less than key_still bins since the previous frame (the robot is not turning: driving
 *   straight, frame-to-frame comparison keeps the profile's change from the robot's own
 *   forward motion small), after key_frames frames, and when the encoders overrule the
 *   rotation (fusion). The rotation since the key is exact up to the last comparison, so
 *   dtheta_vis = key_heading + s dphi_row - heading.
 *
 * TRANSLATION. Harris corners (bvb/harris.h) of the previous frame in the floor region (image
 * rows from floor_y0, where the ground plane is nearer than max_range) are tracked into this
 * frame (tracker 0: pyramidal Lucas-Kanade, bvb/lk.h, Q16 positions; tracker 1: NCC matching,
 * bvb/ncc.h, whole pixels, refined with a parabola through the NCC scores of the 3 x 3 offsets
 * around the match when ncc_subpixel is set). Each point is put on the floor: the ray through
 * (x, y) meets the plane z = 0 at
 *   F = h (fy cos(tilt) - v sin(tilt)) / D + cam_offset   (ahead of the axle centre)
 *   L = -h (x - cx) (fy / fx) / D                           (to the left)
 *   D = fy sin(tilt) + v cos(tilt),  v = y - cy,  h = cam_height,
 * valid below the horizon (D > 0; points with F beyond 2 max_range are dropped). With P the
 * floor point seen in the previous frame and Q in this one (both in the robot's frame at the
 * time), a static point obeys P - T = R(dtheta) Q for the robot's motion T, so T = P -
 * R(dtheta) Q: the rotation is compensated with this frame's dtheta. Per point, the motion along
 * the chord direction dtheta / 2, d = T . (cos dtheta/2, sin dtheta/2), and across it, e (zero
 * for a wheeled robot). The estimate: the median of d; inliers are the points with |d - median|
 * <= inlier_tol and |e| <= inlier_tol; the forward motion is the mean of the inliers' d
 * (rounded to nearest). A static floor gives agreeing points; features on obstacles (not on
 * the floor) or on a moving object do not.
 *
 * ROTATION FROM THE FLOOR (rot_feat = 1; the seed: "the shift in x direction is used for the
 * small rotation information. To measure large rotation, scan line algorithm is used in
 * parallel"). Driving towards obstacles their edges spread outwards, unevenly, and the profile's
 * shift follows the strongest of them: a slow heading drift on straight legs; and its bins'
 * angle is right only on one row, so turns come out some 0.3% large. The tracked floor points
 * have neither problem: each is the same point of a rigid plane seen from two robot poses.
 * With this frame's turn a and d forward along the chord, P = R(a) Q + d (cos a/2, sin a/2)
 * (P, Q on the floor as under TRANSLATION, in the previous and this frame's robot frames).
 * About a start a0, with Q' = R(a0) Q, the sideways part gives the remainder da = a - a0 to
 * first order: lat = P.L - Q'.L - d sin(a0/2) = da (Q'.F + d/2) =: da den, with d the median
 * of P.F - Q'.F. A point's sideways error grows with its distance as den does, so each point's
 * ratio lat / den has about the same error and the points are weighed alike: da = sum lat /
 * sum den over the inliers (one division; sums in 64 bits, Q16 inches). Robustly: the start
 * a0 is the profile's rotation; when fewer than half the points lie within rot_sel_tol (0.25
 * in) of its prediction, forward and sideways, it is the median of the points' ratios about
 * no turn instead (a profile that jumps by degrees on a straight leg does not matter); the
 * points within rot_sel_tol of the start's prediction give a first fit, those within
 * inlier_tol (0.1 in) of the first fit's the second, which is the rotation. The rule: the
 * features' rotation when at least rot_min_inliers points (8) agree in both selections and it
 * is at most rot_small (4.5 degrees: the robot turns 3 degrees a frame in place, which the
 * tracker follows); otherwise the profile's (larger rotations, no floor in view, too few
 * points agreeing). Flag BVB_ODO_F_ROT_FEAT says which. It is chosen in stage 5, after the
 * tracking, before the rotation's fusion and the translation, which then use it; the key
 * profile's heading follows it.
 *
 * FUSION with the wheel encoders (fuse = 1; the seed's proposed remedy for a moving object in
 * view). From the tick increments dl, dr since the previous frame: dfwd_enc = (dl + dr) /
 * (2 tpi), dtheta_enc = (dr - dl) / (tpi wheelbase) radians. Rotation, two tests:
 *   per frame: the encoders' dtheta when |dtheta_vis - dtheta_enc| > fuse_rot_tol (a gross
 *     error: a moving object crossing the band, an ambiguous profile);
 *   per window of fuse_window frames, while the encoders say the robot drives straight (their
 *     heading change over the window at most fuse_rot_tol): the heading change since the
 *     window's start against the encoders' (from the tick counts at its start, so their
 *     rounding does not add up); when they differ by more than fuse_rot_tol the heading is set
 *     to the window's start plus the encoders' change. This catches a slow drift (a moving
 *     object that biases the shift by a tenth of a degree per frame, under the per-frame
 *     tolerance). Turns are left out because wheels that slip are wrong in proportion to the
 *     turn (4% of 90 degrees with the scenes' slip = 0.05), while straight ahead both wheels
 *     over-count alike. A new window starts after a correction or after fuse_window frames.
 *   The features' rotation compensation uses the frame's own turn (after the per-frame test),
 *   not the window's correction. A frame whose rotation came from the floor features
 *   (BVB_ODO_F_ROT_FEAT) keeps it and starts a new window: the mover does not drag them, and
 *   the encoders' slip would only be let in (the square with slip=0.05 ended 1.00 in, 1.85 deg
 *   off fused, 0.22 in, 0.42 deg by vision alone), so the rotation's fusion covers the
 *   profile's frames (no floor in view, too few points agreeing, rotations over rot_small).
 * Translation: the encoders' when fewer than min_inliers points agree (no floor in view) or
 * |dfwd_vis - dfwd_enc| > fuse_trans_tol; otherwise vision is kept (it does not count wheel
 * slip). Without fusion, a frame with fewer than min_inliers inliers has zero translation (flag
 * BVB_ODO_F_FWD_NONE). The result's flags say which source each frame used.
 *
 * POSE. heading_mid = heading + dtheta / 2; x += dfwd cos(heading_mid); y += dfwd sin(
 * heading_mid); heading += dtheta (not wrapped). Frame 0 sets the pose to (start_x, start_y,
 * start_heading) and only stores the frame, the profile and the features.
 *
 * TRIGONOMETRY: CORDIC, 28 iterations over a table of atan(2^-i) in Q24 degrees
 * (round(atan(2^-i) * 180 / pi * 2^24)); angles in and out are Q16 degrees. Rotation mode gives
 * cos and sin in Q30 (start vector K 2^30, K = prod 1 / sqrt(1 + 2^-2i) = 0.6072529350,
 * round(K 2^30) = 652032874; angles reduced to [-90, 90] degrees first), within 2^-25 of the
 * exact values. Vectoring mode gives atan2(y, x) for x > 0 (inputs scaled to [2^27, 2^28)
 * first), within one Q16 unit (1.5e-5 degrees) for inputs of at least 1000 (host unit tests).
 * Divisions: integer, truncating, by positive divisors; one 32-bit division per floor point.
 *
 * CALL (the pipeline contract of bvb/pipeline.h). bvb_pipe_odometry_c runs the orchestration
 * (bvb_pipe_odometry_run) over the C kernels, bvb_pipe_odometry_asm (firmware only, its table in
 * firmware/pipelines/pipe_odometry_table.c) over the assembly ones: scan-line profile and shift,
 * Harris response and NMS, LK pyramid and tracking, NCC matching and score map; the Harris
 * selection is C in both. The two give identical results, and the host build the same again.
 *   frame: width x height bytes, stride between rows (the grey image; no alignment needed).
 *   info: struct bvb_pipe_frame (index 0 starts the pose at start_x, start_y, start_heading and
 *   only stores the frame, its profile and features; cumulative encoder ticks; stages).
 *   p: struct bvb_odo_params. state: bvb_pipe_odometry_state_bytes() bytes, 4-byte aligned, left
 *   alone between calls (frame 0 initialises it; its contents before do not matter). out: the
 *   pose (has_pose = 1, x_q16, y_q16 in inches, heading_q16 in degrees, counter-clockwise, not
 *   wrapped), decision BVB_PIPE_STOP (this pipeline steers nothing), diag BVB_ODO_DIAG_*.
 *   work: bvb_pipe_odometry_work_bytes() bytes, 4-byte aligned, any contents (SDRAM: the
 *   response map, 4 bytes per pixel of the floor region, when it does not go in strips through
 *   fast). fast:
 *   bvb_pipe_odometry_fast_bytes() bytes, 4-byte aligned, any contents: the working rows that
 *   want L1 data SRAM, one after the other: stage 1's profile scratch (the band streams through
 *   L1), then the tracker's features and scratch (placed by bvb_lk_scratch_place, so that its
 *   arrays fall in different sub-banks) with this frame's LK pyramid and the previous frame's
 *   (brought from the state by memory DMA during the rotation), then the Harris response's and
 *   the NMS's scratch (there the assembly
 *   response streams the frame through L1 by DMA, bvb/harris.h) with strips of the response
 *   map (bvb_odo_harris_strips: 20 rows at 160x120), each scanned by the NMS while in L1; the
 *   pyramids and the strips while the whole stays within BVB_ODO_FAST_MAX bytes. Returns
 *   BVB_PIPE_STOP, or -1 when the parameters are out of range (nothing written).
 *   Limits (else -1): 16 <= width, height <= 1024, width <= stride <= 4096; 1 <= fx, fy <= 1024
 *   px; cam_height 1/16..64 in; tilt -45..45 deg; 1 <= band_rows <= 256 inside the frame; the
 *   window inside the frame, 1 <= rho <= win_w, at least one bin of overlap; key_shift,
 *   key_frames >= 1; max_range 1..256 in, and the floor at max_range at least 5 rows above
 *   the bottom; 1 <= max_features <= BVB_ODO_MAX_FEATURES; lk_levels 1..4, lk_win odd 3..15,
 *   lk_max_iter 1..100; ncc_radius 1..5, ncc_search 1..16; tpi 1..65536 ticks per inch,
 *   wheelbase 1/16..256 in, fuse_window >= 1.
 *   Working set with the harness's defaults: state 52,156 bytes at 160x120 (two slots of a
 *   frame and its pyramid: the previous one, and this one's, copied in while the tracker reads
 *   the other, by memory DMA in the assembly build; 206,420 at 320x240), work 48,804 bytes (295,904, where the Harris
 *   response of the floor region is most of it); both in SDRAM; fast 23,792 bytes (13,552 at
 *   320x240: no pyramid, the response map in work). */
#ifndef BVB_PIPE_ODOMETRY_H
#define BVB_PIPE_ODOMETRY_H

#include <stdint.h>

#include "bvb/lk.h"
#include "bvb/pipeline.h"

#define BVB_ODO_MAX_FEATURES 127
#define BVB_ODO_STATE_VERSION 0x4F444F33 /* "ODO3" */

#define BVB_ODO_TRACK_LK 0
#define BVB_ODO_TRACK_NCC 1

/* Stages (info->stages = k > 0 stops after k; diag[0] says how many ran): 1 profile and angle
 * bins, 2 rotation from the profile (shift search), 3 LK pyramid, 4 tracking, 5 rotation
 * from the floor features, the rotation's fusion, floor motion,
 * translation and pose, 6 Harris response (and the NMS, when the map goes in strips through
 * fast), 7 NMS and selection, 8 commit (the state: pose, key
 * profile, features, this frame's slot as the previous one; a full run copies this frame and
 * its pyramid into the other slot after stage 3). A call stopped early leaves the state as it
 * was (except frame 0's bin table, always the same). */
#define BVB_ODO_STAGES 8

/* diag words of the result */
#define BVB_ODO_DIAG_STAGES 0       /* stages run */
#define BVB_ODO_DIAG_DTHETA_VIS 1   /* this frame's rotation from the profile shift, Q16 degrees */
#define BVB_ODO_DIAG_DTHETA_ENC 2   /* ... from the encoders */
#define BVB_ODO_DIAG_DTHETA 3       /* ... used */
#define BVB_ODO_DIAG_DFWD_VIS 4     /* this frame's forward motion from the features, Q16 inches */
#define BVB_ODO_DIAG_DFWD_ENC 5     /* ... from the encoders */
#define BVB_ODO_DIAG_DFWD 6         /* ... used */
#define BVB_ODO_DIAG_POINTS 7       /* flags | inliers << 8 | points on the floor << 16 |
                                       features found for the next frame << 24 */

/* flags, bits 0-7 of diag[BVB_ODO_DIAG_POINTS] */
#define BVB_ODO_F_ROT_ENC 1      /* rotation taken from the encoders */
#define BVB_ODO_F_FWD_ENC 2      /* translation taken from the encoders */
#define BVB_ODO_F_FWD_NONE 4     /* no visual translation (too few inliers) */
#define BVB_ODO_F_ROT_WIN 8      /* ... because of the window test */
#define BVB_ODO_F_ROT_FEAT 16    /* rotation from the floor features (else the profile's) */

struct bvb_odo_params {
  int32_t fx, fy, cx, cy;          /* Q8 pixels */
  int32_t cam_height;              /* Q16 inches */
  int32_t tilt;                    /* Q16 degrees below the horizontal, -45..45 */
  int32_t cam_offset;              /* Q16 inches */
  int32_t start_x, start_y;        /* Q16 inches */
  int32_t start_heading;           /* Q16 degrees */
  /* rotation */
  int32_t band_y0, band_rows;      /* rows of the profile band */
  int32_t win_x0, win_w, rho;      /* columns compared, minimum overlap */
  int32_t shift_fit;               /* sub-pixel step: 0 none, 1 parabola, 2 equiangular */
  int32_t rot_bins;                /* 1: compare the profile in angle bins; 0: in columns */
  int32_t key_shift, key_frames;   /* a new key profile after this shift (bins) or frames */
  int32_t key_still;               /* ... or when the shift changed by less (bins) */
  /* translation */
  int32_t tracker;                 /* BVB_ODO_TRACK_* */
  int32_t max_range;               /* Q16 inches of floor ahead of the camera: sets floor_y0 */
  int32_t max_features, min_distance, harris_threshold;
  int32_t lk_levels, lk_win, lk_max_iter, lk_eps, lk_min_det;  /* bvb_lk_params */
  int32_t ncc_radius, ncc_search, ncc_subpixel;
  int32_t inlier_tol;              /* Q16 inches */
  int32_t min_inliers;
  /* encoders and fusion */
  int32_t fuse;
  int32_t tpi;                     /* Q8 ticks per inch of wheel travel */
  int32_t wheelbase;               /* Q16 inches */
  int32_t fuse_rot_tol;            /* Q16 degrees */
  int32_t fuse_trans_tol;          /* Q16 inches */
  int32_t fuse_window;             /* frames */
  /* small rotations from the floor features (ROTATION FROM THE FLOOR, above) */
  int32_t rot_feat;                /* 1: use them; 0: the profile alone */
  int32_t rot_small;               /* Q16 degrees: the largest turn they measure */
  int32_t rot_min_inliers;         /* fewest agreeing points */
  int32_t rot_sel_tol;             /* Q16 inches: the first selection's tolerance */
};

/* The kernels one build calls. */
/* fast holds the LK pyramid and the Harris strips while it stays within this (L1 data bank B
 * has 24 KB above its stack; the guard bands the checks put around it take 128 bytes). */
#define BVB_ODO_FAST_MAX 24320u

struct bvb_odo_kernels {
  void (*profile)(const uint8_t *src, int32_t width, int32_t rows, int32_t stride, uint8_t *profile,
                  void *scratch);
  void (*shift)(const uint8_t *p1, const uint8_t *p2, int32_t w, int32_t rho, int32_t *result,
                uint32_t *curve);
  void (*harris_response)(const uint8_t *src, int32_t *dst, int32_t width, int32_t height,
                          int32_t src_stride, int32_t dst_stride, void *scratch);
  int32_t (*harris_nms)(const int32_t *resp, int32_t width, int32_t height, int32_t stride,
                        int32_t threshold, int32_t *cand, int32_t *count, void *scratch);
  /* bvb_lk_pyramid's levels; scratch (scratch_bytes, 4-byte aligned, in fast) is where the
   * assembly build streams the frame through L1 (0 bytes: the kernel reads it in place). */
  void (*lk_pyramid)(const uint8_t *src, int32_t width, int32_t height, int32_t stride,
                     int32_t levels, uint8_t *pyr, void *scratch, uint32_t scratch_bytes);
  void (*lk_track)(const uint8_t *prev, const uint8_t *prev_pyr, const uint8_t *next,
                   const uint8_t *next_pyr, int32_t width, int32_t height, int32_t stride,
                   const struct bvb_lk_params *params, const int32_t *in, int32_t *out, void *scratch);
  void (*ncc_match)(const uint8_t *frame1, const uint8_t *frame2, int32_t stride, int32_t width,
                    int32_t height, const int16_t *points, int32_t npoints, int32_t radius,
                    int32_t search, int16_t *results, void *scratch);
  void (*ncc_scoremap)(const uint8_t *frame1, const uint8_t *frame2, int32_t stride, int32_t width,
                       int32_t height, int32_t x, int32_t y, int32_t radius, int32_t search,
                       int16_t *map, void *scratch);
  /* The state update's copies of the frame and its pyramid: n bytes from src to dst and n2
   * from src2 to dst2 (4-byte aligned, multiples of 4; n2 may be 0), done when copy_wait
   * returns. The C build copies at once; the assembly build's starts a memory DMA job (its
   * descriptors in job, BVB_ODO_COPY_JOB_BYTES) that runs while the core goes on. */
  void (*copy)(void *job, uint8_t *dst, const uint8_t *src, uint32_t n, uint8_t *dst2, const uint8_t *src2,
               uint32_t n2);
  void (*copy_wait)(void);
};
#define BVB_ODO_COPY_JOB_BYTES 112

#ifdef __cplusplus
extern "C" {
#endif

/* Bytes of state and work for a frame size and these parameters (0 when out of range). */
uint32_t bvb_pipe_odometry_state_bytes(int32_t width, int32_t height, int32_t stride,
                                       const struct bvb_odo_params *p);
uint32_t bvb_pipe_odometry_work_bytes(int32_t width, int32_t height, int32_t stride,
                                      const struct bvb_odo_params *p);
uint32_t bvb_pipe_odometry_fast_bytes(int32_t width, int32_t height, int32_t stride,
                                      const struct bvb_odo_params *p);
/* The first image row of the feature region (floor nearer than max_range), as the pipeline
 * computes it; -1 when the parameters are out of range. */
int32_t bvb_pipe_odometry_floor_y0(int32_t width, int32_t height, int32_t stride, const struct bvb_odo_params *p);
/* 1 when a frame (info) with this geometry and these parameters takes its derived quantities
 * from the state (a full run of the same ones left them there) instead of deriving them again;
 * 0 when it derives them. Exported for the host tests. */
int32_t bvb_pipe_odometry_setup_cached(const uint8_t *state, const struct bvb_pipe_frame *info, int32_t width,
                                       int32_t height, int32_t stride, const struct bvb_odo_params *p);

int32_t bvb_pipe_odometry_run(const struct bvb_odo_kernels *k, const uint8_t *frame, int32_t width,
                              int32_t height, int32_t stride, const struct bvb_pipe_frame *info,
                              const struct bvb_odo_params *p, uint8_t *state, struct bvb_pipe_result *out,
                              void *work, void *fast);
int32_t bvb_pipe_odometry_c(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                            const struct bvb_pipe_frame *info, const struct bvb_odo_params *p, uint8_t *state,
                            struct bvb_pipe_result *out, void *work, void *fast);
int32_t bvb_pipe_odometry_asm(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                              const struct bvb_pipe_frame *info, const struct bvb_odo_params *p,
                              uint8_t *state, struct bvb_pipe_result *out, void *work, void *fast);

/* Stages 6 and 7's candidates over strips of kr response rows (kr >= 1, 5 <= hreg): the
 * same list as ops->harris_nms over ops->harris_response's whole map of the hreg rows at src.
 * save: 2 rows, buf: kr + 4 rows of width int32; hscr, nmsscr: the kernels' scratch. The
 * pipeline's own, exported for the host tests. */
int32_t bvb_odo_harris_strips(const struct bvb_odo_kernels *ops, const uint8_t *src, int32_t width,
                              int32_t hreg, int32_t stride, int32_t kr, int32_t threshold, int32_t *cand,
                              void *hscr, void *nmsscr, int32_t *save, int32_t *buf);

/* The fixed-point trigonometry, exported for the host tests. */
void bvb_odo_sincos(int32_t angle_q16deg, int32_t *cos_q30, int32_t *sin_q30);
int32_t bvb_odo_atan2(int32_t y, int32_t x);  /* Q16 degrees; x > 0 */

#ifdef __cplusplus
}
#endif

#endif
