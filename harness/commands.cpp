// bfbench commands beyond the kernel harness (scenes, pipelines, accuracy reports), dispatched
// by name so each lives with its own code.
#include <string>

namespace bvb {

int extra_command(const std::string &name, int argc, char **argv, bool *handled) {
  (void)name;
  (void)argc;
  (void)argv;
  *handled = false;
  return 2;
}

}  // namespace bvb
