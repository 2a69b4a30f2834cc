// Where one kernel call's modelled cycles go (bfbench profile): the simulator's per-instruction
// profile of the call (bfin-elf-run --timing-profile, our patch 0024), every instruction with its
// executed count, its cycles and its stall cycles by cause, mapped onto the assembly or C source
// lines (the firmware carries line information) and summarised per loop.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "io.h"
#include "patterns.h"
#include "target.h"

namespace bvb {

// The simulator's file, as written by timing-profile.c.
struct ProfileRecord {
  uint32_t pc = 0;
  uint64_t count = 0, cycles = 0;
  std::vector<uint64_t> cause;  // cycles per cause, in ProfileData::causes order
  std::string stall_reg;        // the register its last address-stage stall waited for, or "-"
};
struct ProfileData {
  std::vector<std::string> causes;
  std::vector<uint64_t> windows;  // each window's cycles, in run order
  std::vector<ProfileRecord> records;
};
// Throws InputError naming what is wrong.
ProfileData parse_profile(const std::string &text);

// What objdump says about an instruction address.
struct Disassembly {
  std::string function;  // the symbol it is in, without the ABI's underscore
  std::string text;      // the instruction as objdump prints it
  std::string file;      // source file and line from the line information ("" if none)
  int line = 0;
  // A hardware loop set-up (LSETUP) or a backward conditional branch: the loop body's first
  // and last instruction addresses.
  uint32_t loop_start = 0, loop_end = 0;
  bool loop_hw = false;
};
// Parses `objdump -d -l` output: address -> its disassembly, in address order.
std::vector<std::pair<uint32_t, Disassembly>> parse_objdump(const std::string &text);

struct ProfileLine {  // one source line: the sum of its instructions
  std::string file;
  int line = 0;
  std::string source;  // the line's text, when the file could be read
  uint64_t count = 0, cycles = 0;  // count: executions of its first instruction
  std::vector<uint64_t> cause;
};
struct ProfileLoop {
  uint32_t start = 0, end = 0;
  bool hw = false;  // a hardware loop (else a loop closed by a backward branch)
  std::string where;  // "file:line" of its first instruction, else the function+offset
  uint64_t iterations = 0, cycles = 0;
  int body = 0;           // instructions in the body (inner loops' included once)
  double issue_bound = 0;  // instructions it issued per iteration (inner loops' iterations
                           // included): its cycles per iteration without any stall
  std::vector<uint64_t> cause;
};
struct ProfileInstruction {
  uint32_t pc = 0;
  Disassembly dis;
  ProfileRecord rec;
};

struct Profile {
  std::string kernel, impl, case_name, timing;
  uint64_t measured = 0;    // the call's cycles as bench measures them (overhead subtracted)
  uint64_t overhead = 0;    // the empty call's cycles through the same trampoline
  uint64_t total = 0;       // the profile's cycles: equals measured + overhead
  uint64_t issue = 0;       // one cycle per instruction executed
  std::vector<std::string> causes;
  std::vector<uint64_t> cause;  // totals per cause; issue + sum(cause) == total
  std::vector<ProfileInstruction> insns;
  std::vector<ProfileLine> lines;  // in file and line order
  std::vector<ProfileLoop> loops;  // hottest first
};

// Joins the simulator's profile with the disassembly: per line, per loop, totals. `measured` and
// `overhead` come from the call.
Profile build_profile(const ProfileData &data, const std::vector<std::pair<uint32_t, Disassembly>> &dis);

struct ProfileOptions {
  std::string kernel;
  std::string impl = "asm";  // or "c"
  Size size{320, 240};
  uint32_t seed = 1;
};
// The profiled call failed its check: its cycles mean nothing (bfbench profile exits 1).
struct ProfileCheckFailed : CallFailed {
  using CallFailed::CallFailed;
};

// Runs the kernel's bench call once under the profile, checks it (a wrong answer is reported,
// not profiled), and builds the profile. Throws InputError / sim::SetupError.
Profile run_profile(const Target &target, const ProfileOptions &opts);

std::string profile_text(const Profile &p, size_t top_lines = 25);
std::string profile_json(const Profile &p);
// One static page, no server: the annotated source with a heat colour per line, the loops and
// the totals; rendered by its own script from the data it embeds.
std::string profile_html(const Profile &p);

}  // namespace bvb
