// bfbench run as the user runs it, through the shell, for the tests of its command line
// (BFBENCH_EXE names the binary): its exit status and what it wrote to stdout and stderr.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "tempdir.h"

namespace bvb {

struct CliRun {
  int status;  // exit status, or 128 + signal as a shell reports it
  std::string out, err;
};

inline std::string slurp(const std::string &p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// env goes before the command ("VAR=x", "ulimit -v N;").
inline CliRun bfbench(const std::string &args, const std::string &env = "") {
  // Per process: ctest runs the tests of a file in parallel.
  const std::string id = std::to_string(getpid());
  const std::string o = test_dir() + "bfbench." + id + ".out", e = test_dir() + "bfbench." + id + ".err";
  const std::string cmd = env + " " + BFBENCH_EXE + " " + args + " >" + o + " 2>" + e;
  const int rc = std::system(cmd.c_str());
  const int status = WIFEXITED(rc) ? WEXITSTATUS(rc) : WIFSIGNALED(rc) ? 128 + WTERMSIG(rc) : -1;
  return {status, slurp(o), slurp(e)};
}

}  // namespace bvb
