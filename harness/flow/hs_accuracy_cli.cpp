#include "hs_accuracy_cli.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "bvb/hornschunck.h"
#include "hs_accuracy.h"
#include "io.h"
#include "patterns.h"
#include "simdriver.h"

namespace bvb {

namespace {

const char *kUsage =
    "usage: hs-accuracy [--alpha A] [--iterations N] [--sequence NAME]... [--frames DIR]\n"
    "       hs-accuracy --help\n"
    "Runs the fixed-point Horn-Schunck C reference (bvb_hornschunck_c) and its double-precision\n"
    "twin (same definitions) on every frames-real sequence with ground-truth flow and prints,\n"
    "per sequence: the mean and largest endpoint distance between the two flows (all pixels), and\n"
    "the average endpoint error (EPE, pixels) and angular error (AE, degrees) of each against the\n"
    "ground truth (pixels of unknown truth left out).\n"
    "  --alpha A        smoothness weight in grey levels, 8..256 (default 8); the kernels take\n"
    "                   alpha2_q4 = 16 A^2, rounded to an integer\n"
    "  --iterations N   Jacobi iterations from zero flow, 0..100000 (default 10)\n"
    "  --sequence NAME  only this sequence (repeatable): RubberWhale Hydrangea Dimetrodon Grove2\n"
    "                   Urban2 Yosemite\n"
    "  --frames DIR     the frames-real directory (default $BFBENCH_FRAMES_REAL, else the\n"
    "                   build-time path)\n"
    "Exit status: 0 table printed, 2 bad usage or unreadable input.\n";

int usage_error(const std::string &msg) {
  std::fprintf(stderr, "hs-accuracy: %s (try --help)\n", sim::printable(msg, 2000).c_str());
  return 2;
}

// A finite number, whole string.
bool parse_double(const std::string &s, double *out) {
  if (s.empty()) return false;
  char *end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (*end || errno || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

bool parse_int(const std::string &s, long lo, long hi, long *out) {
  if (s.empty()) return false;
  char *end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (*end || errno || v < lo || v > hi) return false;
  *out = v;
  return true;
}

}  // namespace

int hs_accuracy_command(int argc, char **argv) {
  double alpha = 8;
  long iterations = 10;
  std::vector<std::string> only;
  std::string frames = default_frames_real();
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string &dst) {
      if (i + 1 >= argc) return false;
      dst = argv[++i];
      return true;
    };
    std::string v;
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--alpha") {
      if (!value(v) || !parse_double(v, &alpha) || alpha < 8 || alpha > 256)
        return usage_error("--alpha wants a number in 8..256");
    } else if (a == "--iterations") {
      if (!value(v) || !parse_int(v, 0, 100000, &iterations))
        return usage_error("--iterations wants an integer in 0..100000");
    } else if (a == "--sequence") {
      if (!value(v) || v.empty()) return usage_error("--sequence needs a name");
      only.push_back(v);
    } else if (a == "--frames") {
      if (!value(frames) || frames.empty()) return usage_error("--frames needs a directory");
    } else {
      return usage_error("unknown argument '" + a + "'");
    }
  }
  const int32_t alpha2_q4 = int32_t(std::lround(16 * alpha * alpha));
  try {
    const std::vector<HsAccuracyRow> rows = hs_accuracy_table(frames, alpha2_q4, int(iterations), only);
    std::fputs(format_hs_accuracy_table(rows, alpha2_q4, int(iterations)).c_str(), stdout);
    return 0;
  } catch (const InputError &e) {
    std::fprintf(stderr, "hs-accuracy: %s\n", sim::printable(e.what(), 2000).c_str());
    return 2;
  } catch (const std::exception &e) {
    // Exit 1 means a check failed; a fault of the program is reported as bfbench's main does.
    std::fprintf(stderr, "hs-accuracy: internal error: %s\n", sim::printable(e.what(), 2000).c_str());
    return 2;
  }
}

}  // namespace bvb
