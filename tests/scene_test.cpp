// Tests of the scene generator (harness/scene): geometry against closed-form camera maths,
// flow against the ground-plane and rotation formulas and against the rendered frames
// themselves, paths and encoders against hand integration, file formats, spec and CLI errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include "io.h"
#include "scene/camera.h"
#include "scene/paths.h"
#include "scene/render.h"
#include "scene/scene_cli.h"
#include "scene/scene_io.h"
#include "scene/world.h"

namespace {

namespace fs = std::filesystem;
using namespace bvb;

const double kTilt = deg2rad(kDefaultTiltDeg);

std::string arena_path(const std::string &name) {
  return std::string(BVB_SOURCE_DIR) + "/frames/arenas/" + name + ".txt";
}

std::string fresh_dir(const std::string &name) {
  const fs::path p = fs::path(testing::TempDir()) / ("scene_test_" + name);
  fs::remove_all(p);
  return p.string();
}

// An endless floor and nothing else.
World open_world() {
  World w;
  w.name = "open";
  finalize_world(w);
  return w;
}

// A wall across the +x axis whose face is at x = d.
World wall_world(double d) {
  World w = open_world();
  Obstacle o;
  o.kind = ObstacleKind::Wall;
  o.p = {d + 0.5, -1000, d + 0.5, 1000, 1.0};
  o.height_in = 30;
  o.color = {255, 255, 255};
  o.contrast = 0.02;
  w.obstacles.push_back(o);
  finalize_world(w);
  return w;
}

Obstacle cylinder(double x, double y, double r, double h) {
  Obstacle o;
  o.kind = ObstacleKind::Cylinder;
  o.p = {x, y, r, 0, 0};
  o.height_in = h;
  o.color = {50, 50, 60};
  o.finalize();
  return o;
}

double bilinear(const Image &img, double x, double y) {
  const int x0 = std::clamp(int(std::floor(x)), 0, img.width - 2);
  const int y0 = std::clamp(int(std::floor(y)), 0, img.height - 2);
  const double tx = x - x0, ty = y - y0;
  const double a = img.at(x0, y0), b = img.at(x0 + 1, y0), c = img.at(x0, y0 + 1),
               d = img.at(x0 + 1, y0 + 1);
  return (a * (1 - tx) + b * tx) * (1 - ty) + (c * (1 - tx) + d * tx) * ty;
}

// ---------------------------------------------------------------------------------------------
// Camera

TEST(SceneCamera, StandardIntrinsicsAndHorizon) {
  const Camera c = Camera::standard(160, 120);
  EXPECT_DOUBLE_EQ(c.fx, 140);
  EXPECT_DOUBLE_EQ(c.fy, 140);
  EXPECT_DOUBLE_EQ(c.cx, 79.5);
  EXPECT_DOUBLE_EQ(c.cy, 59.5);
  EXPECT_NEAR(rad2deg(2 * std::atan(80.0 / c.fx)), 59.49, 0.01);
  EXPECT_DOUBLE_EQ(Camera::standard(320, 240).fx, 280);
  // A far point at the camera's height, straight ahead, lies on the horizon row
  // cy - fy tan(tilt), on the centre column.
  const CameraView v(c, Pose{10, 20, 30});
  const double h = deg2rad(30);
  double x, y;
  ASSERT_TRUE(v.project({10 + 1e7 * std::cos(h), 20 + 1e7 * std::sin(h), c.cam_height_in}, x, y));
  EXPECT_NEAR(x, 79.5, 1e-4);
  EXPECT_NEAR(y, 59.5 - 140 * std::tan(kTilt), 1e-4);
  // A floor point 10 in ahead and 3 in to the robot's left appears left of centre (smaller x)
  // and, being 21.8 degrees below the horizontal, below the optical axis (larger y).
  ASSERT_TRUE(v.project({10 + 10 * std::cos(h) - 3 * std::sin(h), 20 + 10 * std::sin(h) + 3 * std::cos(h), 0}, x, y));
  EXPECT_LT(x, 79.5);
  EXPECT_GT(y, 59.5);
}

// ---------------------------------------------------------------------------------------------
// Column truth, blocked, collisions

TEST(SceneColumns, WallAtKnownDistanceGivesAnalyticRowAndDistance) {
  const Camera cam = Camera::standard(160, 120);
  const double h = cam.cam_height_in;
  for (double d : {30.0, 47.3, 5.0}) {
    SCOPED_TRACE("wall at " + std::to_string(d));
    const World w = wall_world(d);
    const Pose pose{0, 0, 0};
    // The wall's base, the line x = d on the floor, is a horizontal image line: depth
    // d cos(tilt) + h sin(tilt) and height h cos(tilt) - d sin(tilt) in camera coordinates.
    const double zc = d * std::cos(kTilt) + h * std::sin(kTilt);
    const double ystar = cam.cy + cam.fy * (h * std::cos(kTilt) - d * std::sin(kTilt)) / zc;
    const int expect_row = ystar > cam.height - 1 ? cam.height - 1 : int(std::floor(ystar));
    if (ystar <= cam.height - 1) {
      const double frac = ystar - std::floor(ystar);
      ASSERT_TRUE(frac > 0.02 && frac < 0.98) << "pick a distance whose row is not ambiguous";
    }
    const ColumnTruth ct = column_truth(w, pose, cam);
    const RenderResult r = render(w, pose, cam);
    for (int x = 0; x < cam.width; ++x) {
      const double lateral = (cam.cx - x) * zc / cam.fx;  // to the left for x < cx
      EXPECT_EQ(ct.boundary_row[x], expect_row) << "column " << x;
      EXPECT_NEAR(ct.distance_in[x], std::hypot(d, lateral), 1e-4 * d) << "column " << x;
      // The picture agrees: floor below the boundary, wall on it and above.
      if (expect_row + 1 < cam.height) {
        EXPECT_EQ(r.surface[(expect_row + 1) * cam.width + x], kSurfaceFloor);
      }
      EXPECT_EQ(r.surface[expect_row * cam.width + x], 0) << "column " << x;
      if (expect_row + 3 < cam.height) {
        EXPECT_LT(r.grey.at(x, expect_row + 3), 165);
      }
      if (expect_row >= 3) {
        EXPECT_GT(r.grey.at(x, expect_row - 3), 170);
      }
    }
  }
}

TEST(SceneColumns, OpenFloorIsInfinite) {
  const Camera cam = Camera::standard(64, 48);
  const ColumnTruth ct = column_truth(open_world(), Pose{}, cam);
  const int horizon = int(std::floor(cam.cy - cam.fy * std::tan(kTilt)));
  for (int x = 0; x < cam.width; ++x) {
    EXPECT_TRUE(std::isinf(ct.distance_in[x]));
    EXPECT_EQ(ct.boundary_row[x], horizon);
  }
}

TEST(SceneTruth, CorridorClearanceAndBlocked) {
  // Wall face at x = 16: the robot's front (radius 3) is 13 in away.
  EXPECT_NEAR(corridor_clearance(wall_world(16), Pose{0, 0, 0}), 13, 1e-9);
  EXPECT_NEAR(corridor_clearance(wall_world(16), Pose{4, 0, 0}), 9, 1e-9);
  // Facing away: nothing ahead.
  EXPECT_TRUE(std::isinf(corridor_clearance(wall_world(16), Pose{0, 0, 180})));
  // Heading 90: a wall at y = 20 (face at y = 19.5).
  World w = open_world();
  Obstacle o;
  o.kind = ObstacleKind::Wall;
  o.p = {-100, 20, 100, 20, 1};
  o.height_in = 10;
  w.obstacles.push_back(o);
  finalize_world(w);
  EXPECT_NEAR(corridor_clearance(w, Pose{0, 0, 90}), 19.5 - 3, 1e-9);
  // A post beside the corridor: counts only while it reaches into |lateral| <= 3.
  World p = open_world();
  p.obstacles.push_back(cylinder(30, 3 + 2 + 0.1, 2, 5));  // just outside
  EXPECT_TRUE(std::isinf(corridor_clearance(p, Pose{})));
  p.obstacles[0] = cylinder(30, -(3 + 2 - 0.5), 2, 5);  // reaches 0.5 in into the corridor
  EXPECT_NEAR(corridor_clearance(p, Pose{}), 30 - std::sqrt(2 * 2 - 1.5 * 1.5) - 3, 1e-9);
  // The spec's "blocked" is clearance <= block_dist.
  SceneSpec s;
  s.arena = "unused";
  s.path = "S1";
  s.block_dist_in = 12;
  s.start = {4, 0, 0};
  s.has_start = true;
  SceneGenerator g(s, wall_world(16));
  EXPECT_TRUE(g.truth().blocked);   // 9 in
  s.start = {0, 0, 0};
  SceneGenerator g2(s, wall_world(16));
  EXPECT_FALSE(g2.truth().blocked);  // 13 in
}

TEST(SceneTruth, Collides) {
  const World w = wall_world(20);  // face at x = 20
  EXPECT_FALSE(collides(w, Pose{16.9, 0, 0}));
  EXPECT_TRUE(collides(w, Pose{17.1, 0, 0}));
  EXPECT_TRUE(collides(w, Pose{20.5, 0, 0}));  // inside the wall
  World p = open_world();
  p.obstacles.push_back(cylinder(10, 0, 2, 5));
  EXPECT_TRUE(collides(p, Pose{5.1, 0, 0}));
  EXPECT_FALSE(collides(p, Pose{4.9, 0, 0}));
}

// ---------------------------------------------------------------------------------------------
// Flow

TEST(SceneFlow, ForwardTranslationMatchesGroundPlaneFlow) {
  const Camera cam = Camera::standard(160, 120);
  const World w = open_world();
  RenderOptions o;
  o.supersample = 1;
  const double s = 0.5;
  const Pose pa{3, -2, 25}, pb = step_pose(pa, s, 0);
  const RenderResult ra = render(w, pa, cam, o), rb = render(w, pb, cam, o);
  const FlowField f = true_flow(w, pa, ra, w, pb, rb, cam);
  // In camera coordinates the floor is {P : up_c . P = -h} with up_c = (0, -cos t, -sin t) and
  // the camera moves by s along forward_c = (0, -sin t, cos t).
  const double h = cam.cam_height_in, ct = std::cos(kTilt), st = std::sin(kTilt);
  int floor_px = 0, sky_px = 0;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      const size_t i = size_t(y) * cam.width + x;
      const double a = (x - cam.cx) / cam.fx, b = (y - cam.cy) / cam.fy;
      const double denom = b * ct + st;
      if (denom < 0.02) {  // at or above the horizon: infinitely far, no translation flow
        if (denom < 0) {
          EXPECT_NEAR(f.u[i], 0, 1e-4);
          EXPECT_NEAR(f.v[i], 0, 1e-4);
          ++sky_px;
        }
        continue;
      }
      const double t = h / denom;
      const double X = t * a, Y = t * b + s * st, Z = t - s * ct;
      EXPECT_NEAR(f.u[i], cam.cx + cam.fx * X / Z - x, 2e-3) << x << "," << y;
      EXPECT_NEAR(f.v[i], cam.cy + cam.fy * Y / Z - y, 2e-3) << x << "," << y;
      ++floor_px;
    }
  EXPECT_GT(floor_px, 160 * 80);
  EXPECT_GT(sky_px, 160 * 30);
  // Sanity of the sign: the floor below the centre streams downwards (v > 0).
  EXPECT_GT(f.v[size_t(110) * cam.width + 80], 0.3);
}

TEST(SceneFlow, TurnInPlaceIsPureRotation) {
  const double theta = 3.0;
  {
    // Level camera: exact rotation homography about the camera's vertical axis. A left turn
    // moves the scene to the right.
    Camera cam = Camera::standard(160, 120);
    cam.tilt_deg = 0;
    const World w = wall_world(40);
    const Pose pa{0, 0, 0}, pb = step_pose(pa, 0, theta);
    const RenderResult ra = render(w, pa, cam), rb = render(w, pb, cam);
    const FlowField f = true_flow(w, pa, ra, w, pb, rb, cam);
    const double c = std::cos(deg2rad(theta)), s = std::sin(deg2rad(theta));
    for (int y = 0; y < cam.height; y += 7)
      for (int x = 0; x < cam.width; x += 5) {
        const size_t i = size_t(y) * cam.width + x;
        const double a = (x - cam.cx) / cam.fx, b = (y - cam.cy) / cam.fy;
        const double den = c - a * s;
        ASSERT_FALSE(FlowField::unknown(f.u[i])) << x << "," << y;
        EXPECT_NEAR(f.u[i], cam.cx + cam.fx * (a * c + s) / den - x, 1e-3) << x << "," << y;
        EXPECT_NEAR(f.v[i], cam.cy + cam.fy * b / den - y, 1e-3) << x << "," << y;
      }
    EXPECT_NEAR(f.u[size_t(60) * cam.width + 80], cam.fx * std::tan(deg2rad(theta)), 0.02);
  }
  {
    // The default 10 degree tilt: near the centre, still about f tan(theta); right turns flow left.
    const Camera cam = Camera::standard(160, 120);
    const World w = wall_world(40);
    const Pose pa{0, 0, 0};
    for (double turn : {theta, -theta}) {
      const Pose pb = step_pose(pa, 0, turn);
      const FlowField f = true_flow(w, pa, render(w, pa, cam), w, pb, render(w, pb, cam), cam);
      const double expect = cam.fx * std::tan(deg2rad(turn));
      EXPECT_NEAR(f.u[size_t(60) * cam.width + 80], expect, 0.03 * std::fabs(expect));
      EXPECT_NEAR(f.v[size_t(60) * cam.width + 80], 0, 0.05 * std::fabs(expect));
    }
  }
}

// The frames themselves must agree with the flow: frame a(x, y) ~ frame b(x + u, y + v).
TEST(SceneFlow, WarpsEachFrameOntoTheNext) {
  const Camera cam = Camera::standard(160, 120);
  World arena = load_arena(arena_path("boxes"));
  MoverDef m;  // a mover crossing 20 in ahead, 1 in per frame
  m.a = {44, 22};
  m.b = {44, 40};
  m.speed_in = 1.0;
  arena.movers = {m};
  finalize_world(arena);
  const World wa = world_at_frame(arena, 6), wb = world_at_frame(arena, 7);
  const int mover_id = int(wa.obstacles.size()) - 1;
  const Pose pa{24, 30, 0}, pb = step_pose(pa, 0.5, 1.0);
  const RenderResult ra = render(wa, pa, cam), rb = render(wb, pb, cam);
  const FlowField f = true_flow(wa, pa, ra, wb, pb, rb, cam);
  double err = 0, base = 0, merr = 0, mbase = 0;
  int n = 0, mn = 0, unknown = 0;
  for (int y = 2; y < cam.height - 2; ++y)
    for (int x = 2; x < cam.width - 2; ++x) {
      const size_t i = size_t(y) * cam.width + x;
      if (FlowField::unknown(f.u[i])) {
        ++unknown;
        continue;
      }
      const double xb = x + f.u[i], yb = y + f.v[i];
      if (xb < 1 || yb < 1 || xb > cam.width - 2 || yb > cam.height - 2) continue;
      const double e = std::fabs(ra.grey.at(x, y) - bilinear(rb.grey, xb, yb));
      const double e0 = std::fabs(ra.grey.at(x, y) - double(rb.grey.at(x, y)));
      if (ra.surface[i] == mover_id) {
        merr += e;
        mbase += e0;
        ++mn;
      } else {
        err += e;
        base += e0;
        ++n;
      }
    }
  ASSERT_GT(n, 10000);
  ASSERT_GT(mn, 100) << "the mover must be in view";
  EXPECT_LT(err / n, 2.0) << "mean |a - warped b| over static pixels";
  EXPECT_GT(base / n, 2.0 * err / n) << "zero flow should match much worse";
  EXPECT_LT(merr / mn, 2.5) << "mean |a - warped b| over the mover";
  EXPECT_GT(mbase / mn, 1.5 * merr / mn);
  // The mover hides some floor it moves over, so some pixels are unknown, but few.
  EXPECT_GT(unknown, 0);
  EXPECT_LT(unknown, 160 * 120 / 20);
}

// ---------------------------------------------------------------------------------------------
// Paths and encoders

TEST(ScenePaths, ArcStepIsAQuarterCircle) {
  const Pose q = step_pose(Pose{0, 0, 0}, kPi / 2 * 10, 90);
  EXPECT_NEAR(q.x_in, 10, 1e-9);
  EXPECT_NEAR(q.y_in, 10, 1e-9);
  EXPECT_NEAR(q.heading_deg, 90, 1e-12);
  const Pose r = step_pose(Pose{1, 1, 90}, 2, 0);
  EXPECT_NEAR(r.x_in, 1, 1e-12);
  EXPECT_NEAR(r.y_in, 3, 1e-12);
}

TEST(ScenePaths, ScriptExpansion) {
  const auto s = expand_script("F1.2+R10+S2+B0.5", 0.5, 3);
  ASSERT_EQ(s.size(), 3u + 4u + 2u + 1u);
  EXPECT_DOUBLE_EQ(s[0].forward_in, 0.5);
  EXPECT_NEAR(s[2].forward_in, 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(s[3].turn_deg, -3);
  EXPECT_NEAR(s[6].turn_deg, -1, 1e-12);
  EXPECT_DOUBLE_EQ(s[7].forward_in, 0);
  EXPECT_DOUBLE_EQ(s[9].forward_in, -0.5);
  for (const char *bad : {"", "F", "X3", "F3+", "F-3", "Fabc", "F3++L2", "S1.5", "F1e3"})
    EXPECT_THROW(expand_script(bad, 0.5, 3), InputError) << bad;
  EXPECT_THROW(path_script("circle", 1, 1, 1, true), InputError);
}

// The million-step cap holds for pauses too: each S move alone is within it, their sum is not
// (a 13 KB spec of them once reached 8 GB).
TEST(ScenePaths, StepCapCoversPauses) {
  EXPECT_EQ(expand_script("S1000000", 0.5, 3).size(), 1000000u);
  EXPECT_THROW(expand_script("S1000000+S1", 0.5, 3), InputError);
  EXPECT_THROW(expand_script("F400000+S1000000", 0.5, 3), InputError);
}

TEST(ScenePaths, SquareReturnsToStart) {
  for (bool left : {true, false}) {
    const auto steps = expand_script(path_script("square", 36, 90, 36, left), 0.5, 3);
    ASSERT_EQ(steps.size(), 4u * (72 + 30));
    Pose p{24, 30, 0};
    for (size_t k = 0; k < steps.size(); ++k) {
      p = step_pose(p, steps[k].forward_in, steps[k].turn_deg);
      if (k + 1 == 72) {  // end of the first side
        EXPECT_NEAR(p.x_in, 60, 1e-9);
        EXPECT_NEAR(p.y_in, 30, 1e-9);
      }
      if (k + 1 == 72 + 30 + 72) {  // second corner
        EXPECT_NEAR(p.x_in, 60, 1e-9);
        EXPECT_NEAR(p.y_in, left ? 66 : -6, 1e-9);
      }
    }
    EXPECT_NEAR(p.x_in, 24, 1e-9);
    EXPECT_NEAR(p.y_in, 30, 1e-9);
    EXPECT_NEAR(p.heading_deg, left ? 360 : -360, 1e-9);
  }
}

TEST(ScenePaths, SeedOdometryTests) {
  struct Case {
    const char *name;
    double x, y, h;
    size_t steps;
  } cases[] = {{"odo_a", 36, -11, -90, 72 + 30 + 22}, {"odo_b", 36, 9.5, 90, 72 + 30 + 19}};
  for (const auto &c : cases) {
    const auto steps = expand_script(path_script(c.name, 0, 0, 0, true), 0.5, 3);
    EXPECT_EQ(steps.size(), c.steps) << c.name;
    Pose p;
    for (const auto &s : steps) p = step_pose(p, s.forward_in, s.turn_deg);
    EXPECT_NEAR(p.x_in, c.x, 1e-9) << c.name;
    EXPECT_NEAR(p.y_in, c.y, 1e-9) << c.name;
    EXPECT_NEAR(p.heading_deg, c.h, 1e-9) << c.name;
  }
}

TEST(SceneEncoders, ZeroSlipTicksIntegrateBackToThePath) {
  SceneSpec s = parse_scene_spec("path=F20+L90+F10+R45+F5,tpi=50,wheelbase=4");
  s.arena = arena_path("boxes");
  SceneGenerator g(s);
  std::vector<FrameTruth> truth;
  for (int k = 0; k < g.frames(); ++k) {
    truth.push_back(g.truth());
    if (k + 1 < g.frames()) g.advance();
  }
  // 20 in straight = 1000 ticks per wheel; the 90 degree turn in place = pi/2 * 2 in per wheel.
  EXPECT_EQ(truth[40].left_ticks, 1000);
  EXPECT_EQ(truth[40].right_ticks, 1000);
  EXPECT_EQ(truth[70].right_ticks - truth[40].right_ticks, std::lround(kPi / 2 * 2 * 50));
  EXPECT_EQ(truth[70].left_ticks - truth[40].left_ticks, -std::lround(kPi / 2 * 2 * 50));
  // Hand dead reckoning: each frame's wheel travels -> heading change and mid-heading advance.
  double x = truth[0].pose.x_in, y = truth[0].pose.y_in, h = deg2rad(truth[0].pose.heading_deg);
  for (size_t k = 1; k < truth.size(); ++k) {
    const double dl = (truth[k].left_ticks - truth[k - 1].left_ticks) / 50.0;
    const double dr = (truth[k].right_ticks - truth[k - 1].right_ticks) / 50.0;
    const double dth = (dr - dl) / 4.0, d = 0.5 * (dl + dr);
    x += d * std::cos(h + dth / 2);
    y += d * std::sin(h + dth / 2);
    h += dth;
    EXPECT_NEAR(x, truth[k].pose.x_in, 0.05) << k;
    EXPECT_NEAR(y, truth[k].pose.y_in, 0.05) << k;
    EXPECT_NEAR(rad2deg(h), truth[k].pose.heading_deg, 0.5) << k;
  }
}

TEST(SceneEncoders, SlipOvercountsAndNoiseFollowsTheSeed) {
  auto ticks = [](const std::string &extra) {
    SceneSpec s = parse_scene_spec("path=F10" + extra);
    s.arena = arena_path("boxes");
    SceneGenerator g(s);
    while (g.frame() + 1 < g.frames()) g.advance();
    return std::make_pair(g.truth().left_ticks, g.truth().right_ticks);
  };
  const auto clean = ticks("");
  EXPECT_EQ(clean.first, 500);
  const auto slip = ticks(",slip=0.1");
  EXPECT_GT(slip.first, 500);
  EXPECT_GT(slip.second, 500);
  EXPECT_LT(slip.first, 500 * 1.4);
  EXPECT_NE(slip.first, slip.second);
  EXPECT_EQ(ticks(",slip=0.1,seed=3"), ticks(",slip=0.1,seed=3"));
  EXPECT_NE(ticks(",slip=0.1,seed=3"), ticks(",slip=0.1,seed=4"));
  const auto noisy = ticks(",enc_noise=2");
  EXPECT_NE(noisy, clean);
  EXPECT_NEAR(double(noisy.first), 500, 2 * 2 * std::sqrt(20.0) * 3);
}

// ---------------------------------------------------------------------------------------------
// Pixels

TEST(SceneRender, SameSeedSameBytesOtherSeedOtherNoise) {
  const World w = load_arena(arena_path("boxes"));
  const Camera cam = Camera::standard(160, 120);
  RenderOptions o;
  o.noise_sigma = 3;
  o.noise_seed = 7;
  const RenderResult a = render(w, w.start, cam, o), b = render(w, w.start, cam, o);
  EXPECT_EQ(a.rgb.data, b.rgb.data);
  EXPECT_EQ(a.uyvy, b.uyvy);
  o.noise_seed = 8;
  const RenderResult c = render(w, w.start, cam, o);
  EXPECT_NE(a.rgb.data, c.rgb.data);
  o.noise_sigma = 0;
  const RenderResult clean = render(w, w.start, cam, o);
  double sum = 0, sum2 = 0;
  int n = 0;
  for (size_t i = 0; i < clean.rgb.data.size(); ++i) {
    const int v = clean.rgb.data[i];
    if (v < 15 || v > 240) continue;  // away from clamping
    const double d = double(a.rgb.data[i]) - v;
    sum += d;
    sum2 += d * d;
    ++n;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0, 0.1);
  EXPECT_NEAR(sd, std::sqrt(9 + 1.0 / 12), 0.15);  // Gaussian plus rounding
}

TEST(SceneRender, Bt601Conversion) {
  // Studio-range BT.601: Y = 16 + 219 E'y, Cb = 128 + 224 (B - Y) / 1.772, Cr = 128 + 224 (R - Y) / 1.402.
  const int colours[][3] = {{0, 0, 0}, {255, 255, 255}, {255, 0, 0}, {0, 255, 0}, {0, 0, 255},
                            {128, 64, 200}, {17, 250, 99}};
  for (const auto &c : colours) {
    const double r = c[0] / 255.0, g = c[1] / 255.0, b = c[2] / 255.0;
    const double ey = 0.299 * r + 0.587 * g + 0.114 * b;
    int y, u, v;
    rgb_to_yuv(c[0], c[1], c[2], y, u, v);
    EXPECT_NEAR(y, 16 + 219 * ey, 1.0) << c[0] << "," << c[1] << "," << c[2];
    EXPECT_NEAR(u, 128 + 224 * (b - ey) / 1.772, 1.0) << c[0] << "," << c[1] << "," << c[2];
    EXPECT_NEAR(v, 128 + 224 * (r - ey) / 1.402, 1.0) << c[0] << "," << c[1] << "," << c[2];
  }
  int y, u, v;
  rgb_to_yuv(255, 255, 255, y, u, v);
  EXPECT_EQ(y, 235);
  EXPECT_EQ(u, 128);
  rgb_to_yuv(0, 0, 0, y, u, v);
  EXPECT_EQ(y, 16);
  // Byte order U Y0 V Y1 and the grey plane is Y.
  Image px(2, 1, 3);
  px.data = {255, 0, 0, 0, 0, 255};
  const auto q = rgb_to_uyvy(px);
  int y0, u0, v0, y1, u1, v1;
  rgb_to_yuv(255, 0, 0, y0, u0, v0);
  rgb_to_yuv(0, 0, 255, y1, u1, v1);
  EXPECT_EQ(q, (std::vector<uint8_t>{uint8_t((u0 + u1 + 1) / 2), uint8_t(y0), uint8_t((v0 + v1 + 1) / 2), uint8_t(y1)}));
  const World w = load_arena(arena_path("cylinders"));
  const RenderResult rr = render(w, w.start, Camera::standard(64, 48));
  ASSERT_EQ(rr.uyvy.size(), 64u * 48 * 2);
  for (size_t i = 0; i < 64 * 48; ++i) ASSERT_EQ(rr.uyvy[2 * i + 1], rr.grey.data[i]) << i;
}

TEST(SceneRender, FloorSeparableFromObstaclesAndTextured) {
  const Camera cam = Camera::standard(160, 120);
  for (const char *name : {"boxes", "corridor", "cylinders"}) {
    const World w = load_arena(arena_path(name));
    std::vector<int> floor_y, obst_y;
    double grad = 0;
    int grad_n = 0;
    for (double turn : {0.0, 90.0, 180.0, 270.0}) {
      Pose p = w.start;
      p.heading_deg += turn;
      const RenderResult r = render(w, p, cam);
      for (int y = 1; y < cam.height - 1; ++y)
        for (int x = 1; x < cam.width - 1; ++x) {
          const size_t i = size_t(y) * cam.width + x;
          const int s = r.surface[i];
          if (s != r.surface[i - 1] || s != r.surface[i + 1] || s != r.surface[i - cam.width] ||
              s != r.surface[i + cam.width])
            continue;  // mixed edge pixels
          if (s == kSurfaceFloor) {
            floor_y.push_back(r.grey.data[i]);
            if (y > cam.height / 2 && r.surface[i + 1] == kSurfaceFloor) {
              grad += std::abs(int(r.grey.data[i + 1]) - int(r.grey.data[i]));
              ++grad_n;
            }
          } else if (s >= 0) {
            obst_y.push_back(r.grey.data[i]);
          }
        }
    }
    ASSERT_GT(floor_y.size(), 20000u) << name;
    ASSERT_GT(obst_y.size(), 5000u) << name;
    std::sort(floor_y.begin(), floor_y.end());
    const int lo = floor_y[floor_y.size() / 100], hi = floor_y[floor_y.size() * 99 / 100];
    size_t inside = 0;
    for (int v : obst_y) inside += v >= lo && v <= hi;
    EXPECT_LT(double(inside) / obst_y.size(), 0.03)
        << name << ": obstacle luma inside the floor's 1-99% range " << lo << ".." << hi;
    EXPECT_GT(hi - lo, 25) << name << ": the floor needs texture";
    EXPECT_GT(grad / grad_n, 1.2) << name << ": mean horizontal gradient of the near floor";
  }
}

TEST(SceneRender, LightingStepAndFlicker) {
  SceneSpec s = parse_scene_spec("path=S8,light_step=4,step_gain=0.6,step_offset=0,flicker=0.1,flicker_period=8");
  s.arena = arena_path("boxes");
  SceneGenerator g(s);
  std::vector<double> mean_rgb;
  std::vector<FrameTruth> t;
  for (int k = 0; k < 8; ++k) {
    const RenderResult r = g.render();
    double m = 0;
    for (uint8_t v : r.rgb.data) m += v;
    mean_rgb.push_back(m / r.rgb.data.size());
    t.push_back(g.truth());
    if (k + 1 < 8) g.advance();
  }
  for (int k = 0; k < 8; ++k) {
    const double expect = (1 + 0.1 * std::sin(2 * kPi * k / 8)) * (k >= 4 ? 0.6 : 1.0);
    EXPECT_NEAR(t[k].gain, expect, 1e-6) << k;
    // The robot stands still, so brightness follows the gain (a few bright pixels clip).
    EXPECT_NEAR(mean_rgb[k] / mean_rgb[0], expect, 0.02) << k;
  }
}

TEST(SceneRender, MoverMovesAndIsSeen) {
  SceneSpec s = parse_scene_spec("path=S12,mover=cross");
  s.arena = arena_path("boxes");
  SceneGenerator g(s);
  const World w0 = g.world_now();
  const int id = int(w0.obstacles.size()) - 1;
  ASSERT_EQ(w0.obstacles[size_t(id)].mover, 0);
  const RenderResult r0 = g.render();
  int seen = 0;
  for (auto v : r0.surface) seen += v == id;
  EXPECT_GT(seen, 50);
  for (int k = 0; k < 10; ++k) g.advance();
  const World w10 = g.world_now();
  const double moved = std::hypot(w10.obstacles[size_t(id)].centre.x - w0.obstacles[size_t(id)].centre.x,
                                  w10.obstacles[size_t(id)].centre.y - w0.obstacles[size_t(id)].centre.y);
  EXPECT_NEAR(moved, 4.0, 1e-9);  // 0.4 in per frame
  EXPECT_THROW(SceneGenerator(parse_scene_spec("mover=arena"), load_arena(arena_path("boxes"))), InputError);
}

TEST(SceneRender, OddSizes) {
  const World w = load_arena(arena_path("boxes"));
  const RenderResult odd = render(w, w.start, Camera::standard(33, 17));
  EXPECT_EQ(odd.grey.width, 33);
  EXPECT_EQ(odd.grey.height, 17);
  EXPECT_EQ(odd.grey.data.size(), size_t(33 * 17));
  EXPECT_TRUE(odd.uyvy.empty());  // UYVY needs an even width
}

TEST(SceneGenerator, ClosedLoopStopsAtObstaclesButWheelsTurn) {
  SceneSpec s = parse_scene_spec("path=S1,start=0:0:0,speed=0.5,turn_rate=5,tpi=50");
  SceneGenerator g(s, wall_world(10));  // face at x = 10: the robot's disc touches it at x = 7
  int refused = 0;
  for (int k = 0; k < 20; ++k) {
    const bool moved = g.advance(g.drive_step(Drive::Forward), true);
    refused += !moved;
    EXPECT_FALSE(g.truth().collision) << k;
    if (!moved) {
      EXPECT_DOUBLE_EQ(g.truth().step.forward_in, 0);
    }
  }
  EXPECT_NEAR(g.pose().x_in, 7.0, 1e-9);  // touching (distance = radius) is not a collision
  EXPECT_EQ(refused, 20 - 14);
  EXPECT_TRUE(g.truth().blocked);
  EXPECT_EQ(g.truth().left_ticks, 20 * 25);  // the wheels spun on
  ASSERT_TRUE(g.advance(g.drive_step(Drive::Left), true));
  EXPECT_DOUBLE_EQ(g.pose().heading_deg, 5);
  g.advance(g.drive_step(Drive::Right), true);
  g.advance(g.drive_step(Drive::Right), true);
  EXPECT_DOUBLE_EQ(g.pose().heading_deg, -5);
  EXPECT_EQ(g.frame(), 23);
}

// ---------------------------------------------------------------------------------------------
// Arenas

TEST(SceneArenas, OracleDriverRoamsThousandsOfFramesWithoutCollision) {
  for (const char *name : {"boxes", "corridor", "cylinders"}) {
    SceneSpec s = parse_scene_spec("path=avoid,frames=3000");
    s.arena = arena_path(name);
    SceneGenerator g(s);
    std::set<std::pair<int, int>> cells;
    double travelled = 0;
    int turning = 0;
    while (g.frame() + 1 < g.frames()) {
      const Step st = g.next_step();
      travelled += std::fabs(st.forward_in);
      turning += st.turn_deg != 0;
      g.advance(st, false);
      ASSERT_FALSE(g.truth().collision) << name << " frame " << g.frame();
      cells.insert({int(std::floor(g.pose().x_in / 12)), int(std::floor(g.pose().y_in / 12))});
    }
    EXPECT_GT(travelled, 500) << name;
    EXPECT_GT(turning, 100) << name;
    EXPECT_GE(cells.size(), 12u) << name;
  }
}

TEST(SceneArenas, ScriptedTestPathsAreCollisionFree) {
  const std::pair<const char *, const char *> runs[] = {
      {"boxes", "square"}, {"boxes", "odo_a"}, {"boxes", "odo_b"}, {"boxes", "straight"},
      {"corridor", "odo_a"}, {"corridor", "odo_b"}, {"corridor", "straight"},
      {"cylinders", "straight"}};
  for (const auto &[arena, path] : runs) {
    SceneSpec s = parse_scene_spec(std::string("path=") + path);
    s.arena = arena_path(arena);
    SceneGenerator g(s);
    for (;;) {
      ASSERT_FALSE(g.truth().collision) << arena << " " << path << " frame " << g.frame();
      if (g.frame() + 1 >= g.frames()) break;
      g.advance();
    }
  }
}

TEST(SceneArenas, ParseFormatAndErrors) {
  const World w = load_arena(arena_path("cylinders"));
  EXPECT_EQ(w.name, "cylinders");
  EXPECT_EQ(w.obstacles.size(), 12u);
  EXPECT_EQ(w.movers.size(), 1u);
  const World back = parse_arena(format_arena(w), "roundtrip");
  EXPECT_EQ(format_arena(back), format_arena(w));
  EXPECT_EQ(back.obstacles.size(), w.obstacles.size());
  auto fails = [](const std::string &text, const std::string &needle) {
    try {
      parse_arena(text, "t.txt");
    } catch (const InputError &e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted: " << text;
  };
  fails("start 0 0 0\nbox 1 2 3\n", "t.txt:2:");
  fails("start 0 0 0\n\nteapot 1 2\n", "t.txt:3: unknown item 'teapot'");
  fails("start 0 0 0\ncylinder 1 2 x 4 5 6 7\n", "radius");
  fails("start 0 0 0\ncylinder 1 2 -3 4 5 6 7\n", "radius must be > 0");
  fails("start 0 0 0\nwall 1 1 1 1 5 1 9 9 9\n", "zero length");
  fails("start 0 0 0\nbox 1 2 3 4 5 6 7 8 300\n", "colour");
  fails("wall 0 0 1 1 5 1 9 9 9\n", "no 'start");
  fails("start 0 0 0\nstart 1 1 1\n", "given twice");
  fails("start 0 0 0\nmover blob 1 1 1 1 1 0 0 1 1 1\n", "cylinder' or 'box");
  EXPECT_THROW(load_arena("no_such_arena"), InputError);
  EXPECT_THROW(load_arena("../etc"), InputError);
}

// ---------------------------------------------------------------------------------------------
// Spec strings, scene directories, the CLI

TEST(SceneSpecString, ParsesFormatsAndRejects) {
  const SceneSpec s = parse_scene_spec("arena=boxes,path=square,size=160x120,frames=200,seed=7,noise=2");
  EXPECT_EQ(s.arena, "boxes");
  EXPECT_EQ(s.path, "square");
  EXPECT_EQ(s.width, 160);
  EXPECT_EQ(s.height, 120);
  EXPECT_EQ(s.frames, 200);
  EXPECT_EQ(s.seed, 7u);
  EXPECT_DOUBLE_EQ(s.noise, 2);
  const SceneSpec t = parse_scene_spec("path=F36+R90+F11,start=1:2.5:-30,size=320x240,dir=right,light_step=5,uyvy=0");
  EXPECT_TRUE(t.has_start);
  EXPECT_DOUBLE_EQ(t.start.y_in, 2.5);
  EXPECT_DOUBLE_EQ(t.start.heading_deg, -30);
  EXPECT_FALSE(t.square_left);
  EXPECT_EQ(t.light_step, 5);
  EXPECT_FALSE(t.write_uyvy);
  EXPECT_EQ(format_scene_spec(parse_scene_spec(format_scene_spec(t))), format_scene_spec(t));
  EXPECT_EQ(parse_scene_spec(format_scene_spec(t)).path, "F36+R90+F11");
  EXPECT_NE(format_scene_spec(s), format_scene_spec(t));
  auto fails = [](const std::string &spec, const std::string &needle) {
    try {
      parse_scene_spec(spec);
    } catch (const InputError &e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted: " << spec;
  };
  fails("colour=red", "unknown key 'colour'");
  fails("size=160", "size");
  fails("size=160x0", "size");
  fails("size=abcx12", "size");
  fails("frames=-1", "frames");
  fails("frames=0", "frames");
  fails("noise=abc", "noise");
  fails("noise=-1", "noise");
  fails("path=circle", "circle");
  fails("seed=1,seed=2", "given twice");
  fails("seed=1,,noise=2", "stray comma");
  fails("noise", "not key=value");
  fails("size=161x120", "even width");
  fails("mover=yes", "mover");
  fails("start=1:2", "start");
  fails("uyvy=yes", "uyvy");
  fails("speed=0", "speed");
  EXPECT_NO_THROW(parse_scene_spec("size=161x120,uyvy=0"));
}

void expect_same_files(const std::string &a, const std::string &b) {
  std::vector<std::string> names;
  for (const auto &e : fs::directory_iterator(a)) names.push_back(e.path().filename().string());
  size_t nb = 0;
  for (const auto &e : fs::directory_iterator(b)) (void)e, ++nb;
  EXPECT_EQ(names.size(), nb);
  for (const auto &n : names) EXPECT_EQ(read_file(a + "/" + n), read_file(b + "/" + n)) << n;
}

TEST(SceneIo, WriteReadBackAndReproduce) {
  SceneSpec s = parse_scene_spec("path=F1+L6,size=64x48,noise=1.5,seed=3,rgb=1,mover=cross");
  s.arena = arena_path("boxes");
  const std::string dir = fresh_dir("io"), dir2 = fresh_dir("io2");
  write_scene(s, dir);
  write_scene(s, dir2);
  expect_same_files(dir, dir2);  // same spec, same bytes
  const SceneData d = read_scene(dir);
  ASSERT_EQ(d.frames, 5);  // 2 forward steps + 2 turn steps + the start frame
  EXPECT_TRUE(d.has_uyvy && d.has_flow && d.has_rgb);
  EXPECT_DOUBLE_EQ(d.camera.fx, 0.875 * 64);
  SceneGenerator g(d.spec, d.arena);
  for (int k = 0; k < d.frames; ++k) {
    const FrameTruth t = g.truth();
    EXPECT_NEAR(d.truth[k].pose.x_in, t.pose.x_in, 1e-6);
    EXPECT_NEAR(d.truth[k].pose.heading_deg, t.pose.heading_deg, 1e-6);
    EXPECT_EQ(d.truth[k].left_ticks, t.left_ticks);
    const RenderResult r = g.render();
    EXPECT_EQ(d.grey(k).data, r.grey.data) << k;
    EXPECT_EQ(d.uyvy(k), r.uyvy) << k;
    EXPECT_EQ(d.rgb(k).data, r.rgb.data) << k;
    const ColumnTruth c = g.columns();
    for (int x = 0; x < 64; ++x) {
      EXPECT_EQ(d.columns[k].boundary_row[x], c.boundary_row[x]);
      if (std::isinf(c.distance_in[x])) {
        EXPECT_TRUE(std::isinf(d.columns[k].distance_in[x]));
      } else {
        EXPECT_NEAR(d.columns[k].distance_in[x], c.distance_in[x], 1e-4);
      }
    }
    if (k + 1 < d.frames) {
      const FlowField f = d.flow(k);
      EXPECT_EQ(f.width, 64);
      g.advance();
    }
  }
  EXPECT_NEAR(d.truth[4].pose.heading_deg, 6, 1e-9);
  EXPECT_NEAR(d.truth[2].pose.x_in, d.truth[0].pose.x_in + 1, 1e-6);
  // Another seed changes the noise.
  SceneSpec s3 = s;
  s3.seed = 4;
  const std::string dir3 = fresh_dir("io3");
  write_scene(s3, dir3);
  EXPECT_NE(read_file(dir + "/frame_0000.pgm"), read_file(dir3 + "/frame_0000.pgm"));
  // Existing output: refused unless replacing a scene.
  EXPECT_THROW(write_scene(s, dir), InputError);
  EXPECT_NO_THROW(write_scene(s, dir, true));
  const std::string other = fresh_dir("notascene");
  fs::create_directories(other);
  std::ofstream(other + "/precious.txt") << "keep";
  EXPECT_THROW(write_scene(s, other, true), InputError);
  EXPECT_TRUE(fs::exists(other + "/precious.txt"));
  // No temporary directory of this process is left behind (one of a run that was killed,
  // another pid, is not this run's doing).
  const std::string mine = ".tmp." + std::to_string(getpid());
  for (const auto &e : fs::directory_iterator(fs::path(dir).parent_path())) {
    const std::string n = e.path().filename().string();
    if (n.rfind("scene_test_io", 0) == 0) {
      EXPECT_EQ(n.find(mine), std::string::npos) << n;
    }
  }
}

TEST(SceneIo, MalformedDirectoriesAreInputErrors) {
  SceneSpec s = parse_scene_spec("path=F1,size=32x24,flow=0,uyvy=0");
  s.arena = arena_path("boxes");
  const std::string dir = fresh_dir("bad");
  write_scene(s, dir);
  ASSERT_NO_THROW(read_scene(dir));
  auto edit = [&](const std::string &file, const std::string &from, const std::string &to) {
    auto b = read_file(dir + "/" + file);
    std::string t(b.begin(), b.end());
    const auto pos = t.find(from);
    ASSERT_NE(pos, std::string::npos) << from;
    t.replace(pos, from.size(), to);
    write_file_atomic(dir + "/" + file, t.data(), t.size());
  };
  auto fails = [&](const std::string &needle) {
    try {
      read_scene(dir);
    } catch (const InputError &e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted a broken scene (" << needle << ")";
  };
  const auto truth = read_file(dir + "/truth.csv");
  edit("truth.csv", "\n1,", "\n1,abc");
  fails("truth.csv:3:");
  write_file_atomic(dir + "/truth.csv", truth);
  const auto cols = read_file(dir + "/columns.csv");
  edit("columns.csv", "\n0,5,", "\n0,6,");
  fails("columns.csv:7:");
  write_file_atomic(dir + "/columns.csv", cols);
  const auto scene = read_file(dir + "/scene.txt");
  edit("scene.txt", "frames = 3", "frames = 4");
  fails("scene.txt");
  write_file_atomic(dir + "/scene.txt", scene);
  edit("scene.txt", "format = ", "colour = x\nformat = ");
  fails("unknown key 'colour'");
  write_file_atomic(dir + "/scene.txt", scene);
  ASSERT_NO_THROW(read_scene(dir));
  fs::remove(dir + "/frame_0002.pgm");
  fails("frame_0002.pgm");
  EXPECT_THROW(read_scene(dir + "/nope"), InputError);
}

TEST(SceneCli, ExitCodes) {
  auto run = [](std::vector<std::string> args) {
    args.insert(args.begin(), "scene");
    std::vector<char *> argv;
    for (auto &a : args) argv.push_back(a.data());
    return scene_command(int(argv.size()), argv.data());
  };
  const std::string out = fresh_dir("cli");
  const std::string spec = "arena=" + arena_path("corridor") + ",path=F1,size=32x24,flow=0";
  EXPECT_EQ(run({"--help"}), 0);
  EXPECT_EQ(run({}), 2);
  EXPECT_EQ(run({"--bogus"}), 2);
  EXPECT_EQ(run({"--spec"}), 2);
  EXPECT_EQ(run({"--spec", spec}), 2);  // no --out
  EXPECT_EQ(run({"--spec", "frames=x", "--out", out}), 2);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(run({"--spec", spec, "--out", out}), 0);
  EXPECT_TRUE(fs::exists(out + "/truth.csv"));
  EXPECT_EQ(run({"--spec", spec, "--out", out}), 2);  // exists
  EXPECT_EQ(run({"--spec", spec, "--out", out, "--force"}), 0);
  EXPECT_EQ(run({"--check", out}), 0);
  EXPECT_EQ(run({"--check", out + "/missing"}), 2);
}

// The bundled scenes in frames/scenes/ must read back and be reproducible from their spec.
TEST(SceneIo, BundledScenesReproduce) {
  const fs::path root = fs::path(BVB_SOURCE_DIR) / "frames" / "scenes";
  int scenes = 0;
  for (const auto &e : fs::directory_iterator(root)) {
    if (!e.is_directory()) continue;
    ++scenes;
    const SceneData d = read_scene(e.path().string());
    SceneGenerator g(d.spec, d.arena);
    EXPECT_EQ(g.render().grey.data, d.grey(0).data) << e.path();
    for (int k = 1; k < d.frames; ++k) g.advance();
    EXPECT_EQ(g.render().grey.data, d.grey(d.frames - 1).data) << e.path();
    EXPECT_NEAR(g.pose().x_in, d.truth.back().pose.x_in, 1e-5) << e.path();
  }
  EXPECT_GE(scenes, 2);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// What a spec may say, and what --force may delete

namespace {

// Each key class has a range that says what a scene can mean: inside it parses, just outside
// it is refused naming the key and the range.
void expect_refused(const std::string &spec, const std::string &key) {
  try {
    parse_scene_spec(spec);
  } catch (const InputError &e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("scene spec: " + key + ":"), std::string::npos) << spec << ": " << m;
    EXPECT_NE(m.find("out of range"), std::string::npos) << spec << ": " << m;
    return;
  }
  ADD_FAILURE() << "accepted: " << spec;
}

TEST(SceneSpecRanges, PathLengthsAndSides) {
  EXPECT_DOUBLE_EQ(parse_scene_spec("length=1000").length_in, 1000);
  EXPECT_DOUBLE_EQ(parse_scene_spec("length=-1000").length_in, -1000);
  expect_refused("length=-100000", "length");
  expect_refused("length=1001", "length");
  expect_refused("side=1001", "side");
  expect_refused("block_dist=1e5", "block_dist");
}

TEST(SceneSpecRanges, Angles) {
  EXPECT_DOUBLE_EQ(parse_scene_spec("angle=-3600").angle_deg, -3600);
  expect_refused("angle=-100000", "angle");
  expect_refused("turn_rate=91", "turn_rate");
  expect_refused("tilt=85", "tilt");
}

TEST(SceneSpecRanges, CameraIntrinsicsAndMounting) {
  // fx as a multiple of the width, whichever key comes first.
  EXPECT_DOUBLE_EQ(parse_scene_spec("fx=140,size=160x120").fx, 140);
  EXPECT_DOUBLE_EQ(parse_scene_spec("size=320x240,fx=6400").fx, 6400);
  expect_refused("fx=1", "fx");
  expect_refused("fx=1,size=160x120", "fx");
  expect_refused("size=160x120,fx=3201", "fx");
  EXPECT_DOUBLE_EQ(parse_scene_spec("cam_height=36").cam_height_in, 36);
  expect_refused("cam_height=1000", "cam_height");
  expect_refused("cam_height=0.1", "cam_height");
  expect_refused("cam_offset=50", "cam_offset");
}

TEST(SceneSpecRanges, StartPose) {
  const SceneSpec s = parse_scene_spec("start=-1000:1000:-360");
  EXPECT_DOUBLE_EQ(s.start.x_in, -1000);
  EXPECT_DOUBLE_EQ(s.start.heading_deg, -360);
  expect_refused("start=1e6:1e6:1e6", "start");
  expect_refused("start=0:0:361", "start");
  expect_refused("start=0:1001:0", "start");
}

TEST(SceneSpecRanges, RobotMotionAndEncoders) {
  expect_refused("speed=100", "speed");
  expect_refused("radius=1000", "radius");
  expect_refused("wheelbase=1000", "wheelbase");
  expect_refused("tpi=0.01", "tpi");
  expect_refused("enc_noise=1000", "enc_noise");
  EXPECT_DOUBLE_EQ(parse_scene_spec("speed=12,radius=60,wheelbase=60,tpi=10000").tpi, 10000);
}

TEST(SceneSpecRanges, WholeNumbersAndLight) {
  expect_refused("ss=9", "ss");
  expect_refused("flicker_period=1", "flicker_period");
  expect_refused("flicker=1", "flicker");
  expect_refused("step_gain=11", "step_gain");
  expect_refused("seed=1000000000000000000", "seed");
  expect_refused("texture_seed=1000000000000000000", "texture_seed");
  expect_refused("frames=100001", "frames");
}

// Every key says what it accepts, for --help: the documentation and the check are one table.
TEST(SceneSpecRanges, EveryKeyIsDocumented) {
  const std::string doc = scene_spec_ranges();
  const std::string all = format_scene_spec(SceneSpec{});
  size_t keys = 0;
  for (size_t pos = 0; pos < all.size();) {
    const size_t eq = all.find('=', pos), comma = all.find(',', pos);
    const std::string key = all.substr(pos, eq - pos);
    EXPECT_NE(doc.find("  " + key + ": "), std::string::npos) << key << " has no documented range";
    ++keys;
    pos = comma == std::string::npos ? all.size() : comma + 1;
  }
  EXPECT_EQ(keys, 34u);
  EXPECT_NE(doc.find("  length: -1000..1000 in"), std::string::npos) << doc;
}

// The writer accepts no texture seed its reader cannot take back: the largest one round-trips
// through arena.txt and scene.txt, a larger one is refused before anything is written.
TEST(SceneIo, LargestTextureSeedReadsBack) {
  const std::string out = fresh_dir("big_seed");
  SceneSpec s = parse_scene_spec("arena=" + arena_path("corridor") +
                                 ",path=F1,size=32x24,flow=0,uyvy=0,texture_seed=999999999999999999");
  write_scene(s, out);
  const SceneData d = read_scene(out);
  EXPECT_EQ(d.arena.texture_seed, 999999999999999999ull);
  EXPECT_EQ(d.spec.texture_seed, 999999999999999999ull);
  const World w = parse_arena("start 0 0 0\ntexture_seed 999999999999999999\n", "t.txt");
  EXPECT_EQ(w.texture_seed, 999999999999999999ull);
  EXPECT_THROW(parse_arena("start 0 0 0\ntexture_seed 1000000000000000000\n", "t.txt"), InputError);
  EXPECT_THROW(parse_arena("start 0 0 0\ntexture_seed 1e3\n", "t.txt"), InputError);

  const std::string refused = fresh_dir("too_big_seed");
  const std::string parent = fs::path(refused).parent_path().string();
  char a0[] = "scene", a1[] = "--spec", a3[] = "--out";
  std::string spec = "path=F1,size=32x24,texture_seed=1000000000000000000";
  std::vector<char *> argv = {a0, a1, spec.data(), a3, const_cast<char *>(refused.c_str())};
  EXPECT_EQ(scene_command(int(argv.size()), argv.data()), 2);
  EXPECT_FALSE(fs::exists(refused));
  for (const auto &e : fs::directory_iterator(parent))
    EXPECT_EQ(e.path().filename().string().find("scene_test_too_big_seed.tmp"), std::string::npos)
        << e.path() << " left behind";
}

// --force replaces a scene; a directory that holds anything a scene does not write is refused
// and left as it was (it used to be deleted whole when it held a scene.txt).
TEST(SceneIo, ForceReplacesOnlyWhatASceneWrites) {
  const std::string out = fresh_dir("force");
  const std::string spec_text = "arena=" + arena_path("corridor") + ",path=F1,size=32x24,flow=0";
  write_scene(parse_scene_spec(spec_text), out);
  write_scene(parse_scene_spec(spec_text + ",rgb=1"), out, true);  // a scene over a scene
  EXPECT_TRUE(fs::exists(out + "/frame_0000.ppm"));

  std::ofstream(out + "/notes.txt") << "mine";
  try {
    write_scene(parse_scene_spec(spec_text), out, true);
    ADD_FAILURE() << "replaced a directory holding notes.txt";
  } catch (const InputError &e) {
    EXPECT_NE(std::string(e.what()).find("'notes.txt'"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(out + "/notes.txt"));
  EXPECT_TRUE(fs::exists(out + "/frame_0000.ppm")) << "the old scene was touched";
  fs::remove(out + "/notes.txt");

  fs::create_directory(out + "/keep");
  std::ofstream(out + "/keep/data.bin") << "mine";
  EXPECT_THROW(write_scene(parse_scene_spec(spec_text), out, true), InputError);
  EXPECT_TRUE(fs::exists(out + "/keep/data.bin"));
  fs::remove_all(out + "/keep");

  // A file named like a frame but not one (frame_12.pgm: fewer than 4 digits) is not the scene's.
  std::ofstream(out + "/frame_12.pgm") << "P5";
  EXPECT_THROW(write_scene(parse_scene_spec(spec_text), out, true), InputError);
  fs::remove(out + "/frame_12.pgm");
  write_scene(parse_scene_spec(spec_text), out, true);
  EXPECT_FALSE(fs::exists(out + "/frame_0000.ppm")) << "the old scene's files stayed";
}

}  // namespace

// Found by the arena fuzz target: every texture_seed an arena named kept its ~6 MB texture for
// the life of the process (past 2 GB). Textures of seeds no longer used must be released; a
// seed in use is still shared.
TEST(SceneTexture, CacheKeepsOnlyRecentSeeds) {
  std::vector<std::weak_ptr<const Texture>> made;
  for (uint64_t s = 0; s < kTextureCacheSeeds + 4; ++s) made.push_back(make_texture(7770000 + s));
  size_t alive = 0;
  for (const auto &w : made) alive += !w.expired();
  EXPECT_EQ(alive, kTextureCacheSeeds) << "textures of " << made.size() << " seeds made, none held";
  EXPECT_TRUE(made.front().expired()) << "the least recently used seed is the one dropped";
  const auto a = make_texture(7770000 + kTextureCacheSeeds + 3), b = make_texture(7770000 + kTextureCacheSeeds + 3);
  EXPECT_EQ(a.get(), b.get()) << "a cached seed is built once and shared";
}
