// Each check case draws from a stream of its own, derived from (seed, family, case number), and
// -k filters when queueing, not when generating: so the case a failure names (its id and seed)
// is the same call under any -k, and --case ID re-runs exactly that call. Host-only: calls are
// generated, not run.
#include <gtest/gtest.h>

#include "generate.h"
#include "patterns.h"

namespace bvb {
namespace {

using testing_gen::generate;
using testing_gen::generation_target;

CheckOptions options(uint32_t seed) {
  CheckOptions o;
  o.seed = seed;
  o.frames_real = default_frames_real();
  return o;
}

// The probe: with -k one kernel of a family, 9 of 12 families built other inputs under the same
// case names, so the printed replay command did not replay.
TEST(CaseStreams, EveryCaseIsTheSameCallUnderAnyKernelFilter) {
  const Target t = generation_target();
  for (const Family *f : families()) {
    const auto all = generate(*f, options(11), t);
    ASSERT_FALSE(all.empty()) << f->name;
    for (const auto &k : f->kernels) {
      CheckOptions o = options(11);
      o.kernel_glob = k;
      const auto some = generate(*f, o, t);
      EXPECT_FALSE(some.empty()) << f->name << " -k " << k;
      for (const auto &kv : some) {
        auto it = all.find(kv.first);
        ASSERT_NE(it, all.end()) << f->name << " -k " << k << ": case " << kv.first << " only under -k";
        EXPECT_TRUE(it->second == kv.second) << f->name << " -k " << k << ": case " << kv.first
                                             << " is another call than under -k '*'";
      }
      size_t of_k = 0;
      for (const auto &kv : all) of_k += kv.first.compare(0, k.size() + 1, k + ":") == 0;
      EXPECT_EQ(some.size(), of_k) << f->name << " -k " << k;
    }
  }
}

TEST(CaseStreams, OnlyCaseQueuesExactlyThatCall) {
  const Target t = generation_target();
  for (const Family *f : families()) {
    const auto all = generate(*f, options(3), t);
    // The first, a middle and the last case of each family.
    std::vector<std::string> ids;
    for (const auto &kv : all) ids.push_back(kv.first);
    for (const std::string &id : {ids.front(), ids[ids.size() / 2], ids.back()}) {
      CheckOptions o = options(3);
      o.only_case = id;
      const auto one = generate(*f, o, t);
      ASSERT_EQ(one.size(), 1u) << f->name << " --case " << id;
      EXPECT_EQ(one.begin()->first, id);
      EXPECT_TRUE(one.begin()->second == all.at(id)) << f->name << " --case " << id << " is another call";
    }
  }
}

TEST(CaseStreams, SeedsAndFamiliesGiveDifferentStreams) {
  const Target t = generation_target();
  const Family *f = family_of("add_sat_u8");
  ASSERT_NE(f, nullptr);
  const auto a = generate(*f, options(1), t), b = generate(*f, options(2), t), a2 = generate(*f, options(1), t);
  EXPECT_TRUE(a == a2) << "the same seed must give the same calls";
  size_t same = 0;
  for (const auto &kv : a) same += b.count(kv.first) && b.at(kv.first) == kv.second;
  EXPECT_LT(same, a.size() / 10) << "seeds 1 and 2 give mostly the same calls";
}

TEST(CaseStreams, ReplayCommandNamesTheCase) {
  Failure f;
  f.kernel = "sobel3x3_u8";
  f.seed = 42;
  f.case_id = "sobel3x3_u8:17";
  EXPECT_EQ(replay_command(f), "bfbench check --seed 42 --case sobel3x3_u8:17");
}

}  // namespace
}  // namespace bvb
