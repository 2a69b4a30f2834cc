// Flow-field error measures and the conversion of fixed-point kernel output to a FlowField.
#pragma once

#include <cstdint>

#include "image.h"

namespace bvb {

struct FlowErrors {
  double epe = 0;       // average endpoint error, pixels
  double ae = 0;        // average angular error (Barron et al. 1994), degrees
  long long valid = 0;  // pixels with known ground truth that were averaged
};

// EPE and Barron's angular error of `flow` against `truth`: the angle between the 3-D vectors
// (u, v, 1) and (u_gt, v_gt, 1). Pixels whose ground truth is unknown (|u| or |v| >= 1e9, NaN)
// are left out. Throws InputError if the sizes differ or `flow` has an unknown vector where the
// truth is known.
FlowErrors flow_errors(const FlowField &flow, const FlowField &truth);

// Mean and largest endpoint distance between two flow fields over all pixels (no masking).
struct FlowDistance {
  double mean = 0;
  double max = 0;
};
FlowDistance flow_distance(const FlowField &a, const FlowField &b);

// Interleaved (u, v) int16 pairs with `frac_bits` fractional bits (Q8 for the Horn-Schunck
// kernels), `stride_bytes` between rows, to a FlowField. Every Q8 value is exact in float.
FlowField flow_from_fixed(const int16_t *uv, int width, int height, int stride_bytes,
                          int frac_bits);

}  // namespace bvb
