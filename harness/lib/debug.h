// bfbench debug: one check call, with its buffers, in bfin-elf-gdb's simulator (target sim, the
// same options bfin-elf-run gets), stopped at the kernel's entry. The gdb is built on request
// (emu/bootstrap.sh --with-gdb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "check.h"
#include "target.h"

namespace bvb {

// $BFBENCH_GDB, else the toolchain's bin/bfin-elf-gdb ("" in a host-only build).
std::string default_gdb();

// The call `bfbench check --seed SEED --case ID` runs on implementation impl, as the checker
// makes it (adversarial poison, junk, canaries, placement). Throws InputError when the case does
// not exist for that seed.
Call case_call(const Target &target, const std::string &case_id, uint32_t seed, uint32_t impl,
               std::string *case_name);

struct DebugPlan {
  std::vector<std::string> argv;     // gdb's command line
  std::vector<std::string> buffers;  // "a (in, 19200 bytes) at 0xff800040", one per buffer
  uint32_t entry = 0;                // the kernel's entry address
  std::string entry_name;
};
// Writes the call's window to `window` and plans the gdb session: the image loaded into gdb's
// simulator with the window mapped, a breakpoint at the entry, run; at the stop the buffers'
// addresses as convenience variables ($a, $dst, ...). The addresses come from a run of the same
// window in bfin-elf-run first: the firmware places a window's buffers the same way every run.
// batch: gdb -batch, printing the registers at the entry, for scripts.
DebugPlan plan_debug(const Target &target, const Call &call, const std::string &window, const std::string &gdb,
                     bool batch);

// Runs gdb in the foreground (bfbench ignores SIGINT meanwhile: it is gdb's, to stop the
// simulated program); returns its exit status.
int run_gdb(const std::vector<std::string> &argv);

}  // namespace bvb
