#include "hs_accuracy.h"

#include <cmath>
#include <cstdio>

#include "bvb/hornschunck.h"
#include "hs_double.h"
#include "io.h"
#include "names.h"

namespace bvb {

const std::vector<HsSequence> &hs_ground_truth_sequences() {
  static const std::vector<HsSequence> seqs = {
      {"RubberWhale", "frame10.pgm", "frame11.pgm", "flow10.flo"},
      {"Hydrangea", "frame10.pgm", "frame11.pgm", "flow10.flo"},
      {"Dimetrodon", "frame10.pgm", "frame11.pgm", "flow10.flo"},
      {"Grove2", "frame10.pgm", "frame11.pgm", "flow10.flo"},
      {"Urban2", "frame10.pgm", "frame11.pgm", "flow10.flo"},
      {"Yosemite", "yos9.pgm", "yos10.pgm", "flow9.flo"},
  };
  return seqs;
}

std::vector<HsAccuracyRow> hs_accuracy_table(const std::string &dir, int32_t alpha2_q4,
                                             int iterations, const std::vector<std::string> &only) {
  if (alpha2_q4 < BVB_HS_ALPHA2_Q4_MIN || alpha2_q4 > BVB_HS_ALPHA2_Q4_MAX)
    throw InputError("Horn-Schunck: alpha2_q4 " + std::to_string(alpha2_q4) + " outside " +
                     std::to_string(BVB_HS_ALPHA2_Q4_MIN) + ".." +
                     std::to_string(BVB_HS_ALPHA2_Q4_MAX) + " (alpha 8..256)");
  if (iterations < 0) throw InputError("Horn-Schunck: negative iteration count");
  for (const std::string &name : only) {
    bool known = false;
    for (const HsSequence &s : hs_ground_truth_sequences()) known = known || s.name == name;
    if (!known) throw InputError("Horn-Schunck accuracy: unknown sequence '" + name + "'");
  }
  const double alpha = std::sqrt(alpha2_q4 / 16.0);

  std::vector<HsAccuracyRow> rows;
  for (const HsSequence &s : hs_ground_truth_sequences()) {
    if (!only.empty()) {
      bool wanted = false;
      for (const std::string &name : only) wanted = wanted || name == s.name;
      if (!wanted) continue;
    }
    const std::string base = dir + "/" + s.name + "/";
    const Image f1 = read_pnm(base + s.frame1), f2 = read_pnm(base + s.frame2);
    const FlowField truth = read_flo(base + s.truth);
    if (f1.channels != 1 || f2.channels != 1 || f1.width != f2.width || f1.height != f2.height ||
        truth.width != f1.width || truth.height != f1.height)
      throw InputError(base + ": frames and ground truth do not match (grey, same size)");
    const int w = f1.width, h = f1.height;
    if (w < BVB_HS_MIN_DIM || h < BVB_HS_MIN_DIM) throw InputError(base + ": frames too small");

    std::vector<uint32_t> scratch((BVB_HS_SCRATCH_BYTES(w, h) + 3) / 4);
    std::vector<uint32_t> flow_scratch((BVB_HS_FLOW_SCRATCH_BYTES(w) + 3) / 4);
    std::vector<uint32_t> coef_scratch((BVB_HS_ITER_COEF_SCRATCH_BYTES(w) + 3) / 4);
    std::vector<int16_t> uv(size_t(2) * w * h);
    bvb_hornschunck_c(f1.data.data(), f2.data.data(), w, h, w, alpha2_q4, iterations, uv.data(),
                      4 * w, scratch.data(), flow_scratch.data(), coef_scratch.data());
    const FlowField fixed = flow_from_fixed(uv.data(), w, h, 4 * w, BVB_HS_UV_FRAC_BITS);
    const FlowField dbl = hs_flow_double(f1, f2, alpha, iterations);

    HsAccuracyRow row;
    row.sequence = s.name;
    row.width = w;
    row.height = h;
    row.fixed_vs_double = flow_distance(fixed, dbl);
    row.fixed = flow_errors(fixed, truth);
    row.dbl = flow_errors(dbl, truth);
    // Averages over no pixel would print as a perfect 0.0000.
    if (row.fixed.valid == 0)
      throw InputError(base + s.truth + ": no pixel has a known ground-truth vector (EPE and AE undefined)");
    rows.push_back(row);
  }
  return rows;
}

std::string format_hs_accuracy_table(const std::vector<HsAccuracyRow> &rows, int32_t alpha2_q4,
                                     int iterations) {
  char line[256];
  std::snprintf(line, sizeof line,
                "Horn-Schunck, alpha %.4g (alpha2_q4 %d), %d iterations; fixed = Q9 C reference, "
                "double = same definitions in double\n",
                std::sqrt(alpha2_q4 / 16.0), int(alpha2_q4), iterations);
  std::string out = line;
  std::snprintf(line, sizeof line, "%-12s %9s %10s %10s %9s %9s %9s %9s\n", "sequence", "size",
                "fix-dbl", "fix-dbl", "EPE", "EPE", "AE deg", "AE deg");
  out += line;
  std::snprintf(line, sizeof line, "%-12s %9s %10s %10s %9s %9s %9s %9s\n", "", "", "mean px",
                "max px", "fixed", "double", "fixed", "double");
  out += line;
  for (const HsAccuracyRow &r : rows) {
    const std::string size = size_name(r.width, r.height);
    std::snprintf(line, sizeof line, "%-12s %9s %10.5f %10.4f %9.4f %9.4f %9.3f %9.3f\n",
                  r.sequence.c_str(), size.c_str(), r.fixed_vs_double.mean, r.fixed_vs_double.max,
                  r.fixed.epe, r.dbl.epe, r.fixed.ae, r.dbl.ae);
    out += line;
  }
  return out;
}

}  // namespace bvb
