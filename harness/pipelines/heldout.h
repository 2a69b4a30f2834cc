// bfbench heldout: the pipelines judged on scenes drawn afresh from a seed each run (arenas,
// floor textures, start poses, paths: scene/heldout.h), on rates rather than hand-picked
// cases: collisions per 1,000 closed-loop frames for the avoidance pipelines, percentiles of the
// final pose error over closed polygons for the odometry.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace bvb {

// The limits a held-out run is judged against (measured over many seeds: README, "Held-out
// scenes"). Rates, so that they hold for any number of runs.
struct HeldoutLimits {
  double seg_collisions_per_1000 = 0;
  double flow_collisions_per_1000 = 0;
  double min_forward_share = 0;       // an avoider that only turns never collides
  double odo_heading_p90_per_100in = 0;   // |final heading error| per 100 in driven, degrees
  double odo_position_p90_per_100in = 0;  // final position error per 100 in driven, inches
};
HeldoutLimits heldout_limits();

// The nearest-rank percentile (p in (0, 100]) of `v`: the smallest value with at least p% of
// the values at or below it. NaN for an empty set.
double nearest_rank(std::vector<double> v, double p);

// One avoidance pipeline's totals over its runs, and the verdict.
struct AvoidTally {
  int frames = 0, collisions = 0, forward = 0;
  double per_1000() const { return frames ? 1000.0 * collisions / frames : 0; }
  double forward_share() const { return frames ? double(forward) / frames : 0; }
};
bool avoid_passes(const AvoidTally &t, double max_per_1000, double min_forward_share);

// One odometry loop's outcome.
struct OdoLoop {
  double length_in = 0;
  double position_error_in = 0, heading_error_deg = 0;  // final pose, estimated - true
  double worst_turn_deg = 0, worst_leg_pct = 0;
  double heading_per_100in() const;
  double position_per_100in() const;
};
struct OdoVerdict {
  double heading_p50 = 0, heading_p90 = 0, position_p50 = 0, position_p90 = 0;  // per 100 in
  double position_in_p50 = 0, position_in_p90 = 0;
  bool pass = false;
};
OdoVerdict odometry_verdict(const std::vector<OdoLoop> &loops, const HeldoutLimits &lim);

int heldout_command(int argc, char **argv);

}  // namespace bvb
