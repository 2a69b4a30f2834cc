// What bfbench check prints, from tallies and failures made here (no simulator): counts per
// implementation, the hint for the failures not shown, no repeated kind, escaped bytes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "check.h"

namespace {

using namespace bvb;

size_t count_of(const std::string &text, const std::string &part) {
  size_t n = 0;
  for (size_t p = text.find(part); p != std::string::npos; p = text.find(part, p + 1)) ++n;
  return n;
}

Failure failure(const std::string &impl, Failure::Kind kind, const std::string &message, int n) {
  return {"add_sat_u8", impl, "8x8 case", 7, kind, message, "add_sat_u8:" + std::to_string(n)};
}

// Only the 320 assembly calls failed: the summary says so per implementation (it once said
// "639 failures in 640 calls", counting failure records of both).
TEST(CheckReport, FailedCallsAreCountedPerImplementation) {
  std::map<std::string, Checker::Tally> per_impl;
  per_impl["c"] = {320, 0};
  per_impl["asm"] = {320, 320};
  EXPECT_EQ(format_failed_calls(per_impl), "320 of 640 calls failed (asm 320 of 320, c 0 of 320)");
  per_impl["asm"] = {1, 1};
  per_impl["c"] = {0, 0};
  EXPECT_EQ(format_failed_calls(per_impl), "1 of 1 call failed (asm 1 of 1, c 0 of 0)");
  per_impl["asm"] = {5, 0};
  EXPECT_EQ(format_failed_calls(per_impl), "");
}

// Three failures per kernel and implementation are shown; the rest are counted, with the
// command that shows them.
TEST(CheckReport, FailuresNotShownAreCountedWithTheCommandToSeeThem) {
  Tallies tally;
  tally["add_sat_u8"]["c"] = {10, 0};
  tally["add_sat_u8"]["asm"] = {10, 10};
  std::vector<Failure> fs;
  for (int i = 0; i < 10; ++i) fs.push_back(failure("asm", Failure::Mismatch, "buffer 'dst' 1 element differs", i));
  const std::string r = format_check_report(tally, fs, 3, 7);
  EXPECT_NE(r.find("  add_sat_u8" + std::string(14, ' ') + "asm: 0/10 ok   c: 10/10 ok"), std::string::npos) << r;
  EXPECT_EQ(count_of(r, "FAILED add_sat_u8 (asm)"), 3u) << r;
  EXPECT_EQ(count_of(r, "  replay: bfbench check --seed 7 --case add_sat_u8:"), 3u) << r;
  EXPECT_NE(r.find("... 7 more failures of add_sat_u8 (asm) not shown (-v shows all): "
                   "bfbench check -k add_sat_u8 --seed 7 -v"),
            std::string::npos)
      << r;
  const std::string all = format_check_report(tally, fs, SIZE_MAX, 7);
  EXPECT_EQ(count_of(all, "FAILED add_sat_u8 (asm)"), 10u);
  EXPECT_EQ(all.find("more failure"), std::string::npos);
  fs.resize(4);
  EXPECT_NE(format_check_report(tally, fs, 3, 7).find("... 1 more failure of add_sat_u8"), std::string::npos);
}

// The kind is printed once ("hang: hang:" said it twice), and a message's control bytes are
// escaped so the report stays one line per failure.
TEST(CheckReport, KindOnceAndControlCharactersEscaped) {
  Failure f = failure("asm", Failure::Hang, "hang: still running after its cycle limit of 100 cycles", 3);
  const std::string line = format_failure(f);
  EXPECT_NE(line.find(": hang: still running"), std::string::npos) << line;
  EXPECT_EQ(line.find("hang: hang:"), std::string::npos) << line;
  drop_kind_prefix(f);
  EXPECT_EQ(f.message, "still running after its cycle limit of 100 cycles");
  const std::string odd = format_failure(failure("c", Failure::Crash, "simulator said \x1b[2J\x01\nok", 4));
  EXPECT_NE(odd.find("simulator said \\x1b[2J\\x01\\x0aok"), std::string::npos) << odd;
  EXPECT_EQ(count_of(odd, "\n"), 2u) << odd;  // the failure line and its replay line
}

}  // namespace
