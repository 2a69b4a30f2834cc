#include "bench.h"

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "family.h"
#include "io.h"
#include "json.h"

namespace bvb {

CheckCall bench_call_for(const std::string &kernel, Size size, uint32_t seed) {
  const Family *f = family_of(kernel);
  if (!f || !f->bench_call) return {};
  Rng rng(seed ^ (uint64_t(size.w) << 20) ^ uint64_t(size.h));
  return f->bench_call(kernel, size.w, size.h, rng);
}

std::vector<BenchRow> run_bench(const Target &target, const BenchOptions &opts) {
  // Each measured call in a simulator run of its own: its cycles must not depend on -j, -k or
  // the calls measured before it (caches and SDRAM rows carry over within a run).
  Target isolated = target;
  isolated.set_isolated(true);
  CheckOptions co;
  co.seed = opts.seed;
  co.jobs = opts.jobs;
  co.progress = opts.progress;
  co.run_c = opts.run_c;
  co.adversarial = false;  // the calls exactly as measured: no buffer moved, no poison drawn
  Checker ck(isolated, co);
  std::vector<BenchRow> rows;
  std::vector<CheckCall> calls;
  const bool compare = opts.compare_sim && target.timing() != "none";
  for (const Family *f : families()) {
    if (!f->bench_call) continue;
    for (const auto &k : f->kernels) {
      const KernelInfo *ki = target.registry().find(k);
      if (!ki || !glob_match(opts.kernel_glob, k)) continue;
      for (Size s : opts.sizes) {
        // Sizes the budgets name for other kernels may be below this one's minimum.
        if (!bench_size_problem(k, s.w, s.h).empty()) continue;
        CheckCall c = bench_call_for(k, s, opts.seed);
        if (c.kernel.empty()) continue;
        BenchRow r;
        r.kernel = k;
        r.case_name = c.case_name;
        r.pixels = c.pixels;
        r.lower_bound = f->lower_bound ? f->lower_bound(k, s.w, s.h) : 0;
        r.timing = target.timing();
        r.placement = placement_of(c.bufs);
        rows.push_back(r);
        calls.push_back(std::move(c));
      }
    }
  }
  // The same calls without the timing model, for the simulator's own count beside the model's.
  std::vector<CheckCall> sim_calls;
  if (compare) sim_calls = calls;
  // The bench checks what it measures: a wrong answer is not a fast one.
  for (size_t i = 0; i < calls.size(); ++i) {
    BenchRow *row = &rows[i];
    ck.add(std::move(calls[i]), [row](uint32_t impl, const CallResult &r) {
      if (impl == BVB_IMPL_C) row->has_c = true, row->c_cycles = r.cycles;
      else row->has_asm = true, row->asm_cycles = r.cycles;
    });
  }
  ck.flush();
  target.take_null_call_cycles(isolated);
  std::vector<Failure> failures = ck.failures();
  if (compare) {
    Target plain = isolated;
    plain.set_timing("none");
    Checker sk(plain, co);
    for (size_t i = 0; i < sim_calls.size(); ++i) {
      BenchRow *row = &rows[i];
      sk.add(std::move(sim_calls[i]), [row](uint32_t impl, const CallResult &r) {
        row->has_sim = true;
        if (impl == BVB_IMPL_C) row->c_sim = r.cycles;
        else row->asm_sim = r.cycles;
      });
    }
    sk.flush();
    for (auto f : sk.failures()) {
      f.impl += " (timing none)";
      failures.push_back(f);
    }
  }
  for (const auto &f : failures)
    for (auto &r : rows)
      if (r.kernel == f.kernel && r.case_name == f.case_name && r.error.empty())
        r.error = f.impl + ": " + failure_kind_name(f.kind) + ": " + f.message;
  return rows;
}

const char *place_name(uint32_t place) {
  switch (place) {
    case BVB_PLACE_SDRAM: return "SDRAM";
    case BVB_PLACE_L1A: return "L1A";
    case BVB_PLACE_L1B: return "L1B";
    case BVB_PLACE_SCRATCH: return "scratch";
    case BVB_PLACE_WINDOW: return "window";
    case BVB_PLACE_SDRAM_END: return "SDRAM end";
  }
  return "?";
}

std::string placement_of(const std::vector<Buffer> &bufs) {
  bool same = true;
  for (const auto &b : bufs) same &= b.place == bufs.front().place;
  if (bufs.empty()) return "-";
  if (same) return place_name(bufs.front().place);
  std::string s;
  for (const auto &b : bufs) s += (s.empty() ? "" : " ") + b.name + ":" + place_name(b.place);
  return s;
}

namespace {
std::string fmt(const char *f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}
std::string group(uint64_t v) {
  std::string s = std::to_string(v), o;
  for (size_t i = 0; i < s.size(); ++i) {
    if (i && (s.size() - i) % 3 == 0) o += ',';
    o += s[i];
  }
  return o;
}
}  // namespace

namespace {
std::string ratio(uint32_t model, uint32_t sim) { return sim ? fmt("%.2f", double(model) / sim) : "-"; }
const char *units(const std::string &timing) {
  return timing == "none" ? "simulator cycles (--timing none: no stalls, no memory latency)"
                          : "modelled BF537 cycles (--timing bf537)";
}
}  // namespace

std::string bench_table(const std::vector<BenchRow> &rows, uint32_t null_call) {
  std::ostringstream o;
  char line[768];
  const char *head = "%-20s %-8s %13s %13s %9s %8s %9s %8s %13s %8s  %s\n";
  std::snprintf(line, sizeof line, head, "kernel", "case", "C cycles", "asm cycles", "asm c/px",
                "speed-up", "bound c/px", "asm/bound", "asm sim", "mod/sim", "placement");
  o << line;
  bool any_sim = false;
  for (const auto &r : rows) {
    const double px = r.pixels > 0 ? r.pixels : 1;
    std::string c = r.has_c ? group(r.c_cycles) : "-";
    std::string a = r.has_asm ? group(r.asm_cycles) : "-", app = r.has_asm ? fmt("%.2f", r.asm_cycles / px) : "-";
    std::string sp = r.has_c && r.has_asm && r.asm_cycles ? fmt("%.1fx", double(r.c_cycles) / r.asm_cycles) : "-";
    std::string lb = r.lower_bound > 0 ? fmt("%.2f", r.lower_bound / px) : "-";
    std::string eff = r.lower_bound > 0 && r.has_asm ? fmt("%.2f", r.asm_cycles / r.lower_bound) : "-";
    std::string as = r.has_sim && r.has_asm ? group(r.asm_sim) : "-";
    std::string rt = r.has_sim && r.has_asm ? ratio(r.asm_cycles, r.asm_sim)
                     : r.has_sim && r.has_c ? ratio(r.c_cycles, r.c_sim) : "-";
    any_sim |= r.has_sim;
    std::snprintf(line, sizeof line, head, r.kernel.c_str(), r.case_name.c_str(), c.c_str(), a.c_str(),
                  app.c_str(), sp.c_str(), lb.c_str(), eff.c_str(), as.c_str(), rt.c_str(), r.placement.c_str());
    o << line;
    if (!r.error.empty()) o << "  FAILED: " << r.error << "\n";
  }
  const std::string timing = rows.empty() ? "bf537" : rows.front().timing;
  o << "C and asm cycles are " << units(timing) << " per call, the empty call's " << null_call
    << " cycles subtracted\n";
  if (any_sim)
    o << "asm sim: the simulator's own count of the same call (--timing none); mod/sim: modelled / sim\n";
  return o.str();
}

std::string bench_json(const std::vector<BenchRow> &rows, uint32_t null_call) {
  std::ostringstream o;
  const std::string timing = rows.empty() ? "bf537" : rows.front().timing;
  o << "{\n  \"timing\": " << json::quote(timing) << ",\n  \"units\": " << json::quote(units(timing))
    << ",\n  \"null_call_cycles\": " << null_call << ",\n  \"rows\": [";
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto &r = rows[i];
    o << (i ? ",\n" : "\n") << "    {\"kernel\": " << json::quote(r.kernel)
      << ", \"case\": " << json::quote(r.case_name) << ", \"pixels\": " << r.pixels
      << ", \"placement\": " << json::quote(r.placement);
    if (r.has_c) o << ", \"c_cycles\": " << r.c_cycles;
    if (r.has_asm) o << ", \"asm_cycles\": " << r.asm_cycles;
    if (r.has_sim && r.has_c) o << ", \"c_sim_cycles\": " << r.c_sim;
    if (r.has_sim && r.has_asm) o << ", \"asm_sim_cycles\": " << r.asm_sim;
    if (r.lower_bound > 0) o << ", \"lower_bound\": " << r.lower_bound;
    if (!r.error.empty()) o << ", \"error\": " << json::quote(r.error);
    o << "}";
  }
  o << "\n  ]\n}\n";
  return o.str();
}

std::string bench_csv(const std::vector<BenchRow> &rows) {
  std::ostringstream o;
  o << "kernel,case,pixels,timing,c_cycles,asm_cycles,c_sim_cycles,asm_sim_cycles,lower_bound,placement,error\n";
  for (const auto &r : rows) {
    o << r.kernel << "," << r.case_name << "," << r.pixels << "," << r.timing << ",";
    if (r.has_c) o << r.c_cycles;
    o << ",";
    if (r.has_asm) o << r.asm_cycles;
    o << ",";
    if (r.has_sim && r.has_c) o << r.c_sim;
    o << ",";
    if (r.has_sim && r.has_asm) o << r.asm_sim;
    o << "," << (r.lower_bound > 0 ? std::to_string(r.lower_bound) : "") << "," << r.placement << ","
      << (r.error.empty() ? "" : "\"failed\"") << "\n";
  }
  return o.str();
}

std::string bench_markdown(const std::vector<BenchRow> &rows) {
  std::ostringstream o;
  o << "| kernel | case | C cycles | asm cycles | speed-up | C c/px | asm c/px | bound c/px | C sim | asm sim | "
       "asm model/sim | placement |\n"
       "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const auto &r : rows) {
    const double px = r.pixels > 0 ? r.pixels : 1;
    o << "| " << r.kernel << " | " << r.case_name << " | " << (r.has_c ? group(r.c_cycles) : "-") << " | "
      << (r.has_asm ? group(r.asm_cycles) : "-") << " | "
      << (r.has_c && r.has_asm && r.asm_cycles ? fmt("%.1fx", double(r.c_cycles) / r.asm_cycles) : "-") << " | "
      << (r.has_c ? fmt("%.2f", r.c_cycles / px) : "-") << " | " << (r.has_asm ? fmt("%.2f", r.asm_cycles / px) : "-")
      << " | " << (r.lower_bound > 0 ? fmt("%.2f", r.lower_bound / px) : "-") << " | "
      << (r.has_sim && r.has_c ? group(r.c_sim) : "-") << " | " << (r.has_sim && r.has_asm ? group(r.asm_sim) : "-")
      << " | " << (r.has_sim && r.has_asm ? ratio(r.asm_cycles, r.asm_sim) : "-") << " | " << r.placement << " |\n";
  }
  return o.str();
}


std::vector<Budget> load_budgets(const std::string &path, std::string *timing) {
  auto bytes = read_file(path);
  return parse_budgets(std::string(bytes.begin(), bytes.end()), path, timing);
}

std::vector<Budget> parse_budgets(const std::string &text, const std::string &path, std::string *timing) {
  json::Value v = json::parse(text, path);
  const json::Value *b = v.type == json::Value::Object ? v.get("budgets") : nullptr;
  if (!b || b->type != json::Value::Object) throw InputError(path + ": no \"budgets\" object");
  std::string t = "none";
  if (const json::Value *tv = v.get("timing")) {
    if (tv->type != json::Value::String || !valid_timing(tv->str))
      throw InputError(path + ": \"timing\" must be \"none\" or \"bf537\"");
    t = tv->str;
  }
  if (timing) *timing = t;
  std::vector<Budget> out;
  for (const auto &kv : b->obj) {
    const json::Value *c = kv.second.get("cycles");
    if (!c || c->type != json::Value::Number || c->num < 0 || c->num > 1e15)
      throw InputError(path + ": budget " + kv.first + " has no valid \"cycles\"");
    Budget bd{kv.first, uint64_t(c->num), 0};
    if (const json::Value *t = kv.second.get("tolerance_pct")) {
      if (t->type != json::Value::Number || t->num < 0 || t->num > 100)
        throw InputError(path + ": budget " + kv.first + " has a bad \"tolerance_pct\"");
      bd.tolerance_pct = t->num;
    }
    if (std::count(kv.first.begin(), kv.first.end(), '/') != 2)
      throw InputError(path + ": budget key '" + kv.first + "' is not kernel/impl/case");
    // The case starts with the size it is measured at, which must be one the kernel can take.
    const std::string kernel = budget_key_kernel(kv.first);
    Size sz{0, 0};
    if (!parse_size_prefix(budget_key_case(kv.first), &sz) || sz.w < 1 || sz.h < 1 || sz.w > kMaxFrameDim ||
        sz.h > kMaxFrameDim)
      throw InputError(path + ": budget key '" + kv.first + "': the case must start with WxH, 1.." +
                       std::to_string(kMaxFrameDim) + " each");
    const std::string why = bench_size_problem(kernel, sz.w, sz.h);
    if (!why.empty()) throw InputError(path + ": budget key '" + kv.first + "': " + why);
    out.push_back(bd);
  }
  return out;
}

void save_budgets(const std::string &path, const std::vector<Budget> &budgets, const std::string &timing) {
  std::vector<Budget> sorted = budgets;
  std::sort(sorted.begin(), sorted.end(), [](const Budget &a, const Budget &b) { return a.key < b.key; });
  std::ostringstream o;
  o << "{\n  \"chip\": \"bf537\",\n  \"timing\": " << json::quote(timing) << ",\n  \"units\": "
    << json::quote(std::string(units(timing)) + " per call, empty-call overhead subtracted, buffers where the bench places them")
    << ",\n  \"budgets\": {";
  for (size_t i = 0; i < sorted.size(); ++i) {
    o << (i ? ",\n" : "\n") << "    " << json::quote(sorted[i].key) << ": {\"cycles\": " << sorted[i].cycles;
    if (sorted[i].tolerance_pct > 0) o << ", \"tolerance_pct\": " << sorted[i].tolerance_pct;
    o << "}";
  }
  o << "\n  }\n}\n";
  std::string s = o.str();
  write_file_atomic(path, s.data(), s.size());
}

std::vector<BudgetVerdict> judge_budgets(const std::vector<BenchRow> &rows,
                                         const std::vector<Budget> &budgets) {
  std::map<std::string, const Budget *> by_key;
  for (const auto &b : budgets) by_key[b.key] = &b;
  std::set<std::string> measured;
  std::vector<BudgetVerdict> out;
  for (const auto &r : rows) {
    if (!r.has_asm) continue;
    BudgetVerdict v;
    v.key = r.key("asm");
    v.measured = r.asm_cycles;
    measured.insert(v.key);
    auto it = by_key.find(v.key);
    if (!r.error.empty()) {
      v.status = BudgetVerdict::Failed;
      v.detail = r.error;
      if (it != by_key.end()) v.budget = it->second->cycles;
    } else if (it == by_key.end()) {
      v.status = BudgetVerdict::Missing;
    } else {
      v.budget = it->second->cycles;
      v.status = v.measured > budget_allowed(*it->second) ? BudgetVerdict::Over : BudgetVerdict::Ok;
    }
    out.push_back(v);
  }
  for (const auto &b : budgets)
    if (!measured.count(b.key)) {
      BudgetVerdict v;
      v.key = b.key;
      v.budget = b.cycles;
      v.status = BudgetVerdict::Unmeasured;
      out.push_back(v);
    }
  return out;
}

uint64_t budget_allowed(const Budget &b) {
  const double excess = double(b.cycles) * b.tolerance_pct / 100;
  // Whole cycles; the nudge absorbs the binary error of a decimal percentage (0.1 is stored as
  // a little more or less than 0.1), far below a cycle for any legal budget.
  return b.cycles + uint64_t(std::floor(excess + 1e-7 * (1 + excess)));
}

std::vector<std::string> unjudged_kernels(const std::vector<std::string> &asm_kernels, const std::string &glob,
                                          const std::vector<BudgetVerdict> &verdicts) {
  std::vector<std::string> out;
  for (const auto &k : asm_kernels) {
    if (!glob_match(glob, k)) continue;
    bool judged = false;
    for (const auto &v : verdicts) judged |= v.key.compare(0, k.size() + 5, k + "/asm/") == 0;
    if (!judged) out.push_back(k);
  }
  return out;
}

double budget_slack_pct(const BudgetVerdict &v, double pct) {
  if (v.status != BudgetVerdict::Ok || v.measured == 0) return 0;
  const double slack = (double(v.budget) - double(v.measured)) * 100 / double(v.measured);
  return slack > pct ? slack : 0;
}

std::vector<Size> budget_sizes(const std::vector<Budget> &budgets) {
  std::set<std::pair<int, int>> seen;
  std::vector<Size> out;
  for (const auto &b : budgets) {
    Size s{0, 0};
    if (parse_size_prefix(budget_key_case(b.key), &s) && seen.insert({s.w, s.h}).second) out.push_back(s);
  }
  return out;
}

}  // namespace bvb
