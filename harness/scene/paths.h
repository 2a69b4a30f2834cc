// The robot's motion: differential-drive pose steps, scripted paths, and the wheel encoders.
// Units and axes: camera.h (inches, degrees, heading counter-clockwise, left turns positive).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "camera.h"

namespace bvb {

// One frame's motion: forward_in along the path while the heading changes by turn_deg.
struct Step {
  double forward_in = 0, turn_deg = 0;
};

// Differential drive with constant wheel speeds over the step: a circular arc of length
// forward_in turning by turn_deg (a straight line when turn_deg is 0, a turn in place about the
// axle centre when forward_in is 0). Exact, so a scripted square closes to rounding error.
Pose step_pose(const Pose &p, double forward_in, double turn_deg);

// Path scripts: tokens joined by '+':
//   F<in>  forward     B<in>  backward     L<deg>  turn left in place     R<deg>  turn right
//   S<n>   stand still for n frames
// e.g. "F36+R90+F11". A move is cut into steps of speed_in (turns: turn_rate_deg) per frame,
// the last step of a move taking the remainder. Bad scripts throw InputError.
std::vector<Step> expand_script(const std::string &script, double speed_in, double turn_rate_deg);

// The named paths as scripts:
//   straight  F<length>                       turn   L<angle> (R for a negative angle)
//   square    4 x (F<side> + L90), or R90 with dir = right: the seed paper's Figure 8 square
//   odo_a     F36+R90+F11                     odo_b  F36+L90+F9.5   (the seed's odometry tests)
// Anything else that parses as a script is returned as it is; otherwise InputError.
std::string path_script(const std::string &name, double length_in, double angle_deg,
                        double side_in, bool square_left);

// Wheel encoders. Wheel travel over a step: left = forward - turn_rad * wheelbase / 2, right =
// forward + turn_rad * wheelbase / 2. Each wheel's count advances by its travel *
// ticks_per_inch * (1 + slip * |g1|) + noise_ticks * g2 (g1, g2 ~ N(0, 1), seeded per frame and
// wheel): slip only ever over-counts, as a spinning wheel does. Reported ticks are the cumulative
// count rounded half up (floor(count + 0.5)), so quantisation does not accumulate.
struct EncoderModel {
  double ticks_per_inch = 50;
  double wheelbase_in = 4.0;  // between the left and right wheel (track) centre lines
  double slip = 0;
  double noise_ticks = 0;
};

struct Encoders {
  double left_count = 0, right_count = 0;  // cumulative, in ticks, before rounding
  int64_t left_ticks() const;
  int64_t right_ticks() const;
};

void encoders_step(Encoders &e, const EncoderModel &m, const Step &step, uint64_t seed);

// Dead reckoning from tick increments (the inverse of the above without slip or noise).
Pose odometry_step(const Pose &p, int64_t dleft_ticks, int64_t dright_ticks, const EncoderModel &m);

}  // namespace bvb
