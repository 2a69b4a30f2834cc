// Every kernel's bench call at the smallest sizes its rule allows: the call is built and the host
// C reference runs on it (under the sanitize preset, a read past a buffer fails here), and the
// sizes just below are refused.
#include <gtest/gtest.h>

#include <stdexcept>

#include "check.h"
#include "family.h"

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

}  // namespace
}  // namespace bvb
