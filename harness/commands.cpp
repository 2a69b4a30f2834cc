// bfbench commands beyond the kernel harness (scenes, pipelines, accuracy reports), dispatched
// by name so each lives with its own code.
#include <cstdio>
#include <string>
#include <vector>

#include "extra_commands.h"
#include "flow/hs_accuracy_cli.h"
#include "session/runner.h"
#include "scene/scene_cli.h"

namespace bvb {

static const ExtraCommand kCommands[] = {
    {"scene", "generate a synthetic scene with ground truth (or check one)", scene_command},
    {"pipeline", "run a vision pipeline frame by frame (bfbench pipeline --help)", pipeline_command},
    {"hs-accuracy", "Horn-Schunck fixed point vs double vs ground truth (EPE, AE)", hs_accuracy_command},
};

int extra_command(const std::string &name, int argc, char **argv, bool *handled) {
  for (const auto &c : registered_commands())
    if (name == c.name) {
      *handled = true;
      return c.fn(argc, argv);
    }
  for (const auto &c : kCommands)
    if (name == c.name) {
      *handled = true;
      return c.fn(argc, argv);
    }
  *handled = false;
  return 2;
}

void print_extra_commands(FILE *out) {
  for (const auto &c : kCommands) std::fprintf(out, "  %-24s %s\n", c.name, c.summary);
  for (const auto &c : registered_commands()) std::fprintf(out, "  %-24s %s\n", c.name, c.summary);
}

}  // namespace bvb
