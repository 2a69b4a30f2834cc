// Horn-Schunck optical flow in double precision, with exactly the definitions of the fixed-point
// kernel in firmware/include/bvb/hornschunck.h (derivatives over the 2x2x2 cube, 1/6 and 1/12
// neighbour weights, replicated borders, N Jacobi iterations from zero). It is the yardstick the
// fixed-point flow is measured against, so it shares no code with the C reference.
#pragma once

#include <cstdint>
#include <vector>

#include "image.h"

namespace bvb {

// Horn and Schunck's (1981) derivative estimates at pixel (x, y): each the average of four first
// differences over the cube (x..x+1, y..y+1, frames 1..2); columns/rows past the edge repeat the
// last one. Row-major, width * height values each.
struct HsDerivatives {
  int width = 0;
  int height = 0;
  std::vector<double> ex, ey, et;
};

HsDerivatives hs_derivatives_double(const Image &frame1, const Image &frame2);

// alpha: the smoothness weight in grey levels (alpha^2 is added to Ex^2 + Ey^2).
// iterations >= 0. Both frames must be grey and of the same size (InputError otherwise).
FlowField hs_flow_double(const Image &frame1, const Image &frame2, double alpha, int iterations);

}  // namespace bvb
