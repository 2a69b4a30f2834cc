// The simulator driver with stand-in simulators (shell scripts): a timeout ends the whole
// process group, and nothing the simulator started can keep bfbench waiting on the pipe.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>

#include "simdriver.h"

namespace {

std::string script(const std::string &name, const std::string &body) {
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
  chmod(path.c_str(), 0755);
  return path;
}

bvb::sim::RunSpec spec_for(const std::string &simulator, double timeout_s) {
  bvb::sim::RunSpec spec;
  spec.simulator = simulator;
  spec.elf = simulator;  // any readable file: the stand-ins ignore it
  spec.wall_timeout_s = timeout_s;
  return spec;
}

// Running, not a zombie (a killed orphan may wait for a reaper that is slow or absent).
bool alive(pid_t pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(f, line)) return false;
  const size_t close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A wrapper script that does not exec: the shell is the child, sleep the grandchild holding the
// pipe. Killing only the shell left bfbench waiting for sleep to finish.
TEST(SimDriver, TimeoutKillsTheWholeGroup) {
  const std::string pidfile = testing::TempDir() + "grandchild.pid";
  std::remove(pidfile.c_str());
  const std::string sim = script("sim_no_exec.sh", "echo started\nsleep 30 &\necho $! > " + pidfile + "\nwait");
  const auto t0 = std::chrono::steady_clock::now();
  bvb::sim::RunResult r = bvb::sim::run(spec_for(sim, 1));
  EXPECT_LT(seconds_since(t0), 10) << "waited for the grandchild";
  EXPECT_EQ(r.ending, bvb::sim::Ending::TimedOut);
  EXPECT_NE(r.output.find("started"), std::string::npos) << r.output;
  pid_t grandchild = 0;
  std::ifstream(pidfile) >> grandchild;
  ASSERT_GT(grandchild, 0);
  for (int i = 0; i < 40 && alive(grandchild); ++i) usleep(50000);
  EXPECT_FALSE(alive(grandchild)) << "the simulator's child outlived the timeout";
  if (alive(grandchild)) kill(grandchild, SIGKILL);
}

// A simulator that exits but leaves a child holding its output open: the run ends without
// waiting for that child.
TEST(SimDriver, ExitedSimulatorsLingeringChildDoesNotHold) {
  const std::string sim = script("sim_leaves_child.sh", "sleep 30 &\necho done\nexit 3");
  const auto t0 = std::chrono::steady_clock::now();
  bvb::sim::RunResult r = bvb::sim::run(spec_for(sim, 60));
  EXPECT_LT(seconds_since(t0), 10);
  EXPECT_EQ(r.ending, bvb::sim::Ending::Exited);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.output.find("done"), std::string::npos) << r.output;
}

}  // namespace

namespace {

// A simulator's last line goes into one-line reports: control characters and binary bytes are
// escaped, and a long line is cut.
TEST(SimDriver, DescribeShowsOutputPrintable) {
  bvb::sim::RunResult r;
  r.ending = bvb::sim::Ending::Exited;
  r.exit_code = 1;
  r.output = "first line\nbad \x01\x1b[31mred\x7f" + std::string(500, 'x') + "\n";
  const std::string d = bvb::sim::describe(r);
  for (unsigned char c : d) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << int(c) << " in " << d;
  EXPECT_NE(d.find("bad \\x01\\x1b[31mred\\x7f"), std::string::npos) << d;
  EXPECT_LT(d.size(), 300u) << d;
}

}  // namespace
