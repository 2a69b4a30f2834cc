// Calls kernels in a firmware image running in the simulator, through the memory-mapped window
// (bvb/mailbox.h): packs calls into windows, runs them, reads results and buffers back. A call
// that kills the simulator is blamed on that call and the run resumes after it.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "bvb/mailbox.h"
#include "registry.h"
#include "simdriver.h"

namespace bvb {

// How a buffer's bytes are read when a report shows them: element size and 2-D shape.
struct View {
  int elem = 1;          // bytes per element: 1, 2 or 4
  bool is_signed = false;
  int width = 0;         // elements per row (0: a flat array of size/elem elements)
  int height = 1;
  int stride = 0;        // elements between rows
  int channels = 1;      // interleaved values per pixel (RGB 3, flow u,v 2): width counts all
};

enum class Role { In, Out, InOut, Scratch };

struct Buffer {
  std::string name;
  Role role = Role::In;
  std::vector<uint8_t> data;
  View view;
  uint32_t place = BVB_PLACE_SDRAM;
  uint32_t guard = 64;
  uint32_t align = 4;
  uint32_t skew = 0;
  // In a Session, written into the window only by the first call: later calls of the session
  // see what the kernel left there (a pipeline's state between frames).
  bool persistent = false;
};

struct Arg {
  bool is_buffer = false;
  uint32_t value = 0;  // the word itself, or a buffer index
  static Arg buf(uint32_t index) { return {true, index}; }
  static Arg word(int64_t v) { return {false, uint32_t(v)}; }
};

struct Call {
  uint32_t kernel = 0;
  uint32_t impl = BVB_IMPL_C;
  uint32_t cycle_limit = 0;  // 0: Target's default
  std::vector<Arg> args;
  std::vector<Buffer> bufs;
  // What the caller-saved registers hold on entry (runtime/call.S; 0: zero) and the seed of
  // the callee-saved registers' canaries (0: the firmware's fixed set).
  uint32_t junk_seed = 0;
  uint32_t canary_seed = 0;
};

struct GuardDamage {
  int buffer;
  bool before;     // leading guard band (else trailing)
  int64_t offset;  // of the first damaged byte, relative to the data start (negative before)
};

struct CallResult {
  uint32_t status = BVB_PENDING;
  uint32_t detail = 0;
  uint32_t cycles = 0;
  uint32_t ret = 0;
  uint32_t abi_bad = 0;
  uint32_t seqstat = 0, pc = 0, addr = 0;
  uint32_t limit = 0;  // the watchdog's cycle limit the call ran under
  uint32_t buf_addr[BVB_MAX_BUFS] = {};
  std::vector<std::vector<uint8_t>> data;  // each buffer's data after the call
  std::vector<GuardDamage> guard_damage;
  std::string crash;  // the simulator died in this call: how
  bool ok() const { return status == BVB_OK && abi_bad == 0 && guard_damage.empty(); }
};

// The byte at position i of every guard band.
inline uint8_t guard_byte(size_t i) { return uint8_t(0xA5 ^ (i * 0x3B)); }

// One line saying what went wrong with a call (status, fault, ABI, guards); "" when it is ok().
std::string describe_failure(const Call &call, const CallResult &r, const std::string &elf = "");
// What the ABI bits say: "did not preserve R4, P5", "left L3 non-zero (...)", "left hardware
// loop 1 armed (...)", joined by "; ".
std::string abi_names(uint32_t abi_bad);
// A data access the CPLBs refused (miss, protection, multiple hits): fault_addr is the address.
bool data_cplb_fault(uint32_t seqstat);
const char *excause_name(uint32_t excause);

struct FirmwareImage {
  std::string elf;
  const Registry *registry;
};

class Target {
 public:
  Target(FirmwareImage image, std::string simulator);

  // Runs the calls (in order within a window) using up to `jobs` simulator processes at once.
  // progress(done, total) is called as windows finish.
  std::vector<CallResult> run(const std::vector<Call> &calls, int jobs = 1,
                              const std::function<void(size_t, size_t)> &progress = {}) const;
  CallResult run_one(const Call &call) const { return run({call}).front(); }

  const Registry &registry() const { return *image_.registry; }
  const std::string &elf() const { return image_.elf; }
  const std::string &simulator() const { return simulator_; }
  // Bytes the firmware has for buffers placed in `place` (from the image's linker symbols).
  uint32_t arena_bytes(uint32_t place) const;
  // Arena sizes given instead of read from the image: for generating calls without a firmware
  // (tests of what the checks generate, in host-only builds).
  void set_arena_bytes(uint32_t place, uint32_t bytes) { arena_override_[place] = bytes; }
  uint32_t null_call_cycles() const { return null_call_cycles_; }
  // The simulator's timing model: "bf537" (modelled BF537 cycles: stalls, L1 banks, SDRAM,
  // caches) or "none" (the simulator's own counts: one per instruction, fixed extras).
  const std::string &timing() const { return timing_; }
  void set_timing(const std::string &t);
  // One call per simulator run: under the timing model a call's cycles depend on what ran
  // before it in the same run (cache contents, open SDRAM rows), so measurements that must be
  // exact whatever else is measured with them (bench, budgets) start each call afresh.
  void set_isolated(bool on) { isolated_ = on; }
  // The empty call's cycles as another Target (a copy of this one) measured them.
  void take_null_call_cycles(const Target &from) const { null_call_cycles_ = from.null_call_cycles_; }
  // Further simulator options for the runs of calls of one implementation (bfbench profile's
  // --timing-profile for the call it profiles, not for the reference it is checked with).
  void set_impl_options(uint32_t impl, std::vector<std::string> options) { impl_options_[impl] = std::move(options); }
  static constexpr uint32_t kDefaultCycleLimit = 300000000;
  // Writes the window of one call to `path` and returns the simulator run that would serve it,
  // for running it elsewhere (bfbench debug: under gdb's simulator).
  sim::RunSpec write_window(const Call &call, const std::string &path) const;

 private:
  void run_window(const std::vector<const Call *> &calls, std::vector<CallResult *> &out) const;
  sim::RunSpec run_spec(const std::vector<const Call *> &calls, const std::string &path, uint32_t size,
                        uint64_t limit_total) const;

  FirmwareImage image_;
  std::string simulator_;
  std::string timing_;
  bool isolated_ = false;
  mutable uint32_t null_call_cycles_ = 0;
  std::map<uint32_t, uint32_t> arena_override_;
  std::map<uint32_t, std::vector<std::string>> impl_options_;
};

// One simulator process serving a sequence of calls of one shape (BVB_SERVE in the window): a
// frame sequence through a pipeline without a simulator start per frame. Buffers marked
// persistent keep, from one call to the next, what the kernel left in them.
class Session {
 public:
  explicit Session(const Target &target);
  ~Session();
  Session(const Session &) = delete;
  Session &operator=(const Session &) = delete;
  // The first call fixes the window's layout; later calls must have buffers of the same sizes.
  // Throws sim::SetupError when the simulator dies (the session is then over).
  CallResult call(const Call &c);

 private:
  struct Impl;
  Impl *impl_;
};

// A new temporary file (in $TMPDIR, else /tmp), removed if bfbench is interrupted; the caller
// removes it with remove_temp_file (cleanup.h).
std::string make_temp_file();

// Default paths baked in at build time; BFBENCH_FIRMWARE / BFBENCH_SELFTEST_FIRMWARE override.
FirmwareImage product_firmware();
FirmwareImage selftest_firmware();
std::string default_simulator();
// $BFBENCH_TIMING if set (none or bf537), else "bf537": budgets and reports are modelled cycles.
std::string default_timing();
bool valid_timing(const std::string &t);

}  // namespace bvb
