// bfbench for this tree's kernels (firmware/kernels.def, bvb.elf, ci/budgets.json).
#include "bfbench.h"

int main(int argc, char **argv) { return bvb::bfbench_main(argc, argv); }
