#include "hs_accuracy_cli.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bvb/hornschunck.h"
#include "hs_accuracy.h"
#include "io.h"
#include "options.h"
#include "patterns.h"
#include "simdriver.h"

namespace bvb {

namespace {

int hs_accuracy_main(int argc, char **argv) {
  double alpha = 8;
  long iterations = 10;
  std::vector<std::string> only;
  std::string frames = default_frames_real();
  CommandLine cl("hs-accuracy");
  cl.about("Runs the fixed-point Horn-Schunck C reference (bvb_hornschunck_c) and its double-precision\n"
           "twin (same definitions) on every frames-real sequence with ground-truth flow and prints,\n"
           "per sequence: the mean and largest endpoint distance between the two flows (all pixels), and\n"
           "the average endpoint error (EPE, pixels) and angular error (AE, degrees) of each against the\n"
           "ground truth (pixels of unknown truth left out).")
      .number("--alpha", "A", 8, 256, &alpha,
              "smoothness weight in grey levels (default 8); the kernels take alpha2_q4 = 16 A^2, rounded to an "
              "integer")
      .integer("--iterations", "N", 0, 100000, &iterations, "Jacobi iterations from zero flow (default 10)")
      .texts("--sequence", "NAME", &only,
             "only this sequence: RubberWhale Hydrangea Dimetrodon Grove2 Urban2 Yosemite")
      .text("--frames", "DIR", &frames, "the frames-real directory (default $BFBENCH_FRAMES_REAL, else the build-time path)")
      .exit_status("Exit status: 0 table printed, 2 bad usage or unreadable input.");
  if (!cl.parse(argc, argv)) return kExitOk;
  for (const auto &n : only)
    if (n.empty()) throw UsageError("--sequence needs a name");
  if (frames.empty()) throw UsageError("--frames needs a directory");
  const int32_t alpha2_q4 = int32_t(std::lround(16 * alpha * alpha));
  const std::vector<HsAccuracyRow> rows = hs_accuracy_table(frames, alpha2_q4, int(iterations), only);
  std::fputs(format_hs_accuracy_table(rows, alpha2_q4, int(iterations)).c_str(), stdout);
  return kExitOk;
}

}  // namespace

int hs_accuracy_command(int argc, char **argv) {
  return run_command("hs-accuracy", [&] { return hs_accuracy_main(argc, argv); });
}

}  // namespace bvb
