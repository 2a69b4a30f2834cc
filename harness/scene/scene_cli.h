// `bfbench scene ...`: generate a scene directory from a spec string, or check one.
#pragma once

namespace bvb {

// argv[0] is the subcommand's own name ("scene"); options follow. Returns the exit status:
// 0 success, 2 bad usage or bad input (one line on stderr), 1 an unexpected failure.
int scene_command(int argc, char **argv);

}  // namespace bvb
