#include "extra_commands.h"

namespace bvb {

static std::vector<ExtraCommand> &table() {
  static std::vector<ExtraCommand> t;
  return t;
}

bool register_extra_command(const char *name, const char *summary, int (*fn)(int, char **)) {
  table().push_back({name, summary, fn});
  return true;
}

const std::vector<ExtraCommand> &registered_commands() { return table(); }

}  // namespace bvb
