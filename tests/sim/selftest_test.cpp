// The harness must catch every kind of broken kernel: the self-test image holds add_sat_u8,
// harris_nms and harris_select, and twins of them with one defect each (firmware/selftest/).
// Each twin runs its kernel's own checks and must fail them in the expected way, with a message
// naming the cause; the intact kernels must pass them.
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
  const char *twin_of = "add_sat_u8";
  // Fails every call, not only those whose inputs or placement expose it.
  bool every_call = false;
};

const Case kCases[] = {
    {"broken_wrong_pixel", Failure::Mismatch, "buffer 'dst' element"},
    {"broken_skip_pixel", Failure::Mismatch, "buffer 'dst' element"},
    {"broken_clobber_r4", Failure::Abi, "did not preserve R4", "add_sat_u8", true},
    {"broken_clobber_p5", Failure::Abi, "did not preserve P5", "add_sat_u8", true},
    {"broken_leave_l3", Failure::Abi, "left L3 non-zero", "add_sat_u8", true},
    {"broken_move_sp", Failure::Abi, "did not preserve SP", "add_sat_u8", true},
    {"broken_loop_armed", Failure::Abi, "left hardware loop 1 armed (LC1 non-zero", "add_sat_u8", true},
    {"broken_write_past_end", Failure::Guard, "after buffer 'dst'"},
    {"broken_write_before_start", Failure::Guard, "before buffer 'dst'"},
    {"broken_write_input", Failure::InputModified, "input buffer 'a'"},
    {"broken_write_inout", Failure::Mismatch, "in/out buffer 'cand'", "harris_select"},
    {"broken_wrong_return", Failure::ReturnValue, "returned", "harris_nms"},
    {"broken_read_past_end", Failure::Fault, "past the end of buffer 'a'"},
    {"broken_uninit_a1", Failure::Mismatch, "it reads a register (or an argument) it never set"},
    {"broken_endless_loop", Failure::Hang, "cycle limit", "add_sat_u8", true},
    {"broken_illegal_insn", Failure::Fault, "undefined instruction", "add_sat_u8", true},
    {"broken_misaligned", Failure::Fault, "misaligned data access", "add_sat_u8", true},
    {"broken_read_unmapped", Failure::Fault, "", "add_sat_u8", true},
    {"broken_wild_jump", Failure::Fault, "", "add_sat_u8", true},
};

void PrintTo(const Case &c, std::ostream *os) { *os << c.kernel; }

// Runs `kernel`'s family's checks with `kernel` played by `twin`.
std::vector<Failure> check_as(const std::string &kernel, const std::string &twin, size_t *asm_calls,
                              uint32_t seed = 7) {
  Target target(selftest_firmware(), default_simulator());
  CheckOptions o;
  o.seed = seed;
  o.frames_real = default_frames_real();
  o.kernel_alias[kernel] = twin;
  Checker ck(target, o);
  const Family *f = family_of(kernel);
  EXPECT_NE(f, nullptr);
  ck.reseed(f->name);
  f->check(ck);
  ck.flush();
  *asm_calls = ck.tally().at(twin).at("asm").calls;
  return ck.failures();
}

class IntactKernel : public testing::TestWithParam<std::string> {};

// Under the adversarial call (junk, random canaries and poison, buffers at the end of SDRAM) on
// two seeds: a correct kernel is never blamed.
TEST_P(IntactKernel, Passes) {
  for (uint32_t seed : {7u, 8u}) {
    size_t calls = 0;
    auto failures = check_as(GetParam(), GetParam(), &calls, seed);
    EXPECT_GT(calls, 10u);
    for (const auto &f : failures) ADD_FAILURE() << f.impl << " " << f.case_name << ": " << f.message;
  }
}

INSTANTIATE_TEST_SUITE_P(Harness, IntactKernel, testing::Values("add_sat_u8", "harris_nms", "harris_select"));

class BrokenKernel : public testing::TestWithParam<Case> {};

TEST_P(BrokenKernel, IsCaughtAsExpected) {
  const Case &c = GetParam();
  size_t calls = 0;
  auto failures = check_as(c.twin_of, c.kernel, &calls);
  ASSERT_GT(calls, 10u);
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
  if (c.every_call) EXPECT_EQ(asm_expected, calls) << "every call should fail the same way";
}

INSTANTIATE_TEST_SUITE_P(Harness, BrokenKernel, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case> &i) { return std::string(i.param.kernel); });

}  // namespace
}  // namespace bvb
