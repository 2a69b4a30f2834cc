// The harness must catch every kind of broken kernel: the self-test image holds add_sat_u8 and
// twins of its assembly with one defect each (firmware/selftest/). Each twin runs add_sat_u8's
// own checks and must fail them in the expected way; the intact kernel must pass them.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "check.h"
#include "family.h"
#include "patterns.h"
#include "target.h"

namespace bvb {
namespace {

struct Case {
  const char *kernel;
  Failure::Kind kind;
  const char *message_part;  // the report must say this
};

const Case kCases[] = {
    {"broken_wrong_pixel", Failure::Mismatch, "buffer 'dst' element"},
    {"broken_skip_pixel", Failure::Mismatch, "buffer 'dst' element"},
    {"broken_clobber_r4", Failure::Abi, "R4"},
    {"broken_clobber_p5", Failure::Abi, "P5"},
    {"broken_leave_l3", Failure::Abi, "L3"},
    {"broken_move_sp", Failure::Abi, "SP"},
    {"broken_write_past_end", Failure::Guard, "after buffer 'dst'"},
    {"broken_write_before_start", Failure::Guard, "before buffer 'dst'"},
    {"broken_write_input", Failure::InputModified, "input buffer 'a'"},
    {"broken_endless_loop", Failure::Hang, "cycle limit"},
    {"broken_illegal_insn", Failure::Fault, "undefined instruction"},
    {"broken_misaligned", Failure::Fault, "misaligned data access"},
    {"broken_read_unmapped", Failure::Fault, ""},
    {"broken_wild_jump", Failure::Fault, ""},
};

void PrintTo(const Case &c, std::ostream *os) { *os << c.kernel; }

std::vector<Failure> check_as(const std::string &kernel, size_t *asm_calls) {
  Target target(selftest_firmware(), default_simulator());
  CheckOptions o;
  o.seed = 7;
  o.frames_real = default_frames_real();
  o.kernel_alias["add_sat_u8"] = kernel;
  Checker ck(target, o);
  const Family *f = family_of("add_sat_u8");
  EXPECT_NE(f, nullptr);
  ck.reseed(f->name);
  f->check(ck);
  ck.flush();
  *asm_calls = ck.tally().at(kernel).at("asm").calls;
  return ck.failures();
}

TEST(SelfTest, IntactKernelPasses) {
  size_t calls = 0;
  auto failures = check_as("add_sat_u8", &calls);
  EXPECT_GT(calls, 50u);
  for (const auto &f : failures) ADD_FAILURE() << f.impl << " " << f.case_name << ": " << f.message;
}

class BrokenKernel : public testing::TestWithParam<Case> {};

TEST_P(BrokenKernel, IsCaughtAsExpected) {
  const Case &c = GetParam();
  size_t calls = 0;
  auto failures = check_as(c.kernel, &calls);
  ASSERT_GT(calls, 50u);
  size_t asm_expected = 0;
  for (const auto &f : failures) {
    // The C twin is the intact reference: it must never be blamed.
    EXPECT_EQ(f.impl, "asm") << f.message;
    if (f.impl == "asm" && f.kind == c.kind) {
      ++asm_expected;
      EXPECT_NE(f.message.find(c.message_part), std::string::npos) << f.message;
    }
    // The report prints the kind before the message: the message must not repeat it.
    EXPECT_NE(f.message.rfind(std::string(failure_kind_name(f.kind)) + ": ", 0), 0u) << f.message;
  }
  for (const auto &f : failures)
    if (f.kind == c.kind) {
      std::printf("  caught %s on %s: %s\n", c.kernel, f.case_name.c_str(), f.message.c_str());
      break;
    }
  EXPECT_GT(asm_expected, 0u) << c.kernel << " was not reported as " << failure_kind_name(c.kind);
  // A defect that fires on every call must fail every call; later calls still run after faults.
  if (c.kind == Failure::Hang || c.kind == Failure::Fault || c.kind == Failure::Abi) {
    EXPECT_EQ(asm_expected, calls) << "every call should fail the same way";
  }
}

INSTANTIATE_TEST_SUITE_P(Harness, BrokenKernel, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case> &i) { return std::string(i.param.kernel); });

}  // namespace
}  // namespace bvb
