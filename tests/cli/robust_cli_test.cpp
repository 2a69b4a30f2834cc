// bfbench on bad input and hostile paths, where no simulator is needed: one clear line and
// exit 2, never a crash, a hang, or a file destroyed or half-written.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "io.h"

namespace bvb {
namespace {

struct CliRun {
  int status;  // exit status, or 128 + signal as a shell reports it
  std::string out, err;
};

std::string dir() { return testing::TempDir(); }

std::string slurp(const std::string &p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

CliRun bfbench(const std::string &args, const std::string &env = "") {
  const std::string o = dir() + "rcli.out", e = dir() + "rcli.err";
  const std::string cmd = env + " " + BFBENCH_EXE + " " + args + " >" + o + " 2>" + e;
  int rc = std::system(cmd.c_str());
  int status = WIFEXITED(rc) ? WEXITSTATUS(rc) : WIFSIGNALED(rc) ? 128 + WTERMSIG(rc) : -1;
  return {status, slurp(o), slurp(e)};
}


Image frame(int w, int h, int seed) {
  Image img(w, h);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = uint8_t(i * 37 + seed * 101);
  return img;
}

// One line naming the problem, exit 2.
void expect_bad_input(const std::string &args, const std::string &message_part) {
  CliRun r = bfbench(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(message_part), std::string::npos) << args << ": " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(HostOnly, HostCommandsRun) {
  const std::string in = dir() + "ho.pgm", out = dir() + "ho_out.pgm";
  write_pnm(in, frame(16, 16, 1));
  CliRun r = bfbench("run erode3x3_u8 --impl host --in " + in + " --out " + out);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_pnm(out).width, 16);
  EXPECT_EQ(bfbench("list").status, 0);
}

}  // namespace
}  // namespace bvb
