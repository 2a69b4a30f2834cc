// bfbench's command line as a function: harness/main.cpp calls it for this tree's kernels, and
// the bfbench that bvb_add_kernel_family builds for a family outside this tree calls it after
// set_product (registry.h) names that family's kernels, image and budgets.
#pragma once

namespace bvb {

// Exit status: 0 success, 1 a check or budget failed, 2 bad usage or bad input.
int bfbench_main(int argc, char **argv);

}  // namespace bvb
