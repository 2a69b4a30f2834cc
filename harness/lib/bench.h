// Benchmarks (simulator cycles per call, the empty call's overhead already subtracted by the
// firmware) and the cycle budgets in ci/budgets.json that gate merges.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "check.h"
#include "patterns.h"

namespace bvb {

struct BenchRow {
  std::string kernel;
  std::string case_name;  // e.g. "160x120"
  double pixels = 0;
  bool has_c = false, has_asm = false;
  uint32_t c_cycles = 0, asm_cycles = 0;  // under the target's timing model (modelled cycles)
  // The same calls under --timing none (the simulator's own count), when the bench compared.
  bool has_sim = false;
  uint32_t c_sim = 0, asm_sim = 0;
  std::string timing;     // the model c_cycles and asm_cycles are in: "bf537" or "none"
  std::string placement;  // where the buffers were: "SDRAM", or "src:SDRAM dst:L1A ..."
  double lower_bound = 0;  // cycles; 0 when the kernel states none
  std::string error;       // the kernel failed its check during the bench
  std::string key(const char *impl) const { return budget_key(kernel, impl, case_name); }
};

struct BenchOptions {
  std::string kernel_glob = "*";
  std::vector<Size> sizes = {{160, 120}, {320, 240}, {640, 480}};
  bool run_c = true;
  int jobs = 1;
  uint32_t seed = 1;
  bool progress = false;
  // Also run every call under --timing none and report both counts (when the target models).
  bool compare_sim = true;
};

// Where a place is: "SDRAM", "L1A", "L1B", "scratch", "window".
const char *place_name(uint32_t place);
// Every buffer's place: the one name when all agree, else "name:PLACE ...".
std::string placement_of(const std::vector<Buffer> &bufs);

// The call the bench measures for a kernel at a size (its family's bench call, with the random
// stream bench draws it from); an empty kernel name when the family has none.
CheckCall bench_call_for(const std::string &kernel, Size size, uint32_t seed);

std::vector<BenchRow> run_bench(const Target &target, const BenchOptions &opts);
std::string bench_table(const std::vector<BenchRow> &rows, uint32_t null_call_cycles);
std::string bench_json(const std::vector<BenchRow> &rows, uint32_t null_call_cycles);
std::string bench_csv(const std::vector<BenchRow> &rows);
// The README's cycle table.
std::string bench_markdown(const std::vector<BenchRow> &rows);

struct Budget {
  std::string key;  // kernel/impl/case
  uint64_t cycles = 0;
  double tolerance_pct = 0;  // allowed excess; 0 = exact
};

// The file's "timing" (the model its cycles are in) goes to *timing: "none" when the file
// names none (budgets from before the timing model were the simulator's own counts).
std::vector<Budget> load_budgets(const std::string &path, std::string *timing = nullptr);
// load_budgets without the file: the text of one, `path` naming it in errors.
std::vector<Budget> parse_budgets(const std::string &text, const std::string &path, std::string *timing = nullptr);
void save_budgets(const std::string &path, const std::vector<Budget> &budgets, const std::string &timing);

struct BudgetVerdict {
  std::string key;
  uint64_t budget = 0;  // 0 when there is none
  uint64_t measured = 0;
  enum { Ok, Over, Missing, Unmeasured, Failed } status = Ok;
  std::string detail;
};
// Every assembly row needs a budget and must not exceed it; a budget no row measured is
// reported (a kernel removed or renamed) and fails too.
std::vector<BudgetVerdict> judge_budgets(const std::vector<BenchRow> &rows,
                                         const std::vector<Budget> &budgets);
// The most cycles a budget allows: its cycles plus tolerance_pct percent of them, rounded down
// to a whole cycle (the percentage taken as the decimal it is written as, not its binary
// approximation: 0.1% of 1000 allows 1001).
uint64_t budget_allowed(const Budget &b);
// Assembly kernels of the registry under glob that no verdict names: nothing measured them, so
// nothing judged them.
std::vector<std::string> unjudged_kernels(const std::vector<std::string> &asm_kernels, const std::string &glob,
                                          const std::vector<BudgetVerdict> &verdicts);
// A passing budget more than pct percent above what was measured: slack that would let a
// regression through. Returns the excess in percent, or 0 when within pct.
double budget_slack_pct(const BudgetVerdict &v, double pct = 2.0);
// The sizes the budgets name, so the gate measures exactly those.
std::vector<Size> budget_sizes(const std::vector<Budget> &budgets);

}  // namespace bvb
