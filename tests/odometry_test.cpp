// The odometry pipeline's fixed-point trigonometry (CORDIC) against the C library's doubles,
// its parameter checks, its Harris strips against the whole response map, and its rotation
// from the floor features on straight legs and turns (host build, rendered scenes).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "bvb/harris.h"
#include "bvb/pipe_odometry.h"
#include "session/runner.h"
#include "scene/scene_io.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

// The SRV-1 scene camera at 160x120 (harness/scene/camera.h) and the pipeline's usual settings.
bvb_odo_params params_160x120() {
  bvb_odo_params p{};
  p.fx = p.fy = 140 * 256;
  p.cx = 79 * 256 + 128, p.cy = 59 * 256 + 128;
  p.cam_height = 4 << 16, p.tilt = 10 << 16, p.cam_offset = 0;
  p.band_y0 = 21, p.band_rows = 32, p.win_x0 = 8, p.win_w = 144, p.rho = 104;
  p.shift_fit = 1, p.rot_bins = 1, p.key_shift = 24, p.key_frames = 8, p.key_still = 2;
  p.tracker = BVB_ODO_TRACK_LK, p.max_range = 24 << 16;
  p.max_features = 32, p.min_distance = 8, p.harris_threshold = 300;
  p.lk_levels = 3, p.lk_win = 7, p.lk_max_iter = 10, p.lk_eps = 655, p.lk_min_det = 1;
  p.ncc_radius = 5, p.ncc_search = 8, p.ncc_subpixel = 1;
  p.inlier_tol = 6554, p.min_inliers = 5;
  p.tpi = 50 * 256, p.wheelbase = 4 << 16, p.fuse_rot_tol = 65536, p.fuse_trans_tol = 6554, p.fuse_window = 16;
  p.rot_feat = 1, p.rot_small = 98304, p.rot_min_inliers = 8, p.rot_sel_tol = 16384;
  return p;
}

TEST(OdometryCordic, SinCosWithinTwoToTheMinus25) {
  // Every 0.37 degrees over several turns either way, plus the reduction's edges.
  std::vector<int32_t> angles;
  for (int32_t a = -1080 * 65536; a <= 1080 * 65536; a += 24301) angles.push_back(a);
  for (int32_t d : {-270, -180, -90, 0, 90, 180, 270, 360})
    for (int32_t e : {-1, 0, 1}) angles.push_back(d * 65536 + e);
  for (int32_t a : angles) {
    int32_t c, s;
    bvb_odo_sincos(a, &c, &s);
    const double rad = a / 65536.0 * kPi / 180.0;
    ASSERT_NEAR(c / 1073741824.0, std::cos(rad), 1.0 / (1 << 25)) << "angle " << a / 65536.0;
    ASSERT_NEAR(s / 1073741824.0, std::sin(rad), 1.0 / (1 << 25)) << "angle " << a / 65536.0;
  }
}

TEST(OdometryCordic, Atan2WithinOneUnit) {
  // Small and large magnitudes (the scaling), every direction of the right half plane.
  for (int32_t mag : {3, 1000, 1 << 20, (1 << 30) + 12345}) {
    for (int k = -89; k <= 89; k += 2) {
      const double r = k * kPi / 180.0 + 0.0123;
      const int32_t x = int32_t(std::lround(mag * std::cos(r))), y = int32_t(std::lround(mag * std::sin(r)));
      if (x <= 0) continue;
      const double want = std::atan2(double(y), double(x)) * 180.0 / kPi * 65536.0;
      // Inputs below 10 carry their own rounding of the direction: allow it.
      const double tol = mag < 10 ? 65536.0 * 15 : 1;
      ASSERT_NEAR(bvb_odo_atan2(y, x), want, tol) << "y " << y << " x " << x;
    }
  }
  EXPECT_EQ(bvb_odo_atan2(0, 5), 0);
  EXPECT_NEAR(bvb_odo_atan2(7, 7), 45 * 65536, 1);
  EXPECT_NEAR(bvb_odo_atan2(-7, 7), -45 * 65536, 1);
}

TEST(OdometryParams, FloorRegionStartsWhereTheFloorIsMaxRangeAway) {
  // 160x120, fx = 140, camera 4 in up, 10 deg down: the floor 24 in ahead of the camera's foot
  // is seen at yn = (4 cos 10 - 24 sin 10) / (24 cos 10 + 4 sin 10) = -0.00939, row 58.19.
  const bvb_odo_params p = params_160x120();
  const double t = 10 * kPi / 180, yn = (4 * std::cos(t) - 24 * std::sin(t)) / (24 * std::cos(t) + 4 * std::sin(t));
  EXPECT_EQ(bvb_pipe_odometry_floor_y0(160, 120, 160, &p), int(std::ceil(59.5 + 140 * yn)));
  EXPECT_GT(bvb_pipe_odometry_state_bytes(160, 120, 160, &p), uint32_t(160 * 120));
  // The response map of the floor region lives in strips in fast (L1), not in work.
  EXPECT_LE(bvb_pipe_odometry_fast_bytes(160, 120, 160, &p), BVB_ODO_FAST_MAX);
  EXPECT_GT(bvb_pipe_odometry_work_bytes(160, 120, 160, &p), 0u);
}

// Strips of every height give the whole map's candidates, in its order: corners straddle the
// strips' seams (blocks of 3 to 9 pixels with noise; threshold 0 keeps every maximum).
TEST(OdometryHarrisStrips, SameCandidatesAsTheWholeMap) {
  bvb_odo_kernels ops{};
  ops.harris_response = bvb_harris_response_c;
  ops.harris_nms = bvb_harris_nms_c;
  uint32_t seed = 12345;
  auto rnd = [&seed]() { return (seed = seed * 1103515245u + 12345u) >> 16; };
  const int sizes[][3] = {{160, 61, 163}, {37, 9, 40}, {16, 5, 16}, {48, 23, 48}};
  for (const auto &sz : sizes) {
    const int w = sz[0], hreg = sz[1], stride = sz[2];
    std::vector<uint8_t> img(size_t(stride) * hreg);
    const int bw = 3 + int(rnd() % 7);
    for (int y = 0; y < hreg; ++y)
      for (int x = 0; x < stride; ++x)
        img[size_t(y) * stride + x] = uint8_t((((x / bw) ^ (y / bw)) & 1) * 160 + rnd() % 64);
    std::vector<uint8_t> hscr(BVB_HARRIS_SCRATCH_BYTES(w)), nscr(BVB_HARRIS_NMS_SCRATCH_BYTES(w));
    std::vector<int32_t> map(size_t(w) * hreg), want(2 * size_t(BVB_HARRIS_NMS_CAPACITY(w, hreg)) + 2);
    bvb_harris_response_c(img.data(), map.data(), w, hreg, stride, w, hscr.data());
    int32_t n = 0;
    bvb_harris_nms_c(map.data(), w, hreg, w, 0, want.data(), &n, nscr.data());
    ASSERT_GT(n, w >= 48 ? 20 : 0);
    for (int kr = 1; kr <= hreg - 4; ++kr) {
      std::vector<int32_t> got(want.size(), 0), save(2 * size_t(w)), buf(size_t(kr + 4) * w);
      const int32_t m = bvb_odo_harris_strips(&ops, img.data(), w, hreg, stride, kr, 0, got.data(), hscr.data(),
                                              nscr.data(), save.data(), buf.data());
      ASSERT_EQ(m, n) << w << "x" << hreg << " strips of " << kr;
      for (int i = 0; i < 2 * n; ++i) ASSERT_EQ(got[size_t(i)], want[size_t(i)]) << w << "x" << hreg << " strips of " << kr << " entry " << i;
    }
  }
}

TEST(OdometryParams, OutOfRangeIsRejectedWithoutWriting) {
  bvb_odo_params p = params_160x120();
  EXPECT_GT(bvb_pipe_odometry_state_bytes(160, 120, 160, &p), 0u);
  p.lk_win = 8;  // even
  EXPECT_EQ(bvb_pipe_odometry_state_bytes(160, 120, 160, &p), 0u);
  std::vector<uint8_t> frame(160 * 120), state(64, 0xAB), work(64), fast(64);
  bvb_pipe_result result;
  std::memset(&result, 0x5A, sizeof result);
  const bvb_pipe_frame info{0, 0, 0, 0};
  EXPECT_EQ(bvb_pipe_odometry_c(frame.data(), 160, 120, 160, &info, &p, state.data(), &result, work.data(), fast.data()), -1);
  for (uint8_t b : state) EXPECT_EQ(b, 0xAB);
  const uint8_t *r = reinterpret_cast<const uint8_t *>(&result);
  for (size_t i = 0; i < sizeof result; ++i) EXPECT_EQ(r[i], 0x5A);
}

// A frame takes the quantities setup derives from the state when a full run of the same
// geometry and parameters left them there, and derives them afresh when any of them changed
// (every parameter word, the size, the stride), on frame 0, or after a run stopped early.
TEST(OdometryParams, SetupIsTakenFromTheStateOnlyForTheSameGeometryAndParameters) {
  const int w = 160, h = 120;
  const bvb_odo_params p = params_160x120();
  std::vector<uint8_t> frame(size_t(w) * h);
  uint32_t r = 12345;
  for (uint8_t &b : frame) b = uint8_t((r = r * 1103515245u + 12345u) >> 24);
  std::vector<uint8_t> state(bvb_pipe_odometry_state_bytes(w, h, w, &p)), work(bvb_pipe_odometry_work_bytes(w, h, w, &p)),
      fast(bvb_pipe_odometry_fast_bytes(w, h, w, &p));
  bvb_pipe_result result;
  const bvb_pipe_frame f0{0, 0, 0, 0}, f1{1, 0, 0, 0}, f2{2, 0, 0, 0}, f2_early{2, 0, 0, 3};
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f0, w, h, w, &p), 0);
  ASSERT_GE(bvb_pipe_odometry_c(frame.data(), w, h, w, &f0, &p, state.data(), &result, work.data(), fast.data()), 0);
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f1, w, h, w, &p), 1);
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f0, w, h, w, &p), 0);
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f1, w - 1, h, w, &p), 0);
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f1, w, h - 1, w, &p), 0);
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f1, w, h, w + 4, &p), 0);
  const size_t words = sizeof p / sizeof(int32_t);
  for (size_t i = 0; i < words; ++i) {
    bvb_odo_params q = p;
    reinterpret_cast<int32_t *>(&q)[i] += 1;
    EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f1, w, h, w, &q), 0) << "parameter word " << i;
  }
  // A run stopped early leaves the state as it was, its cache included; a changed parameter's
  // full run replaces it.
  bvb_odo_params q = p;
  q.max_range = 18 << 16;
  ASSERT_GE(bvb_pipe_odometry_c(frame.data(), w, h, w, &f2_early, &q, state.data(), &result, work.data(), fast.data()), 0);
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f2, w, h, w, &q), 0);
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f2, w, h, w, &p), 1);
  ASSERT_GE(bvb_pipe_odometry_c(frame.data(), w, h, w, &f2, &q, state.data(), &result, work.data(), fast.data()), 0);
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f2, w, h, w, &q), 1);
  EXPECT_EQ(bvb_pipe_odometry_setup_cached(state.data(), &f2, w, h, w, &p), 0);
}

// The square's first two sides (F36 + L90 + F36), vision alone. Driving towards the boxes the
// profile follows their edges as they spread outwards: with the profile alone (rot_feat=0) the
// heading ends 4.9 degrees off. The floor features hold it: within 0.3 degrees, measured by
// them on nearly every frame of the legs and of the turn (3 degrees a frame, under rot_small).
TEST(OdometryFloorRotation, HoldsTheHeadingOnStraightLegs) {
  for (const int rot_feat : {1, 0}) {
    SCOPED_TRACE("rot_feat=" + std::to_string(rot_feat));
    bvb::SceneGenerator gen(bvb::parse_scene_spec("arena=boxes,ss=3,path=F36+L90+F36"));
    bvb::Params params;
    params.set("rot_feat=" + std::to_string(rot_feat));
    bvb::PipelineRunOptions o;
    o.impl = "host";
    const bvb::PipelineDef *def = bvb::find_pipeline("odometry");
    ASSERT_NE(def, nullptr);
    const bvb::PipelineRun run = bvb::run_pipeline(*def, nullptr, nullptr, &gen, params, o);
    const bvb::FrameRecord &last = run.frames.back();
    const double err = last.out.heading_deg - last.in.truth.pose.heading_deg;
    int moved = 0, by_features = 0;
    for (const auto &r : run.frames) {
      if (r.in.index == 0) continue;
      ++moved;
      for (const auto &d : r.out.diag)
        if (d.first == "flags") by_features += (int(d.second) & BVB_ODO_F_ROT_FEAT) != 0;
    }
    if (rot_feat) {
      EXPECT_LE(std::fabs(err), 0.3);
      EXPECT_GE(by_features, moved * 9 / 10);
    } else {
      EXPECT_GT(std::fabs(err), 2.0) << "the profile alone no longer drifts: the test shows nothing";
      EXPECT_EQ(by_features, 0);
    }
  }
}

}  // namespace
