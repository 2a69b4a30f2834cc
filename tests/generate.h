// What the kernel families' checks generate, without a firmware or a simulator: a Target whose
// arena sizes are given (the BF537 map the firmware uses) and a Checker that queues calls that
// are never run. For the tests of coverage and of each case's own random stream.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "check.h"
#include "family.h"
#include "registry.h"
#include "target.h"

namespace bvb {
namespace testing_gen {

inline Target generation_target(const Registry &registry = Registry::product()) {
  Target t(FirmwareImage{"(no firmware: calls are generated, not run)", &registry}, "(no simulator)");
  t.set_arena_bytes(BVB_PLACE_SDRAM, 28u << 20);
  t.set_arena_bytes(BVB_PLACE_L1A, 16u << 10);
  t.set_arena_bytes(BVB_PLACE_L1B, 24u << 10);
  t.set_arena_bytes(BVB_PLACE_SCRATCH, 4u << 10);
  return t;
}

// Everything that makes a call what it is, as one string: two calls are the same call when
// these are equal.
inline std::string fingerprint(const CheckCall &c) {
  std::string s = c.kernel + "|" + c.case_name + "|" + c.case_id + "|junk " + std::to_string(c.junk_seed) + "|";
  for (const auto &a : c.args) s += (a.is_buffer ? "b" : "w") + std::to_string(a.value) + ",";
  for (const auto &b : c.bufs) {
    s += "|" + b.name + ":" + std::to_string(int(b.role)) + ":" + std::to_string(b.place) + ":" +
         std::to_string(b.skew) + ":" + std::to_string(b.align) + ":";
    s.append(b.data.begin(), b.data.end());
  }
  return s;
}

// The calls one family's check queues for seed and options (kernel_glob, only_case, frames_real).
inline std::map<std::string, std::string> generate(const Family &f, CheckOptions o, const Target &t,
                                                   Checker **keep = nullptr) {
  static std::vector<std::unique_ptr<Checker>> alive;  // a kept checker outlives the call
  alive.push_back(std::make_unique<Checker>(t, o));
  Checker &ck = *alive.back();
  ck.reseed(f.name);
  f.check(ck);
  std::map<std::string, std::string> out;
  for (const CheckCall *c : ck.pending()) out[c->case_id] = fingerprint(*c);
  if (keep) *keep = &ck;
  else alive.pop_back();
  return out;
}

}  // namespace testing_gen
}  // namespace bvb
