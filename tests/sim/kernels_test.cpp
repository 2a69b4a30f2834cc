// Every kernel family's checks (bfbench check) as tests: host C = Blackfin C = assembly on
// random, crafted and real frames, guard bands, ABI. One test per family and seed; under ctest
// each is its own process, and GoogleTest's sharding variables split them across machines.
#include <gtest/gtest.h>

#include <cstdio>

#include "check.h"
#include "family.h"
#include "patterns.h"
#include "target.h"

namespace bvb {
namespace {

struct Param {
  const Family *family;
  uint32_t seed;
};

void PrintTo(const Param &p, std::ostream *os) { *os << p.family->name << " seed " << p.seed; }

std::vector<Param> params() {
  std::vector<Param> p;
  for (const Family *f : families())
    for (uint32_t seed : {1u, 2u}) p.push_back({f, seed});
  return p;
}

class Kernels : public testing::TestWithParam<Param> {};

TEST_P(Kernels, BitExactAgainstReference) {
  const Param &p = GetParam();
  Target target(product_firmware(), default_simulator());
  CheckOptions o;
  o.seed = p.seed;
  o.frames_real = default_frames_real();
  Checker ck(target, o);
  ck.reseed(p.family->name);
  p.family->check(ck);
  ck.flush();
  size_t calls = 0;
  for (const auto &kv : ck.tally())
    for (const auto &it : kv.second) calls += it.second.calls;
  EXPECT_GT(calls, 0u) << "family " << p.family->name << " checked nothing";
  // Each of the family's kernels judged on every implementation (host, C, assembly).
  for (const auto &gap : ck.coverage_gaps())
    for (const auto &k : p.family->kernels)
      if (gap.compare(0, k.size() + 2, k + " (") == 0) ADD_FAILURE() << gap << ": no call judged";
  // Real-frame cases left out for want of the frames: said, and an error where they are required.
  if (!ck.skipped_real().empty()) {
    if (frames_required()) ADD_FAILURE() << frames_missing_message(o.frames_real);
    else std::printf("[ NOTE     ] %s: %s\n", p.family->name.c_str(), frames_missing_message(o.frames_real).c_str());
  }
  for (const auto &f : ck.failures())
    ADD_FAILURE() << f.kernel << " (" << f.impl << ") " << f.case_name << ", seed " << f.seed << ": "
                  << failure_kind_name(f.kind) << ": " << f.message << "\n  replay: " << replay_command(f);
}

INSTANTIATE_TEST_SUITE_P(Check, Kernels, testing::ValuesIn(params()),
                         [](const testing::TestParamInfo<Param> &i) {
                           return i.param.family->name + "_seed" + std::to_string(i.param.seed);
                         });

}  // namespace
}  // namespace bvb
