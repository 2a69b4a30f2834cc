// Every kernel's bench call at the smallest sizes its rule allows: the call is built and the host
// C reference runs on it (under the sanitize preset, a read past a buffer fails here), and the
// sizes just below are refused.
#include <gtest/gtest.h>

#include <stdexcept>

#include "check.h"
#include "family.h"
#include "io.h"

namespace bvb {
namespace {

TEST(Rng, EmptyRangeIsReportedNotDividedBy) {
  Rng rng(1);
  EXPECT_EQ(rng.uniform(3, 3), 3);
  EXPECT_THROW(rng.uniform(0, -1), std::logic_error);
  EXPECT_THROW(rng.uniform(5, 2), std::logic_error);
}

TEST(BenchSizes, EveryKernelRunsAtItsMinimumAndRefusesLess) {
  for (const Family *f : families()) {
    if (!f->bench_call) continue;
    for (const auto &k : f->kernels) {
      const SizeRule *r = bench_size_rule(k);
      ASSERT_NE(r, nullptr) << k << " has a bench call but no size rule (harness/lib/family.cpp)";
      const int step = r->even_width ? 2 : 1;
      for (int dw = 0; dw <= 2 * step; dw += step)
        for (int dh = 0; dh <= 2; ++dh) {
          const int w = r->min_w + dw, h = r->min_h + dh;
          EXPECT_EQ(bench_size_problem(k, w, h), "") << k;
          Rng rng(7);
          CheckCall c;
          ASSERT_NO_THROW(c = f->bench_call(k, w, h, rng)) << k << " " << w << "x" << h;
          if (c.kernel.empty()) continue;  // a size the kernel's bench skips
          std::vector<std::vector<uint8_t>> bufs;
          for (const auto &b : c.bufs) bufs.push_back(b.data);
          HostBuffers hb(bufs);
          ASSERT_NO_THROW(c.host(hb)) << k << " " << w << "x" << h;
          for (size_t b = 0; b < bufs.size(); ++b) EXPECT_EQ(bufs[b].size(), c.bufs[b].data.size()) << k;
        }
      if (r->min_w > 1) {
        EXPECT_NE(bench_size_problem(k, r->min_w - step, r->min_h), "") << k;
      }
      if (r->min_h > 1) {
        EXPECT_NE(bench_size_problem(k, r->min_w, r->min_h - 1), "") << k;
      }
      if (r->even_width) {
        EXPECT_NE(bench_size_problem(k, r->min_w + 1, r->min_h), "") << k;
      }
    }
  }
}

// A run's grid of points gets a cycle limit that covers its work: the C reference takes about
// 1,540 simulator cycles a candidate (289 candidates a point, 11x11 templates), so 64x64 points
// need some 1.8e9 cycles (under the bf537 model too), six times the default limit that
// reported them as a hang; the limit allows twice that.
TEST(RunPlans, NccCycleLimitScalesWithThePoints) {
  const std::string a = testing::TempDir() + "ncc_plan_a.pgm";
  Image img(160, 120);
  write_pnm(a, img);
  const Family *f = family_of("ncc_match");
  ASSERT_NE(f, nullptr);
  for (int n : {8, 64}) {
    RunRequest req;
    req.kernel = "ncc_match";
    req.inputs = {a, a};
    req.params.set("cols=" + std::to_string(n));
    req.params.set("rows=" + std::to_string(n));
    RunPlan p = f->plan_run(req);
    const uint32_t limit = p.call.cycle_limit ? p.call.cycle_limit : Target::kDefaultCycleLimit;
    EXPECT_GE(double(limit), 2.0 * 1540 * 289 * n * n) << n << "x" << n << " points";
  }
}

}  // namespace
}  // namespace bvb
