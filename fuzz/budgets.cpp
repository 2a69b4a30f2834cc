// The budgets file (ci/budgets.json): parse_budgets, what load_budgets runs on the file's text,
// with the kernel registry linked so budget keys are checked against the kernels' sizes.
#include "bench.h"
#include "fuzz_target.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  fuzz::parse_or_reject([&] { return parse_budgets(fuzz::text_of(data, size), "budgets.json"); });
  return 0;
}
