// bfbench: check, benchmark and run Blackfin vision kernels in the GNU simulator.
// Exit status: 0 success, 1 a check or budget failed, 2 bad usage or bad input.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "bench.h"
#include "bfbench.h"
#include "check.h"
#include "cleanup.h"
#include "debug.h"
#include "family.h"
#include "io.h"
#include "patterns.h"
#include "profile.h"
#include "simdriver.h"
#include "target.h"

namespace bvb {
int extra_command(const std::string &name, int argc, char **argv, bool *handled);
void print_extra_commands(FILE *out);
}

namespace {

using namespace bvb;

struct Usage : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char *kMainHelp =
    "usage: bfbench COMMAND [options]\n"
    "\n"
    "Checks, benchmarks and runs Blackfin vision kernels inside the GNU Blackfin simulator.\n"
    "\n"
    "commands:\n"
    "  list                     kernels and their implementations\n"
    "  check                    C reference (host and Blackfin) vs assembly, bit for bit\n"
    "  bench                    modelled BF537 cycles per call and per pixel, C vs assembly\n"
    "  run KERNEL               one kernel on given frames\n"
    "  budgets                  compare the bench with the budgets (ci/budgets.json)\n"
    "  profile KERNEL           where one call's modelled cycles go, per source line and loop\n"
    "  debug KERNEL             one check call in bfin-elf-gdb, stopped at the kernel's entry\n";
const char *kMainHelpTail =
    "\n"
    "'bfbench COMMAND --help' describes each. Exit status: 0 success, 1 a check or budget\n"
    "failed, 2 bad usage or bad input.\n";

void print_help(FILE *out) {
  std::fputs(kMainHelp, out);
  bvb::print_extra_commands(out);
  std::fputs(kMainHelpTail, out);
}

// Minimal option scanner: --name value, --name=value, and flags.
class Args {
 public:
  Args(int argc, char **argv, int first) {
    for (int i = first; i < argc; ++i) a_.push_back(argv[i]);
  }
  bool flag(const std::string &name) {
    for (size_t i = 0; i < a_.size(); ++i)
      if (a_[i] == name) {
        a_.erase(a_.begin() + long(i));
        return true;
      }
    return false;
  }
  std::vector<std::string> values(const std::string &name, const std::string &alias = "") {
    std::vector<std::string> out;
    for (size_t i = 0; i < a_.size();) {
      const std::string &s = a_[i];
      if (s == name || (!alias.empty() && s == alias)) {
        if (i + 1 >= a_.size()) throw Usage(s + " needs a value");
        out.push_back(a_[i + 1]);
        a_.erase(a_.begin() + long(i), a_.begin() + long(i) + 2);
      } else if (s.rfind(name + "=", 0) == 0) {
        out.push_back(s.substr(name.size() + 1));
        a_.erase(a_.begin() + long(i));
      } else {
        ++i;
      }
    }
    return out;
  }
  std::string value(const std::string &name, const std::string &fallback, const std::string &alias = "") {
    auto v = values(name, alias);
    if (v.size() > 1) throw Usage(name + " given more than once");
    return v.empty() ? fallback : v[0];
  }
  // The values of an option, without taking them.
  std::vector<std::string> values_peek(const std::string &name) const {
    std::vector<std::string> out;
    for (size_t i = 0; i < a_.size(); ++i) {
      if (a_[i] == name && i + 1 < a_.size()) out.push_back(a_[i + 1]);
      else if (a_[i].rfind(name + "=", 0) == 0) out.push_back(a_[i].substr(name.size() + 1));
    }
    return out;
  }
  std::vector<std::string> positional() {
    std::vector<std::string> out;
    for (auto &s : a_) {
      if (s.size() > 1 && s[0] == '-') throw Usage("unknown option " + s);
      out.push_back(s);
    }
    a_.clear();
    return out;
  }

 private:
  std::vector<std::string> a_;
};

long to_long(const std::string &s, const std::string &what, long lo, long hi) {
  char *end = nullptr;
  errno = 0;
  long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end || errno || v < lo || v > hi)
    throw Usage(what + " wants an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                ", got '" + s + "'");
  return v;
}

Size parse_size(const std::string &s) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 ||
      w > kMaxFrameDim || h > kMaxFrameDim)
    throw Usage("--size wants WxH (1.." + std::to_string(kMaxFrameDim) + "), got '" + s + "'");
  return {w, h};
}

int default_jobs() {
  unsigned n = std::thread::hardware_concurrency();
  return n ? int(n) : 2;
}

bool help_requested(Args &args, const char *text) {
  if (args.flag("--help") || args.flag("-h")) {
    std::fputs(text, stdout);
    return true;
  }
  return false;
}

Target make_target(Args &args, bool selftest = false) {
  FirmwareImage fw = selftest ? selftest_firmware() : product_firmware();
  std::string elf = args.value("--firmware", "");
  if (!elf.empty()) fw.elf = elf;
  Target t(fw, default_simulator());
  std::string timing = args.value("--timing", "");
  if (!timing.empty()) {
    if (!valid_timing(timing)) throw Usage("--timing wants none or bf537, got '" + timing + "'");
    t.set_timing(timing);
  }
  return t;
}

// ---------------------------------------------------------------------------------------------

int cmd_list(Args &args) {
  if (help_requested(args, "usage: bfbench list\n\nLists every kernel: its family and implementations.\n"))
    return 0;
  args.positional();
  for (const auto &k : Registry::product().kernels()) {
    const Family *f = family_of(k.name);
    std::printf("%-24s %-14s c%s\n", k.name.c_str(), f ? f->name.c_str() : "-", k.has_asm ? " asm" : "");
  }
  return 0;
}

int cmd_check(Args &args) {
  if (help_requested(args,
                     "usage: bfbench check [-k GLOB] [--seed N] [--seeds COUNT] [-j N] [--campaign]\n"
                     "                     [--case KERNEL:N] [--timing none|bf537] [--firmware ELF] [-v]\n\n"
                     "Runs every kernel's C reference on the Blackfin and its assembly in the simulator\n"
                     "on seeded random, crafted and real frames over many sizes, and compares both with\n"
                     "the host-compiled C reference, bit for bit; guard bands, callee-saved registers,\n"
                     "faults and hangs are checked too. The seed is printed; --seed replays it.\n"
                     "  -k GLOB       kernels to check (shell glob, default *)\n"
                     "  --seed N      first seed (default: from the clock)\n"
                     "  --seeds COUNT seeds N, N+1, ... (default 1)\n"
                     "  -j N          simulator processes at once (default: cores)\n"
                     "  --campaign    larger sizes (up to 640x480) and more random cases\n"
                     "  --case ID     only the call ID (KERNEL:N, as a failure prints it), with its seed\n"
                     "Fails (exit 1) when a selected kernel gets no judged call for one of its\n"
                     "implementations. Real-frame cases need $BFBENCH_FRAMES_REAL (default\n"
                     "../shared/frames-real): without it they are skipped, with a message, or with\n"
                     "BVB_REQUIRE_FRAMES=1 the check stops with an error.\n"))
    return 0;
  CheckOptions opts;
  opts.kernel_glob = args.value("-k", "*", "--kernel");
  std::string seed = args.value("--seed", "");
  opts.seed = seed.empty() ? uint32_t(std::time(nullptr)) % 1000000 : uint32_t(to_long(seed, "--seed", 0, 4294967295L));
  long seeds = to_long(args.value("--seeds", "1"), "--seeds", 1, 100000);
  opts.jobs = int(to_long(args.value("-j", std::to_string(default_jobs())), "-j", 1, 256));
  opts.campaign = args.flag("--campaign");
  opts.verbose = args.flag("-v");
  opts.progress = isatty(2);
  opts.frames_real = default_frames_real();
  opts.only_case = args.value("--case", "");
  Target target = make_target(args);
  args.positional();

  if (!opts.only_case.empty()) {
    // KERNEL:N names one call; the kernel selects its family, as -k would.
    const size_t colon = opts.only_case.rfind(':');
    const std::string kernel = colon == std::string::npos ? "" : opts.only_case.substr(0, colon);
    const std::string n = colon == std::string::npos ? "" : opts.only_case.substr(colon + 1);
    if (kernel.empty() || n.empty() || n.find_first_not_of("0123456789") != std::string::npos)
      throw Usage("--case wants KERNEL:N as a failure prints it, got '" + opts.only_case + "'");
    target.registry().get(kernel);
    if (opts.kernel_glob != "*" && !glob_match(opts.kernel_glob, kernel))
      throw Usage("--case " + opts.only_case + " is not of a kernel -k '" + opts.kernel_glob + "' selects");
    opts.kernel_glob = kernel;
    if (seed.empty()) throw Usage("--case needs the --seed the failure printed");
  }
  bool any = false;
  for (const auto &k : target.registry().kernels()) any |= glob_match(opts.kernel_glob, k.name);
  if (!any) throw InputError("no kernel matches '" + opts.kernel_glob + "' (bfbench list)");
  if (!frames_real_present(opts.frames_real) && frames_required())
    throw InputError(frames_missing_message(opts.frames_real));

  size_t failures = 0, calls = 0, host_failures = 0;
  std::map<std::string, Checker::Tally> per_impl;  // Blackfin calls, over every seed
  std::vector<std::string> gaps;
  for (long s = 0; s < seeds; ++s) {
    CheckOptions o = opts;
    o.seed = opts.seed + uint32_t(s);
    Checker ck(target, o);
    for (const Family *f : families()) {
      bool wanted = false;
      for (const auto &k : f->kernels) wanted |= ck.wants(k);
      if (!wanted) continue;
      ck.reseed(f->name);
      f->check(ck);
      ck.flush();
    }
    std::printf("seed %u:\n", o.seed);
    std::fputs(format_check_report(ck.tally(), ck.failures(), opts.verbose ? SIZE_MAX : 3, o.seed).c_str(), stdout);
    for (const auto &kv : ck.skipped_real())
      std::printf("  %s: %s\n", kv.first.c_str(), frames_missing_message(o.frames_real).c_str());
    // Calls that failed, not failure records: one call can fail several ways at once. The host
    // reference's runs are judged (its inputs) but are not calls on the Blackfin.
    for (const auto &kv : ck.tally())
      for (const auto &it : kv.second) {
        if (it.first == "host") {
          host_failures += it.second.failed;
        } else {
          calls += it.second.calls, failures += it.second.failed;
          per_impl[it.first].calls += it.second.calls;
          per_impl[it.first].failed += it.second.failed;
        }
      }
    if (s == 0) gaps = ck.coverage_gaps();
  }
  // A kernel, or one of its implementations, that no call reached was not checked at all: that
  // is no pass (a registry entry without a family, a family that forgets a kernel, a --case that
  // names no call).
  for (const auto &g : gaps) std::printf("NOT CHECKED %s: no call judged\n", g.c_str());
  if (failures || host_failures || !gaps.empty()) {
    if (failures) std::printf("%s\n", format_failed_calls(per_impl).c_str());
    if (host_failures) std::printf("%zu host reference runs failed (they wrote their inputs)\n", host_failures);
    if (!gaps.empty()) std::printf("%zu kernel implementations not checked\n", gaps.size());
    return 1;
  }
  std::printf("all %zu calls bit-exact, guards intact, ABI kept\n", calls);
  return 0;
}

// A size below a selected kernel's minimum is the user's mistake, caught before anything runs
// (below it the helpers divide by empty ranges and the assembly reads past its buffers).
void check_bench_sizes(const std::string &glob, const std::vector<Size> &sizes) {
  for (const auto &k : Registry::product().kernels()) {
    if (!glob_match(glob, k.name)) continue;
    for (Size s : sizes) {
      std::string why = bench_size_problem(k.name, s.w, s.h);
      if (!why.empty()) throw Usage("--size " + std::to_string(s.w) + "x" + std::to_string(s.h) + ": " + why +
                                    " (-k selects kernels)");
    }
  }
}

// Only assembly kernels have budgets: a -k that selects none would judge nothing and pass.
void check_budget_glob(const std::string &glob) {
  for (const auto &k : Registry::product().kernels())
    if (k.has_asm && glob_match(glob, k.name)) return;
  throw InputError("no assembly kernel matches '" + glob + "' (bfbench list)");
}

std::vector<Size> parse_sizes(Args &args) {
  std::vector<Size> sizes;
  for (const auto &s : args.values("--size")) sizes.push_back(parse_size(s));
  return sizes;
}

int cmd_bench(Args &args) {
  if (help_requested(args,
                     "usage: bfbench bench [-k GLOB] [--size WxH]... [--json FILE] [--csv FILE]\n"
                     "                     [--markdown FILE] [--asm-only] [--timing none|bf537] [--no-sim]\n"
                     "                     [-j N] [--firmware ELF]\n\n"
                     "Cycles per call and per pixel for each kernel's C reference built for the\n"
                     "Blackfin and for its assembly, the empty-call overhead measured and subtracted,\n"
                     "the speed-up, and the kernel's stated lower bound. Cycles are modelled BF537\n"
                     "cycles (bfin-elf-run --timing bf537: pipeline stalls, L1 banks, SDRAM, caches);\n"
                     "each call also runs under --timing none and the simulator's own count is shown\n"
                     "beside the model's (--no-sim skips that run), with where the buffers were\n"
                     "placed. Sizes default to 160x120, 320x240 and 640x480. Every measured call is\n"
                     "also checked. $BFBENCH_TIMING sets the default model.\n"))
    return 0;
  BenchOptions opts;
  opts.kernel_glob = args.value("-k", "*", "--kernel");
  auto sizes = parse_sizes(args);
  check_bench_sizes(opts.kernel_glob, sizes);
  if (!sizes.empty()) opts.sizes = sizes;
  std::string json_path = args.value("--json", ""), csv_path = args.value("--csv", ""),
              md_path = args.value("--markdown", "");
  opts.run_c = !args.flag("--asm-only");
  opts.compare_sim = !args.flag("--no-sim");
  opts.jobs = int(to_long(args.value("-j", std::to_string(default_jobs())), "-j", 1, 256));
  opts.progress = isatty(2);
  Target target = make_target(args);
  args.positional();
  auto rows = run_bench(target, opts);
  if (rows.empty()) throw InputError("no kernel matches '" + opts.kernel_glob + "' (bfbench list)");
  std::fputs(bench_table(rows, target.null_call_cycles()).c_str(), stdout);
  if (!json_path.empty()) {
    std::string j = bench_json(rows, target.null_call_cycles());
    write_file_atomic(json_path, j.data(), j.size());
  }
  if (!csv_path.empty()) {
    std::string c = bench_csv(rows);
    write_file_atomic(csv_path, c.data(), c.size());
  }
  if (!md_path.empty()) {
    std::string m = bench_markdown(rows);
    write_file_atomic(md_path, m.data(), m.size());
  }
  for (const auto &r : rows)
    if (!r.error.empty()) return 1;
  return 0;
}

// The buffer an --out F.npy writes: the one --out-buffer names, else the call's first output.
int pick_output_buffer(const CheckCall &call, const std::string &name) {
  std::string outputs;
  int first = -1;
  for (size_t i = 0; i < call.bufs.size(); ++i) {
    const Buffer &b = call.bufs[i];
    if (b.role != Role::Out && b.role != Role::InOut) continue;
    if (first < 0) first = int(i);
    if (b.name == name) return int(i);
    outputs += (outputs.empty() ? "" : ", ") + b.name;
  }
  if (name.empty() && first >= 0) return first;
  if (first < 0) throw InputError(call.kernel + " has no output buffer to write as .npy");
  throw Usage("--out-buffer " + name + ": no such output buffer (this call has " + outputs + ")");
}

int cmd_run(Args &args) {
  if (help_requested(args,
                     "usage: bfbench run KERNEL --in FILE [--in FILE] --out FILE [--impl asm|c|host]\n"
                     "                  [--param K=V]... [--size WxH] [--grey] [--out-buffer NAME]\n"
                     "                  [--timing none|bf537] [--firmware ELF]\n\n"
                     "Runs one kernel on the given frames and writes its output; prints the cycles of the\n"
                     "call (modelled BF537 cycles, or the simulator's own with --timing none). --impl\n"
                     "defaults to asm, or c for kernels without assembly.\n"
                     "Formats follow the file names: frames in and out as .pgm (grey), .ppm (RGB), .pnm,\n"
                     ".png (8-bit grey or RGB) or .npy (uint8 HxW or HxWx3), raw .uyvy with --size WxH;\n"
                     "flow out as .flo or .npy (float32 HxWx2); lists out as .csv or .txt. --out F.npy\n"
                     "writes an output buffer as it is, with its element type and shape (--out-buffer NAME\n"
                     "picks which; default the first). A name without an extension gets the output's own\n"
                     "format (PNM, .flo or text), any other extension is an error.\n"
                     "  --grey           convert colour frames for a kernel of grey frames (BT.601 luma);\n"
                     "                   without it a colour frame is an error\n"))
    return 0;
  RunRequest req;
  req.inputs = args.values("--in");
  req.output = args.value("--out", "");
  req.grey_from_colour = args.flag("--grey");
  const std::string out_buffer = args.value("--out-buffer", "");
  std::string impl = args.value("--impl", "");
  for (const auto &p : args.values("--param")) req.params.set(p);
  auto sizes = parse_sizes(args);
  if (sizes.size() > 1) throw Usage("--size given more than once");
  if (!sizes.empty()) req.raw_width = sizes[0].w, req.raw_height = sizes[0].h;
  std::string elf = args.value("--firmware", "");
  std::string timing = args.value("--timing", "");
  if (!timing.empty() && !valid_timing(timing)) throw Usage("--timing wants none or bf537, got '" + timing + "'");
  auto pos = args.positional();
  if (pos.size() != 1) throw Usage("run takes one KERNEL (bfbench list)");
  req.kernel = pos[0];
  if (req.inputs.empty()) throw Usage("run needs --in FILE");
  if (req.output.empty()) throw Usage("run needs --out FILE");
  // The output's name decides its format: an unknown one is refused before anything runs.
  const bool as_npy = format_of(req.output) == FileFormat::Npy;
  if (!out_buffer.empty() && !as_npy) throw Usage("--out-buffer picks the buffer of an --out F.npy");
  for (const auto &in : req.inputs) format_of(in);
  const KernelInfo &k = Registry::product().get(req.kernel);
  if (impl.empty()) impl = k.has_asm ? "asm" : "c";
  const Family *f = family_of(req.kernel);
  if (!f || !f->plan_run) throw InputError("kernel " + req.kernel + " cannot be run on files");
  if (impl != "host") {
    if (parse_impl(impl) == BVB_IMPL_ASM && !k.has_asm)
      throw InputError("kernel " + req.kernel + " has no assembly implementation (use --impl c)");
  }
  RunPlan plan = f->plan_run(req);
  check_output_name(req.output, plan.kind);
  const int npy_buffer = as_npy ? pick_output_buffer(plan.call, out_buffer) : -1;
  // .npy: the chosen buffer as the kernel left it; otherwise the family's view of the outputs.
  auto write_output = [&](std::vector<std::vector<uint8_t>> &data) {
    if (npy_buffer >= 0)
      write_file_atomic(req.output, encode_npy(npy_of_buffer(plan.call.bufs[size_t(npy_buffer)], data[size_t(npy_buffer)])));
    else
      plan.write(data, req.output);
  };
  std::vector<std::vector<uint8_t>> bufs;
  for (const auto &b : plan.call.bufs) bufs.push_back(b.data);
  if (impl == "host") {
    HostBuffers hb(bufs);
    plan.call.host(hb);
    write_output(bufs);
    std::printf("%s host %s: done\n", req.kernel.c_str(), plan.summary.c_str());
    return 0;
  }
  FirmwareImage fw = product_firmware();
  if (!elf.empty()) fw.elf = elf;
  Target target(fw, default_simulator());
  if (!timing.empty()) target.set_timing(timing);
  const Call call = target_call(plan.call, k.index, parse_impl(impl));
  CallResult r = target.run_one(call);
  // Frames too large for the Blackfin's memory are the input's fault, not the kernel's.
  if (r.crash.empty() && r.status == BVB_NO_SPACE && r.detail < call.bufs.size()) {
    const Buffer &b = call.bufs[r.detail];
    throw InputError(req.kernel + ": the frames are too large for the Blackfin: buffer '" + b.name + "' (" +
                     std::to_string(b.data.size()) + " bytes) does not fit " + place_name(b.place) +
                     " (use smaller frames, or --impl host)");
  }
  std::string err = describe_failure(call, r, target.elf());
  if (!err.empty()) {
    std::fprintf(stderr, "bfbench: %s (%s): %s\n", req.kernel.c_str(), impl.c_str(), err.c_str());
    return 1;
  }
  write_output(r.data);
  std::printf("%s %s %s: %u cycles", req.kernel.c_str(), impl.c_str(), plan.summary.c_str(), r.cycles);
  if (plan.call.pixels > 0) std::printf(" (%.2f per pixel)", r.cycles / plan.call.pixels);
  std::printf("\n");
  return 0;
}

int cmd_budgets(Args &args) {
  if (help_requested(args,
                     "usage: bfbench budgets [--update] [--file FILE] [-k GLOB] [-j N] [--timing none|bf537]\n\n"
                     "Measures every assembly kernel at the sizes its budgets name (and at 160x120,\n"
                     "320x240, 640x480 for kernels without one) and compares with the budgets file\n"
                     "(default ci/budgets.json; in the bfbench of a family built outside this tree,\n"
                     "the family's BUDGETS file). Fails when a kernel exceeds its budget, has none, or\n"
                     "a budget names nothing measured. --update rewrites the file atomically with the\n"
                     "measured cycles and prints old -> new for every entry. Budgets are judged under the\n"
                     "timing model the file names (its \"timing\"; none when absent); --update --timing T\n"
                     "re-measures the file in model T.\n"))
    return 0;
  const bool update = args.flag("--update");
  const bool timing_given = !args.values_peek("--timing").empty();
  std::string path = args.value("--file", product().budgets);
  BenchOptions opts;
  opts.kernel_glob = args.value("-k", "*", "--kernel");
  opts.jobs = int(to_long(args.value("-j", std::to_string(default_jobs())), "-j", 1, 256));
  opts.run_c = false;
  opts.progress = isatty(2);
  check_budget_glob(opts.kernel_glob);
  Target target = make_target(args);
  args.positional();
  // Held until the file is rewritten: two updates at once would each write what they loaded,
  // and the later rename would drop the other's entries.
  FileLock lock;
  if (update)
    lock = FileLock(path, [&] { std::fprintf(stderr, "bfbench: waiting for another budgets --update of %s\n", path.c_str()); });
  std::vector<Budget> budgets;
  bool exists = access(path.c_str(), F_OK) == 0;
  std::string file_timing = target.timing();
  if (exists || !update) budgets = load_budgets(path, &file_timing);
  // Budgets are judged under the model they were measured in; --update --timing T re-measures
  // the whole file in T.
  if (update && timing_given) file_timing = target.timing();
  else target.set_timing(file_timing);
  opts.compare_sim = false;
  for (Size s : budget_sizes(budgets)) {
    bool have = false;
    for (Size t : opts.sizes) have |= t.w == s.w && t.h == s.h;
    if (!have) opts.sizes.push_back(s);
  }
  auto rows = run_bench(target, opts);
  std::vector<Budget> scoped;  // only budgets of kernels under -k are judged or rewritten
  std::vector<Budget> others;
  for (const auto &b : budgets)
    (glob_match(opts.kernel_glob, b.key.substr(0, b.key.find('/'))) ? scoped : others).push_back(b);
  auto verdicts = judge_budgets(rows, scoped);
  if (update) {
    std::vector<Budget> next = others;
    for (const auto &v : verdicts) {
      if (v.status == BudgetVerdict::Failed) {
        std::printf("%-40s FAILED its check, budget kept: %s\n", v.key.c_str(), v.detail.c_str());
        if (v.budget) next.push_back({v.key, v.budget, 0});
        continue;
      }
      if (v.status == BudgetVerdict::Unmeasured) {
        std::printf("%-40s %llu -> removed (nothing measures it)\n", v.key.c_str(), (unsigned long long)v.budget);
        continue;
      }
      double tol = 0;
      for (const auto &b : scoped)
        if (b.key == v.key) tol = b.tolerance_pct;
      next.push_back({v.key, v.measured, tol});
      if (v.status == BudgetVerdict::Missing)
        std::printf("%-40s new -> %llu\n", v.key.c_str(), (unsigned long long)v.measured);
      else
        std::printf("%-40s %llu -> %llu%s\n", v.key.c_str(), (unsigned long long)v.budget,
                    (unsigned long long)v.measured, v.budget == v.measured ? "" : "  (changed)");
    }
    if (timing_given && !others.empty() && exists) {
      std::string old_timing;
      load_budgets(path, &old_timing);
      if (old_timing != file_timing)
        throw Usage("--update --timing " + file_timing + " with -k would mix models in one file: update all kernels");
    }
    save_budgets(path, next, file_timing);
    std::printf("wrote %s\n", path.c_str());
    for (const auto &v : verdicts)
      if (v.status == BudgetVerdict::Failed) return 1;
    return 0;
  }
  int bad = 0, loose = 0;
  for (const auto &v : verdicts) {
    const char *st = "ok";
    switch (v.status) {
      case BudgetVerdict::Ok: break;
      case BudgetVerdict::Over: st = "OVER BUDGET"; ++bad; break;
      case BudgetVerdict::Missing: st = "NO BUDGET"; ++bad; break;
      case BudgetVerdict::Unmeasured: st = "BUDGET FOR NOTHING MEASURED"; ++bad; break;
      case BudgetVerdict::Failed: st = "FAILED CHECK"; ++bad; break;
    }
    char slack[64] = "";
    if (double pct = budget_slack_pct(v)) {
      std::snprintf(slack, sizeof slack, "  (loose: %.1f%% above measured)", pct);
      ++loose;
    }
    std::printf("%-40s budget %12llu  measured %12llu  %s%s\n", v.key.c_str(), (unsigned long long)v.budget,
                (unsigned long long)v.measured, st, slack);
    if (v.status == BudgetVerdict::Failed) std::printf("  %s\n", v.detail.c_str());
  }
  // An assembly kernel that no row measured was not judged: that is no pass.
  std::vector<std::string> asm_kernels;
  for (const auto &k : target.registry().kernels())
    if (k.has_asm) asm_kernels.push_back(k.name);
  const std::vector<std::string> unjudged = unjudged_kernels(asm_kernels, opts.kernel_glob, verdicts);
  for (const auto &k : unjudged) std::printf("%-40s NOT JUDGED: no bench call measured it\n", k.c_str());
  bad += int(unjudged.size());
  std::printf("%zu budgets, %d problems", verdicts.size(), bad);
  if (loose) std::printf(", %d loose by more than 2%% (bfbench budgets --update -k KERNEL tightens them)", loose);
  std::printf(" (%s)\n", path.c_str());
  if (verdicts.empty()) {
    std::printf("no budget judged\n");
    return 1;
  }
  return bad ? 1 : 0;
}

int cmd_profile(Args &args) {
  if (help_requested(args,
                     "usage: bfbench profile KERNEL [--size WxH] [--impl asm|c] [--seed N] [--json FILE]\n"
                     "                      [--html FILE] [--lines N] [--firmware ELF]\n\n"
                     "Runs the kernel's bench call (default 320x240) once under the timing model with the\n"
                     "simulator's per-instruction profile and shows where its cycles go: the issue cycles\n"
                     "and each stall cause (address-register load/move, L1 sub-bank collision, SDRAM\n"
                     "read/write, MMR, external fetch, caches, multi-cycle instructions), the hot loops\n"
                     "(cycles per iteration against the body's issue bound) and the hottest source lines.\n"
                     "The profile's cycles equal the call's measured cycles plus the call overhead, or it\n"
                     "fails. --json writes every instruction, line and loop; --html a static page of the\n"
                     "annotated source with a heat colour per line. Exit 1 if the call fails its check.\n"))
    return 0;
  ProfileOptions po;
  po.impl = args.value("--impl", "asm");
  auto sizes = parse_sizes(args);
  if (sizes.size() > 1) throw Usage("--size given more than once");
  if (!sizes.empty()) po.size = sizes[0];
  po.seed = uint32_t(to_long(args.value("--seed", "1"), "--seed", 0, 0xffffffffL));
  const std::string json_path = args.value("--json", ""), html_path = args.value("--html", "");
  const long top = to_long(args.value("--lines", "25"), "--lines", 0, 100000);
  if (args.values_peek("--timing").size() && args.values_peek("--timing")[0] != "bf537")
    throw Usage("profile measures the timing model's cycles: --timing bf537 only");
  Target target = make_target(args);
  target.set_timing("bf537");
  auto pos = args.positional();
  if (pos.size() != 1) throw Usage("profile takes one KERNEL (bfbench list)");
  po.kernel = pos[0];
  Profile p;
  try {
    p = run_profile(target, po);
  } catch (const ProfileCheckFailed &e) {
    std::fprintf(stderr, "bfbench: %s\n", e.what());
    return 1;
  }
  std::fputs(profile_text(p, size_t(top)).c_str(), stdout);
  if (!json_path.empty()) {
    std::string j = profile_json(p);
    write_file_atomic(json_path, j.data(), j.size());
  }
  if (!html_path.empty()) {
    std::string h = profile_html(p);
    write_file_atomic(html_path, h.data(), h.size());
  }
  return 0;
}

int cmd_debug(Args &args) {
  if (help_requested(args,
                     "usage: bfbench debug KERNEL --case KERNEL:N --seed S [--impl asm|c] [--batch]\n"
                     "                    [--timing none|bf537] [--firmware ELF]\n\n"
                     "The call that `bfbench check --seed S --case KERNEL:N` runs (a failure prints both),\n"
                     "with its buffers, in bfin-elf-gdb's built-in simulator (target sim, as bfin-elf-run\n"
                     "runs it), stopped at the kernel's entry; each buffer's address is printed and set\n"
                     "as a gdb variable ($a, $dst, ...). --batch prints the registers at the entry and\n"
                     "quits (for scripts). Needs the gdb: emu/bootstrap.sh --with-gdb (about 25 minutes;\n"
                     "$BFBENCH_GDB names another). Exit status: gdb's; 2 without a gdb or on bad input.\n"))
    return 0;
  const std::string id = args.value("--case", "");
  const std::string seed = args.value("--seed", "");
  const std::string impl_s = args.value("--impl", "");
  const bool batch = args.flag("--batch");
  const std::string gdb = default_gdb();
  // No gdb: one line saying how to get it, before anything else is looked at.
  if (gdb.empty() || access(gdb.c_str(), X_OK) != 0)
    throw InputError("no bfin-elf-gdb" + (gdb.empty() ? std::string(" in a host-only build") : " at " + gdb) +
                     ": build it with emu/bootstrap.sh --with-gdb (about 25 minutes), or set $BFBENCH_GDB");
  Target target = make_target(args);
  auto pos = args.positional();
  if (pos.size() != 1) throw Usage("debug takes one KERNEL (bfbench list)");
  const KernelInfo &k = target.registry().get(pos[0]);
  if (id.empty() || seed.empty()) throw Usage("debug needs --case KERNEL:N and --seed S, as a check failure prints them");
  const size_t colon = id.rfind(':');
  if (colon == std::string::npos || id.substr(0, colon) != k.name || colon + 1 == id.size() ||
      id.find_first_not_of("0123456789", colon + 1) != std::string::npos)
    throw Usage("--case wants " + k.name + ":N, got '" + id + "'");
  const uint32_t impl = impl_s.empty() ? uint32_t(k.has_asm ? BVB_IMPL_ASM : BVB_IMPL_C) : parse_impl(impl_s);
  std::string case_name;
  const Call call = case_call(target, id, uint32_t(to_long(seed, "--seed", 0, 4294967295L)), impl, &case_name);
  const std::string window = make_temp_file();
  struct Cleanup {
    std::string p;
    ~Cleanup() { remove_temp_file(p); }
  } cleanup{window};
  const DebugPlan plan = plan_debug(target, call, window, gdb, batch);
  std::printf("%s (%s) %s, seed %s: stopping at %s (0x%08x)\n", id.c_str(), impl_name(impl), case_name.c_str(),
              seed.c_str(), plan.entry_name.c_str(), plan.entry);
  for (const auto &b : plan.buffers) std::printf("  %s\n", b.c_str());
  return run_gdb(plan.argv);
}

}  // namespace

int bvb::bfbench_main(int argc, char **argv) {
  // An interrupted run removes its window files and kills its simulators.
  bvb::install_interrupt_cleanup();
  if (argc < 2) {
    print_help(stderr);
    return 2;
  }
  const std::string cmd = argv[1];
  try {
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
      print_help(stdout);
      return 0;
    }
    Args args(argc, argv, 2);
    if (cmd == "list") return cmd_list(args);
    if (cmd == "check") return cmd_check(args);
    if (cmd == "bench") return cmd_bench(args);
    if (cmd == "run") return cmd_run(args);
    if (cmd == "budgets") return cmd_budgets(args);
    if (cmd == "profile") return cmd_profile(args);
    if (cmd == "debug") return cmd_debug(args);
    bool handled = false;
    int rc = bvb::extra_command(cmd, argc - 1, argv + 1, &handled);
    if (handled) return rc;
    throw Usage("unknown command '" + cmd + "' (bfbench --help)");
  } catch (const Usage &e) {
    std::fprintf(stderr, "bfbench: %s\n", sim::printable(e.what(), 2000).c_str());
    return 2;
  } catch (const InputError &e) {
    std::fprintf(stderr, "bfbench: %s\n", sim::printable(e.what(), 2000).c_str());
    return 2;
  } catch (const sim::SetupError &e) {
    std::fprintf(stderr, "bfbench: %s\n", sim::printable(e.what(), 2000).c_str());
    return 2;
  } catch (const std::exception &e) {
    std::fprintf(stderr, "bfbench: internal error: %s\n", sim::printable(e.what(), 2000).c_str());
    return 2;
  }
}
