// The gate's judgements, without a simulator: budgets (equal passes, one cycle over fails, a
// missing or unmeasured budget fails, tolerances in whole cycles, slack reported) and the
// checker's comparisons (outputs against the host reference, inputs against their original
// bytes for every implementation including the host, return values).
#include <gtest/gtest.h>

#include "bench.h"
#include "check.h"

namespace bvb {
namespace {

BenchRow row(const std::string &kernel, const std::string &size, uint32_t asm_cycles) {
  BenchRow r;
  r.kernel = kernel;
  r.case_name = size;
  r.has_asm = true;
  r.asm_cycles = asm_cycles;
  return r;
}

BudgetVerdict only(const std::vector<BudgetVerdict> &v) {
  EXPECT_EQ(v.size(), 1u);
  return v.empty() ? BudgetVerdict{} : v[0];
}

TEST(Budgets, EqualPassesOneCycleOverFails) {
  const std::vector<Budget> b = {{"k/asm/160x120", 1000, 0}};
  EXPECT_EQ(only(judge_budgets({row("k", "160x120", 1000)}, b)).status, BudgetVerdict::Ok);
  EXPECT_EQ(only(judge_budgets({row("k", "160x120", 999)}, b)).status, BudgetVerdict::Ok);
  EXPECT_EQ(only(judge_budgets({row("k", "160x120", 1001)}, b)).status, BudgetVerdict::Over);
}

TEST(Budgets, MissingAndUnmeasuredFail) {
  auto v = judge_budgets({row("k", "160x120", 1000)}, {});
  EXPECT_EQ(only(v).status, BudgetVerdict::Missing);
  v = judge_budgets({}, {{"k/asm/160x120", 1000, 0}});
  EXPECT_EQ(only(v).status, BudgetVerdict::Unmeasured);
  BenchRow failed = row("k", "160x120", 10);
  failed.error = "asm: mismatch";
  v = judge_budgets({failed}, {{"k/asm/160x120", 1000, 0}});
  EXPECT_EQ(only(v).status, BudgetVerdict::Failed);
  // A C-only row has no budget to miss.
  BenchRow c = row("k", "160x120", 0);
  c.has_asm = false;
  EXPECT_TRUE(judge_budgets({c}, {}).empty());
}

// 0.1% of 1000 is 1 cycle: 1001 passes, 1002 does not. In binary, 1000 * (1 + 0.1 / 100) is
// 1000.9999999999999, which failed 1001.
TEST(Budgets, ToleranceInWholeCycles) {
  for (uint64_t base : {1000ull, 3000ull, 7000ull, 2000ull, 333740ull}) {
    for (uint64_t tenths : {1, 3, 7, 11, 23, 50}) {
      const double pct = double(tenths) / 10;
      const uint64_t excess = base * tenths / 1000;  // the decimal answer, in integers, floored
      const std::vector<Budget> b = {{"k/asm/160x120", base, pct}};
      EXPECT_EQ(budget_allowed(b[0]), base + excess) << base << " " << pct;
      EXPECT_EQ(only(judge_budgets({row("k", "160x120", uint32_t(base + excess))}, b)).status, BudgetVerdict::Ok)
          << base << " +" << pct << "%";
      EXPECT_EQ(only(judge_budgets({row("k", "160x120", uint32_t(base + excess + 1))}, b)).status,
                BudgetVerdict::Over)
          << base << " +" << pct << "%";
    }
  }
  EXPECT_EQ(budget_allowed({"k/asm/160x120", 1000, 0.15}), 1001u);  // 1.5 cycles: rounded down
  EXPECT_EQ(budget_allowed({"k/asm/160x120", 1000, 0}), 1000u);
}

TEST(Budgets, SlackAboveTwoPercentIsReported) {
  BudgetVerdict v;
  v.status = BudgetVerdict::Ok;
  v.measured = 1000;
  v.budget = 1020;
  EXPECT_EQ(budget_slack_pct(v), 0);  // exactly 2%
  v.budget = 1021;
  EXPECT_NEAR(budget_slack_pct(v), 2.1, 1e-9);
  v.status = BudgetVerdict::Over;
  EXPECT_EQ(budget_slack_pct(v), 0);
}

// ---- the checker's comparisons ----

// A call with an input, an output, an in/out buffer and scratch, and a host reference that
// computes out = in + 1 and inout += in, setting its return value.
struct Fixture {
  CheckCall c;
  int in, out, io, scr;
  bool reference_writes_input = false;
  Fixture() {
    c.kernel = "k";
    c.case_name = "4x1";
    c.case_id = "k:3";
    in = c.in("in", {1, 2, 3, 4});
    out = c.out("out", 4);
    io = c.inout("io", {10, 20, 30, 40});
    scr = c.scratch("scratch", 4);
    c.host = [this](HostBuffers &m) {
      for (int i = 0; i < 4; ++i) {
        m.u8(out)[i] = uint8_t(m.u8(in)[i] + 1);
        m.u8(io)[i] = uint8_t(m.u8(io)[i] + m.u8(in)[i]);
      }
      if (reference_writes_input) m.u8(in)[2] = 99;
      m.set_ret(7);
    };
  }
  // The host reference's buffers, as the checker computes them.
  std::vector<std::vector<uint8_t>> expected(HostBuffers **hb) {
    exp.clear();
    for (const auto &b : c.bufs) exp.push_back(b.data);
    host = std::make_unique<HostBuffers>(exp);
    c.host(*host);
    *hb = host.get();
    return exp;
  }
  // What a correct implementation leaves: the right outputs, the input untouched.
  std::vector<std::vector<uint8_t>> correct() {
    std::vector<std::vector<uint8_t>> d;
    for (const auto &b : c.bufs) d.push_back(b.data);
    for (int i = 0; i < 4; ++i) d[out][i] = uint8_t(d[in][i] + 1), d[io][i] = uint8_t(d[io][i] + d[in][i]);
    d[scr] = {9, 9, 9, 9};  // scratch may hold anything
    return d;
  }
  std::vector<std::vector<uint8_t>> exp;
  std::unique_ptr<HostBuffers> host;
};

TEST(Comparisons, ACorrectImplementationPasses) {
  Fixture f;
  HostBuffers *hb;
  auto e = f.expected(&hb);
  const uint32_t ret = 7;
  EXPECT_TRUE(compare_call(f.c, "asm", 5, f.correct(), e, *hb, &ret).empty());
  EXPECT_TRUE(compare_call(f.c, "host", 5, e, e, *hb, nullptr).empty());
}

TEST(Comparisons, WrongOutputWrongInOutWrongReturn) {
  Fixture f;
  HostBuffers *hb;
  auto e = f.expected(&hb);
  auto d = f.correct();
  d[f.out][1] ^= 1;
  d[f.io][3] ^= 1;
  const uint32_t ret = 8;
  auto v = compare_call(f.c, "asm", 5, d, e, *hb, &ret);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].kind, Failure::ReturnValue);
  EXPECT_EQ(v[1].kind, Failure::Mismatch);
  EXPECT_NE(v[1].message.find("'out'"), std::string::npos) << v[1].message;
  EXPECT_EQ(v[2].kind, Failure::Mismatch);
  EXPECT_NE(v[2].message.find("'io'"), std::string::npos) << v[2].message;
  EXPECT_EQ(v[0].case_id, "k:3");
  EXPECT_EQ(v[0].seed, 5u);
}

TEST(Comparisons, AnImplementationThatWritesItsInputIsBlamed) {
  Fixture f;
  HostBuffers *hb;
  auto e = f.expected(&hb);
  auto d = f.correct();
  d[f.in][0] = 0;
  const uint32_t ret = 7;
  auto v = compare_call(f.c, "asm", 5, d, e, *hb, &ret);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].kind, Failure::InputModified);
}

// The probe: a C reference that wrote its input made the correct assembly the one blamed. The
// inputs are compared with their original bytes: the host is blamed, the assembly is not.
TEST(Comparisons, AReferenceThatWritesItsInputIsBlamedNotTheImplementation) {
  Fixture f;
  f.reference_writes_input = true;
  HostBuffers *hb;
  auto e = f.expected(&hb);
  const uint32_t ret = 7;
  auto d = f.correct();
  EXPECT_TRUE(compare_call(f.c, "asm", 5, d, e, *hb, &ret).empty())
      << compare_call(f.c, "asm", 5, d, e, *hb, &ret)[0].message;
  auto v = compare_call(f.c, "host", 5, e, e, *hb, nullptr);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].kind, Failure::InputModified);
  EXPECT_EQ(v[0].impl, "host");
  EXPECT_NE(v[0].message.find("element 2: expected 3, got 99"), std::string::npos) << v[0].message;
}

}  // namespace
}  // namespace bvb
