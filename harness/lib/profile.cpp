#include "profile.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench.h"
#include "cleanup.h"
#include "elf_symbols.h"
#include "family.h"
#include "io.h"
#include "json.h"
#include "simdriver.h"
#include "names.h"

namespace bvb {

namespace {

std::vector<std::string> words(const std::string &line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

bool to_u64(const std::string &s, uint64_t *v, int base = 10) {
  if (s.empty()) return false;
  char *end = nullptr;
  errno = 0;
  unsigned long long x = std::strtoull(s.c_str(), &end, base);
  if (errno || *end || s[0] == '-') return false;
  *v = x;
  return true;
}

std::string fmt(const char *f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string with_commas(uint64_t v) {
  std::string s = std::to_string(v), out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (i && (s.size() - i) % 3 == 0) out += ',';
    out += s[i];
  }
  return out;
}

std::string hex32(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "%08x", v);
  return b;
}

// Runs argv, returns its standard output; its standard error goes to ours.
std::string capture(const std::vector<std::string> &argv) {
  int fd[2];
  if (pipe(fd) != 0) throw sim::SetupError("pipe failed");
  pid_t pid = fork();
  if (pid < 0) throw sim::SetupError("fork failed");
  if (pid == 0) {
    dup2(fd[1], 1);
    close(fd[0]);
    close(fd[1]);
    std::vector<char *> a;
    for (const auto &s : argv) a.push_back(const_cast<char *>(s.c_str()));
    a.push_back(nullptr);
    execv(a[0], a.data());
    _exit(127);
  }
  close(fd[1]);
  std::string out;
  char buf[65536];
  for (ssize_t n; (n = read(fd[0], buf, sizeof buf)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    out.append(buf, size_t(n));
  }
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw sim::SetupError(argv[0] + " failed (is the toolchain installed? emu/bootstrap.sh)");
  return out;
}

// "0xffa0001c" -> value.
bool parse_hex_token(const std::string &t, uint32_t *v) {
  uint64_t x;
  std::string s = t.rfind("0x", 0) == 0 ? t.substr(2) : t;
  if (!to_u64(s, &x, 16) || x > 0xffffffffu) return false;
  *v = uint32_t(x);
  return true;
}

std::string lower(std::string s) {
  for (auto &c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

ProfileData parse_profile(const std::string &text) {
  ProfileData d;
  std::istringstream in(text);
  std::string line;
  int n = 0;
  auto bad = [&](const std::string &why) {
    throw InputError("simulator profile, line " + std::to_string(n) + ": " + why);
  };
  uint64_t nwin = 0;
  bool have_windows = false;
  while (std::getline(in, line)) {
    ++n;
    auto w = words(line);
    if (w.empty()) continue;
    if (n == 1) {
      if (w.size() != 2 || w[0] != "bfin-timing-profile" || w[1] != "1") bad("not a version 1 profile");
      continue;
    }
    if (w[0] == "causes") {
      d.causes.assign(w.begin() + 1, w.end());
      continue;
    }
    if (w[0] == "windows") {
      if (w.size() < 2 || !to_u64(w[1], &nwin)) bad("bad window count");
      have_windows = true;
      continue;
    }
    if (w[0] == "window") {
      uint64_t c;
      if (w.size() != 6 || w[2] != "cycles" || !to_u64(w[3], &c)) bad("bad window line");
      d.windows.push_back(c);
      continue;
    }
    if (d.causes.empty()) bad("instruction record before the causes line");
    ProfileRecord r;
    uint32_t pc;
    if (w.size() != d.causes.size() + 4 || !parse_hex_token(w[0], &pc) || !to_u64(w[1], &r.count) ||
        !to_u64(w[2], &r.cycles))
      bad("bad instruction record");
    r.pc = pc;
    r.cause.resize(d.causes.size());
    for (size_t i = 0; i < d.causes.size(); ++i)
      if (!to_u64(w[3 + i], &r.cause[i])) bad("bad cause count");
    r.stall_reg = w.back();
    d.records.push_back(std::move(r));
  }
  if (n == 0) throw InputError("simulator profile is empty (did the simulator run with --timing-profile?)");
  if (!have_windows || d.windows.size() != nwin) bad("window lines do not match the window count");
  return d;
}

std::vector<std::pair<uint32_t, Disassembly>> parse_objdump(const std::string &text) {
  std::vector<std::pair<uint32_t, Disassembly>> out;
  std::istringstream in(text);
  std::string line, function, file;
  int src_line = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    // "ffa00000 <_bvb_null>:"  a symbol
    size_t lt = line.find(" <");
    if (lt != std::string::npos && line.size() > 2 && line.compare(line.size() - 2, 2, ">:") == 0 &&
        line.find('\t') == std::string::npos) {
      function = line.substr(lt + 2, line.size() - lt - 4);
      if (!function.empty() && function[0] == '_') function.erase(0, 1);
      file.clear();
      src_line = 0;
      continue;
    }
    // "/path/file.S:123" (or "... (discriminator 1)") from -l
    size_t colon = line.rfind(':');
    if (line[0] == '/' && colon != std::string::npos) {
      std::string tail = line.substr(colon + 1);
      size_t sp = tail.find(' ');
      if (sp != std::string::npos) tail.resize(sp);
      uint64_t ln;
      if (to_u64(tail, &ln)) {
        file = std::filesystem::path(line.substr(0, colon)).lexically_normal().string();
        src_line = int(ln);
      }
      continue;
    }
    // "ffa00004:\tP0 = R0;"  an instruction
    size_t tab = line.find(":\t");
    if (tab == std::string::npos) continue;
    std::string addr = line.substr(0, tab);
    while (!addr.empty() && addr[0] == ' ') addr.erase(0, 1);
    uint32_t pc;
    if (!parse_hex_token(addr, &pc)) continue;
    Disassembly d;
    d.function = function;
    d.text = line.substr(tab + 2);
    d.file = file;
    d.line = src_line;
    const std::string t = lower(d.text);
    // LSETUP(0xffa0001c <...>, 0xffa00024 <...>) LC0 = P1;  the body is [start, end]
    if (t.rfind("lsetup", 0) == 0) {
      size_t a = t.find("0x"), b = a == std::string::npos ? a : t.find("0x", t.find(',', a));
      uint32_t s = 0, e = 0;
      if (a != std::string::npos && b != std::string::npos &&
          parse_hex_token(t.substr(a, t.find_first_of(" ,", a) - a), &s) &&
          parse_hex_token(t.substr(b, t.find_first_of(" )", b) - b), &e)) {
        d.loop_start = s, d.loop_end = e, d.loop_hw = true;
      }
    } else if (t.find("jump") != std::string::npos && t.find("if ") == 0) {
      // IF CC JUMP 0xffa00010 <...>;  backwards: a loop from the target to here
      size_t a = t.find("0x");
      uint32_t target = 0;
      if (a != std::string::npos && parse_hex_token(t.substr(a, t.find_first_of(" ;", a) - a), &target) &&
          target < pc)
        d.loop_start = target, d.loop_end = pc;
    }
    out.push_back({pc, std::move(d)});
  }
  std::sort(out.begin(), out.end(), [](const auto &x, const auto &y) { return x.first < y.first; });
  return out;
}

Profile build_profile(const ProfileData &data, const std::vector<std::pair<uint32_t, Disassembly>> &dis) {
  Profile p;
  p.causes = data.causes;
  p.cause.assign(data.causes.size(), 0);
  auto find_dis = [&](uint32_t pc) -> const Disassembly * {
    auto it = std::lower_bound(dis.begin(), dis.end(), pc,
                               [](const auto &e, uint32_t v) { return e.first < v; });
    return it != dis.end() && it->first == pc ? &it->second : nullptr;
  };
  std::map<std::pair<std::string, int>, ProfileLine> lines;
  std::map<uint32_t, const ProfileRecord *> by_pc;
  for (const auto &r : data.records) {
    ProfileInstruction in;
    in.pc = r.pc;
    in.rec = r;
    if (const Disassembly *d = find_dis(r.pc)) in.dis = *d;
    p.total += r.cycles;
    p.issue += r.count;
    for (size_t i = 0; i < r.cause.size(); ++i) p.cause[i] += r.cause[i];
    auto key = std::make_pair(in.dis.file.empty() ? in.dis.function : in.dis.file, in.dis.line);
    ProfileLine &l = lines[key];
    if (l.cause.empty()) {
      l.file = key.first;
      l.line = key.second;
      l.cause.assign(data.causes.size(), 0);
      l.count = r.count;
    }
    l.cycles += r.cycles;
    for (size_t i = 0; i < r.cause.size(); ++i) l.cause[i] += r.cause[i];
    by_pc[r.pc] = &r;
    p.insns.push_back(std::move(in));
  }
  // The source text of each line, read once per file.
  std::map<std::string, std::vector<std::string>> sources;
  for (auto &kv : lines) {
    ProfileLine &l = kv.second;
    if (l.file.empty() || l.file[0] != '/' || l.line <= 0) continue;
    auto it = sources.find(l.file);
    if (it == sources.end()) {
      std::vector<std::string> text;
      std::ifstream f(l.file);
      for (std::string s; std::getline(f, s);) text.push_back(s);
      it = sources.emplace(l.file, std::move(text)).first;
    }
    if (size_t(l.line) <= it->second.size()) l.source = it->second[size_t(l.line) - 1];
    p.lines.push_back(l);
  }
  for (auto &kv : lines)
    if (kv.second.file.empty() || kv.second.file[0] != '/' || kv.second.line <= 0) p.lines.push_back(kv.second);

  // Loops: every LSETUP and backward branch the call executed.
  for (const auto &in : p.insns) {
    if (!in.dis.loop_start) continue;
    ProfileLoop lp;
    lp.start = in.dis.loop_start;
    lp.end = in.dis.loop_end;
    lp.hw = in.dis.loop_hw;
    bool dup = false;
    for (const auto &o : p.loops) dup |= o.start == lp.start && o.end == lp.end;
    if (dup) continue;
    lp.cause.assign(data.causes.size(), 0);
    for (auto it = std::lower_bound(dis.begin(), dis.end(), lp.start,
                                    [](const auto &e, uint32_t v) { return e.first < v; });
         it != dis.end() && it->first <= lp.end; ++it)
      lp.body++;
    // Issue bound: one cycle per instruction issued (a bundle is one), what the body would
    // take per iteration without a stall or a multi-cycle instruction.
    uint64_t issued = 0;
    for (const auto &r : data.records)
      if (r.pc >= lp.start && r.pc <= lp.end) {
        lp.cycles += r.cycles;
        issued += r.count;
        for (size_t i = 0; i < r.cause.size(); ++i) lp.cause[i] += r.cause[i];
      }
    // Iterations: how often the body's last instruction ran (a backward branch runs once per
    // iteration, taken or not).
    auto e = by_pc.find(lp.end);
    lp.iterations = e == by_pc.end() ? 0 : e->second->count;
    if (!lp.iterations || !lp.cycles) continue;
    lp.issue_bound = double(issued) / double(lp.iterations);
    if (const Disassembly *d = find_dis(lp.start))
      lp.where = (d->file.empty() ? d->function : d->file + ":" + std::to_string(d->line)) +
                 // A macro's loops share its invocation's line: the address tells them apart.
                 " @" + hex32(lp.start);
    p.loops.push_back(std::move(lp));
  }
  std::sort(p.loops.begin(), p.loops.end(), [](const auto &a, const auto &b) { return a.cycles > b.cycles; });
  return p;
}

Profile run_profile(const Target &target, const ProfileOptions &opts) {
  const KernelInfo *ki = target.registry().find(opts.kernel);
  if (!ki) throw InputError("no kernel '" + opts.kernel + "' (bfbench list)");
  if (opts.impl != "asm" && opts.impl != "c") throw InputError("--impl wants asm or c, got '" + opts.impl + "'");
  if (opts.impl == "asm" && !ki->has_asm)
    throw InputError(opts.kernel + " has no assembly implementation: --impl c");
  if (target.timing() != "bf537")
    throw InputError("the profile is of the timing model's cycles: --timing bf537");
  std::string problem = bench_size_problem(opts.kernel, opts.size.w, opts.size.h);
  if (!problem.empty()) throw InputError(problem);
  CheckCall call = bench_call_for(opts.kernel, opts.size, opts.seed);
  if (call.kernel.empty()) throw InputError(opts.kernel + " has no bench call to profile");

  uint32_t t0 = 0, t1 = 0;
  if (!symbol_value(target.elf(), "bvb_call_t0", &t0) || !symbol_value(target.elf(), "bvb_call_t1", &t1))
    throw sim::SetupError(target.elf() + ": no bvb_call_t0/bvb_call_t1 symbols (firmware too old?)");
  const std::string file = make_temp_file();
  struct Cleanup {
    std::string p;
    ~Cleanup() { remove_temp_file(p); }
  } cleanup{file};
  const uint32_t impl = opts.impl == "asm" ? BVB_IMPL_ASM : BVB_IMPL_C;
  Target t = target;
  t.set_isolated(true);
  t.set_impl_options(impl, {"--timing-profile", file, "--timing-profile-window",
                            "0x" + hex32(t0) + ",0x" + hex32(t1)});
  CheckOptions co;
  co.seed = opts.seed;
  co.run_c = impl == BVB_IMPL_C;
  co.adversarial = false;  // the call exactly as the bench measures it
  Checker ck(t, co);
  Profile p;
  p.kernel = opts.kernel;
  p.impl = opts.impl;
  p.case_name = call.case_name;
  p.timing = t.timing();
  bool seen = false;
  ck.add(std::move(call), [&](uint32_t i, const CallResult &r) {
    if (i == impl) p.measured = r.cycles, seen = true;
  });
  ck.flush();
  if (!ck.failures().empty()) {
    const Failure &f = ck.failures().front();
    throw ProfileCheckFailed(kernel_impl_name(f.kernel, f.impl) + " fails its check on the profiled call, so its " +
                             "cycles mean nothing: " + failure_kind_name(f.kind) + ": " + f.message);
  }
  if (!seen) throw sim::SetupError("the profiled call did not run");
  p.overhead = t.null_call_cycles();
  const std::vector<uint8_t> raw = read_file(file);
  ProfileData data = parse_profile(std::string(raw.begin(), raw.end()));
  // The run's windows are the empty call (the overhead) and then the profiled call.
  if (data.windows.size() != 2)
    throw sim::SetupError("the profile has " + std::to_string(data.windows.size()) +
                          " call windows, expected the empty call and the profiled one");
  const std::string objdump =
      std::string(BVB_DEFAULT_SIMULATOR).substr(0, std::string(BVB_DEFAULT_SIMULATOR).rfind('/') + 1) +
      "bfin-elf-objdump";
  auto dis = parse_objdump(capture({objdump, "-d", "-l", "--no-show-raw-insn", target.elf()}));
  Profile built = build_profile(data, dis);
  built.kernel = p.kernel, built.impl = p.impl, built.case_name = p.case_name, built.timing = p.timing;
  built.measured = p.measured, built.overhead = p.overhead;
  // The profile accounts for every cycle the firmware counted, or it is not to be believed.
  if (data.windows[0] != p.overhead || built.total != data.windows[1] || built.total != p.measured + p.overhead)
    throw sim::SetupError("the profile's cycles (" + std::to_string(built.total) + ", empty call " +
                          std::to_string(data.windows[0]) + ") do not add up to the call's " +
                          std::to_string(p.measured) + " + overhead " + std::to_string(p.overhead));
  return built;
}

namespace {

std::string cause_summary(const std::vector<std::string> &names, const std::vector<uint64_t> &c) {
  std::string s;
  for (size_t i = 0; i < c.size(); ++i)
    if (c[i]) s += (s.empty() ? "" : ", ") + names[i] + " " + with_commas(c[i]);
  return s.empty() ? "-" : s;
}

std::string short_file(const std::string &f) {
  size_t k = f.find("/firmware/");
  return k == std::string::npos ? f : f.substr(k + 1);
}

}  // namespace

std::string profile_text(const Profile &p, size_t top_lines) {
  std::ostringstream o;
  o << kernel_impl_name(p.kernel, p.impl) << " " << p.case_name << ", timing " << p.timing << ": "
    << with_commas(p.measured) << " cycles (the call's count; the profile's " << with_commas(p.total)
    << " include the " << p.overhead << "-cycle call overhead)\n";
  o << "  issue " << with_commas(p.issue) << " (" << fmt("%.1f", 100.0 * double(p.issue) / double(p.total))
    << "%)";
  for (size_t i = 0; i < p.causes.size(); ++i)
    if (p.cause[i])
      o << ", " << p.causes[i] << " " << with_commas(p.cause[i]) << " ("
        << fmt("%.1f", 100.0 * double(p.cause[i]) / double(p.total)) << "%)";
  o << "\n\nhot loops (cycles per iteration against the body's issue bound):\n";
  size_t shown = 0;
  for (const auto &l : p.loops) {
    if (shown++ == 10) break;
    double per = double(l.cycles) / double(l.iterations);
    o << "  " << (l.hw ? "hw loop " : "loop    ") << short_file(l.where) << "  " << with_commas(l.iterations)
      << " iterations, " << fmt("%.2f", per) << " cycles each, issue bound " << fmt("%.2f", l.issue_bound)
      << " (" << fmt("%.2fx", per / std::max(1e-9, l.issue_bound)) << ", " << l.body << " instructions), " << fmt("%.1f", 100.0 * double(l.cycles) / double(p.total))
      << "% of the call; stalls: " << cause_summary(p.causes, l.cause) << "\n";
  }
  if (p.loops.empty()) o << "  (none)\n";
  std::vector<const ProfileLine *> hot;
  for (const auto &l : p.lines) hot.push_back(&l);
  std::sort(hot.begin(), hot.end(), [](auto a, auto b) { return a->cycles > b->cycles; });
  o << "\nhottest source lines:\n";
  for (size_t i = 0; i < hot.size() && i < top_lines; ++i) {
    const ProfileLine &l = *hot[i];
    std::string src = l.source;
    while (!src.empty() && (src[0] == ' ' || src[0] == '\t')) src.erase(0, 1);
    if (src.size() > 60) src = src.substr(0, 57) + "...";
      o << "  " << fmt("%5.1f%%", 100.0 * double(l.cycles) / double(p.total)) << " " << with_commas(l.cycles)
      << " cycles, " << with_commas(l.count) << "x  " << short_file(l.file) << ":" << l.line << "  " << src
      << "  [" << cause_summary(p.causes, l.cause) << "]\n";
  }
  return o.str();
}

std::string profile_json(const Profile &p) {
  std::ostringstream o;
  auto arr = [&](const std::vector<uint64_t> &v) {
    std::string s = "{";
    for (size_t i = 0; i < v.size(); ++i)
      s += (i ? ", " : "") + json::quote(p.causes[i]) + ": " + std::to_string(v[i]);
    return s + "}";
  };
  o << "{\n  \"kernel\": " << json::quote(p.kernel) << ", \"impl\": " << json::quote(p.impl)
    << ", \"case\": " << json::quote(p.case_name) << ", \"timing\": " << json::quote(p.timing) << ",\n"
    << "  \"measured_cycles\": " << p.measured << ", \"call_overhead\": " << p.overhead
    << ", \"profile_cycles\": " << p.total << ", \"issue_cycles\": " << p.issue << ",\n"
    << "  \"causes\": " << arr(p.cause) << ",\n  \"loops\": [";
  for (size_t i = 0; i < p.loops.size(); ++i) {
    const auto &l = p.loops[i];
    o << (i ? ",\n    " : "\n    ") << "{\"start\": \"0x" << hex32(l.start) << "\", \"end\": \"0x" << hex32(l.end)
      << "\", \"hardware\": " << (l.hw ? "true" : "false") << ", \"where\": " << json::quote(short_file(l.where))
      << ", \"iterations\": " << l.iterations << ", \"cycles\": " << l.cycles
      << ", \"body_instructions\": " << l.body << ", \"issue_bound\": " << fmt("%.4f", l.issue_bound)
      << ", \"causes\": " << arr(l.cause) << "}";
  }
  o << "],\n  \"lines\": [";
  for (size_t i = 0; i < p.lines.size(); ++i) {
    const auto &l = p.lines[i];
    o << (i ? ",\n    " : "\n    ") << "{\"file\": " << json::quote(short_file(l.file)) << ", \"line\": " << l.line
      << ", \"source\": " << json::quote(l.source) << ", \"count\": " << l.count << ", \"cycles\": " << l.cycles
      << ", \"causes\": " << arr(l.cause) << "}";
  }
  o << "],\n  \"instructions\": [";
  for (size_t i = 0; i < p.insns.size(); ++i) {
    const auto &in = p.insns[i];
    o << (i ? ",\n    " : "\n    ") << "{\"pc\": \"0x" << hex32(in.pc) << "\", \"function\": "
      << json::quote(in.dis.function) << ", \"text\": " << json::quote(in.dis.text) << ", \"file\": "
      << json::quote(short_file(in.dis.file)) << ", \"line\": " << in.dis.line << ", \"count\": " << in.rec.count
      << ", \"cycles\": " << in.rec.cycles << ", \"causes\": " << arr(in.rec.cause)
      << ", \"stall_register\": " << json::quote(in.rec.stall_reg == "-" ? "" : in.rec.stall_reg) << "}";
  }
  o << "]\n}\n";
  return o.str();
}

std::string profile_html(const Profile &p) {
  // The data as JSON inside the page; "</" is escaped so no source text can close the script.
  std::string data = profile_json(p);
  for (size_t k = 0; (k = data.find("</", k)) != std::string::npos; k += 3) data.replace(k, 2, "<\\/");
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>bfbench profile: "
    << kernel_impl_name(p.kernel, p.impl) << " " << p.case_name << "</title>\n<style>\n"
       "body{font:13px/1.35 system-ui,sans-serif;margin:1.5em;color:#222}\n"
       "table{border-collapse:collapse}td,th{padding:1px 6px;text-align:right;white-space:nowrap}\n"
       "td.src{text-align:left;font-family:monospace;white-space:pre}th{border-bottom:1px solid #999}\n"
       "h2{font-size:15px;margin-top:1.5em}.file td{background:#eee;text-align:left;font-weight:bold}\n"
       "</style></head><body>\n<h1 id=\"title\"></h1><p id=\"summary\"></p>\n"
       "<h2>Hot loops</h2><table id=\"loops\"></table>\n"
       "<h2>Source, hottest lines in red</h2><table id=\"source\"></table>\n"
       "<script id=\"profile-data\" type=\"application/json\">\n"
    << data
    << "</script>\n<script>\n"
       "const P = JSON.parse(document.getElementById('profile-data').textContent);\n"
       "const fmt = n => n.toLocaleString('en-US');\n"
       "const pct = n => (100 * n / P.profile_cycles).toFixed(1) + '%';\n"
       "const stalls = c => Object.entries(c).filter(e => e[1] > 0).map(e => e[0] + ' ' + fmt(e[1])).join(', ');\n"
       "function cell(tr, text, cls) { const td = document.createElement(tr.className === 'head' ? 'th' : 'td');\n"
       "  td.textContent = text; if (cls) td.className = cls; tr.appendChild(td); return td; }\n"
       "function row(t, cells, cls) { const tr = document.createElement('tr'); if (cls) tr.className = cls;\n"
       "  cells.forEach(c => cell(tr, c[0], c[1])); t.appendChild(tr); return tr; }\n"
       "document.getElementById('title').textContent = P.kernel + ' (' + P.impl + ') ' + P.case;\n"
       "document.getElementById('summary').textContent = fmt(P.measured_cycles) + ' cycles (timing ' +\n"
       "  P.timing + '; the profile counts ' + fmt(P.profile_cycles) + ' with the ' + P.call_overhead +\n"
       "  '-cycle call overhead): issue ' + fmt(P.issue_cycles) + ', ' + stalls(P.causes);\n"
       "const L = document.getElementById('loops');\n"
       "row(L, [['where', 'src'], ['iterations'], ['cycles'], ['cycles/iteration'], ['issue bound'], ['of call'], ['stalls', 'src']], 'head');\n"
       "P.loops.forEach(l => row(L, [[l.where, 'src'], [fmt(l.iterations)], [fmt(l.cycles)],\n"
       "  [(l.cycles / l.iterations).toFixed(2)], [l.issue_bound.toFixed(2)], [pct(l.cycles)], [stalls(l.causes), 'src']], 'loop'));\n"
       "const S = document.getElementById('source');\n"
       "row(S, [['line'], ['count'], ['cycles'], ['of call'], ['source', 'src'], ['stalls', 'src']], 'head');\n"
       "const max = Math.max(1, ...P.lines.map(l => l.cycles));\n"
       "let file = null;\n"
       "P.lines.forEach(l => {\n"
       "  if (l.file !== file) { file = l.file; const tr = row(S, [[file]], 'file'); tr.firstChild.colSpan = 6; }\n"
       "  const tr = row(S, [[l.line], [fmt(l.count)], [fmt(l.cycles)], [pct(l.cycles)], [l.source, 'src'],\n"
       "    [stalls(l.causes), 'src']], 'line');\n"
       "  const heat = l.cycles / max;\n"
       "  tr.dataset.cycles = l.cycles;\n"
       "  tr.style.background = 'rgba(220, 40, 20, ' + (0.08 + 0.72 * heat).toFixed(3) + ')';\n"
       "});\n"
       "document.body.dataset.rendered = P.lines.length;\n"
       "</script></body></html>\n";
  return o.str();
}

}  // namespace bvb
