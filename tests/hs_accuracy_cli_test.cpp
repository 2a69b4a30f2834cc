// bfbench hs-accuracy: usage errors exit 2, --help exits 0, and the table's numbers for zero
// iterations (both flows are then exactly zero) match the ground truth's own statistics computed
// here from the .flo file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "flow/hs_accuracy_cli.h"
#include "frames.h"
#include "io.h"

namespace {

int run(std::vector<std::string> args, std::string *out = nullptr) {
  args.insert(args.begin(), "hs-accuracy");
  std::vector<char *> argv;
  for (auto &a : args) argv.push_back(&a[0]);
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int rc = bvb::hs_accuracy_command(int(argv.size()), argv.data());
  const std::string o = testing::internal::GetCapturedStdout();
  testing::internal::GetCapturedStderr();
  if (out) *out = o;
  return rc;
}

TEST(HsAccuracyCli, HelpAndUsageErrors) {
  std::string out;
  EXPECT_EQ(run({"--help"}, &out), 0);
  EXPECT_NE(out.find("usage: bfbench hs-accuracy"), std::string::npos);
  EXPECT_EQ(run({"--alpha", "7.9"}), 2);
  EXPECT_EQ(run({"--alpha", "257"}), 2);
  EXPECT_EQ(run({"--alpha", "eight"}), 2);
  EXPECT_EQ(run({"--alpha"}), 2);
  EXPECT_EQ(run({"--iterations", "-1"}), 2);
  EXPECT_EQ(run({"--iterations", "1.5"}), 2);
  EXPECT_EQ(run({"--bogus"}), 2);
  EXPECT_EQ(run({"--frames", BVB_FRAMES_REAL, "--sequence", "NoSuchSequence"}), 2);
  EXPECT_EQ(run({"--frames", "/nonexistent-frames-dir", "--sequence", "Yosemite"}), 2);
}

// With N = 0 the fixed and double flows are both zero, so their distance is 0, EPE is the mean
// length of the known ground-truth vectors and AE the mean of atan(|truth|) in degrees.
TEST(HsAccuracyCli, ZeroIterationsGiveTheGroundTruthStatistics) {
  const std::string dir = BVB_FRAMES_REAL;
  BVB_NEED_REAL_FRAMES(dir);
  const bvb::FlowField truth = bvb::read_flo(dir + "/Yosemite/flow9.flo");
  double sum_len = 0, sum_ang = 0;
  long n = 0;
  for (size_t p = 0; p < truth.u.size(); ++p) {
    if (bvb::FlowField::unknown(truth.u[p]) || bvb::FlowField::unknown(truth.v[p])) continue;
    const double len = std::hypot(double(truth.u[p]), double(truth.v[p]));
    sum_len += len;
    sum_ang += std::atan(len) * 180.0 / 3.14159265358979323846;
    ++n;
  }
  ASSERT_GT(n, 0);

  std::string out;
  ASSERT_EQ(run({"--frames", dir, "--sequence", "Yosemite", "--iterations", "0", "--alpha", "16"}, &out), 0);
  EXPECT_NE(out.find("alpha 16 (alpha2_q4 4096), 0 iterations"), std::string::npos) << out;
  std::istringstream lines(out);
  std::string line;
  bool found = false;
  while (std::getline(lines, line)) {
    char name[32], size[32];
    double mean, max, epe_f, epe_d, ae_f, ae_d;
    if (std::sscanf(line.c_str(), "%31s %31s %lf %lf %lf %lf %lf %lf", name, size, &mean, &max, &epe_f,
                    &epe_d, &ae_f, &ae_d) != 8)
      continue;
    found = true;
    EXPECT_STREQ(name, "Yosemite");
    EXPECT_STREQ(size, "316x252");
    EXPECT_EQ(mean, 0.0);
    EXPECT_EQ(max, 0.0);
    EXPECT_NEAR(epe_f, sum_len / n, 1e-4);
    EXPECT_NEAR(epe_d, sum_len / n, 1e-4);
    EXPECT_NEAR(ae_f, sum_ang / n, 1e-3);
    EXPECT_NEAR(ae_d, sum_ang / n, 1e-3);
  }
  EXPECT_TRUE(found) << out;
}

}  // namespace
