#include "target.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <thread>
#include <chrono>
#include <memory>

#include <csignal>
#include <fcntl.h>

#include <sys/mman.h>
#include <unistd.h>

#include "cleanup.h"
#include "elf_symbols.h"
#include "io.h"
#include "simdriver.h"

namespace bvb {

namespace {

constexpr uint32_t kHeaderSize = sizeof(bvb_header);
constexpr uint32_t kCommandSize = sizeof(bvb_command);

uint32_t align_up(uint32_t v, uint32_t a) { return (v + a - 1) & ~(a - 1); }

// Where each buffer goes in the window: its guard band starts at offset, its data at
// offset + guard, which is placed at a multiple of align plus skew (what the firmware does for
// buffers that stay in the window).
struct Layout {
  std::vector<std::vector<uint32_t>> offsets;
  uint32_t size = 0;
};

Layout lay_out(const std::vector<const Call *> &calls) {
  Layout l;
  uint64_t pos = kHeaderSize + uint64_t(kCommandSize) * calls.size();
  for (const Call *c : calls) {
    std::vector<uint32_t> offs;
    for (const Buffer &b : c->bufs) {
      uint64_t data = ((pos + b.guard + b.align - 1) / b.align) * b.align + b.skew;
      offs.push_back(uint32_t(data - b.guard));
      pos = data + b.data.size() + b.guard;
      if (pos > BVB_WINDOW_MAX) throw InputError("a call's buffers do not fit the 32 MB window: the frames are too large for the Blackfin");
    }
    l.offsets.push_back(std::move(offs));
  }
  l.size = align_up(uint32_t(pos), 4096);
  return l;
}

uint64_t window_bytes(const Call &c) {
  uint64_t n = kCommandSize;
  for (const auto &b : c.bufs) n += b.data.size() + 2 * b.guard + b.align;
  return n;
}

void validate(const Call &c, const Registry &reg) {
  if (c.kernel >= reg.kernels().size()) throw InputError("call names no registered kernel");
  if (c.args.size() > BVB_MAX_ARGS) throw InputError("more than 12 arguments in a call");
  if (c.bufs.size() > BVB_MAX_BUFS) throw InputError("more than 8 buffers in a call");
  for (const auto &a : c.args)
    if (a.is_buffer && a.value >= c.bufs.size()) throw InputError("argument names no buffer");
  for (const auto &b : c.bufs)
    if (b.align < 4 || (b.align & (b.align - 1)) || b.skew >= b.align || (b.guard & 3))
      throw InputError("buffer " + b.name + ": bad alignment or guard");
}

std::string hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", v);
  return buf;
}

}  // namespace

const char *excause_name(uint32_t e) {
  switch (e) {
    case 0x10: return "single step";
    case 0x11: return "trace buffer full";
    case 0x21: return "undefined instruction";
    case 0x22: return "illegal instruction combination";
    case 0x23: return "data access CPLB protection violation";
    case 0x24: return "misaligned data access";
    case 0x25: return "unrecoverable event";
    case 0x26: return "data access CPLB miss";
    case 0x27: return "data access multiple CPLB hits";
    case 0x28: return "emulation watchpoint";
    case 0x2a: return "misaligned instruction fetch";
    case 0x2b: return "instruction fetch CPLB protection violation";
    case 0x2c: return "instruction fetch CPLB miss";
    case 0x2d: return "instruction fetch multiple CPLB hits";
    case 0x2e: return "illegal use of supervisor resource";
    default: return e < 0x10 ? "EXCPT instruction" : "exception";
  }
}

bool data_cplb_fault(uint32_t seqstat) {
  const uint32_t e = seqstat & 0x3f;
  return e == 0x23 || e == 0x26 || e == 0x27;
}

std::string abi_names(uint32_t abi) {
  static const char *names[] = {"R4", "R5", "R6", "R7", "P3", "P4", "P5", "FP", "SP"};
  std::string kept, circular, loops, counters;
  for (int i = 0; i < 9; ++i)
    if (abi >> i & 1) kept += (kept.empty() ? "" : ", ") + std::string(names[i]);
  for (int i = 0; i < 4; ++i)
    if (abi >> (9 + i) & 1) circular += (circular.empty() ? "L" : ", L") + std::to_string(i);
  for (int i = 0; i < 2; ++i)
    if (abi >> (13 + i) & 1) {
      loops += (loops.empty() ? "" : " and ") + std::to_string(i);
      counters += (counters.empty() ? "LC" : " and LC") + std::to_string(i);
    }
  std::string s;
  auto add = [&](const std::string &m) { s += (s.empty() ? "" : "; ") + m; };
  if (!kept.empty()) add("did not preserve " + kept);
  if (!circular.empty())
    add("left " + circular + " non-zero (circular addressing left on breaks every caller)");
  if (!loops.empty())
    add("left hardware loop " + loops + " armed (" + counters +
        " non-zero on return, its loop set up by the kernel: the caller's code would jump back "
        "at its loop bottom)");
  return s;
}

std::string describe_failure(const Call &call, const CallResult &r, const std::string &elf) {
  auto at = [&](uint32_t pc) {
    std::string sym = elf.empty() ? "" : symbolize(elf, pc);
    return hex(pc) + (sym.empty() ? "" : " (" + sym + ")");
  };
  std::string s;
  auto add = [&](const std::string &m) { s += (s.empty() ? "" : "; ") + m; };
  if (!r.crash.empty()) add("crashed the simulator: " + r.crash);
  switch (r.status) {
    case BVB_OK: break;
    case BVB_PENDING: if (r.crash.empty()) add("not run"); break;
    case BVB_FAULT: {
      uint32_t hw = (r.seqstat >> 14) & 0x1f;
      if (hw)
        add("hardware error (HWERRCAUSE " + std::to_string(hw) + ", e.g. an access to unmapped memory) near pc " + at(r.pc));
      else
        add(std::string("fault: ") + excause_name(r.seqstat & 0x3f) + " (EXCAUSE " +
            hex(r.seqstat & 0x3f) + ") at pc " + at(r.pc) +
            (data_cplb_fault(r.seqstat) ? ", address " + hex(r.addr) : ""));
      break;
    }
    case BVB_HANG:
      add("hang: still running after its cycle limit of " + std::to_string(r.limit) + " cycles, at pc " + at(r.pc));
      break;
    case BVB_BAD_COMMAND: add("firmware rejected the command (detail " + std::to_string(r.detail) + ")"); break;
    case BVB_NO_IMPL: add("no such implementation in the firmware"); break;
    case BVB_NO_SPACE:
      add("buffer " + (r.detail < call.bufs.size() ? call.bufs[r.detail].name : std::to_string(r.detail)) +
          " does not fit the memory it was placed in");
      break;
    default: add("unknown status " + std::to_string(r.status));
  }
  if (r.abi_bad) add("ABI violation: " + abi_names(r.abi_bad));
  for (const auto &g : r.guard_damage)
    add("overwrite " + std::string(g.before ? "before" : "after") + " buffer '" +
        call.bufs[g.buffer].name + "' at byte offset " + std::to_string(g.offset));
  return s;
}

namespace {

// Writes call c as command `index` of the window, its buffers (with guard bands) at offsets.
// Returns the cycle limit it runs under.
uint32_t encode_call(const Call &c, const std::vector<uint32_t> &offsets, uint32_t index, uint8_t *win,
                     bool with_persistent) {
  bvb_command cmd{};
  cmd.kernel = c.kernel;
  cmd.impl = c.impl;
  cmd.cycle_limit = c.cycle_limit ? c.cycle_limit : Target::kDefaultCycleLimit;
  cmd.nargs = uint32_t(c.args.size());
  cmd.nbufs = uint32_t(c.bufs.size());
  cmd.junk_seed = c.junk_seed;
  cmd.canary_seed = c.canary_seed;
  for (size_t a = 0; a < c.args.size(); ++a) {
    cmd.args[a] = c.args[a].value;
    if (c.args[a].is_buffer) cmd.argbuf |= 1u << a;
  }
  for (size_t b = 0; b < c.bufs.size(); ++b) {
    const Buffer &buf = c.bufs[b];
    cmd.bufs[b] = {offsets[b], uint32_t(buf.data.size()), buf.guard, buf.place, buf.align, buf.skew};
    if (buf.persistent && !with_persistent) continue;
    uint8_t *p = win + offsets[b];
    for (uint32_t g = 0; g < buf.guard; ++g) p[g] = p[buf.guard + buf.data.size() + g] = guard_byte(g);
    std::copy(buf.data.begin(), buf.data.end(), p + buf.guard);
  }
  std::memcpy(win + kHeaderSize + size_t(index) * kCommandSize, &cmd, sizeof cmd);
  return cmd.cycle_limit;
}

void decode_result(const Call &c, const std::vector<uint32_t> &offsets, uint32_t index, const uint8_t *win,
                   CallResult &r) {
  bvb_command cmd;
  std::memcpy(&cmd, win + kHeaderSize + size_t(index) * kCommandSize, sizeof cmd);
  r.status = cmd.status;
  r.limit = cmd.cycle_limit;
  r.detail = cmd.detail;
  r.cycles = cmd.cycles;
  r.ret = cmd.ret;
  r.abi_bad = cmd.abi_bad;
  r.seqstat = cmd.fault_seqstat;
  r.pc = cmd.fault_pc;
  r.addr = cmd.fault_addr;
  std::copy(std::begin(cmd.buf_addr), std::end(cmd.buf_addr), r.buf_addr);
  r.data.clear();
  r.guard_damage.clear();
  for (size_t b = 0; b < c.bufs.size(); ++b) {
    const Buffer &buf = c.bufs[b];
    const uint8_t *p = win + offsets[b];
    const size_t n = buf.data.size();
    r.data.emplace_back(p + buf.guard, p + buf.guard + n);
    for (uint32_t g = 0; g < buf.guard; ++g)
      if (p[buf.guard - 1 - g] != guard_byte(buf.guard - 1 - g)) {
        r.guard_damage.push_back({int(b), true, -int64_t(g) - 1});
        break;
      }
    for (uint32_t g = 0; g < buf.guard; ++g)
      if (p[buf.guard + n + g] != guard_byte(g)) {
        r.guard_damage.push_back({int(b), false, int64_t(n + g)});
        break;
      }
  }
}

// A window of calls, its header in h (run_window writes it at the start before each run, with
// the first command to run); limit_total sums their watchdog limits.
std::vector<uint8_t> encode_window(const std::vector<const Call *> &calls, Layout &l, bvb_header &h,
                                   uint64_t &limit_total) {
  l = lay_out(calls);
  std::vector<uint8_t> win(l.size, 0);
  h = bvb_header{};
  h.magic = BVB_MAGIC;
  h.version = BVB_VERSION;
  h.window_size = l.size;
  h.ncommands = uint32_t(calls.size());
  limit_total = 0;
  for (size_t i = 0; i < calls.size(); ++i)
    limit_total += encode_call(*calls[i], l.offsets[i], uint32_t(i), win.data(), true);
  return win;
}

}  // namespace

std::string make_temp_file() {
  const char *tmpdir = std::getenv("TMPDIR");
  std::string tmpl = std::string(tmpdir && *tmpdir ? tmpdir : "/tmp") + "/bfbench-window-XXXXXX";
  std::vector<char> pathbuf(tmpl.begin(), tmpl.end());
  pathbuf.push_back(0);
  int fd = mkstemp(pathbuf.data());
  if (fd < 0) throw sim::SetupError("cannot create a window file: " + tmpl);
  close(fd);
  register_temp_file(pathbuf.data());  // removed if bfbench is interrupted
  return pathbuf.data();
}

Target::Target(FirmwareImage image, std::string simulator)
    : image_(std::move(image)), simulator_(std::move(simulator)), timing_(default_timing()) {}

void Target::set_timing(const std::string &t) {
  if (!valid_timing(t)) throw InputError("timing model '" + t + "' unknown (none or bf537)");
  timing_ = t;
}

uint32_t Target::arena_bytes(uint32_t place) const {
  static const char *names[][2] = {{"_sdram_arena_start", "_sdram_arena_end"},
                                   {"_l1a_arena_start", "_l1a_arena_end"},
                                   {"_l1b_arena_start", "_l1b_arena_end"},
                                   {"_scratch_arena_start", "_scratch_arena_end"}};
  if (place >= BVB_PLACE_WINDOW) return BVB_WINDOW_MAX;
  auto it = arena_override_.find(place);
  if (it != arena_override_.end()) return it->second;
  uint32_t lo = 0, hi = 0;
  if (!symbol_value(image_.elf, names[place][0], &lo) || !symbol_value(image_.elf, names[place][1], &hi))
    throw sim::SetupError(image_.elf + ": no arena symbols (not a bfbench firmware image?)");
  return hi > lo ? hi - lo : 0;
}

sim::RunSpec Target::run_spec(const std::vector<const Call *> &calls, const std::string &path, uint32_t size,
                              uint64_t limit_total) const {
  sim::RunSpec spec;
  spec.simulator = simulator_;
  spec.options = {"--timing", timing_};
  for (const auto &[impl, opts] : impl_options_)
    if (std::any_of(calls.begin(), calls.end(), [impl = impl](const Call *c) { return c->impl == impl; }))
      spec.options.insert(spec.options.end(), opts.begin(), opts.end());
  spec.elf = image_.elf;
  spec.maps.push_back({path, BVB_WINDOW_ADDR, size});
  // A generous floor for slow machines: the simulator runs well over 5 M cycles per second.
  spec.wall_timeout_s = 120 + double(limit_total) / 5e6;
  return spec;
}

sim::RunSpec Target::write_window(const Call &call, const std::string &path) const {
  validate(call, registry());
  const std::vector<const Call *> calls = {&call};
  Layout l;
  bvb_header h;
  uint64_t limit_total = 0;
  std::vector<uint8_t> win = encode_window(calls, l, h, limit_total);
  std::memcpy(win.data(), &h, sizeof h);
  write_file_atomic(path, win);
  return run_spec(calls, path, l.size, limit_total);
}

void Target::run_window(const std::vector<const Call *> &calls,
                        std::vector<CallResult *> &out) const {
  const std::string path = make_temp_file();
  struct Cleanup {
    std::string p;
    ~Cleanup() { remove_temp_file(p); }
  } cleanup{path};
  Layout l;
  bvb_header h;
  uint64_t limit_total = 0;
  std::vector<uint8_t> win = encode_window(calls, l, h, limit_total);
  const sim::RunSpec spec = run_spec(calls, path, l.size, limit_total);

  for (;;) {
    std::memcpy(win.data(), &h, sizeof h);
    write_file_atomic(path, win);
    sim::RunResult rr = sim::run(spec);
    win = read_file(path);
    if (win.size() != l.size) throw sim::SetupError("window file changed size");
    bvb_header got;
    std::memcpy(&got, win.data(), sizeof got);
    if (got.state == BVB_FW_NOT_STARTED || got.state == BVB_FW_BAD_HEADER)
      throw sim::SetupError("firmware " + image_.elf + " did not start: " + sim::describe(rr));
    if (got.registry_count != registry().kernels().size() || got.registry_hash != registry().hash())
      throw sim::SetupError("firmware " + image_.elf +
                            " has a different kernel registry than this bfbench: rebuild both");
    null_call_cycles_ = got.null_call_cycles;

    // Killed from outside (by a user, a job control, the OOM killer), the simulator says nothing
    // about the kernel it was running: that is no failure of the kernel's.
    if (rr.ending == sim::Ending::Signalled &&
        (rr.signal == SIGKILL || rr.signal == SIGTERM || rr.signal == SIGINT || rr.signal == SIGHUP))
      throw sim::SetupError("the simulator was killed from outside bfbench (" + sim::describe(rr) +
                            "); no kernel is to blame: run again");
    uint32_t resume = uint32_t(calls.size());
    if (got.state != BVB_FW_DONE) {
      // The simulator died inside command `current`: blame it, go on after it.
      uint32_t cur = got.current;
      if (cur < h.first || cur >= calls.size()) throw sim::SetupError("firmware died: " + sim::describe(rr));
      std::string why = sim::describe(rr);
      if (got.fatal_pc)
        why += " (firmware fault: " + std::string(excause_name(got.fatal_seqstat & 0x3f)) +
               " at pc " + hex(got.fatal_pc) + " " + symbolize(image_.elf, got.fatal_pc) + ")";
      out[cur]->crash = why;
      resume = cur + 1;
    } else if (rr.ending != sim::Ending::Exited || rr.exit_code != 0) {
      throw sim::SetupError("firmware finished but " + sim::describe(rr));
    }

    for (uint32_t i = h.first; i < std::min<uint32_t>(resume, uint32_t(calls.size())); ++i) {
      decode_result(*calls[i], l.offsets[i], uint32_t(i), win.data(), *out[i]);
    }
    if (resume >= calls.size()) return;
    h.first = resume;
    win = read_file(path);
  }
}

std::vector<CallResult> Target::run(const std::vector<Call> &calls, int jobs,
                                    const std::function<void(size_t, size_t)> &progress) const {
  for (const auto &c : calls) validate(c, registry());
  std::vector<CallResult> results(calls.size());
  if (calls.empty()) return results;

  // Split into windows: at most the window size, and enough of them to keep `jobs` busy.
  jobs = std::max(1, jobs);
  uint64_t total = 0;
  for (const auto &c : calls) total += window_bytes(c);
  const uint64_t cap = uint64_t(BVB_WINDOW_MAX) - 65536;
  const size_t per_window_calls =
      isolated_ ? 1 : std::max<size_t>(1, (calls.size() + jobs - 1) / jobs);
  std::vector<std::pair<size_t, size_t>> windows;  // [begin, end)
  size_t begin = 0;
  uint64_t bytes = sizeof(bvb_header);
  for (size_t i = 0; i < calls.size(); ++i) {
    uint64_t b = window_bytes(calls[i]);
    if (i > begin && (bytes + b > cap || i - begin >= per_window_calls)) {
      windows.push_back({begin, i});
      begin = i;
      bytes = sizeof(bvb_header);
    }
    bytes += b;
  }
  windows.push_back({begin, calls.size()});

  std::atomic<size_t> next{0}, done{0};
  std::mutex mu;
  std::exception_ptr error;
  auto worker = [&] {
    for (;;) {
      size_t w = next++;
      if (w >= windows.size()) return;
      std::vector<const Call *> cs;
      std::vector<CallResult *> rs;
      for (size_t i = windows[w].first; i < windows[w].second; ++i) {
        cs.push_back(&calls[i]);
        rs.push_back(&results[i]);
      }
      try {
        run_window(cs, rs);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mu);
        if (!error) error = std::current_exception();
        next = windows.size();
        return;
      }
      size_t d = done += cs.size();
      if (progress) {
        std::lock_guard<std::mutex> lock(mu);
        progress(d, calls.size());
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < std::min<int>(jobs, int(windows.size())); ++t) threads.emplace_back(worker);
  worker();
  for (auto &t : threads) t.join();
  if (error) std::rethrow_exception(error);
  return results;
}

struct Session::Impl {
  const Target &target;
  std::string path;
  Layout layout;
  std::vector<size_t> sizes;  // buffer sizes the layout was made for
  uint8_t *win = nullptr;
  std::unique_ptr<sim::Process> proc;
  uint32_t request = 0;

  explicit Impl(const Target &t) : target(t) {}
  ~Impl() {
    if (proc && win) {
      auto *h = reinterpret_cast<volatile bvb_header *>(win);
      h->request = BVB_STOP;
      proc->finish(10);
    }
    if (win) munmap(win, layout.size);
    if (!path.empty()) remove_temp_file(path);
  }

  bvb_header *header() { return reinterpret_cast<bvb_header *>(win); }

  void start(const Call &c) {
    std::vector<const Call *> one = {&c};
    layout = lay_out(one);
    for (const auto &b : c.bufs) sizes.push_back(b.data.size());
    path = make_temp_file();
    if (truncate(path.c_str(), off_t(layout.size)) != 0) throw sim::SetupError("cannot size " + path);
    int fd = open(path.c_str(), O_RDWR);
    if (fd < 0) throw sim::SetupError("cannot open " + path);
    void *m = mmap(nullptr, layout.size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    close(fd);
    if (m == MAP_FAILED) throw sim::SetupError("cannot map " + path);
    win = static_cast<uint8_t *>(m);
    bvb_header h{};
    h.magic = BVB_MAGIC;
    h.version = BVB_VERSION;
    h.window_size = layout.size;
    h.ncommands = 1;
    h.flags = BVB_SERVE;
    h.served = ~0u - 1;  // nothing served yet: request 0 is answered when served becomes 0
    std::memcpy(win, &h, sizeof h);
    encode_call(c, layout.offsets[0], 0, win, true);
    sim::RunSpec spec;
    spec.simulator = target.simulator();
    spec.options = {"--timing", target.timing()};
    spec.elf = target.elf();
    spec.maps.push_back({path, BVB_WINDOW_ADDR, layout.size});
    proc = std::make_unique<sim::Process>(spec);
  }

  // Waits until the firmware has served the current request.
  void wait(uint32_t cycle_limit) {
    auto *h = reinterpret_cast<volatile bvb_header *>(win);
    // Backstop only: the firmware's watchdog bounds the call itself.
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::seconds(120 + int64_t(cycle_limit / 5000000));
    int spins = 0;
    for (;;) {
      std::atomic_thread_fence(std::memory_order_acquire);
      if (h->served == request && h->state == BVB_FW_DONE) return;
      if (h->state == BVB_FW_BAD_HEADER) throw sim::SetupError("firmware rejected the window");
      if (!proc->running()) {
        sim::RunResult r = proc->finish(1);
        proc.reset();
        throw sim::SetupError("simulator died during a call: " + sim::describe(r));
      }
      if (std::chrono::steady_clock::now() > deadline)
        throw sim::SetupError("simulator did not answer in time");
      if (++spins > 1000) usleep(50);
    }
  }
};

Session::Session(const Target &target) : impl_(new Impl(target)) {}
Session::~Session() { delete impl_; }

CallResult Session::call(const Call &c) {
  Impl &s = *impl_;
  if (!s.proc && s.win) throw sim::SetupError("session is over (the simulator died)");
  if (!s.win) {
    s.start(c);
  } else {
    if (c.bufs.size() != s.sizes.size()) throw InputError("session call with another buffer layout");
    for (size_t b = 0; b < c.bufs.size(); ++b)
      if (c.bufs[b].data.size() != s.sizes[b]) throw InputError("session call with other buffer sizes");
    encode_call(c, s.layout.offsets[0], 0, s.win, false);
    auto *h = reinterpret_cast<volatile bvb_header *>(s.win);
    h->state = BVB_FW_RUNNING;
    std::atomic_thread_fence(std::memory_order_release);
    h->request = ++s.request;
  }
  s.wait(c.cycle_limit ? c.cycle_limit : Target::kDefaultCycleLimit);
  CallResult r;
  decode_result(c, s.layout.offsets[0], 0, s.win, r);
  return r;
}

namespace {
std::string env_or(const char *name, const std::string &fallback) {
  const char *v = std::getenv(name);
  return v && *v ? v : fallback;
}
}  // namespace

FirmwareImage product_firmware() {
  return {env_or("BFBENCH_FIRMWARE", product().elf), &Registry::product()};
}

FirmwareImage selftest_firmware() {
  return {env_or("BFBENCH_SELFTEST_FIRMWARE", BVB_SELFTEST_ELF), &Registry::selftest()};
}

std::string default_simulator() { return sim::find_simulator(BVB_DEFAULT_SIMULATOR); }

bool valid_timing(const std::string &t) { return t == "none" || t == "bf537"; }

std::string default_timing() {
  const char *env = std::getenv("BFBENCH_TIMING");
  if (!env || !*env) return "bf537";
  if (!valid_timing(env))
    throw InputError(std::string("BFBENCH_TIMING='") + env + "' is not a timing model (none or bf537)");
  return env;
}

}  // namespace bvb
