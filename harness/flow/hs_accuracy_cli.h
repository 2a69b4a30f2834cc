// `bfbench hs-accuracy`: the accuracy of the fixed-point Horn-Schunck reference on the frames-real
// sequences with ground truth (harness/flow/hs_accuracy.h), as a table.
#pragma once

namespace bvb {

// argv[0] is the command's own name; options follow. Returns the exit status: 0 success, 2 bad
// usage or input (one line on stderr), 1 an unexpected failure.
int hs_accuracy_command(int argc, char **argv);

}  // namespace bvb
