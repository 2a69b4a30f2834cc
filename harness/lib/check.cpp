#include "check.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sstream>

#include "patterns.h"
#include "simdriver.h"
#include "names.h"

namespace bvb {

namespace {

Buffer make_buffer(std::string name, Role role, std::vector<uint8_t> bytes, View v) {
  Buffer b;
  b.name = std::move(name);
  b.role = role;
  b.data = std::move(bytes);
  b.view = v;
  return b;
}

int64_t element(const std::vector<uint8_t> &d, size_t index, const View &v) {
  const uint8_t *p = d.data() + index * size_t(v.elem);
  switch (v.elem) {
    case 1: return v.is_signed ? int64_t(int8_t(p[0])) : int64_t(p[0]);
    case 2: {
      uint16_t x;
      std::memcpy(&x, p, 2);
      return v.is_signed ? int64_t(int16_t(x)) : int64_t(x);
    }
    default: {
      uint32_t x;
      std::memcpy(&x, p, 4);
      return v.is_signed ? int64_t(int32_t(x)) : int64_t(x);
    }
  }
}

// An assembly kernel slower than this many times its C reference is taken to be hung.
constexpr uint64_t kAsmCycleFactor = 8;

uint32_t fnv(const std::string &s) {
  uint32_t h = 2166136261u;
  for (char c : s) h = (h ^ uint8_t(c)) * 16777619u;
  return h;
}

}  // namespace

const char *failure_kind_name(Failure::Kind k) {
  switch (k) {
    case Failure::Mismatch: return "mismatch";
    case Failure::ReturnValue: return "return value";
    case Failure::InputModified: return "input modified";
    case Failure::Guard: return "write outside buffer";
    case Failure::Abi: return "ABI violation";
    case Failure::Fault: return "fault";
    case Failure::Hang: return "hang";
    case Failure::Crash: return "simulator crash";
    default: return "failure";
  }
}

int CheckCall::in(std::string name, std::vector<uint8_t> bytes, View v) {
  bufs.push_back(make_buffer(std::move(name), Role::In, std::move(bytes), v));
  return int(bufs.size()) - 1;
}

int CheckCall::out(std::string name, size_t bytes, View v) {
  std::vector<uint8_t> d(bytes);
  for (size_t i = 0; i < bytes; ++i) d[i] = poison_byte(i);
  bufs.push_back(make_buffer(std::move(name), Role::Out, std::move(d), v));
  return int(bufs.size()) - 1;
}

int CheckCall::inout(std::string name, std::vector<uint8_t> bytes, View v) {
  bufs.push_back(make_buffer(std::move(name), Role::InOut, std::move(bytes), v));
  return int(bufs.size()) - 1;
}

int CheckCall::scratch(std::string name, size_t bytes) {
  std::vector<uint8_t> d(bytes);
  for (size_t i = 0; i < bytes; ++i) d[i] = poison_byte(i);
  bufs.push_back(make_buffer(std::move(name), Role::Scratch, std::move(d), {}));
  return int(bufs.size()) - 1;
}

namespace {
std::string differ(size_t n) { return std::to_string(n) + (n == 1 ? " element differs" : " elements differ"); }
}  // namespace

std::string first_difference(const std::vector<uint8_t> &expected, const std::vector<uint8_t> &actual,
                             const View &view) {
  View v = view;
  if (v.elem != 1 && v.elem != 2 && v.elem != 4) v.elem = 1;
  const size_t n = std::min(expected.size(), actual.size()) / size_t(v.elem);
  if (expected.size() != actual.size()) return "sizes differ";
  size_t first = n;
  for (size_t i = 0; i < n; ++i)
    if (element(expected, i, v) != element(actual, i, v)) {
      first = i;
      break;
    }
  if (first == n) {
    // An empty buffer (no points) has null data(), which memcmp must not see.
    if (expected.empty() || std::memcmp(expected.data(), actual.data(), expected.size()) == 0) return "";
    return "trailing bytes differ";
  }
  size_t ndiff = 0;
  for (size_t i = first; i < n; ++i) ndiff += element(expected, i, v) != element(actual, i, v);
  const int stride = v.width > 0 ? (v.stride > 0 ? v.stride : v.width) : 0;
  std::ostringstream s;
  if (stride > 0) {
    const int x = int(first % size_t(stride)), y = int(first / size_t(stride));
    s << "element (" << x << ", " << y << ")";
    if (x >= v.width) s << " (in the row padding)";
    s << ": expected " << element(expected, first, v) << ", got " << element(actual, first, v)
      << "; " << differ(ndiff) << "\n";
    // The 5x5 neighbourhood, expected | actual.
    for (int dy = -2; dy <= 2; ++dy) {
      const int yy = y + dy;
      if (yy < 0 || size_t(yy) * stride >= n) continue;
      std::string le, la;
      for (int dx = -2; dx <= 2; ++dx) {
        const int xx = x + dx;
        char b1[16], b2[16];
        if (xx < 0 || xx >= stride || size_t(yy) * stride + xx >= n) {
          std::snprintf(b1, sizeof b1, "%7s", ".");
          std::snprintf(b2, sizeof b2, "%7s", ".");
        } else {
          size_t k = size_t(yy) * stride + xx;
          std::snprintf(b1, sizeof b1, "%7lld", (long long)element(expected, k, v));
          std::snprintf(b2, sizeof b2, "%6lld%c", (long long)element(actual, k, v),
                        element(expected, k, v) != element(actual, k, v) ? '*' : ' ');
        }
        le += b1;
        la += b2;
      }
      s << "      y=" << yy << (dy == 0 ? ">" : " ") << le << "   |" << la << "\n";
    }
  } else {
    s << "element " << first << ": expected " << element(expected, first, v) << ", got "
      << element(actual, first, v) << "; " << differ(ndiff) << "\n";
  }
  return s.str();
}

std::string replay_command(const Failure &f) {
  if (f.case_id.empty()) return bfbench_name() + " check -k " + f.kernel + " --seed " + std::to_string(f.seed);
  return bfbench_name() + " check --seed " + std::to_string(f.seed) + " --case " + f.case_id;
}

namespace {
// A case's stream: (seed, family, case number) through splitmix's finaliser, so neighbouring
// cases and seeds give unrelated streams.
Rng case_stream(uint32_t seed, const std::string &family, uint32_t n) {
  Rng mix((uint64_t(seed) << 32 | n) ^ (uint64_t(fnv(family)) << 16));
  return Rng(mix.next());
}

// checkasm's adversarial oracle, per call: outputs and scratch start as random bytes (a pixel
// left unwritten shows whatever the poison), the caller-saved registers as junk, and a buffer
// may end where SDRAM does.
void make_adversarial(CheckCall &call, Rng &rng) {
  Rng poison(rng.next());
  for (auto &b : call.bufs)
    if (b.role == Role::Out || b.role == Role::Scratch)
      for (auto &v : b.data) v = uint8_t(poison.u32());
  call.junk_seed = rng.u32() | 1;  // 0 would mean "no junk"
  if (rng.uniform(0, 1) == 0) {
    std::vector<size_t> inputs, any;
    for (size_t i = 0; i < call.bufs.size(); ++i) {
      if (call.bufs[i].place != BVB_PLACE_SDRAM) continue;
      any.push_back(i);
      if (call.bufs[i].role == Role::In || call.bufs[i].role == Role::InOut) inputs.push_back(i);
    }
    const std::vector<size_t> &from = inputs.empty() ? any : inputs;
    const int pick = from.empty() ? 0 : rng.uniform(0, int(from.size()) - 1);
    if (!from.empty()) {
      call.bufs[from[size_t(pick)]].place = BVB_PLACE_SDRAM_END;
      call.case_name += " '" + call.bufs[from[size_t(pick)]].name + "' at SDRAM end";
    }
  }
}

}  // namespace

uint32_t canary_seed_of(uint32_t seed) {
  Rng r(uint64_t(seed) ^ 0xCA0A51E5ull);
  return r.u32() | 1;
}

Call target_call(const CheckCall &cc, uint32_t kernel, uint32_t impl, uint32_t canary_seed) {
  Call c;
  c.kernel = kernel;
  c.impl = impl;
  c.cycle_limit = cc.cycle_limit;
  c.args = cc.args;
  c.bufs = cc.bufs;
  c.junk_seed = cc.junk_seed;
  c.canary_seed = canary_seed;
  return c;
}

std::string fault_near_buffer(const Call &call, const CallResult &r) {
  if (r.status != BVB_FAULT || !data_cplb_fault(r.seqstat)) return "";
  // How far from a buffer a stray access still counts as that buffer's: a row or two of a
  // large frame, never another buffer's body.
  constexpr uint64_t kNear = 4096;
  std::string best;
  uint64_t best_dist = kNear;
  for (size_t i = 0; i < call.bufs.size() && i < BVB_MAX_BUFS; ++i) {
    const Buffer &b = call.bufs[i];
    const uint64_t start = r.buf_addr[i], end = start + b.data.size(), a = r.addr;
    std::string what;
    uint64_t dist = kNear;
    if (a >= end && a - end < best_dist) {
      dist = a - end;
      what = "an access " + std::to_string(dist + 1) + (dist ? " bytes" : " byte") + " past the end of buffer '" +
             b.name + "' (byte offset " + std::to_string(a - start) + " of " + std::to_string(b.data.size()) + ")";
      if (b.place == BVB_PLACE_SDRAM_END) what += "; it ended at the end of SDRAM, where nothing is mapped";
    } else if (a < start && start - a <= best_dist) {
      dist = start - a;
      what = "an access " + std::to_string(dist) + (dist == 1 ? " byte" : " bytes") + " before the start of buffer '" +
             b.name + "'";
    }
    if (!what.empty() && dist < best_dist) best = what, best_dist = dist;
  }
  return best;
}

Checker::Checker(const Target &target, CheckOptions opts)
    : target_(target), opts_(std::move(opts)), rng_(case_stream(opts_.seed, "", 0)),
      have_frames_(frames_real_present(opts_.frames_real)) {}

void Checker::reseed(const std::string &family) {
  family_ = family;
  case_no_ = 0;
  rng_ = case_stream(opts_.seed, family_, case_no_);
}

const std::vector<Pattern> &Checker::patterns() {
  static const std::vector<Pattern> without_real = [] {
    std::vector<Pattern> p;
    for (Pattern q : all_patterns())
      if (q != Pattern::Real) p.push_back(q);
    return p;
  }();
  if (have_frames_) return all_patterns();
  skip_real();
  return without_real;
}

void Checker::skip_real() { ++skipped_real_[family_]; }

std::string Checker::resolve(const std::string &kernel) const {
  auto it = opts_.kernel_alias.find(kernel);
  return it == opts_.kernel_alias.end() ? kernel : it->second;
}

bool Checker::wants(const std::string &kernel) const {
  const std::string k = resolve(kernel);
  return glob_match(opts_.kernel_glob, k) && target_.registry().find(k) != nullptr;
}

void Checker::place_randomly(CheckCall &call) {
  // One call in four keeps everything in SDRAM; otherwise each buffer goes to the first of the
  // L1 memories, tried from a random one, that still has room for it, else to SDRAM.
  static const uint32_t l1[3] = {BVB_PLACE_L1A, BVB_PLACE_L1B, BVB_PLACE_SCRATCH};
  uint64_t room[3];
  for (int i = 0; i < 3; ++i) room[i] = target_.arena_bytes(l1[i]);
  const bool sdram_only = rng_.uniform(0, 3) == 0;
  const int first = rng_.uniform(0, 2);
  for (auto &b : call.bufs) {
    b.place = BVB_PLACE_SDRAM;
    if (sdram_only) continue;
    const uint64_t need = b.data.size() + 2 * b.guard + b.align + b.skew;
    for (int k = 0; k < 3; ++k) {
      const int i = (first + k) % 3;
      if (need <= room[i]) {
        room[i] -= need;
        b.place = l1[i];
        break;
      }
    }
  }
}

void Checker::place_streaming(CheckCall &call, size_t scratch, Rng &rng) {
  const Buffer &b = call.bufs[scratch];
  const size_t need = b.data.size() + 2 * b.guard;
  const uint32_t l1 = need <= target_.arena_bytes(BVB_PLACE_L1A) ? BVB_PLACE_L1A : BVB_PLACE_L1B;
  if (rng.uniform(0, 1) == 0 && need <= target_.arena_bytes(l1)) {
    call.bufs[scratch].place = l1;
    call.case_name += " frames SDRAM";
  } else {
    place_randomly(call);
  }
}

void Checker::add(CheckCall call, Observer observer) {
  // The case number counts every call the family makes, queued or not, so -k and --case leave
  // every other case's number and stream as they are.
  call.case_id = case_id(call.kernel, case_no_);
  if (opts_.adversarial) make_adversarial(call, rng_);
  rng_ = case_stream(opts_.seed, family_, ++case_no_);
  if (!wants(call.kernel)) return;
  if (!opts_.only_case.empty() && call.case_id != opts_.only_case) return;
  call.kernel = resolve(call.kernel);
  pending_.push_back({std::move(call), std::move(observer)});
}

std::vector<const CheckCall *> Checker::pending() const {
  std::vector<const CheckCall *> out;
  for (const auto &p : pending_) out.push_back(&p.call);
  return out;
}

std::vector<std::string> Checker::coverage_gaps() const {
  std::vector<std::string> gaps;
  std::string only_kernel;
  if (!opts_.only_case.empty()) only_kernel = case_kernel(opts_.only_case);
  for (const auto &k : target_.registry().kernels()) {
    if (!glob_match(opts_.kernel_glob, k.name)) continue;
    if (!only_kernel.empty() && resolve(only_kernel) != k.name) continue;
    std::vector<std::string> impls = {"host"};
    if (opts_.run_c || !k.has_asm) impls.push_back(impl_name(BVB_IMPL_C));
    if (k.has_asm) impls.push_back(impl_name(BVB_IMPL_ASM));
    auto it = tally_.find(k.name);
    for (const auto &impl : impls)
      if (it == tally_.end() || !it->second.count(impl) || it->second.at(impl).calls == 0)
        gaps.push_back(kernel_impl_name(k.name, impl));
  }
  return gaps;
}

std::vector<Failure> compare_call(const CheckCall &cc, const std::string &impl, uint32_t seed,
                                  const std::vector<std::vector<uint8_t>> &actual,
                                  const std::vector<std::vector<uint8_t>> &expected, const HostBuffers &host,
                                  const uint32_t *ret) {
  std::vector<Failure> out;
  auto fail = [&](Failure::Kind kind, std::string msg) {
    out.push_back({cc.kernel, impl, cc.case_name, seed, kind, std::move(msg), cc.case_id});
  };
  if (ret && host.has_ret() && int32_t(*ret) != host.ret())
    fail(Failure::ReturnValue, "returned " + std::to_string(int32_t(*ret)) + ", expected " + std::to_string(host.ret()));
  for (size_t b = 0; b < cc.bufs.size() && b < actual.size(); ++b) {
    const Buffer &buf = cc.bufs[b];
    if (buf.role == Role::Scratch) continue;
    // Inputs against the bytes they were generated with: a reference that wrote its input must
    // not make the implementations that left it alone look guilty.
    const std::vector<uint8_t> &want = buf.role == Role::In ? buf.data : expected[b];
    std::string d = first_difference(want, actual[b], buf.view);
    if (d.empty()) continue;
    if (buf.role == Role::In)
      fail(Failure::InputModified, "input buffer '" + buf.name + "' was written: " + d);
    else
      fail(Failure::Mismatch, std::string(buf.role == Role::InOut ? "in/out " : "") + "buffer '" + buf.name + "' " + d);
  }
  return out;
}

void drop_kind_prefix(Failure &f) {
  const std::string prefix = std::string(failure_kind_name(f.kind)) + ": ";
  while (f.message.compare(0, prefix.size(), prefix) == 0) f.message.erase(0, prefix.size());
}

std::string format_failure(const Failure &f) {
  Failure g = f;
  drop_kind_prefix(g);
  char seed[16];
  std::snprintf(seed, sizeof seed, "%u", g.seed);
  return "FAILED " + kernel_impl_name(g.kernel, g.impl) + " " + g.case_name + ", seed " + seed + ", case " + g.case_id +
         ": " + failure_kind_name(g.kind) + ": " + sim::printable(g.message, 2000) + "\n  replay: " +
         replay_command(g) + "\n";
}

std::string format_check_report(const Tallies &tally, const std::vector<Failure> &failures, size_t max_shown,
                                uint32_t seed) {
  std::string out;
  for (const auto &kv : tally) {
    std::string line = "  " + kv.first;
    line.resize(std::max<size_t>(line.size() + 1, 26), ' ');
    for (const auto &it : kv.second)
      line += it.first + ": " + std::to_string(it.second.calls - it.second.failed) + "/" +
              std::to_string(it.second.calls) + " ok   ";
    out += line + "\n";
  }
  std::map<std::string, size_t> shown;
  std::map<std::string, std::string> kernel_of;  // "kernel (impl)" -> kernel, for those cut short
  for (const auto &f : failures) {
    const std::string key = kernel_impl_name(f.kernel, f.impl);
    if (shown[key]++ >= max_shown) {
      kernel_of[key] = f.kernel;
      continue;
    }
    out += format_failure(f);
  }
  // Say what was left out and how to see it, rather than stopping silently at the first few.
  for (const auto &kv : kernel_of) {
    const size_t more = shown[kv.first] - max_shown;
    out += "  ... " + std::to_string(more) + " more failure" + (more == 1 ? "" : "s") + " of " + kv.first +
           " not shown (-v shows all): " + bfbench_name() + " check -k " + kv.second + " --seed " + std::to_string(seed) + " -v\n";
  }
  return out;
}

std::string format_failed_calls(const std::map<std::string, Checker::Tally> &per_impl) {
  size_t calls = 0, failed = 0;
  std::string each;
  // The assembly first: it is what a failing check is usually about.
  std::vector<std::string> order;
  if (per_impl.count("asm")) order.push_back("asm");
  for (const auto &kv : per_impl)
    if (kv.first != "asm") order.push_back(kv.first);
  for (const auto &impl : order) {
    const Checker::Tally &t = per_impl.at(impl);
    calls += t.calls;
    failed += t.failed;
    each += (each.empty() ? "" : ", ") + impl + " " + std::to_string(t.failed) + " of " + std::to_string(t.calls);
  }
  if (!failed) return "";
  return std::to_string(failed) + " of " + std::to_string(calls) + " call" + (calls == 1 ? "" : "s") + " failed (" +
         each + ")";
}

void Checker::record(const CheckCall &cc, const std::string &impl, const std::vector<Failure> &found) {
  auto &t = tally_[cc.kernel][impl];
  ++t.calls;
  for (Failure f : found) {
    drop_kind_prefix(f);
    failures_.push_back(std::move(f));
  }
  if (!found.empty()) ++t.failed;
}

std::vector<Failure> Checker::judge(const CheckCall &cc, uint32_t impl, const Call &call, const CallResult &r,
                                    const std::vector<std::vector<uint8_t>> &expected,
                                    const HostBuffers &host) const {
  std::vector<Failure> found;
  auto fail = [&](Failure::Kind kind, std::string msg) {
    found.push_back({cc.kernel, impl_name(impl), cc.case_name, opts_.seed, kind, std::move(msg), cc.case_id});
  };
  if (!r.crash.empty()) {
    fail(Failure::Crash, describe_failure(call, r, target_.elf()));
  } else if (r.status == BVB_FAULT) {
    const std::string near = fault_near_buffer(call, r);
    fail(Failure::Fault, describe_failure(call, r, target_.elf()) + (near.empty() ? "" : ": " + near));
  } else if (r.status == BVB_HANG) {
    fail(Failure::Hang, describe_failure(call, r, target_.elf()));
  } else if (r.status != BVB_OK) {
    fail(Failure::Other, describe_failure(call, r, target_.elf()));
  } else {
    if (r.abi_bad) fail(Failure::Abi, abi_names(r.abi_bad));
    for (const auto &g : r.guard_damage)
      fail(Failure::Guard, std::string("overwrite ") + (g.before ? "before" : "after") + " buffer '" +
                               call.bufs[g.buffer].name + "' at byte offset " + std::to_string(g.offset));
    for (auto &f : compare_call(cc, impl_name(impl), opts_.seed, r.data, expected, host, &r.ret))
      found.push_back(std::move(f));
  }
  return found;
}

size_t Checker::flush() {
  if (pending_.empty()) return 0;
  const size_t before = failures_.size();
  std::vector<Call> calls;
  struct Slot {
    size_t pending;
    uint32_t impl;
  };
  std::vector<Slot> slots;
  for (size_t p = 0; p < pending_.size(); ++p) {
    const CheckCall &cc = pending_[p].call;
    const KernelInfo &k = target_.registry().get(cc.kernel);
    for (uint32_t impl : {uint32_t(BVB_IMPL_C), uint32_t(BVB_IMPL_ASM)}) {
      if (impl == BVB_IMPL_ASM && !k.has_asm) continue;
      if (impl == BVB_IMPL_C && !opts_.run_c && k.has_asm) continue;
      calls.push_back(target_call(cc, k.index, impl, opts_.adversarial ? canary_seed_of(opts_.seed) : 0));
      slots.push_back({p, impl});
    }
  }
  std::function<void(size_t, size_t)> progress;
  if (opts_.progress)
    progress = [](size_t done, size_t total) {
      std::fprintf(stderr, "\r  %zu/%zu calls", done, total);
      if (done == total) std::fprintf(stderr, "\r%*s\r", 30, "");
    };
  // The C calls run first: their cycles set the assembly's watchdog, so a runaway assembly
  // kernel costs a few times its reference's cycles, not the default limit.
  std::vector<CallResult> results(calls.size());
  for (uint32_t impl : {uint32_t(BVB_IMPL_C), uint32_t(BVB_IMPL_ASM)}) {
    std::vector<Call> batch;
    std::vector<size_t> index;
    for (size_t i = 0; i < calls.size(); ++i) {
      if (slots[i].impl != impl) continue;
      Call c = calls[i];
      if (impl == BVB_IMPL_ASM && !c.cycle_limit) {
        for (size_t j = 0; j < calls.size(); ++j)
          if (slots[j].pending == slots[i].pending && slots[j].impl == BVB_IMPL_C &&
              results[j].status == BVB_OK)
            c.cycle_limit = uint32_t(std::min<uint64_t>(Target::kDefaultCycleLimit,
                                                        kAsmCycleFactor * uint64_t(results[j].cycles) + 200000));
      }
      batch.push_back(std::move(c));
      index.push_back(i);
    }
    std::vector<CallResult> r = target_.run(batch, opts_.jobs, progress);
    for (size_t k = 0; k < index.size(); ++k) results[index[k]] = std::move(r[k]);
  }

  // Host reference per pending call, then judge each implementation against it.
  struct Reference {
    std::vector<std::vector<uint8_t>> expected;
    HostBuffers host{expected};
  };
  std::vector<std::unique_ptr<Reference>> refs;
  std::vector<std::vector<Failure>> found(calls.size());
  size_t s = 0;
  for (size_t p = 0; p < pending_.size(); ++p) {
    const CheckCall &cc = pending_[p].call;
    refs.push_back(std::make_unique<Reference>());
    Reference &ref = *refs.back();
    for (const auto &b : cc.bufs) ref.expected.push_back(b.data);
    if (cc.host) cc.host(ref.host);
    // The host reference is judged too: it must leave its inputs as they were.
    record(cc, "host", compare_call(cc, "host", opts_.seed, ref.expected, ref.expected, ref.host, nullptr));
    for (; s < slots.size() && slots[s].pending == p; ++s)
      found[s] = judge(cc, slots[s].impl, calls[s], results[s], ref.expected, ref.host);
  }
  // A failure that goes away when the caller-saved registers enter zero instead of junk comes
  // from a register (or an argument slot) the kernel read without setting it: say so.
  std::vector<Call> again;
  std::vector<size_t> which;
  for (size_t i = 0; i < calls.size(); ++i)
    if (!found[i].empty() && results[i].crash.empty() && calls[i].junk_seed) {
      Call c = calls[i];
      c.junk_seed = 0;
      c.cycle_limit = results[i].limit;
      again.push_back(std::move(c));
      which.push_back(i);
    }
  if (!again.empty()) {
    std::vector<CallResult> r = target_.run(again, opts_.jobs);
    for (size_t k = 0; k < which.size(); ++k) {
      const size_t i = which[k], p = slots[i].pending;
      if (!judge(pending_[p].call, slots[i].impl, again[k], r[k], refs[p]->expected, refs[p]->host).empty())
        continue;
      for (auto &f : found[i])
        f.message += "; with zero instead of junk in the caller-saved registers it passes: it reads a "
                     "register (or an argument) it never set";
    }
  }
  for (s = 0; s < slots.size(); ++s) {
    const size_t p = slots[s].pending;
    record(pending_[p].call, impl_name(slots[s].impl), found[s]);
    if (pending_[p].observer) pending_[p].observer(slots[s].impl, results[s]);
  }
  pending_.clear();
  return failures_.size() - before;
}

}  // namespace bvb
