// bfbench commands that only this tree's bfbench links (its pipelines' commands), registered at
// start-up by the code that defines them, so that a kernel family's bfbench
// (bvb_add_kernel_family), which links bvb_cli and its own checks only, does not need them.
#pragma once

#include <vector>

namespace bvb {

struct ExtraCommand {
  const char *name;
  const char *summary;
  int (*fn)(int argc, char **argv);  // argv[0] is the command's name
};

// Adds a command (from a static initialiser); returns true.
bool register_extra_command(const char *name, const char *summary, int (*fn)(int argc, char **argv));
const std::vector<ExtraCommand> &registered_commands();

}  // namespace bvb
