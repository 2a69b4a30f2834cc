// The check framework: a checkasm for the Blackfin. A kernel family describes calls (buffers,
// arguments, and the host C reference to run on the same buffers); the Checker runs each call
// on the firmware's C and assembly implementations in the simulator, runs the host reference,
// and compares every buffer bit for bit: outputs against the host's, inputs against their
// original contents, guard bands against their pattern, callee-saved registers against their
// canaries. Failures say what differs, where, and how to replay it.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "target.h"

namespace bvb {
enum class Pattern;
}

namespace bvb {

// splitmix64: small, fast, and the same sequence on every platform.
class Rng {
 public:
  explicit Rng(uint64_t seed) : s_(seed) {}
  uint64_t next() {
    uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  uint32_t u32() { return uint32_t(next() >> 32); }
  // [lo, hi]; an empty range is the caller's bug (a size below a kernel's minimum), reported
  // rather than divided by.
  int uniform(int lo, int hi) {
    if (hi < lo)
      throw std::logic_error("random value wanted from the empty range " + std::to_string(lo) + ".." +
                             std::to_string(hi));
    return lo + int(next() % (uint64_t(int64_t(hi) - lo) + 1));
  }

 private:
  uint64_t s_;
};

// A vector of values as the bytes a call's buffer holds (the host's order, little-endian as the
// Blackfin's).
template <class T> std::vector<uint8_t> as_bytes(const std::vector<T> &v) {
  std::vector<uint8_t> b(v.size() * sizeof(T));
  if (!b.empty()) std::memcpy(b.data(), v.data(), b.size());
  return b;
}

// One object (a kernel's parameter struct, laid out as the firmware's) as a buffer's bytes.
template <class T> std::vector<uint8_t> bytes_of(const T &v) {
  std::vector<uint8_t> b(sizeof v);
  std::memcpy(b.data(), &v, sizeof v);
  return b;
}

// The host reference's view of a call's buffers (the same bytes the firmware gets).
class HostBuffers {
 public:
  explicit HostBuffers(std::vector<std::vector<uint8_t>> &d) : d_(d) {}
  uint8_t *u8(int i) { return d_[i].data(); }
  int8_t *s8(int i) { return reinterpret_cast<int8_t *>(d_[i].data()); }
  uint16_t *u16(int i) { return reinterpret_cast<uint16_t *>(d_[i].data()); }
  int16_t *s16(int i) { return reinterpret_cast<int16_t *>(d_[i].data()); }
  int32_t *s32(int i) { return reinterpret_cast<int32_t *>(d_[i].data()); }
  uint32_t *u32(int i) { return reinterpret_cast<uint32_t *>(d_[i].data()); }
  template <class T> T *as(int i) { return reinterpret_cast<T *>(d_[i].data()); }
  // The host reference's return value; when set, the firmware's R0 must equal it.
  void set_ret(int32_t v) { ret_ = v, has_ret_ = true; }
  bool has_ret() const { return has_ret_; }
  int32_t ret() const { return ret_; }

 private:
  std::vector<std::vector<uint8_t>> &d_;
  int32_t ret_ = 0;
  bool has_ret_ = false;
};

struct CheckCall {
  std::string kernel;
  std::string case_name;  // e.g. "13x5 stride 16 ramp"
  // "kernel:N": the N-th call its family's check queued (Checker::add sets it); with the seed,
  // `bfbench check --seed S --case ID` replays exactly this call.
  std::string case_id;
  std::vector<Buffer> bufs;
  std::vector<Arg> args;
  std::function<void(HostBuffers &)> host;  // runs the host C reference on the buffers
  uint32_t cycle_limit = 0;
  double pixels = 0;  // for cycles per pixel
  // The caller-saved registers' junk on entry (Call::junk_seed); Checker::add draws it from the
  // case's stream.
  uint32_t junk_seed = 0;

  // Builders: return the buffer's index for Arg::buf().
  int in(std::string name, std::vector<uint8_t> bytes, View v = {});
  int out(std::string name, size_t bytes, View v = {});  // filled with a poison pattern
  int inout(std::string name, std::vector<uint8_t> bytes, View v = {});
  int scratch(std::string name, size_t bytes);
  CheckCall &arg(Arg a) { args.push_back(a); return *this; }
  CheckCall &buf(int i) { return arg(Arg::buf(uint32_t(i))); }
  CheckCall &word(int64_t v) { return arg(Arg::word(v)); }
};

struct Failure {
  enum Kind { Mismatch, ReturnValue, InputModified, Guard, Abi, Fault, Hang, Crash, Other };
  std::string kernel;
  std::string impl;
  std::string case_name;
  uint32_t seed = 0;
  Kind kind = Other;
  std::string message;
  std::string case_id;  // CheckCall::case_id
};
const char *failure_kind_name(Failure::Kind k);
// The command that re-runs exactly the failed call: "bfbench check --seed S --case ID".
std::string replay_command(const Failure &f);

struct CheckOptions {
  uint32_t seed = 0;
  std::string kernel_glob = "*";
  int jobs = 1;
  bool campaign = false;   // larger sizes and more cases
  bool verbose = false;
  bool progress = false;   // a progress line on stderr
  bool run_c = true;       // also run the C reference on the Blackfin (else assembly only)
  // Checks written for one kernel run against another of the same prototype (the self-test
  // runs add_sat_u8's checks against its broken twins).
  std::map<std::string, std::string> kernel_alias;
  std::string frames_real; // ../shared/frames-real, for crops of real frames
  // Only the call with this CheckCall::case_id ("kernel:N") is queued; every other call is still
  // generated (its family's draws are the same), just not run.
  std::string only_case;
  // The adversarial call (Checker::add): random poison, junk in the caller-saved registers,
  // canaries per seed, buffers at the end of SDRAM. Off for the bench, which measures its calls
  // as the robot places them.
  bool adversarial = true;
};

class Checker {
 public:
  using Observer = std::function<void(uint32_t impl, const CallResult &)>;

  Checker(const Target &target, CheckOptions opts);

  const CheckOptions &options() const { return opts_; }
  const Target &target() const { return target_; }
  uint32_t seed() const { return opts_.seed; }
  // The current case's random stream. Each call a family queues draws from a stream of its own,
  // derived from (seed, family, case number): add() starts the next case's stream. A family
  // generates every case of every kernel whatever -k says; add() filters. So a case's inputs do
  // not depend on -k, --case or the other cases.
  Rng &rng() { return rng_; }
  void reseed(const std::string &family);  // starts the family: case 0's stream

  // Is this kernel selected by -k and present in the firmware?
  bool wants(const std::string &kernel) const;

  // Real frames (opts.frames_real) for the cases that crop them. Without them such cases are
  // not generated: patterns() leaves Pattern::Real out and skipped_real() names the families
  // that skipped cases, for a visible message; BVB_REQUIRE_FRAMES=1 makes bfbench check an
  // error instead. Never a substitute under the real case's name.
  bool have_frames() const { return have_frames_; }
  const std::vector<Pattern> &patterns();
  // Call where a real-frame case is left out for want of the frames (patterns() calls it).
  void skip_real();
  const std::map<std::string, size_t> &skipped_real() const { return skipped_real_; }

  // Places the call's buffers as firmware would: in L1 (data bank A, B, the scratchpad) while
  // there is room, the rest in SDRAM; which bank is tried first, and whether a call stays all
  // in SDRAM, is random. Uses the firmware image's real arena sizes.
  void place_randomly(CheckCall &call);
  // For a kernel with a DMA path: half the calls (a draw from `rng`) where the robot runs it,
  // its frames in SDRAM and buffer `scratch` in L1 (bank A if it fits, else B), with " frames
  // SDRAM" added to the case name; the others, and all when the scratch fits neither bank,
  // placed at random (place_randomly).
  void place_streaming(CheckCall &call, size_t scratch, Rng &rng);

  // Queues the call on every implementation the firmware has (plus the host reference). Makes
  // the call adversarial first, with draws from the end of the case's stream (after the
  // family's, so its inputs stay what they were): output and scratch poison of random bytes,
  // the junk seed, and in half the calls one SDRAM buffer (an input where there is one) moved
  // to the end of SDRAM (BVB_PLACE_SDRAM_END), so a read past it faults.
  void add(CheckCall call, Observer observer = {});
  // Runs everything queued; records failures. Returns the number of new failures.
  size_t flush();
  // The calls queued and not yet run (for tests of what a family generates).
  std::vector<const CheckCall *> pending() const;
  // Kernels selected by -k (and, with only_case, that case's kernel) without a judged call for
  // each implementation: the host reference, the C on the Blackfin (unless run_c is off for an
  // assembly kernel), the assembly. "kernel (impl)" each; empty when every one was judged.
  std::vector<std::string> coverage_gaps() const;

  const std::vector<Failure> &failures() const { return failures_; }
  // Per kernel and implementation: calls checked and calls that failed.
  struct Tally { size_t calls = 0, failed = 0; };
  const std::map<std::string, std::map<std::string, Tally>> &tally() const { return tally_; }

 private:
  std::string resolve(const std::string &kernel) const;
  std::vector<Failure> judge(const CheckCall &cc, uint32_t impl, const Call &call, const CallResult &r,
                             const std::vector<std::vector<uint8_t>> &expected, const HostBuffers &host) const;
  void record(const CheckCall &cc, const std::string &impl, const std::vector<Failure> &found);

  const Target &target_;
  CheckOptions opts_;
  Rng rng_;
  std::string family_;
  uint32_t case_no_ = 0;
  bool have_frames_ = false;
  std::map<std::string, size_t> skipped_real_;
  struct Pending {
    CheckCall call;
    Observer observer;
  };
  std::vector<Pending> pending_;
  std::vector<Failure> failures_;
  std::map<std::string, std::map<std::string, Tally>> tally_;
};

// The comparisons behind a call's verdict, without the simulator: the implementation's buffers
// after the call against what they must hold. An input must still hold its original bytes
// (call.bufs[i].data, as generated: not the host reference's copy, which a faulty reference may
// have written); outputs and in/out buffers must equal the host reference's (expected); the
// return value must be the host's when it set one. For the host reference itself, pass its
// buffers as `actual` and `expected` both: only its inputs are then judged. Failures carry the
// call's kernel, case and id, impl and seed.
std::vector<Failure> compare_call(const CheckCall &call, const std::string &impl, uint32_t seed,
                                  const std::vector<std::vector<uint8_t>> &actual,
                                  const std::vector<std::vector<uint8_t>> &expected, const HostBuffers &host,
                                  const uint32_t *ret);

// Reports print the kind before the message ("hang: ..."): a message that starts with its own
// kind loses that prefix, so a report never says "hang: hang:".
void drop_kind_prefix(Failure &f);
// One failure as the report shows it: "FAILED kernel (impl) case, seed S, case ID: kind: message",
// then the replay command on its own line. Control characters in the message are escaped.
std::string format_failure(const Failure &f);

using Tallies = std::map<std::string, std::map<std::string, Checker::Tally>>;  // kernel -> impl
// The report of one seed's check: a line per kernel with each implementation's passed/checked
// calls, then at most max_shown failures per kernel and implementation; for the rest, how many
// were left out and the command that shows them all (-v).
std::string format_check_report(const Tallies &tally, const std::vector<Failure> &failures, size_t max_shown,
                                uint32_t seed);
// Calls on the Blackfin that failed, counted per implementation (one call that fails several
// ways counts once; the host reference's runs are not Blackfin calls):
// "320 of 640 calls failed (asm 320 of 320, c 0 of 320)". Empty when none failed.
std::string format_failed_calls(const std::map<std::string, Checker::Tally> &per_impl);

// The byte that output buffers start as until Checker::add poisons them with random bytes (and
// for calls that never go through it: bench, run): a kernel that skips a pixel leaves it showing.
inline uint8_t poison_byte(size_t i) { return uint8_t(0xC3 + i * 0x29); }
// The canaries' seed for a check seed: the callee-saved registers' canaries differ per seed.
uint32_t canary_seed_of(uint32_t seed);
// The simulator's call for `cc`: its arguments, buffers, cycle limit and junk, run as `impl` of
// the registry's kernel `kernel` (check, debug, run and the pipelines build theirs here).
Call target_call(const CheckCall &cc, uint32_t kernel, uint32_t impl, uint32_t canary_seed = 0);
// For a fault at a data address: which buffer it lies just past the end of (or just before),
// as "an access N bytes past the end of buffer 'a' ..."; "" when none is near.
std::string fault_near_buffer(const Call &call, const CallResult &r);

// Renders the first difference between two buffers under a view, with its neighbourhood.
// Returns "" when they are equal.
std::string first_difference(const std::vector<uint8_t> &expected, const std::vector<uint8_t> &actual,
                             const View &v);

}  // namespace bvb
