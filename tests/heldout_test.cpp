// The held-out scenes (harness/scene/heldout.h) and the held-out verdicts
// (harness/pipelines/heldout.h): polygons that close within their limits, scenes that are a
// function of (seed, index) alone, scripted paths that never touch an obstacle, starts with
// room to move, and the percentile and rate rules at their edges.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "pipelines/heldout.h"
#include "scene/heldout.h"
#include "scene/paths.h"
#include "scene/scene_io.h"

namespace bvb {
namespace {

SceneSpec base_spec() { return parse_scene_spec("size=160x120,ss=1,uyvy=0,flow=0"); }

TEST(HeldoutPolygon, ClosesWithinItsLimitsForEverySeed) {
  std::set<size_t> sides;
  for (uint64_t seed = 0; seed < 2000; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const HeldoutPolygon p = heldout_polygon(seed);
    ASSERT_GE(p.legs_in.size(), 3u);
    ASSERT_LE(p.legs_in.size(), 8u);
    ASSERT_EQ(p.turns_deg.size(), p.legs_in.size());
    sides.insert(p.legs_in.size());
    double turned = 0;
    for (size_t i = 0; i < p.legs_in.size(); ++i) {
      EXPECT_GE(p.legs_in[i], 12.0);
      EXPECT_LE(p.legs_in[i], 36.0);
      EXPECT_GE(std::fabs(p.turns_deg[i]), 15.0);
      EXPECT_LE(std::fabs(p.turns_deg[i]), 165.0);
      EXPECT_EQ(p.turns_deg[i] > 0, p.turns_deg[0] > 0) << "a convex polygon turns one way";
      turned += p.turns_deg[i];
    }
    EXPECT_NEAR(std::fabs(turned), 360.0, 1e-6);
    // Driven as the scene drives it (steps of 0.5 in and 3 degrees): back at the start.
    Pose q{0, 0, 0};
    for (const Step &s : expand_script(p.script(), 0.5, 3)) q = step_pose(q, s.forward_in, s.turn_deg);
    EXPECT_LT(std::hypot(q.x_in, q.y_in), 0.05) << p.script();
    EXPECT_NEAR(std::fabs(q.heading_deg), 360.0, 1e-6);
  }
  EXPECT_EQ(sides.size(), 6u) << "every side count from 3 to 8 occurs";
}

TEST(HeldoutScenes, AFunctionOfSeedAndIndexAlone) {
  const SceneSpec b = base_spec();
  const HeldoutScene a = heldout_odometry_scene(77, 3, b), again = heldout_odometry_scene(77, 3, b);
  EXPECT_EQ(format_arena(a.arena), format_arena(again.arena));
  EXPECT_EQ(format_scene_spec(a.spec), format_scene_spec(again.spec));
  EXPECT_NE(format_arena(a.arena), format_arena(heldout_odometry_scene(77, 4, b).arena));
  EXPECT_NE(format_arena(a.arena), format_arena(heldout_odometry_scene(78, 3, b).arena));
  const HeldoutScene c = heldout_avoid_scene(77, 3, 500, b);
  EXPECT_EQ(format_arena(c.arena), format_arena(heldout_avoid_scene(77, 3, 500, b).arena));
  EXPECT_NE(format_arena(c.arena), format_arena(heldout_avoid_scene(77, 2, 500, b).arena));
  EXPECT_NE(a.arena.texture_seed, c.arena.texture_seed);
  // The arena file a replay reads gives the same world.
  EXPECT_EQ(format_arena(parse_arena(format_arena(a.arena), "saved")), format_arena(a.arena));
}

// The odometry's scripted path must never drive into an obstacle (the scene would render the
// inside of a box): every frame of 100 scenes collision-free, and there is something to see.
TEST(HeldoutScenes, OdometryPathsNeverTouchAnObstacle) {
  const SceneSpec b = base_spec();
  for (int k = 0; k < 100; ++k) {
    const HeldoutScene s = heldout_odometry_scene(12345, k, b);
    SCOPED_TRACE(s.describe());
    SceneGenerator gen(s.spec, s.arena);
    EXPECT_EQ(gen.script(), s.polygon.script());
    EXPECT_GT(s.arena.obstacles.size(), 4u) << "walls and at least one obstacle";
    for (int f = 0; f < gen.frames(); ++f) {
      ASSERT_FALSE(gen.truth().collision) << "frame " << f;
      if (f + 1 < gen.frames()) gen.advance();
    }
    const Pose &end = gen.pose();
    EXPECT_LT(std::hypot(end.x_in - s.spec.start.x_in, end.y_in - s.spec.start.y_in), 0.05);
  }
}

TEST(HeldoutScenes, AvoidanceStartsFreeInVariedRooms) {
  const SceneSpec b = base_spec();
  std::set<int> widths;
  int partitions = 0;
  for (int k = 0; k < 100; ++k) {
    const HeldoutScene s = heldout_avoid_scene(999, k, 500, b);
    SCOPED_TRACE(s.describe());
    EXPECT_EQ(s.spec.path, "avoid");
    EXPECT_EQ(s.spec.frames, 500);
    SceneGenerator gen(s.spec, s.arena);
    EXPECT_FALSE(gen.truth().collision);
    EXPECT_FALSE(collides(s.arena, s.spec.start, kRobotRadiusIn + 3));
    widths.insert(int(s.arena.obstacles[0].p[2]));
    partitions += s.describe().find("partition") != std::string::npos;
  }
  EXPECT_GT(widths.size(), 30u);
  EXPECT_GT(partitions, 20);
  EXPECT_LT(partitions, 60);
}

TEST(HeldoutVerdict, NearestRankPercentile) {
  EXPECT_TRUE(std::isnan(nearest_rank({}, 90)));
  EXPECT_EQ(nearest_rank({5}, 90), 5);
  // 10 values: the 90th percentile is the 9th smallest, the 50th the 5th.
  const std::vector<double> v = {10, 1, 9, 2, 8, 3, 7, 4, 6, 5};
  EXPECT_EQ(nearest_rank(v, 90), 9);
  EXPECT_EQ(nearest_rank(v, 50), 5);
  EXPECT_EQ(nearest_rank(v, 100), 10);
  EXPECT_EQ(nearest_rank({1, 2, 3, 4}, 90), 4);
}

TEST(HeldoutVerdict, AvoidanceRateAndProgress) {
  AvoidTally t;
  EXPECT_FALSE(avoid_passes(t, 10, 0.25)) << "no frames judged is no pass";
  t.frames = 2000;
  t.forward = 500;
  t.collisions = 20;  // 10.00 per 1,000
  EXPECT_TRUE(avoid_passes(t, 10, 0.25));
  t.collisions = 21;
  EXPECT_FALSE(avoid_passes(t, 10, 0.25));
  t.collisions = 0;
  t.forward = 499;  // one frame short of a quarter: a robot that mostly turns
  EXPECT_FALSE(avoid_passes(t, 10, 0.25));
}

TEST(HeldoutVerdict, OdometryPercentilesPer100Inches) {
  HeldoutLimits lim;
  lim.odo_heading_p90_per_100in = 2;
  lim.odo_position_p90_per_100in = 1;
  std::vector<OdoLoop> loops;
  for (int i = 0; i < 10; ++i) {
    OdoLoop l;
    l.length_in = 200;
    l.heading_error_deg = i % 2 ? -0.4 * i : 0.4 * i;  // |.| per 100 in: 0, 0.2 .. 1.8
    l.position_error_in = 0.2 * i;                     // per 100 in: 0 .. 0.9
    loops.push_back(l);
  }
  OdoVerdict v = odometry_verdict(loops, lim);
  EXPECT_NEAR(v.heading_p90, 1.6, 1e-9);
  EXPECT_NEAR(v.position_p90, 0.8, 1e-9);
  EXPECT_NEAR(v.position_in_p90, 1.6, 1e-9);
  EXPECT_TRUE(v.pass);
  // One loop far off is the tenth value: the 90th percentile ignores it, two do not.
  loops[0].heading_error_deg = -30;
  EXPECT_TRUE(odometry_verdict(loops, lim).pass);
  loops[1].heading_error_deg = 30;
  v = odometry_verdict(loops, lim);
  EXPECT_NEAR(v.heading_p90, 15, 1e-9);
  EXPECT_FALSE(v.pass);
  EXPECT_FALSE(odometry_verdict({}, lim).pass);
}

}  // namespace
}  // namespace bvb
