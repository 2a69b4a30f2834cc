// Coverage of the gate: every kernel of the registry (firmware/kernels.def) has a family, its
// family's check queues calls for it, every assembly kernel has a bench call and budget rows,
// and the checks that judge nothing say so. Host-only: calls are generated, not run.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "bench.h"
#include "generate.h"
#include "patterns.h"

namespace bvb {
namespace {

using testing_gen::generate;
using testing_gen::generation_target;

TEST(Coverage, EveryRegistryKernelHasAFamilyAndEveryFamilyKernelIsRegistered) {
  for (const auto &k : Registry::product().kernels())
    EXPECT_NE(family_of(k.name), nullptr) << k.name << " (kernels.def) has no family in harness/checks";
  for (const Family *f : families())
    for (const auto &k : f->kernels)
      EXPECT_NE(Registry::product().find(k), nullptr) << "family " << f->name << " names " << k
                                                      << ", which kernels.def does not";
}

// With and without the real frames: each kernel gets calls either way (the real-frame cases are
// left out, with a note, when the frames are not there), and nothing is generated from frames
// that are missing.
void expect_every_kernel_generated(const std::string &frames) {
  const Target t = generation_target();
  for (const Family *f : families()) {
    CheckOptions o;
    o.seed = 7;
    o.frames_real = frames;
    Checker *ck = nullptr;
    std::map<std::string, std::string> calls;
    ASSERT_NO_THROW(calls = generate(*f, o, t, &ck)) << f->name << " with frames '" << frames << "'";
    std::map<std::string, size_t> per_kernel;
    for (const CheckCall *c : ck->pending()) ++per_kernel[c->kernel];
    for (const auto &k : f->kernels)
      EXPECT_GT(per_kernel[k], 0u) << f->name << ": no check call for " << k << " (frames '" << frames << "')";
  }
}

TEST(Coverage, EveryKernelGetsCheckCallsWithTheFrames) {
  if (!frames_real_present(default_frames_real())) {
    if (frames_required()) FAIL() << frames_missing_message(default_frames_real());
    GTEST_SKIP() << frames_missing_message(default_frames_real());
  }
  expect_every_kernel_generated(default_frames_real());
}

TEST(Coverage, EveryKernelGetsCheckCallsWithoutTheFrames) {
  expect_every_kernel_generated("/nonexistent/frames-real");
  // And the families that crop real frames say that they skipped those cases.
  const Target t = generation_target();
  std::set<std::string> skipped;
  for (const Family *f : families()) {
    CheckOptions o;
    o.frames_real = "/nonexistent/frames-real";
    Checker *ck = nullptr;
    generate(*f, o, t, &ck);
    for (const auto &kv : ck->skipped_real()) skipped.insert(kv.first);
  }
  for (const char *f : {"add_sat", "harris", "hornschunck", "lk", "ncc", "sobel"})
    EXPECT_TRUE(skipped.count(f)) << f << " skipped no real-frame case without the frames";
}

TEST(Coverage, EveryAssemblyKernelHasABenchCallAndBudgetRows) {
  const std::vector<Budget> budgets = load_budgets(BVB_SOURCE_DIR "/ci/budgets.json");
  std::map<std::string, int> rows;
  for (const auto &b : budgets) ++rows[b.key.substr(0, b.key.find('/'))];
  for (const auto &k : Registry::product().kernels()) {
    if (!k.has_asm) continue;
    const Family *f = family_of(k.name);
    ASSERT_NE(f, nullptr) << k.name;
    ASSERT_TRUE(bool(f->bench_call)) << k.name << ": its family has no bench call";
    Rng rng(1);
    EXPECT_EQ(f->bench_call(k.name, 160, 120, rng).kernel, k.name) << k.name << ": no bench call at 160x120";
    EXPECT_GT(rows[k.name], 0) << k.name << ": no budget in ci/budgets.json (bfbench budgets --update -k " << k.name << ")";
  }
  for (const auto &kv : rows) {
    const KernelInfo *k = Registry::product().find(kv.first);
    EXPECT_TRUE(k && k->has_asm) << "ci/budgets.json budgets " << kv.first << ", which has no assembly";
  }
}

// The probe: harris_nms, lk_track and Horn-Schunck benched on crops of ../shared/frames-real and
// on a synthetic substitute without it (harris_nms 160x120: 278,439 cycles against a budget of
// 65,368). Every bench call must be the same bytes whether the frames are there or not.
TEST(Coverage, BenchInputsDoNotDependOnFilesOutsideTheRepository) {
  auto bench_calls = [] {
    std::map<std::string, std::string> out;
    for (const Family *f : families()) {
      if (!f->bench_call) continue;
      for (const auto &k : f->kernels)
        for (Size s : {Size{160, 120}, Size{320, 240}}) {
          Rng rng(1 ^ (uint64_t(s.w) << 20) ^ uint64_t(s.h));  // as run_bench seeds it
          CheckCall c = f->bench_call(k, s.w, s.h, rng);
          if (!c.kernel.empty()) out[k + "/" + c.case_name] = testing_gen::fingerprint(c);
        }
    }
    return out;
  };
  const char *old = std::getenv("BFBENCH_FRAMES_REAL");
  const std::string saved = old ? old : "";
  setenv("BFBENCH_FRAMES_REAL", "/nonexistent/frames-real", 1);
  const auto without = bench_calls();
  if (old) setenv("BFBENCH_FRAMES_REAL", saved.c_str(), 1);
  else unsetenv("BFBENCH_FRAMES_REAL");
  if (!frames_real_present(default_frames_real())) GTEST_SKIP() << frames_missing_message(default_frames_real());
  const auto with = bench_calls();
  ASSERT_EQ(with.size(), without.size());
  for (const auto &kv : with)
    EXPECT_TRUE(without.count(kv.first) && without.at(kv.first) == kv.second)
        << kv.first << ": the bench call differs without ../shared/frames-real";
}

// A registry entry with assembly and no family (the probe: it used to give "all 0 calls
// bit-exact" and "0 budgets, 0 problems"): the check's coverage names each implementation
// it never judged, and the budgets name the kernel.
TEST(Coverage, AKernelWithoutAFamilyIsReportedNotPassed) {
  std::vector<KernelInfo> ks = Registry::product().kernels();
  ks.push_back({"ghost_u8", uint32_t(ks.size()), true, "ghost_u8_c", "ghost_u8_asm"});
  const Registry reg(ks);
  const Target t = generation_target(reg);
  CheckOptions o;
  o.kernel_glob = "ghost*";
  Checker ck(t, o);
  for (const Family *f : families()) {
    bool wanted = false;
    for (const auto &k : f->kernels) wanted |= ck.wants(k);
    if (wanted) f->check(ck);
  }
  EXPECT_TRUE(ck.pending().empty());
  const std::vector<std::string> gaps = ck.coverage_gaps();
  EXPECT_EQ(gaps, (std::vector<std::string>{"ghost_u8 (host)", "ghost_u8 (c)", "ghost_u8 (asm)"}));

  EXPECT_EQ(unjudged_kernels({"add_sat_u8", "ghost_u8"}, "*", {}), (std::vector<std::string>{"add_sat_u8", "ghost_u8"}));
  BudgetVerdict v;
  v.key = "add_sat_u8/asm/160x120";
  EXPECT_EQ(unjudged_kernels({"add_sat_u8", "ghost_u8"}, "*", {v}), (std::vector<std::string>{"ghost_u8"}));
  EXPECT_TRUE(unjudged_kernels({"add_sat_u8", "ghost_u8"}, "add*", {v}).empty());
}

}  // namespace
}  // namespace bvb
