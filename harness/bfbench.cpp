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
#include "extra_commands.h"
#include "family.h"
#include "io.h"
#include "names.h"
#include "options.h"
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

int default_jobs() {
  unsigned n = std::thread::hardware_concurrency();
  return n ? int(n) : 2;
}

// The options every command that runs the Blackfin takes: which firmware and which timing model.
struct TargetArgs {
  std::string firmware, timing;
};

void declare_target(CommandLine &cl, TargetArgs *t, bool timing = true) {
  if (timing)
    cl.choice("--timing", {"none", "bf537"}, &t->timing,
              "the simulator's timing model (default $BFBENCH_TIMING, else bf537)");
  cl.text("--firmware", "ELF", &t->firmware, "the firmware image (default this build's)");
}

Target make_target(const TargetArgs &args, bool selftest = false) {
  FirmwareImage fw = selftest ? selftest_firmware() : product_firmware();
  if (!args.firmware.empty()) fw.elf = args.firmware;
  Target t(fw, default_simulator());
  if (!args.timing.empty()) t.set_timing(args.timing);
  return t;
}

void declare_jobs(CommandLine &cl, int *jobs) {
  *jobs = default_jobs();
  cl.integer("-j", "N", 1, 256, jobs, "simulator processes at once (default: cores)");
}

const char *const kKernelGlobHelp = "kernels (shell glob, default *; bfbench list names them)";

// ---------------------------------------------------------------------------------------------

int cmd_list(int argc, char **argv) {
  CommandLine cl("list");
  cl.about("Lists every kernel: its family and implementations.");
  if (!cl.parse(argc, argv)) return kExitOk;
  for (const auto &k : Registry::product().kernels()) {
    const Family *f = family_of(k.name);
    std::printf("%-24s %-14s c%s\n", k.name.c_str(), f ? f->name.c_str() : "-", k.has_asm ? " asm" : "");
  }
  return kExitOk;
}

int cmd_check(int argc, char **argv) {
  CheckOptions opts;
  long seeds = 1;
  TargetArgs ta;
  CommandLine cl("check");
  cl.about("Runs every kernel's C reference on the Blackfin and its assembly in the simulator\n"
           "on seeded random, crafted and real frames over many sizes, and compares both with\n"
           "the host-compiled C reference, bit for bit; guard bands, callee-saved registers,\n"
           "faults and hangs are checked too. The seed is printed; --seed replays it.")
      .text("-k,--kernel", "GLOB", &opts.kernel_glob, kKernelGlobHelp)
      .integer("--seed", "N", 0, 4294967295LL, &opts.seed, "first seed (default: from the clock)")
      .integer("--seeds", "COUNT", 1, 100000, &seeds, "seeds N, N+1, ... (default 1)");
  declare_jobs(cl, &opts.jobs);
  cl.flag("--campaign", &opts.campaign, "larger sizes (up to 640x480) and more random cases")
      .text("--case", "KERNEL:N", &opts.only_case, "only that call (as a failure prints it), with its --seed")
      .flag("-v", &opts.verbose, "every failure, not the first three");
  declare_target(cl, &ta);
  cl.tail("Fails (exit 1) when a selected kernel gets no judged call for one of its\n"
          "implementations. Real-frame cases need $BFBENCH_FRAMES_REAL (default\n"
          "../shared/frames-real): without it they are skipped, with a message, or with\n"
          "BVB_REQUIRE_FRAMES=1 the check stops with an error.");
  if (!cl.parse(argc, argv)) return kExitOk;
  if (!cl.given("--seed")) opts.seed = uint32_t(std::time(nullptr)) % 1000000;
  opts.progress = isatty(2);
  opts.frames_real = default_frames_real();
  Target target = make_target(ta);

  if (!opts.only_case.empty()) {
    // KERNEL:N names one call; the kernel selects its family, as -k would.
    std::string kernel;
    if (!parse_case_id(opts.only_case, &kernel))
      throw UsageError("--case wants KERNEL:N as a failure prints it, got '" + opts.only_case + "'");
    target.registry().get(kernel);
    if (opts.kernel_glob != "*" && !glob_match(opts.kernel_glob, kernel))
      throw UsageError("--case " + opts.only_case + " is not of a kernel -k '" + opts.kernel_glob + "' selects");
    opts.kernel_glob = kernel;
    if (!cl.given("--seed")) throw UsageError("--case needs the --seed the failure printed");
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
      if (!why.empty()) throw UsageError("--size " + size_name(s) + ": " + why + " (-k selects kernels)");
    }
  }
}

// Only assembly kernels have budgets: a -k that selects none would judge nothing and pass.
void check_budget_glob(const std::string &glob) {
  for (const auto &k : Registry::product().kernels())
    if (k.has_asm && glob_match(glob, k.name)) return;
  throw InputError("no assembly kernel matches '" + glob + "' (bfbench list)");
}

int cmd_bench(int argc, char **argv) {
  BenchOptions opts;
  std::vector<Size> sizes;
  std::string json_path, csv_path, md_path;
  bool asm_only = false, no_sim = false;
  TargetArgs ta;
  CommandLine cl("bench");
  cl.about("Cycles per call and per pixel for each kernel's C reference built for the\n"
           "Blackfin and for its assembly, the empty-call overhead measured and subtracted,\n"
           "the speed-up, and the kernel's stated lower bound. Cycles are modelled BF537\n"
           "cycles (bfin-elf-run --timing bf537: pipeline stalls, L1 banks, SDRAM, caches);\n"
           "each call also runs under --timing none and the simulator's own count is shown\n"
           "beside the model's (--no-sim skips that run), with where the buffers were\n"
           "placed. Every measured call is also checked. $BFBENCH_TIMING sets the default model.")
      .text("-k,--kernel", "GLOB", &opts.kernel_glob, kKernelGlobHelp)
      .sizes("--size", &sizes, "a frame size (default 160x120, 320x240 and 640x480)")
      .text("--json", "FILE", &json_path, "also write the rows as JSON")
      .text("--csv", "FILE", &csv_path, "also write the rows as CSV")
      .text("--markdown", "FILE", &md_path, "also write the README's cycle table")
      .flag("--asm-only", &asm_only, "measure the assembly only, not the C reference")
      .flag("--no-sim", &no_sim, "skip the run under --timing none");
  declare_jobs(cl, &opts.jobs);
  declare_target(cl, &ta);
  if (!cl.parse(argc, argv)) return kExitOk;
  check_bench_sizes(opts.kernel_glob, sizes);
  if (!sizes.empty()) opts.sizes = sizes;
  opts.run_c = !asm_only;
  opts.compare_sim = !no_sim;
  opts.progress = isatty(2);
  Target target = make_target(ta);
  auto rows = run_bench(target, opts);
  if (rows.empty()) throw InputError("no kernel matches '" + opts.kernel_glob + "' (bfbench list)");
  std::fputs(bench_table(rows, target.null_call_cycles()).c_str(), stdout);
  if (!json_path.empty()) write_file_atomic(json_path, bench_json(rows, target.null_call_cycles()));
  if (!csv_path.empty()) write_file_atomic(csv_path, bench_csv(rows));
  if (!md_path.empty()) write_file_atomic(md_path, bench_markdown(rows));
  for (const auto &r : rows)
    if (!r.error.empty()) return kExitFailed;
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
  throw UsageError("--out-buffer " + name + ": no such output buffer (this call has " + outputs + ")");
}

int cmd_run(int argc, char **argv) {
  RunRequest req;
  std::string out_buffer, impl;
  std::vector<std::string> params, kernel;
  Size raw{0, 0};
  TargetArgs ta;
  CommandLine cl("run");
  cl.about("Runs one kernel on the given frames and writes its output; prints the cycles of the\n"
           "call (modelled BF537 cycles, or the simulator's own with --timing none).\n"
           "Formats follow the file names: frames in and out as .pgm (grey), .ppm (RGB), .pnm,\n"
           ".png (8-bit grey or RGB) or .npy (uint8 HxW or HxWx3), raw .uyvy with --size WxH;\n"
           "flow out as .flo or .npy (float32 HxWx2); lists out as .csv or .txt. --out F.npy\n"
           "writes an output buffer as it is, with its element type and shape (--out-buffer NAME\n"
           "picks which; default the first). A name without an extension gets the output's own\n"
           "format (PNM, .flo or text), any other extension is an error.")
      .operands("KERNEL", &kernel, 1, 1, "(bfbench list)")
      .texts("--in", "FILE", &req.inputs, "an input frame, in the order the kernel takes them")
      .required()
      .text("--out", "FILE", &req.output, "the output; its extension says its format")
      .required()
      .text("--impl", "asm|c|host", &impl, "the implementation (default asm, or c for kernels without assembly)")
      .texts("--param", "K=V", &params, "a kernel parameter")
      .size("--size", &raw, "the frame size of raw .uyvy input")
      .flag("--grey", &req.grey_from_colour,
            "convert colour frames for a kernel of grey frames (BT.601 luma); without it a colour frame is an error")
      .text("--out-buffer", "NAME", &out_buffer, "the output buffer an --out F.npy writes (default the first)");
  declare_target(cl, &ta);
  if (!cl.parse(argc, argv)) return kExitOk;
  for (const auto &p : params) req.params.set(p);
  if (cl.given("--size")) req.raw_width = raw.w, req.raw_height = raw.h;
  req.kernel = kernel[0];
  if (req.output.empty()) throw UsageError("run needs --out FILE");
  // The output's name decides its format: an unknown one is refused before anything runs.
  const bool as_npy = format_of(req.output) == FileFormat::Npy;
  if (!out_buffer.empty() && !as_npy) throw UsageError("--out-buffer picks the buffer of an --out F.npy");
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
  Target target = make_target(ta);
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
    std::fprintf(stderr, "%s run: %s: %s\n", bfbench_name().c_str(), kernel_impl_name(req.kernel, impl).c_str(),
                 err.c_str());
    return kExitFailed;
  }
  write_output(r.data);
  std::printf("%s %s %s: %u cycles", req.kernel.c_str(), impl.c_str(), plan.summary.c_str(), r.cycles);
  if (plan.call.pixels > 0) std::printf(" (%.2f per pixel)", r.cycles / plan.call.pixels);
  std::printf("\n");
  return 0;
}

int cmd_budgets(int argc, char **argv) {
  bool update = false;
  std::string path = product().budgets;
  BenchOptions opts;
  TargetArgs ta;
  CommandLine cl("budgets");
  cl.about("Measures every assembly kernel at the sizes its budgets name (and at 160x120,\n"
           "320x240, 640x480 for kernels without one) and compares with the budgets file\n"
           "(default ci/budgets.json; in the bfbench of a family built outside this tree,\n"
           "the family's BUDGETS file). Fails when a kernel exceeds its budget, has none, or\n"
           "a budget names nothing measured. --update rewrites the file atomically with the\n"
           "measured cycles and prints old -> new for every entry. Budgets are judged under the\n"
           "timing model the file names (its \"timing\"; none when absent); --update --timing T\n"
           "re-measures the file in model T.")
      .flag("--update", &update, "rewrite the file with the measured cycles")
      .text("--file", "FILE", &path, "the budgets file (default " + product().budgets + ")")
      .text("-k,--kernel", "GLOB", &opts.kernel_glob, kKernelGlobHelp);
  declare_jobs(cl, &opts.jobs);
  declare_target(cl, &ta);
  if (!cl.parse(argc, argv)) return kExitOk;
  const bool timing_given = cl.given("--timing");
  opts.run_c = false;
  opts.progress = isatty(2);
  check_budget_glob(opts.kernel_glob);
  Target target = make_target(ta);
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
    (glob_match(opts.kernel_glob, budget_key_kernel(b.key)) ? scoped : others).push_back(b);
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
        throw UsageError("--update --timing " + file_timing + " with -k would mix models in one file: update all kernels");
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

int cmd_profile(int argc, char **argv) {
  ProfileOptions po;
  po.impl = "asm";
  po.seed = 1;
  std::string json_path, html_path, timing;
  long top = 25;
  std::vector<std::string> kernel;
  TargetArgs ta;
  CommandLine cl("profile");
  cl.about("Runs the kernel's bench call once under the timing model with the\n"
           "simulator's per-instruction profile and shows where its cycles go: the issue cycles\n"
           "and each stall cause (address-register load/move, L1 sub-bank collision, SDRAM\n"
           "read/write, MMR, external fetch, caches, multi-cycle instructions), the hot loops\n"
           "(cycles per iteration against the body's issue bound) and the hottest source lines.\n"
           "The profile's cycles equal the call's measured cycles plus the call overhead, or it\n"
           "fails. --json writes every instruction, line and loop; --html a static page of the\n"
           "annotated source with a heat colour per line. Exit 1 if the call fails its check.")
      .operands("KERNEL", &kernel, 1, 1, "(bfbench list)")
      .size("--size", &po.size, "the bench call's size (default 320x240)")
      .text("--impl", "asm|c", &po.impl, "the implementation (default asm)")
      .integer("--seed", "N", 0, 0xffffffffLL, &po.seed, "the bench call's seed (default 1)")
      .text("--json", "FILE", &json_path, "write every instruction, line and loop as JSON")
      .text("--html", "FILE", &html_path, "write the annotated source as one static page")
      .integer("--lines", "N", 0, 100000, &top, "the hottest source lines shown (default 25)")
      // The profile is the timing model's: the option exists for scripts that pass it on.
      .choice("--timing", {"bf537"}, &timing, "the timing model (bf537 only: the profile is its cycles)");
  declare_target(cl, &ta, false);
  if (!cl.parse(argc, argv)) return kExitOk;
  Target target = make_target(ta);
  target.set_timing("bf537");
  po.kernel = kernel[0];
  const Profile p = run_profile(target, po);  // ProfileCheckFailed: exit 1 (run_command)
  std::fputs(profile_text(p, size_t(top)).c_str(), stdout);
  if (!json_path.empty()) write_file_atomic(json_path, profile_json(p));
  if (!html_path.empty()) write_file_atomic(html_path, profile_html(p));
  return 0;
}

int cmd_debug(int argc, char **argv) {
  std::string id, impl_s;
  uint32_t seed = 0;
  bool batch = false;
  std::vector<std::string> kernel;
  TargetArgs ta;
  CommandLine cl("debug");
  cl.about("The call that `bfbench check --seed S --case KERNEL:N` runs (a failure prints both),\n"
           "with its buffers, in bfin-elf-gdb's built-in simulator (target sim, as bfin-elf-run\n"
           "runs it), stopped at the kernel's entry; each buffer's address is printed and set\n"
           "as a gdb variable ($a, $dst, ...). Needs the gdb: emu/bootstrap.sh --with-gdb (about\n"
           "25 minutes; $BFBENCH_GDB names another).")
      .operands("KERNEL", &kernel, 1, 1, "(bfbench list)")
      .text("--case", "KERNEL:N", &id, "the call, as a check failure prints it")
      .required()
      .integer("--seed", "S", 0, 4294967295LL, &seed, "the check's seed, as the failure prints it")
      .required()
      .text("--impl", "asm|c", &impl_s, "the implementation (default asm, or c for kernels without assembly)")
      .flag("--batch", &batch, "print the registers at the entry and quit (for scripts)")
      .exit_status("Exit status: gdb's; 2 without a gdb or on bad usage or input.");
  declare_target(cl, &ta);
  if (!cl.parse(argc, argv)) return kExitOk;
  const std::string gdb = default_gdb();
  // No gdb: one line saying how to get it, before the kernel and the call are looked at.
  if (gdb.empty() || access(gdb.c_str(), X_OK) != 0)
    throw InputError("no bfin-elf-gdb" + (gdb.empty() ? std::string(" in a host-only build") : " at " + gdb) +
                     ": build it with emu/bootstrap.sh --with-gdb (about 25 minutes), or set $BFBENCH_GDB");
  Target target = make_target(ta);
  const KernelInfo &k = target.registry().get(kernel[0]);
  std::string case_kernel_name;
  if (!parse_case_id(id, &case_kernel_name) || case_kernel_name != k.name)
    throw UsageError("--case wants " + k.name + ":N, got '" + id + "'");
  const uint32_t impl = impl_s.empty() ? uint32_t(k.has_asm ? BVB_IMPL_ASM : BVB_IMPL_C) : parse_impl(impl_s);
  std::string case_name;
  const Call call = case_call(target, id, seed, impl, &case_name);
  const std::string window = make_temp_file();
  struct Cleanup {
    std::string p;
    ~Cleanup() { remove_temp_file(p); }
  } cleanup{window};
  const DebugPlan plan = plan_debug(target, call, window, gdb, batch);
  std::printf("%s (%s) %s, seed %u: stopping at %s (0x%08x)\n", id.c_str(), impl_name(impl), case_name.c_str(),
              seed, plan.entry_name.c_str(), plan.entry);
  for (const auto &b : plan.buffers) std::printf("  %s\n", b.c_str());
  return run_gdb(plan.argv);
}

// The kernel harness's commands; the others (commands.cpp, extra_commands.h) follow them in the
// help. Each gets argv from its own name on.
const ExtraCommand kHarnessCommands[] = {
    {"list", "kernels and their implementations", cmd_list},
    {"check", "C reference (host and Blackfin) vs assembly, bit for bit", cmd_check},
    {"bench", "modelled BF537 cycles per call and per pixel, C vs assembly", cmd_bench},
    {"run", "one kernel on given frames (bfbench run KERNEL)", cmd_run},
    {"budgets", "compare the bench with the budgets (ci/budgets.json)", cmd_budgets},
    {"profile", "where one call's modelled cycles go, per source line and loop", cmd_profile},
    {"debug", "one check call in bfin-elf-gdb, stopped at the kernel's entry", cmd_debug},
};

void print_help(FILE *out) {
  std::fprintf(out,
               "usage: %s COMMAND [options]\n\n"
               "Checks, benchmarks and runs Blackfin vision kernels inside the GNU Blackfin simulator.\n\n"
               "commands:\n",
               bfbench_name().c_str());
  for (const auto &c : kHarnessCommands) std::fprintf(out, "  %-24s %s\n", c.name, c.summary);
  bvb::print_extra_commands(out);
  std::fprintf(out, "\n'%s COMMAND --help' describes each.\n%s\n", bfbench_name().c_str(), kExitStatusHelp);
}

}  // namespace

int bvb::bfbench_main(int argc, char **argv) {
  // An interrupted run removes its window files and kills its simulators.
  bvb::install_interrupt_cleanup();
  if (argc < 2) {
    print_help(stderr);
    return kExitUsage;
  }
  const std::string cmd = argv[1];
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    print_help(stdout);
    return kExitOk;
  }
  for (const auto &c : kHarnessCommands)
    if (cmd == c.name) return run_command(cmd, [&] { return c.fn(argc - 1, argv + 1); });
  bool handled = false;
  const int rc = run_command(cmd, [&] { return bvb::extra_command(cmd, argc - 1, argv + 1, &handled); });
  if (handled) return rc;
  return run_command("", [&]() -> int {
    throw UsageError("unknown command '" + cmd + "' (" + bfbench_name() + " --help)");
  });
}
