/* Visual odometry pipeline: see bvb/pipe_odometry.h for what it computes and in which units. */
#include "bvb/pipe_odometry.h"

#include "bvb/harris.h"
#include "bvb/lk.h"
#include "bvb/ncc.h"
#include "bvb/scanline.h"
#include "bvb/stream.h"

/* ---- fixed-point helpers ---- */

#define Q16 65536
#define DEG90 (90 * Q16)
#define DEG180 (180 * Q16)
#define DEG360 (360 * Q16)
#define CORDIC_N 28
#define CORDIC_K_Q30 652032874
/* 180 / pi in Q16 degrees per radian: round(180 / pi * 65536). */
#define RAD_Q16DEG 3754936

/* atan(2^-i) in Q24 degrees: round(atan(2^-i) * 180 / pi * 2^24). */
static const int32_t atan_q24deg[CORDIC_N] = {
    754974720, 445687602, 235489088, 119537938, 60000934, 30029717, 15018523, 7509720, 3754917, 1877466,
    938734,    469367,    234684,    117342,    58671,    29335,    14668,    7334,    3667,    1833,
    917,       458,       229,       115,       57,       29,       14,       7};

/* On the Blackfin a 64-bit division is a libgcc call that loops over 32-bit divisions
 * (__divdi3: some 1,500 cycles); both helpers take one 32-bit division when the operands fit,
 * which gives the same quotient. */
static int32_t fits32(int64_t v) { return v >= -0x7FFFFFFF && v <= 0x7FFFFFFF; }

/* n / d truncated towards zero, as C's int64 division. */
static int64_t div64(int64_t n, int64_t d) {
  if (fits32(n) && fits32(d)) return (int32_t)n / (int32_t)d;
  return n / d;
}

/* n / d rounded to nearest (halves away from zero), d > 0. */
static int64_t div_round(int64_t n, int64_t d) {
  if (fits32(n) && fits32(d)) {
    /* |n| + d / 2 < 2^32: unsigned 32 bits hold it */
    const uint32_t m = (uint32_t)(n >= 0 ? n : -n), q = (m + (uint32_t)d / 2) / (uint32_t)d;
    return n >= 0 ? (int64_t)q : -(int64_t)q;
  }
  return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
}

/* v * 2^-s rounded to nearest (halves up); arithmetic shift of a possibly negative value. */
static int64_t shr_round(int64_t v, int32_t s) {
  return (v + ((int64_t)1 << (s - 1))) >> s;
}

static int32_t iabs(int32_t v) { return v < 0 ? -v : v; }

void bvb_odo_sincos(int32_t angle, int32_t *cos_q30, int32_t *sin_q30) {
  /* Reduce to (-180, 180], then to [-90, 90] with a sign flip. */
  int32_t a = angle % DEG360;
  if (a > DEG180) a -= DEG360;
  if (a <= -DEG180) a += DEG360;
  int32_t neg = 0;
  if (a > DEG90) {
    a -= DEG180;
    neg = 1;
  } else if (a < -DEG90) {
    a += DEG180;
    neg = 1;
  }
  int32_t x = CORDIC_K_Q30, y = 0, z = a * 256; /* Q24 degrees, |z| <= 90 * 2^24 */
  for (int32_t i = 0; i < CORDIC_N; ++i) {
    const int32_t xs = x >> i, ys = y >> i;
    if (z >= 0) {
      x -= ys;
      y += xs;
      z -= atan_q24deg[i];
    } else {
      x += ys;
      y -= xs;
      z += atan_q24deg[i];
    }
  }
  *cos_q30 = neg ? -x : x;
  *sin_q30 = neg ? -y : y;
}

int32_t bvb_odo_atan2(int32_t y, int32_t x) {
  if (x <= 0) return 0;
  /* Scale so that the larger magnitude lies in [2^27, 2^28): the vector's length stays below
   * 2^30 through the CORDIC gain of 1.65. */
  int64_t xx = x, yy = y;
  int64_t m = xx > (yy < 0 ? -yy : yy) ? xx : (yy < 0 ? -yy : yy);
  while (m >= ((int64_t)1 << 28)) {
    xx >>= 1;
    yy >>= 1;
    m >>= 1;
  }
  while (m < ((int64_t)1 << 27)) {
    xx *= 2;
    yy *= 2;
    m *= 2;
  }
  int32_t vx = (int32_t)xx, vy = (int32_t)yy, z = 0;
  for (int32_t i = 0; i < CORDIC_N; ++i) {
    const int32_t xs = vx >> i, ys = vy >> i;
    if (vy > 0) {
      vx += ys;
      vy -= xs;
      z += atan_q24deg[i];
    } else {
      vx -= ys;
      vy += xs;
      z -= atan_q24deg[i];
    }
  }
  return (int32_t)shr_round(z, 8);
}

/* v * c in Q30, rounded. */
static int32_t mul_q30(int32_t v, int32_t c) { return (int32_t)shr_round((int64_t)v * c, 30); }

/* ---- layout ---- */

/* Derived quantities and the byte layout of state and work. */
struct odo_setup {
  int32_t ok;
  int32_t w, h, stride;
  int32_t floor_y0, hreg;      /* feature region: rows floor_y0 .. height-1 */
  int32_t sin18, cos18;        /* tilt, Q18 */
  int32_t fy_fx;               /* fy / fx, Q16 */
  int32_t gain_q8;             /* G of the rotation, Q8 pixels per radian */
  int32_t shift_range;         /* T = win_w - rho */
  int32_t bins, bins_rho;      /* the compared profile: angle bins, or the window's columns */
  int32_t dphi, phi0;          /* angle bins: width and the first bin's centre, Q16 degrees */
  int32_t dphi_row;            /* the turn that moves the band's centre row by one bin */
  uint32_t pyr_bytes;
  /* state offsets */
  uint32_t s_table, s_profile, s_frame, s_frame_bytes, s_pyr, s_total;
  /* work offsets */
  uint32_t x_profile, x_bins, x_pscratch, x_result, x_curve, x_pyr, x_points,
      x_nres, x_nscr, x_map, x_pairs, x_d, x_e, x_sort, x_resp, x_cand, x_corners, x_floor, x_fsort,
      x_fwd, x_fkeep, x_total;
  /* fast offsets: the job, then the tracker's buffers (f_lk*) and this frame's pyramid, and
   * over the same bytes later the Harris stages' (f_hscr .. f_strip) */
  uint32_t f_job, f_lkin, f_lkout, f_lkscr, f_pscratch, f_hscr, f_nmsscr, f_save, f_strip, f_pyr, f_total;
  int32_t pyr_fast;            /* this frame's pyramid in fast (f_pyr), else in work (x_pyr) */
  uint32_t f_ppyr;             /* the previous frame's pyramid brought into fast, if ppyr_fast */
  int32_t ppyr_fast;
  uint32_t pyr_scr_bytes;      /* the pyramid's stream scratch at f_lkin (0: none) */
  int32_t strip_rows;          /* response rows per strip in fast (f_strip); 0: the whole map in
                                * work (x_resp) */
};

/* The geometry and parameters of the last full run and what setup derived from them: a frame
 * run with the same ones takes them from here instead of deriving them again (at 160x120 about
 * 11,700 modelled cycles a frame, most of them fetching setup's code into the instruction
 * cache; a robot derives them once). Written with the commit, as the rest of the state. */
struct odo_cache {
  int32_t w, h, stride;
  struct bvb_odo_params p;
  struct odo_setup s;
};

struct odo_state {
  int32_t version;       /* written in frame 0: a state without it is started afresh */
  int32_t frames;
  int32_t x, y, heading;
  int32_t left, right;
  int32_t key_heading;   /* the heading when the key profile was taken */
  int32_t key_age;       /* frames since */
  int32_t key_shift;     /* the previous frame's whole-bin shift from the key profile */
  int32_t win_heading;   /* fusion window: the heading and the ticks at its start */
  int32_t win_left, win_right;
  int32_t win_age;
  int32_t slot;          /* which of the two frame and pyramid slots holds the previous frame */
  int32_t nfeat;
  int32_t feat[2 * BVB_ODO_MAX_FEATURES]; /* Q16 positions in the previous frame */
  struct odo_cache cache;
  /* then: the angle bins' columns (bins int32, made in frame 0), the key profile (bins bytes,
   * padded to 4), two frame slots (stride x height, padded), two LK pyramid slots (levels
   * 1..): slot `slot` holds the previous frame and its pyramid, the other one receives this
   * frame's while the tracker still reads the previous one */
};

#define ALIGN4(n) (((n) + 3u) & ~3u)


/* Bytes beyond the tracker's scratch that let bvb_lk_scratch_place choose where it starts, so
 * that its arrays fall in different L1 sub-banks wherever fast is. */
#define LK_SCRATCH_SLACK 1536u

/* Fewest response rows per strip worth the per-call costs (each strip brings 4 image rows more
 * than it makes and copies 2 response rows back and forth); below it the map goes to work. */
#define STRIP_MIN_ROWS 8

static int32_t in_range(int32_t v, int32_t lo, int32_t hi) { return v >= lo && v <= hi; }

static void setup(int32_t w, int32_t h, int32_t stride, const struct bvb_odo_params *p, struct odo_setup *s) {
  /* Every field defined (those a configuration does not use stay 0): the state keeps a copy. */
  for (uint32_t i = 0; i < sizeof *s / 4; ++i) ((int32_t *)s)[i] = 0;
  s->w = w;
  s->h = h;
  s->stride = stride;
  if (!in_range(w, 16, 1024) || !in_range(h, 16, 1024) || stride < w || stride > 4096) return;
  if (!in_range(p->fx, 256, 1 << 18) || !in_range(p->fy, 256, 1 << 18)) return;
  if (!in_range(p->cx, -(1 << 20), 1 << 20) || !in_range(p->cy, -(1 << 20), 1 << 20)) return;
  if (!in_range(p->cam_height, Q16 / 16, 64 * Q16) || !in_range(p->tilt, -45 * Q16, 45 * Q16)) return;
  if (!in_range(p->cam_offset, -64 * Q16, 64 * Q16)) return;
  if (!in_range(p->band_rows, 1, BVB_SCANLINE_MAX_ROWS) || !in_range(p->band_y0, 0, h - p->band_rows)) return;
  if (!in_range(p->win_w, 1, BVB_SCANLINE_MAX_WINDOW) || !in_range(p->win_x0, 0, w - p->win_w)) return;
  if (!in_range(p->rho, 1, p->win_w) || p->key_shift < 1 || p->key_frames < 1) return;
  if (p->tracker != BVB_ODO_TRACK_LK && p->tracker != BVB_ODO_TRACK_NCC) return;
  if (!in_range(p->max_range, Q16, 256 * Q16)) return;
  if (!in_range(p->max_features, 1, BVB_ODO_MAX_FEATURES) || !in_range(p->min_distance, 0, 1024)) return;
  if (p->harris_threshold < 0) return;
  if (!in_range(p->lk_levels, 1, 4) || !in_range(p->lk_win, 3, 15) || (p->lk_win & 1) == 0) return;
  if (!in_range(p->lk_max_iter, 1, 100) || p->lk_eps < 0 || !in_range(p->lk_min_det, 0, 1 << 20)) return;
  if (!in_range(p->ncc_radius, 1, BVB_NCC_MAX_RADIUS) || !in_range(p->ncc_search, 1, BVB_NCC_MAX_SEARCH)) return;
  if (!in_range(p->inlier_tol, 0, 64 * Q16) || !in_range(p->min_inliers, 1, BVB_ODO_MAX_FEATURES)) return;
  if (!in_range(p->tpi, 256, 1 << 24) || !in_range(p->wheelbase, Q16 / 16, 256 * Q16)) return;
  if (p->fuse_rot_tol < 0 || p->fuse_trans_tol < 0 || p->fuse_window < 1) return;
  if (!in_range(p->rot_feat, 0, 1) || !in_range(p->rot_small, 0, 90 * Q16)) return;
  if (!in_range(p->rot_min_inliers, 2, BVB_ODO_MAX_FEATURES) || !in_range(p->rot_sel_tol, 0, 64 * Q16)) return;

  int32_t c30, s30;
  bvb_odo_sincos(p->tilt, &c30, &s30);
  s->cos18 = (int32_t)shr_round(c30, 12);
  s->fy_fx = (int32_t)div_round((int64_t)p->fy * 65536, p->fx);
  s->sin18 = (int32_t)shr_round(s30, 12);

  /* The floor at distance R (from the camera's foot) is seen at yn = (h cos - R sin) /
   * (R cos + h sin); the region starts at the first row at or below it, and below the horizon. */
  {
    const int64_t R = p->max_range, hh = p->cam_height;
    const int64_t num = hh * s->cos18 - R * s->sin18, den = R * s->cos18 + hh * s->sin18; /* Q34 */
    if (den <= 0) return;
    /* row = cy + fy yn in Q8, rounded up to a whole row */
    const int64_t yq8 = p->cy + div64(num * p->fy, den);
    int64_t row = yq8 >= 0 ? (yq8 + 255) >> 8 : -((-yq8) >> 8);
    /* the horizon: cy - fy tan(tilt) */
    const int64_t hq8 = p->cy - div64((int64_t)p->fy * s->sin18, s->cos18);
    const int64_t hrow = (hq8 >= 0 ? hq8 >> 8 : -((-hq8 + 255) >> 8)) + 1;
    if (row < hrow) row = hrow;
    if (row < 0) row = 0;
    if (row > h - 5) return;
    s->floor_y0 = (int32_t)row;
    s->hreg = h - s->floor_y0;
  }

  /* G = fx ((1 + m2) cos - yc sin), m2 = ((xm - cx)^2 + (win_w^2 - 1) / 12) / fx^2 */
  {
    const int64_t xm_q8 = (int64_t)p->win_x0 * 256 + (int64_t)(p->win_w - 1) * 128;
    const int64_t dx = xm_q8 - p->cx;
    const int64_t num = dx * dx + div64(((int64_t)p->win_w * p->win_w - 1) * 65536, 12); /* Q16 px^2 */
    const int64_t m2_q16 = div64(num << 16, (int64_t)p->fx * p->fx);
    const int64_t yc_q8 = (int64_t)p->band_y0 * 256 + (int64_t)(p->band_rows - 1) * 128;
    const int64_t yc_q16 = div64((yc_q8 - p->cy) * 65536, p->fy);
    const int64_t f_q16 = (((int64_t)Q16 + m2_q16) * s->cos18 - yc_q16 * s->sin18) >> 18;
    const int64_t g = (int64_t)p->fx * f_q16 >> 16;
    if (g < 256 || g > ((int64_t)1 << 28)) return;
    s->gain_q8 = (int32_t)g;
  }
  s->shift_range = p->win_w - p->rho;
  s->bins = p->win_w;
  s->bins_rho = p->rho;
  s->dphi = s->phi0 = 0;
  if (p->rot_bins) {
    /* Bins of cos(tilt) / fx radians (one pixel at the image centre on the horizon row) from
     * the window's first column to its last. */
    const int64_t dphi = div_round((int64_t)RAD_Q16DEG * s->cos18, (int64_t)p->fx * 1024);
    const int32_t a0 = bvb_odo_atan2((int32_t)shr_round(((int64_t)p->win_x0 * 256 - p->cx) * s->cos18, 18), p->fx);
    const int32_t a1 = bvb_odo_atan2(
        (int32_t)shr_round(((int64_t)(p->win_x0 + p->win_w - 1) * 256 - p->cx) * s->cos18, 18), p->fx);
    if (dphi < 1) return;
    /* A bin's angle on the band's centre row yc rather than the horizon row: the turn's flow
     * there, in bins, is cos(tilt) (cos(tilt) - yc sin(tilt)) at the image centre. */
    const int64_t yc_q8 = (int64_t)p->band_y0 * 256 + (int64_t)(p->band_rows - 1) * 128;
    const int64_t yc_q18 = div64((yc_q8 - p->cy) * 262144, p->fy);
    const int64_t g_q18 = ((int64_t)s->cos18 * s->cos18 - yc_q18 * s->sin18 / 262144 * s->cos18) >> 18;
    if (g_q18 < 65536) return;
    s->dphi_row = (int32_t)div_round(dphi * 262144, g_q18);
    s->dphi = (int32_t)dphi;
    s->phi0 = a0;
    s->bins = (int32_t)div64(a1 - a0, dphi) + 1;
    s->bins_rho = s->bins - s->shift_range;
    if (s->bins_rho < 1) return;
  }

  const uint32_t W = (uint32_t)w, H = (uint32_t)h, S = (uint32_t)stride, M = BVB_ODO_MAX_FEATURES;
  s->pyr_bytes = ALIGN4(bvb_lk_pyramid_bytes(w, h, p->lk_levels)) + 4;
  s->s_table = sizeof(struct odo_state);
  s->s_profile = s->s_table + 4 * (uint32_t)s->bins;
  s->s_frame = s->s_profile + ALIGN4((uint32_t)s->bins);
  s->s_frame_bytes = ALIGN4(S * H);
  s->s_pyr = s->s_frame + 2 * s->s_frame_bytes;
  s->s_total = s->s_pyr + 2 * s->pyr_bytes;

  uint32_t o = 0;
  s->x_profile = o, o += ALIGN4(W);
  s->x_bins = o, o += ALIGN4((uint32_t)s->bins);
  s->x_pscratch = o, o += BVB_SCANLINE_PROFILE_SCRATCH_BYTES(W);
  s->x_result = o, o += 16;
  s->x_curve = o, o += 4 * (2 * (uint32_t)s->shift_range + 1);
  s->x_pyr = o, o += s->pyr_bytes;
  s->x_points = o, o += 4 * M;
  s->x_nres = o, o += 8 * M;
  s->x_nscr = o, o += ALIGN4(BVB_NCC_SCRATCH_SIZE(p->ncc_radius, p->ncc_search));
  s->x_map = o, o += 20 + 4;
  s->x_pairs = o, o += 16 * M;
  s->x_d = o, o += 4 * M;
  s->x_e = o, o += 4 * M;
  s->x_sort = o, o += 4 * M;
  const uint32_t x_rest = o;
  o = 0;
  s->f_job = o, o += BVB_ODO_COPY_JOB_BYTES;
  /* The tracker's features, results and scratch. */
  s->f_lkin = o;
  s->f_lkout = s->f_lkin + 8 * M;
  s->f_lkscr = s->f_lkout + 4 * BVB_LK_OUT_WORDS * M;
  const uint32_t lk_end = s->f_lkscr + BVB_LK_SCRATCH_BYTES + LK_SCRATCH_SLACK;
  /* The pyramid after them while fast stays within BVB_ODO_FAST_MAX (160x120: 11 KB so far):
   * the tracker reads it there, and its copy into the state leaves L1 by DMA. */
  s->f_pyr = lk_end;
  s->pyr_fast = lk_end + s->pyr_bytes <= BVB_ODO_FAST_MAX;
  uint32_t lk_total = s->pyr_fast ? lk_end + s->pyr_bytes : lk_end;
  /* And the previous frame's pyramid after it when that fits too: brought from the state by
   * memory DMA during the rotation, so that the tracker's templates read L1. */
  s->f_ppyr = lk_total;
  s->ppyr_fast = s->pyr_fast && s->f_ppyr + s->pyr_bytes <= BVB_ODO_FAST_MAX;
  if (s->ppyr_fast) lk_total = s->f_ppyr + s->pyr_bytes;
  /* The pyramid's stream (the frame's rows through L1 by DMA, bvb/stream.h) over the
   * tracker's buffers, which stage 4 fills only after it, up to the pyramid or the end of
   * fast. */
  {
    const uint32_t need = BVB_STREAM_SCRATCH_BYTES(W, 0, 0);
    const uint32_t end = s->pyr_fast ? s->f_pyr : BVB_ODO_FAST_MAX;
    s->pyr_scr_bytes = s->f_lkin + need <= end ? need : 0;
    if (s->pyr_scr_bytes && s->f_lkin + need > lk_total) lk_total = s->f_lkin + need;
  }
  /* Then, from the job on, over the same bytes (the pyramid is in the state by then): the
   * Harris scratch, the NMS scratch, two saved response rows and a strip of response rows as
   * tall as the rest of BVB_ODO_FAST_MAX allows (160x120: 20 rows), which the NMS reads in L1
   * (the map never goes to SDRAM, where each of its lines would cost a fill); strips of fewer
   * than STRIP_MIN_ROWS are not worth their calls, and the map goes to work. */
  s->f_hscr = o, o += ALIGN4(BVB_HARRIS_SCRATCH_BYTES(W));
  s->f_nmsscr = o, o += ALIGN4(BVB_HARRIS_NMS_SCRATCH_BYTES(W));
  s->f_save = o, o += 8 * W;
  s->f_strip = o;
  {
    const uint32_t rowb = 4 * W, most = (uint32_t)s->hreg - 4;
    const uint32_t room = o + 5 * rowb <= BVB_ODO_FAST_MAX ? BVB_ODO_FAST_MAX - o : 0;
    uint32_t k = room / rowb >= 5 ? room / rowb - 4 : 0;
    if (k > most) k = most;
    if (k < STRIP_MIN_ROWS && k < most) k = 0;
    s->strip_rows = (int32_t)k;
    o = k ? o + (k + 4) * rowb : s->f_save;
  }
  s->f_total = o > lk_total ? o : lk_total;
  /* Stage 1's profile scratch at the start of fast (nothing else is there yet) when it fits in
   * what the later stages take, so that the band streams through L1; else in work. */
  s->f_pscratch = BVB_SCANLINE_PROFILE_SCRATCH_BYTES(W) <= s->f_total ? 0 : UINT32_MAX;
  o = x_rest;
  s->x_resp = o;
  if (!s->strip_rows) o += 4 * W * (uint32_t)s->hreg;
  s->x_cand = o, o += 8 * ((uint32_t)BVB_HARRIS_NMS_CAPACITY(w, s->hreg) + 1);
  s->x_corners = o, o += 12 * M;
  s->x_floor = o, o += 16 * M;
  s->x_fsort = o, o += 4 * M;
  s->x_fwd = o, o += 4 * M;
  s->x_fkeep = o, o += ALIGN4(M);
  s->x_total = o;
  s->ok = 1;
}

uint32_t bvb_pipe_odometry_state_bytes(int32_t width, int32_t height, int32_t stride,
                                       const struct bvb_odo_params *p) {
  struct odo_setup s;
  setup(width, height, stride, p, &s);
  return s.ok ? s.s_total : 0;
}

uint32_t bvb_pipe_odometry_work_bytes(int32_t width, int32_t height, int32_t stride,
                                      const struct bvb_odo_params *p) {
  struct odo_setup s;
  setup(width, height, stride, p, &s);
  return s.ok ? s.x_total : 0;
}

uint32_t bvb_pipe_odometry_fast_bytes(int32_t width, int32_t height, int32_t stride,
                                      const struct bvb_odo_params *p) {
  struct odo_setup s;
  setup(width, height, stride, p, &s);
  return s.ok ? s.f_total : 0;
}

int32_t bvb_pipe_odometry_floor_y0(int32_t width, int32_t height, int32_t stride, const struct bvb_odo_params *p) {
  struct odo_setup s;
  setup(width, height, stride, p, &s);
  return s.ok ? s.floor_y0 : -1;
}

/* ---- pieces ---- */

/* a - b for cumulative tick counts that may have wrapped past 2^31 (the difference itself is
 * small), without signed overflow. */
static int32_t tick_diff(int32_t a, int32_t b) {
  const uint32_t d = (uint32_t)a - (uint32_t)b;
  if (d < 0x80000000u) return (int32_t)d;
  return d == 0x80000000u ? INT32_MIN : -(int32_t)(0u - d);
}

/* The heading change (Q16 degrees) of tick increments dl, dr: (dr - dl) / (tpi wheelbase) rad. */
static int32_t enc_angle(int32_t dl, int32_t dr, const struct bvb_odo_params *p) {
  return (int32_t)div_round((int64_t)(dr - dl) * RAD_Q16DEG * ((int64_t)1 << 24), (int64_t)p->tpi * p->wheelbase);
}

/* Angle bin k (centre phi0 + k dphi) sits at column x = cx + fx tan(phi) / cos(tilt) of the
 * horizon row: Q8 pixels, clamped to the window. */
static void make_table(const struct bvb_odo_params *p, const struct odo_setup *s, int32_t *table) {
  const int64_t lo = (int64_t)p->win_x0 * 256, hi = (int64_t)(p->win_x0 + p->win_w - 1) * 256;
  for (int32_t k = 0; k < s->bins; ++k) {
    int32_t c30, s30;
    bvb_odo_sincos(s->phi0 + k * s->dphi, &c30, &s30);
    const int64_t tan_q16 = (int64_t)s30 * 65536 / c30;
    int64_t xq = p->cx + div_round((int64_t)p->fx * tan_q16 * 4, s->cos18);
    if (xq < lo) xq = lo;
    if (xq > hi) xq = hi;
    table[k] = (int32_t)xq;
  }
}

/* The profile at the bins' columns, linearly interpolated, rounded half up. */
static void resample(const uint8_t *profile, int32_t last, const int32_t *table, int32_t bins, uint8_t *out) {
  for (int32_t k = 0; k < bins; ++k) {
    const int32_t i = table[k] >> 8, f = table[k] & 255;
    out[k] = i >= last ? profile[last]
                       : (uint8_t)((profile[i] * (256 - f) + profile[i + 1] * f + 128) >> 8);
  }
}

static void copy_bytes(uint8_t *dst, const uint8_t *src, uint32_t n) {
  for (uint32_t i = 0; i < n; ++i) dst[i] = src[i];
}

/* Sorts v[0..n) ascending (insertion sort: n is at most BVB_ODO_MAX_FEATURES). */
static void sort_i32(int32_t *v, int32_t n) {
  for (int32_t i = 1; i < n; ++i) {
    const int32_t t = v[i];
    int32_t j = i - 1;
    while (j >= 0 && v[j] > t) {
      v[j + 1] = v[j];
      --j;
    }
    v[j + 1] = t;
  }
}

/* The profile shift's sub-pixel refinement: Q8 pixels. */
static int32_t refine_shift(const int32_t *res, const uint32_t *curve, int32_t w, int32_t T, int32_t fit) {
  const int32_t t = res[0];
  if (t - 1 < -T || t + 1 > T) return t * 256;
  const int64_t nm = w - iabs(t - 1), n0 = w - iabs(t), np = w - iabs(t + 1);
  const int64_t fm = div64((int64_t)curve[t - 1 + T] << 16, nm);
  const int64_t f0 = div64((int64_t)curve[t + T] << 16, n0);
  const int64_t fp = div64((int64_t)curve[t + 1 + T] << 16, np);
  const int64_t den = fit == 2 ? 2 * ((fm > fp ? fm : fp) - f0) : fm - 2 * f0 + fp;
  if (fit == 0 || den <= 0) return t * 256;
  int64_t delta = div_round((fm - fp) * 128, den);
  if (delta > 128) delta = 128;
  if (delta < -128) delta = -128;
  return t * 256 + (int32_t)delta;
}

/* Bit length of v > 0 (v < 2^62). */
static int32_t bitlen64(int64_t v) {
  int32_t n = 0;
  uint32_t w = (uint32_t)(v >> 31);
  if (w) n = 31;
  else w = (uint32_t)v;
  /* the rest by halving, five steps */
  if (w >= 0x10000u) w >>= 16, n += 16;
  if (w >= 0x100u) w >>= 8, n += 8;
  if (w >= 0x10u) w >>= 4, n += 4;
  if (w >= 0x4u) w >>= 2, n += 2;
  if (w >= 0x2u) w >>= 1, n += 1;
  return n + (int32_t)w;
}

/* A point (Q8 pixels) on the floor, robot frame: F ahead of the axle, L to the left, Q16 inches.
 * Returns 0 above the horizon or beyond far. One 32-bit division per point: D is normalised to
 * 16 significant bits and inverted, R = floor((2^31 - 1) / Dn), and the two ratios F / h and
 * L / h (Q16) are products with R; they keep about 16 significant bits. */
static int32_t to_floor(const struct bvb_odo_params *p, const struct odo_setup *s, int32_t xq8, int32_t yq8,
                        int64_t far, int32_t *F, int32_t *L) {
  const int64_t v = (int64_t)yq8 - p->cy, u = (int64_t)xq8 - p->cx;
  const int64_t D = (int64_t)p->fy * s->sin18 + v * s->cos18;      /* Q26 */
  const int64_t NF = (int64_t)p->fy * s->cos18 - v * s->sin18;     /* Q26 */
  if (D < 32768 || NF <= 0) return 0;
  const int32_t sd = bitlen64(D) - 16;
  const uint32_t R = 0x7FFFFFFFu / (uint32_t)(D >> sd);              /* (2^15, 2^16] */
  const int64_t rf = ((NF >> sd) * (int64_t)R) >> 15;                /* F / h, Q16 */
  if (rf > ((int64_t)1 << 30)) return 0;
  const int64_t f = ((int64_t)p->cam_height * rf) >> 16;
  if (f > far) return 0;
  const int64_t uy = (u * s->fy_fx) >> 16;                           /* Q8, scaled by fy / fx */
  const int64_t rl = (((uy * 262144) >> sd) * (int64_t)R) >> 15;     /* -L / h, Q16 */
  *F = (int32_t)(f + p->cam_offset);
  *L = (int32_t)(-(((int64_t)p->cam_height * rl) >> 16));
  return 1;
}

/* NCC's sub-pixel step along one axis from the scores at -1, 0, +1: Q8 pixels, |.| <= 128. */
static int32_t ncc_peak(int32_t sm, int32_t s0, int32_t sp) {
  const int32_t den = sm - 2 * s0 + sp;
  if (den >= 0) return 0;
  int64_t d = div_round((int64_t)(sm - sp) * 128, -(int64_t)den);
  d = -d;
  if (d > 128) d = 128;
  if (d < -128) d = -128;
  return (int32_t)d;
}

/* Tracks the previous frame's features into this one: n pairs of Q8 positions (before, after)
 * in pos (4 int32 per feature). Returns the count. */
static int32_t track(const struct bvb_odo_kernels *ops, const struct bvb_odo_params *p, const struct odo_setup *s,
                     const struct odo_state *st, const uint8_t *prev, const uint8_t *prev_pyr,
                     const uint8_t *frame, const uint8_t *pyr, uint8_t *x, uint8_t *fx, int32_t *pos) {
  const int32_t n = st->nfeat, w = s->w, h = s->h, stride = s->stride;
  int32_t k = 0;
  if (n == 0) return 0;
  if (p->tracker == BVB_ODO_TRACK_LK) {
    int32_t *in = (int32_t *)(fx + s->f_lkin), *out = (int32_t *)(fx + s->f_lkout);
    struct bvb_lk_params lp;
    lp.levels = p->lk_levels;
    lp.win_w = lp.win_h = p->lk_win;
    lp.max_iter = p->lk_max_iter;
    lp.eps_q16 = p->lk_eps;
    lp.min_det = p->lk_min_det;
    lp.flags = 0;
    lp.count = n;
    for (int32_t i = 0; i < 2 * n; ++i) in[i] = st->feat[i];
    void *scr = (void *)bvb_lk_scratch_place(fx + s->f_lkscr, BVB_LK_SCRATCH_BYTES + LK_SCRATCH_SLACK, p->lk_win,
                                             p->lk_win);
    ops->lk_track(prev, prev_pyr, frame, pyr, w, h, stride, &lp, in, out, scr);
    for (int32_t i = 0; i < n; ++i) {
      const int32_t *o = out + BVB_LK_OUT_WORDS * i;
      if (o[2] != BVB_LK_TRACKED) continue;
      pos[4 * k] = (int32_t)shr_round(in[2 * i], 8);
      pos[4 * k + 1] = (int32_t)shr_round(in[2 * i + 1], 8);
      pos[4 * k + 2] = (int32_t)shr_round(o[0], 8);
      pos[4 * k + 3] = (int32_t)shr_round(o[1], 8);
      ++k;
    }
    return k;
  }
  const int32_t r = p->ncc_radius;
  int16_t *pts = (int16_t *)(x + s->x_points), *res = (int16_t *)(x + s->x_nres);
  int16_t *map = (int16_t *)(x + s->x_map);
  for (int32_t i = 0; i < n; ++i) {
    pts[2 * i] = (int16_t)(st->feat[2 * i] >> 16);
    pts[2 * i + 1] = (int16_t)(st->feat[2 * i + 1] >> 16);
  }
  ops->ncc_match(prev, frame, stride, w, h, pts, n, r, p->ncc_search, res, x + s->x_nscr);
  for (int32_t i = 0; i < n; ++i) {
    const int16_t *q = res + 4 * i;
    if (q[3] != BVB_NCC_OK) continue;
    const int32_t px = pts[2 * i], py = pts[2 * i + 1], dx = q[0], dy = q[1];
    int32_t sx = 0, sy = 0;
    /* The 3 x 3 offsets around the match, scored on windows cut out of both frames so that
     * every pointer stays inside its frame. */
    if (p->ncc_subpixel && px + dx - r - 1 >= 0 && px + dx + r + 1 <= w - 1 && py + dy - r - 1 >= 0 &&
        py + dy + r + 1 <= h - 1) {
      ops->ncc_scoremap(prev + (py - r - 1) * stride + (px - r - 1),
                        frame + (py + dy - r - 1) * stride + (px + dx - r - 1), stride, 2 * r + 3, 2 * r + 3,
                        r + 1, r + 1, r, 1, map, x + s->x_nscr);
      if (map[9] == BVB_NCC_OK) {
        sx = ncc_peak(map[3], map[4], map[5]);
        sy = ncc_peak(map[1], map[4], map[7]);
      }
    }
    pos[4 * k] = px * 256;
    pos[4 * k + 1] = py * 256;
    pos[4 * k + 2] = (px + dx) * 256 + sx;
    pos[4 * k + 3] = (py + dy) * 256 + sy;
    ++k;
  }
  return k;
}

static void copy_words(uint8_t *dst, const uint8_t *src, uint32_t n) {
  if ((((uintptr_t)dst | (uintptr_t)src | n) & 3) == 0) {
    uint32_t *d = (uint32_t *)dst;
    const uint32_t *q = (const uint32_t *)src;
    for (uint32_t i = 0; i < n / 4; ++i) d[i] = q[i];
  } else {
    copy_bytes(dst, src, n);
  }
}

static void copy_both(void *job, uint8_t *dst, const uint8_t *src, uint32_t n, uint8_t *dst2, const uint8_t *src2,
                      uint32_t n2) {
  (void)job;
  copy_words(dst, src, n);
  copy_words(dst2, src2, n2);
}

static void copy_none(void) {}

/* The state update's copies by the core: this frame and its pyramid. */
static void copy_state(const struct odo_setup *s, uint8_t *prev, const uint8_t *frame, uint8_t *prev_pyr,
                       const uint8_t *pyr, int32_t lk) {
  for (int32_t r = 0; r < s->h; ++r) copy_bytes(prev + r * s->stride, frame + r * s->stride, (uint32_t)s->w);
  if (lk) copy_words(prev_pyr, pyr, s->pyr_bytes);
}

/* Stages 6 and 7 over strips of the floor region's response map in fast, each made and then
 * scanned while in L1: the same candidates, in the same order, as bvb_harris_nms over the
 * whole map. A strip whose first row is region row y0 holds R(y0) .. R(y0 + K + 3), K =
 * strip_rows: bvb_harris_response over image rows y0 .. y0 + K + 3 makes R(y0 + 2) .. R(y0 +
 * K + 1) exactly as over the whole region (each response row needs the image rows 2 either
 * side), and writes its own two border rows of zeros either side; the two above are then
 * R(y0), R(y0 + 1) saved from the strip before (zeros, as the region's border is, for the
 * first). The NMS of rows 1 .. K (y0 + 1 .. y0 + K) reads rows 0 .. K + 1; the last strip
 * ends at the region's last row, whose two border rows are the region's own, and scans to
 * its end. Returns the candidates, keys in region rows. */
int32_t bvb_odo_harris_strips(const struct bvb_odo_kernels *ops, const uint8_t *src, int32_t w, int32_t hreg,
                              int32_t stride, int32_t kr, int32_t threshold, int32_t *cand, void *hscr,
                              void *nmsscr, int32_t *save, int32_t *buf) {
  int32_t n = 0;
  for (int32_t y0 = 0;; y0 += kr) {
    const int32_t last = y0 + kr + 4 >= hreg, rows = last ? hreg - y0 : kr + 4;
    ops->harris_response(src + y0 * stride, buf, w, rows, stride, w, hscr);
    if (y0 > 0) copy_words((uint8_t *)buf, (const uint8_t *)save, 8 * (uint32_t)w);
    int32_t c = 0;
    ops->harris_nms(buf, w, last ? rows : kr + 2, w, threshold, cand + 2 * n, &c, nmsscr);
    for (int32_t i = n; i < n + c; ++i) cand[2 * i] += y0 << 16;
    n += c;
    if (last) return n;
    copy_words((uint8_t *)save, (const uint8_t *)(buf + kr * w), 8 * (uint32_t)w);
  }
}

static int32_t harris_strips(const struct bvb_odo_kernels *ops, const struct bvb_odo_params *p,
                             const struct odo_setup *s, const uint8_t *src, uint8_t *fx, int32_t *cand) {
  return bvb_odo_harris_strips(ops, src, s->w, s->hreg, s->stride, s->strip_rows, p->harris_threshold, cand,
                               fx + s->f_hscr, fx + s->f_nmsscr, (int32_t *)(fx + s->f_save),
                               (int32_t *)(fx + s->f_strip));
}

/* The tracked pairs (Q8 pixels, 4 words each) on the floor: P in the previous frame's robot
 * frame, Q in this one's, Q16 inches, 4 words per point (P.F, P.L, Q.F, Q.L). Returns the
 * count. */
static int32_t floor_points(const struct bvb_odo_params *p, const struct odo_setup *s, const int32_t *pairs,
                            int32_t n, int32_t *pq) {
  const int64_t far = 2 * (int64_t)p->max_range;
  int32_t m = 0;
  for (int32_t i = 0; i < n; ++i) {
    int32_t *o = pq + 4 * m;
    if (!to_floor(p, s, pairs[4 * i], pairs[4 * i + 1], far, &o[0], &o[1])) continue;
    if (!to_floor(p, s, pairs[4 * i + 2], pairs[4 * i + 3], far, &o[2], &o[3])) continue;
    ++m;
  }
  return m;
}

/* What one frame computes before it is committed to the state. */
struct odo_frame {
  int32_t shift, t, dth_vis, dth_enc, dth, motion, flags;
  int32_t win_restart;
  int32_t tracked, m, inliers, dfwd_vis, dfwd_enc, dfwd;
  int32_t x, y, heading;
  int32_t ncorners;
};

/* Stage 5: the floor motion of the tracked points, the robust forward estimate, the
 * translation's fusion and the pose. */
static void estimate(const struct bvb_odo_params *p, const struct odo_setup *s, const struct odo_state *st,
                     uint8_t *x, struct odo_frame *f, const int32_t *pq, int32_t npq) {
  int32_t c30, s30, ch, sh;
  bvb_odo_sincos(f->motion, &c30, &s30);
  bvb_odo_sincos(f->motion / 2, &ch, &sh);
  int32_t *dv = (int32_t *)(x + s->x_d), *ev = (int32_t *)(x + s->x_e), *srt = (int32_t *)(x + s->x_sort);
  int32_t m = 0;
  for (int32_t i = 0; i < npq; ++i) {
    const int32_t Fp = pq[4 * i], Lp = pq[4 * i + 1], Fq = pq[4 * i + 2], Lq = pq[4 * i + 3];
    /* T = P - R(dtheta) Q, then along and across the chord */
    const int32_t tx = Fp - (int32_t)shr_round((int64_t)c30 * Fq - (int64_t)s30 * Lq, 30);
    const int32_t ty = Lp - (int32_t)shr_round((int64_t)s30 * Fq + (int64_t)c30 * Lq, 30);
    dv[m] = (int32_t)shr_round((int64_t)ch * tx + (int64_t)sh * ty, 30);
    ev[m] = (int32_t)shr_round((int64_t)ch * ty - (int64_t)sh * tx, 30);
    srt[m] = dv[m];
    ++m;
  }
  int32_t inliers = 0, dfwd_vis = 0;
  if (m > 0) {
    sort_i32(srt, m);
    const int32_t med = srt[m / 2];
    int64_t sum = 0;
    for (int32_t i = 0; i < m; ++i)
      if (iabs(dv[i] - med) <= p->inlier_tol && iabs(ev[i]) <= p->inlier_tol) {
        sum += dv[i];
        ++inliers;
      }
    if (inliers > 0) dfwd_vis = (int32_t)div_round(sum, inliers);
  }
  int32_t dfwd = dfwd_vis;
  if (inliers < p->min_inliers) {
    f->flags |= BVB_ODO_F_FWD_NONE;
    dfwd = 0;
  }
  if (p->fuse && (inliers < p->min_inliers || iabs(dfwd_vis - f->dfwd_enc) > p->fuse_trans_tol)) {
    dfwd = f->dfwd_enc;
    f->flags |= BVB_ODO_F_FWD_ENC;
  }
  f->m = m;
  f->inliers = inliers;
  f->dfwd_vis = dfwd_vis;
  f->dfwd = dfwd;
  int32_t cm, sm;
  bvb_odo_sincos(st->heading + f->dth / 2, &cm, &sm);
  f->x = st->x + mul_q30(dfwd, cm);
  f->y = st->y + mul_q30(dfwd, sm);
  f->heading = st->heading + f->dth;
}

/* Stage 2: the profile's rotation since the key, the encoders, and the rotation's fusion. */
static void rotation(const struct bvb_odo_kernels *ops, const struct bvb_odo_params *p, const struct odo_setup *s,
                     const struct odo_state *st, const uint8_t *key, const uint8_t *cur, int32_t left,
                     int32_t right, uint8_t *x, struct odo_frame *f) {
  int32_t *res = (int32_t *)(x + s->x_result);
  uint32_t *curve = (uint32_t *)(x + s->x_curve);
  ops->shift(key, cur, s->bins, s->bins_rho, res, curve);
  f->t = res[0];
  f->shift = refine_shift(res, curve, s->bins, s->shift_range, p->shift_fit);
  const int32_t rel = p->rot_bins ? (int32_t)div_round((int64_t)f->shift * s->dphi_row, 256)
                                  : bvb_odo_atan2(f->shift, s->gain_q8);
  f->dth_vis = st->key_heading + rel - st->heading;
  const int32_t dl = tick_diff(left, st->left), dr = tick_diff(right, st->right);
  f->dfwd_enc = (int32_t)div_round((int64_t)(dl + dr) * ((int64_t)1 << 23), p->tpi);
  f->dth_enc = enc_angle(dl, dr, p);
  f->dth = f->motion = f->dth_vis;
}

/* Stage 5: the rotation's fusion with the encoders, on the visual rotation chosen (the
 * profile's or the floor features'). */
static void fuse_rotation(const struct bvb_odo_params *p, const struct odo_state *st, int32_t left, int32_t right,
                          struct odo_frame *f) {
  f->dth = f->motion = f->dth_vis;
  if (!p->fuse) return;
  /* The floor features' rotation is not dragged by what moves in the band, and the encoders'
   * slip would only make it worse: their frames keep it and start a new window, so the
   * window test spans the profile's frames alone. */
  if (f->flags & BVB_ODO_F_ROT_FEAT) {
    f->win_restart = 1;
    return;
  }
  if (iabs(f->dth_vis - f->dth_enc) > p->fuse_rot_tol) {
    f->dth = f->motion = f->dth_enc;
    f->flags |= BVB_ODO_F_ROT_ENC;
  }
  /* Over the window the encoders' heading change comes from whole tick counts, so their
   * rounding does not add up: a slow visual drift (a moving object in the band) shows. */
  const int32_t e = enc_angle(tick_diff(left, st->win_left), tick_diff(right, st->win_right), p);
  if (iabs(e) <= p->fuse_rot_tol && iabs(st->heading + f->dth - st->win_heading - e) > p->fuse_rot_tol) {
    f->dth = st->win_heading + e - st->heading; /* this frame's turn and the window's correction */
    f->flags |= BVB_ODO_F_ROT_ENC | BVB_ODO_F_ROT_WIN;
  }
  f->win_restart = (f->flags & BVB_ODO_F_ROT_ENC) || st->win_age + 1 >= p->fuse_window;
}

/* ---- the rotation from the floor features (ROTATION FROM THE FLOOR in bvb/pipe_odometry.h) ---- */

/* The median of v[0..n) (n > 0), sorting tmp. */
static int32_t median_i32(const int32_t *v, int32_t n, int32_t *tmp) {
  for (int32_t i = 0; i < n; ++i) tmp[i] = v[i];
  sort_i32(tmp, n);
  return tmp[n / 2];
}

/* The rotation's remainder from the points' sideways motion. With this frame's motion a turn
 * by a and d forward along the chord, a floor point obeys P = R(a) Q + d (cos a/2, sin a/2);
 * about a0 = a - da, with Q' = R(a0) Q: P.L - Q'.L - d sin(a0 / 2) = da (Q'.F + d / 2) to first
 * order in da. Each point's ratio da_i has about the same error (the sideways error of a floor
 * point grows with its distance, as the ratio's denominator does), so the points are weighed
 * alike by da = sum lat_i / sum den_i, where lat_i, den_i are those two sides. */
struct odo_lateral {
  int32_t *lat, *den, *fwd;  /* per point: the sideways motion left, the denominator, P.F - Q'.F */
};

/* Fills l for the rotation a0 (Q16 degrees); returns d, the median of P.F - Q'.F (Q16 inches). */
static int32_t lateral_motion(const int32_t *pq, int32_t m, int32_t a0, const struct odo_lateral *l,
                              int32_t *tmp) {
  int32_t c30, s30, ch, sh;
  bvb_odo_sincos(a0, &c30, &s30);
  bvb_odo_sincos(a0 / 2, &ch, &sh);
  for (int32_t i = 0; i < m; ++i) {
    const int32_t *q = pq + 4 * i;
    const int32_t qf = (int32_t)shr_round((int64_t)c30 * q[2] - (int64_t)s30 * q[3], 30);
    const int32_t ql = (int32_t)shr_round((int64_t)s30 * q[2] + (int64_t)c30 * q[3], 30);
    l->fwd[i] = q[0] - qf;
    l->lat[i] = q[1] - ql;
    l->den[i] = qf;
  }
  const int32_t d = median_i32(l->fwd, m, tmp);
  const int32_t dsin = (int32_t)shr_round((int64_t)d * sh, 30);
  for (int32_t i = 0; i < m; ++i) {
    l->lat[i] -= dsin;
    l->den[i] += d / 2;
    l->fwd[i] -= d;
  }
  return d;
}

/* The points that agree with the remainder da (Q30 radians, so that each prediction is a
 * product): forward within tol of the median, sideways within tol of da's prediction. Sets
 * keep; returns how many, and da's new value over them in *da (unchanged when none, or when
 * their denominators are not positive): one division. */
static int32_t lateral_fit(const struct odo_lateral *l, int32_t m, int32_t tol, uint8_t *keep, int64_t *da) {
  int64_t sl = 0, sd = 0;
  int32_t k = 0;
  /* The prediction only selects, against a tolerance of a tenth of an inch or more: 32-bit
   * products do, da in Q16 radians (clamped to 1/8 radian, 7 degrees, beyond any rotation the
   * features measure) times den in Q8 inches (below 2^17: to_floor's points lie within 2
   * max_range, 512 in), within a thousandth of an inch at 24 in. */
  int64_t d16 = shr_round(*da, 14);
  if (d16 > 8192) d16 = 8192;
  if (d16 < -8192) d16 = -8192;
  for (int32_t i = 0; i < m; ++i) {
    const int32_t pred = ((int32_t)d16 * (l->den[i] >> 8)) >> 8;
    keep[i] = (uint8_t)(iabs(l->fwd[i]) <= tol && iabs(l->lat[i] - pred) <= tol && l->den[i] > 0);
    if (!keep[i]) continue;
    sl += l->lat[i];
    sd += l->den[i];
    ++k;
  }
  if (k > 0 && sd > 0) *da = div_round(sl * ((int64_t)1 << 30), sd);
  return k;
}

/* The median of the points' ratios lat_i / den_i (Q16 degrees) over those with den_i at least
 * 1/16 in; a start for the fit, so 32-bit divisions of 15 or so significant bits do (lat
 * clamped to 2 in: a point that moved sideways more is an outlier anyway). */
static int32_t median_ratio(const struct odo_lateral *l, int32_t m, int32_t *tmp) {
  int32_t n = 0;
  for (int32_t i = 0; i < m; ++i) {
    const int32_t d = l->den[i] >> 12;                   /* Q4 inches */
    if (d < 1) continue;
    int32_t lat = l->lat[i];
    if (lat > 2 * Q16) lat = 2 * Q16;
    if (lat < -2 * Q16) lat = -2 * Q16;
    tmp[n++] = lat * 16 / d;                             /* Q16 radians, |.| < 2^22 */
  }
  if (n == 0) return 0;
  sort_i32(tmp, n);
  return (int32_t)shr_round((int64_t)tmp[n / 2] * RAD_Q16DEG, 16);
}

/* Stage 5's first step: this frame's visual rotation from the floor features when the rule
 * says so (see the header), else the profile's as stage 2 left it. */
static void floor_rotation(const struct bvb_odo_params *p, const struct odo_setup *s, uint8_t *x,
                           struct odo_frame *f, const int32_t *pq, int32_t m) {
  int32_t *tmp = (int32_t *)(x + s->x_fsort);
  struct odo_lateral l;
  l.lat = (int32_t *)(x + s->x_d); /* estimate's, free until then */
  l.den = (int32_t *)(x + s->x_e);
  l.fwd = (int32_t *)(x + s->x_fwd);
  uint8_t *keep = x + s->x_fkeep;
  if (m < p->rot_min_inliers) return;
  /* A wide selection about the profile's rotation and the fit, then the inliers' own. */
  int32_t a0 = f->dth_vis;
  int64_t da = 0;
  lateral_motion(pq, m, a0, &l, tmp);
  int32_t k = lateral_fit(&l, m, p->rot_sel_tol, keep, &da);
  /* The profile can jump by a degree or more on a straight leg: when fewer than half the
   * points agree with it, the start is the median of the points' own ratios about no turn at
   * all (the linear relation holds near the truth, which the features only report when it
   * is small), and the motion is taken again about that, so that the forward test is not
   * thrown by the profile. */
  if (2 * k < m) {
    lateral_motion(pq, m, 0, &l, tmp);
    a0 = median_ratio(&l, m, tmp);
    lateral_motion(pq, m, a0, &l, tmp);
    da = 0;
    k = lateral_fit(&l, m, p->rot_sel_tol, keep, &da);
  }
  if (k < p->rot_min_inliers) return;
  if (lateral_fit(&l, m, p->inlier_tol, keep, &da) < p->rot_min_inliers) return;
  const int32_t a = a0 + (int32_t)shr_round(da * RAD_Q16DEG, 30);
  if (iabs(a) > p->rot_small) return;
  f->dth_vis = a;
  f->flags |= BVB_ODO_F_ROT_FEAT;
}

static int32_t same_words(const void *a, const void *b, uint32_t n) {
  const int32_t *x = (const int32_t *)a, *y = (const int32_t *)b;
  for (uint32_t i = 0; i < n / 4; ++i)
    if (x[i] != y[i]) return 0;
  return 1;
}

/* Whether the state holds the setup of this frame's geometry and parameters (a full run of them
 * left it); then it is copied into s. Frame 0 and a state without the version never read the
 * cache. */
static int32_t cached_setup(const struct odo_state *st, const struct bvb_pipe_frame *info, int32_t w, int32_t h,
                            int32_t stride, const struct bvb_odo_params *p, struct odo_setup *s) {
  if (info->index == 0 || st->version != BVB_ODO_STATE_VERSION) return 0;
  const struct odo_cache *c = &st->cache;
  if (c->w != w || c->h != h || c->stride != stride || !c->s.ok || !same_words(&c->p, p, sizeof *p)) return 0;
  copy_words((uint8_t *)s, (const uint8_t *)&c->s, sizeof *s);
  return 1;
}

int32_t bvb_pipe_odometry_setup_cached(const uint8_t *state, const struct bvb_pipe_frame *info, int32_t width,
                                       int32_t height, int32_t stride, const struct bvb_odo_params *p) {
  struct odo_setup s;
  return cached_setup((const struct odo_state *)state, info, width, height, stride, p, &s);
}

int32_t bvb_pipe_odometry_run(const struct bvb_odo_kernels *ops, const uint8_t *frame, int32_t width,
                              int32_t height, int32_t stride, const struct bvb_pipe_frame *info,
                              const struct bvb_odo_params *p, uint8_t *state, struct bvb_pipe_result *out,
                              void *work, void *fast) {
  struct odo_state *st = (struct odo_state *)state;
  struct odo_setup s;
  if (!cached_setup(st, info, width, height, stride, p, &s)) setup(width, height, stride, p, &s);
  if (!s.ok) return -1;
  uint8_t *x = (uint8_t *)work, *fx = (uint8_t *)fast;
  const int32_t first = info->index == 0 || st->version != BVB_ODO_STATE_VERSION;
  const int32_t slot = first ? 0 : st->slot & 1;
  uint8_t *key = state + s.s_profile;
  uint8_t *prev = state + s.s_frame + (uint32_t)slot * s.s_frame_bytes;
  uint8_t *prev_pyr = state + s.s_pyr + (uint32_t)slot * s.pyr_bytes;
  uint8_t *next = state + s.s_frame + (uint32_t)(1 - slot) * s.s_frame_bytes;
  uint8_t *next_pyr = state + s.s_pyr + (uint32_t)(1 - slot) * s.pyr_bytes;
  uint8_t *profile = x + s.x_profile, *pyr = s.pyr_fast ? fx + s.f_pyr : x + s.x_pyr;
  int32_t *table = (int32_t *)(state + s.s_table);
  int32_t *corners = (int32_t *)(x + s.x_corners);
  uint8_t *cur = p->rot_bins ? x + s.x_bins : profile + p->win_x0;
  const int32_t w = width, h = height, lk = p->tracker == BVB_ODO_TRACK_LK;
  const int32_t left = info->left_ticks, right = info->right_ticks;
  const int32_t stages = info->stages > 0 ? info->stages : BVB_ODO_STAGES;
  struct odo_frame f;
  int32_t k = 0;

  f.flags = f.win_restart = f.tracked = f.m = f.inliers = f.dfwd_vis = f.dfwd_enc = f.dfwd = 0;
  f.shift = f.t = f.dth_vis = f.dth_enc = f.dth = f.motion = f.ncorners = 0;
  f.x = first ? p->start_x : st->x;
  f.y = first ? p->start_y : st->y;
  f.heading = first ? p->start_heading : st->heading;

  /* 1: the band's profile (in angle bins) */
  ops->profile(frame + p->band_y0 * stride, w, p->band_rows, stride, profile,
               s.f_pscratch == UINT32_MAX ? x + s.x_pscratch : fx + s.f_pscratch);
  if (first && p->rot_bins) make_table(p, &s, table);
  if (p->rot_bins) resample(profile, p->win_x0 + p->win_w - 1, table, s.bins, cur);
  if (++k >= stages) goto done;
  /* 2: rotation, while the previous frame's pyramid comes into fast for the tracker */
  const int32_t ppyr = !first && lk && s.ppyr_fast;
  if (ppyr) ops->copy(fx + s.f_job, fx + s.f_ppyr, prev_pyr, s.pyr_bytes, 0, 0, 0);
  if (!first) rotation(ops, p, &s, st, key, cur, left, right, x, &f);
  if (ppyr) ops->copy_wait();
  if (++k >= stages) goto done;
  /* 3: this frame's pyramid */
  if (lk) ops->lk_pyramid(frame, w, h, stride, p->lk_levels, pyr, fx + s.f_lkin, s.pyr_scr_bytes);
  if (++k >= stages) goto done;
  /* A full run copies this frame and its pyramid into the state's other slot now, by memory
   * DMA in the assembly build (a stride of whole words), while the tracker computes: it reads
   * the previous frame's slot, and the copy runs on the bus the tracker's compute leaves
   * free. It is done before the Harris stages, which use the DMA stream and overwrite the
   * pyramid in fast. A run stopped early copies nothing (the state stays as it was). */
  const int32_t full = stages >= BVB_ODO_STAGES, by_dma = full && stride % 4 == 0;
  if (by_dma)
    ops->copy(fx + s.f_job, next, frame, (uint32_t)(stride * h), next_pyr, pyr, lk ? s.pyr_bytes : 0);
  else if (full)
    copy_state(&s, next, frame, next_pyr, pyr, lk);
  /* 4: the previous frame's features tracked into this one */
  if (!first)
    f.tracked = track(ops, p, &s, st, prev, ppyr ? fx + s.f_ppyr : prev_pyr, frame, pyr, x, fx,
                      (int32_t *)(x + s.x_pairs));
  if (++k >= stages) goto done;
  /* 5: the rotation from the floor features, its fusion, translation and pose */
  if (!first) {
    int32_t *pq = (int32_t *)(x + s.x_floor);
    const int32_t npq = floor_points(p, &s, (const int32_t *)(x + s.x_pairs), f.tracked, pq);
    if (p->rot_feat) floor_rotation(p, &s, x, &f, pq, npq);
    fuse_rotation(p, st, left, right, &f);
    estimate(p, &s, st, x, &f, pq, npq);
  }
  if (by_dma) ops->copy_wait();
  if (++k >= stages) goto done;
  /* 6, 7: Harris corners of the floor region, for the next frame */
  int32_t *cand = (int32_t *)(x + s.x_cand), count = 0;
  if (s.strip_rows) {
    count = harris_strips(ops, p, &s, frame + s.floor_y0 * stride, fx, cand);
  } else {
    ops->harris_response(frame + s.floor_y0 * stride, (int32_t *)(x + s.x_resp), w, s.hreg, stride, w,
                         fx + s.f_hscr);
  }
  if (++k >= stages) goto done;
  if (!s.strip_rows)
    ops->harris_nms((int32_t *)(x + s.x_resp), w, s.hreg, w, p->harris_threshold, cand, &count, fx + s.f_nmsscr);
  f.ncorners = bvb_harris_select_c(cand, count, p->max_features, p->min_distance, corners);
  if (++k >= stages) goto done;
  /* 8: commit: the pose, the fusion window, the key profile, this frame's slot as the previous
   * one */
  if (first) {
    st->version = BVB_ODO_STATE_VERSION;
    st->frames = 0;
    st->win_heading = f.heading;
    st->win_left = left;
    st->win_right = right;
    st->win_age = 0;
  } else {
    st->frames += 1;
    if (p->fuse) {
      st->win_age += 1;
      if (f.win_restart) {
        st->win_heading = f.heading;
        st->win_left = left;
        st->win_right = right;
        st->win_age = 0;
      }
    }
  }
  st->x = f.x;
  st->y = f.y;
  st->heading = f.heading;
  st->left = left;
  st->right = right;
  /* A new key profile when this one has moved far enough (the next frame's shift must stay
   * inside the search range), the robot is not turning, the key is old, or the encoders
   * overruled it. */
  st->key_age += 1;
  if (first || (f.flags & BVB_ODO_F_ROT_ENC) || iabs(f.t) >= p->key_shift ||
      iabs(f.t - st->key_shift) < p->key_still || st->key_age >= p->key_frames) {
    copy_words(key, cur, (uint32_t)s.bins);
    st->key_heading = f.heading;
    st->key_age = 0;
    st->key_shift = 0;
  } else {
    st->key_shift = f.t;
  }
  for (int32_t i = 0; i < f.ncorners; ++i) {
    st->feat[2 * i] = corners[3 * i] * Q16;
    st->feat[2 * i + 1] = (corners[3 * i + 1] + s.floor_y0) * Q16;
  }
  st->nfeat = f.ncorners;
  st->slot = 1 - slot;
  st->cache.w = w;
  st->cache.h = h;
  st->cache.stride = stride;
  copy_words((uint8_t *)&st->cache.p, (const uint8_t *)p, sizeof *p);
  copy_words((uint8_t *)&st->cache.s, (const uint8_t *)&s, sizeof s);
  ++k;

done:
  out->decision = BVB_PIPE_STOP;
  out->has_pose = 1;
  out->x_q16 = f.x;
  out->y_q16 = f.y;
  out->heading_q16 = f.heading;
  out->diag[BVB_ODO_DIAG_STAGES] = k;
  out->diag[BVB_ODO_DIAG_DTHETA_VIS] = f.dth_vis;
  out->diag[BVB_ODO_DIAG_DTHETA_ENC] = f.dth_enc;
  out->diag[BVB_ODO_DIAG_DTHETA] = f.dth;
  out->diag[BVB_ODO_DIAG_DFWD_VIS] = f.dfwd_vis;
  out->diag[BVB_ODO_DIAG_DFWD_ENC] = f.dfwd_enc;
  out->diag[BVB_ODO_DIAG_DFWD] = f.dfwd;
  out->diag[BVB_ODO_DIAG_POINTS] = f.flags | f.inliers << 8 | f.m << 16 | f.ncorners << 24;
  return BVB_PIPE_STOP;
}

static void pyramid_c(const uint8_t *src, int32_t width, int32_t height, int32_t stride, int32_t levels,
                      uint8_t *pyr, void *scratch, uint32_t scratch_bytes) {
  (void)scratch;
  (void)scratch_bytes;
  bvb_lk_pyramid_c(src, width, height, stride, levels, pyr);
}

static const struct bvb_odo_kernels c_kernels = {
    bvb_scanline_profile_u8_c, bvb_scanline_shift_u8_c, bvb_harris_response_c, bvb_harris_nms_c,
    pyramid_c,                 bvb_lk_track_c,          bvb_ncc_match_c,       bvb_ncc_scoremap_c,
    copy_both, copy_none};

int32_t bvb_pipe_odometry_c(const uint8_t *frame, int32_t width, int32_t height, int32_t stride,
                            const struct bvb_pipe_frame *info, const struct bvb_odo_params *p, uint8_t *state,
                            struct bvb_pipe_result *out, void *work, void *fast) {
  return bvb_pipe_odometry_run(&c_kernels, frame, width, height, stride, info, p, state, out, work, fast);
}
