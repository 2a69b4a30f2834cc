// The visual odometry pipeline (firmware/c/pipe_odometry.c, bvb/pipe_odometry.h; registry entry
// pipe_odometry, bfbench pipeline odometry) as the harness
// sees it: its parameters, one frame's call, and its accuracy against the ground truth split
// into the path's turns and straight legs.
#pragma once

#include <string>
#include <vector>

#include "bvb/pipe_odometry.h"
#include "family.h"
#include "session/runner.h"

namespace bvb {

// The pipeline's parameters for a camera, from --param keys (defaults in odometry.cpp; every
// key is read so that Params::check_all_used can reject unknown ones).
bvb_odo_params odometry_params(const Camera &cam, Params &params, const Pose &start);

// One frame's call of pipe_odometry: frame (rows of `stride` bytes), info, params, state
// (persistent in a pipeline run; empty: a fresh one), result, work; the host reference runs
// bvb_pipe_odometry_c on the same buffers.
CheckCall odometry_call(const Image &grey, int stride, const bvb_pipe_frame &info, const bvb_odo_params &p,
                        std::vector<uint8_t> state, bool persistent, const std::string &name);
constexpr int kOdoStateBuf = 3, kOdoResultBuf = 4;

// A turn or a straight leg of the true path: frames [first, last], first the frame before the
// segment's first step.
struct OdoSegment {
  bool turn = false;
  int first = 0, last = 0;
  double true_value = 0;  // degrees turned (left positive), or inches driven
  double est_value = 0;
  double error = 0;       // turns: est - true, degrees; legs: (est - true) / true, percent
};
std::vector<OdoSegment> odometry_segments(const std::vector<FrameRecord> &frames);

}  // namespace bvb
