// Accuracy of the fixed-point Horn-Schunck kernel (bvb_hornschunck_c) on the ground-truth
// sequences of frames-real: distance to the double-precision flow with the same definitions, and
// EPE / angular error of both against the ground truth.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "flow_metrics.h"

namespace bvb {

struct HsSequence {
  std::string name;    // directory under frames-real
  std::string frame1;  // file names in it
  std::string frame2;
  std::string truth;
};

// RubberWhale, Hydrangea, Dimetrodon, Grove2, Urban2 (frame10 -> frame11, flow10.flo) and
// Yosemite (yos9 -> yos10, flow9.flo).
const std::vector<HsSequence> &hs_ground_truth_sequences();

struct HsAccuracyRow {
  std::string sequence;
  int width = 0;
  int height = 0;
  FlowDistance fixed_vs_double;  // endpoint distance over all pixels
  FlowErrors fixed;              // against the ground truth, unknown pixels masked
  FlowErrors dbl;
};

// One row per sequence, in the order of hs_ground_truth_sequences(), or only the named ones.
// alpha2_q4 = 16 alpha^2 within the kernel's legal range; iterations >= 0. Bad parameters,
// unknown names or unreadable files throw InputError.
std::vector<HsAccuracyRow> hs_accuracy_table(const std::string &frames_real_dir, int32_t alpha2_q4,
                                             int iterations,
                                             const std::vector<std::string> &only = {});

// The rows as a fixed-width text table with a header line naming alpha and N.
std::string format_hs_accuracy_table(const std::vector<HsAccuracyRow> &rows, int32_t alpha2_q4,
                                     int iterations);

}  // namespace bvb
