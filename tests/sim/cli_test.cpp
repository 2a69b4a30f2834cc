// bfbench's contract with its users: bad input gets one clear line and exit 2, never a crash or
// a half-written output; a good run writes what the host reference computes.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "bvb/add_sat.h"
#include "io.h"

namespace bvb {
namespace {

struct CliRun {
  int status;
  std::string out, err;
};

std::string dir() { return testing::TempDir(); }

CliRun bfbench(const std::string &args, const std::string &env = "") {
  const std::string o = dir() + "cli.out", e = dir() + "cli.err";
  const std::string cmd = env + " " + BFBENCH_EXE + " " + args + " >" + o + " 2>" + e;
  int rc = std::system(cmd.c_str());
  auto slurp = [](const std::string &p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
  };
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(o), slurp(e)};
}

bool exists(const std::string &p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0;
}

void write(const std::string &path, const std::string &bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

Image frame(int w, int h, int seed) {
  Image img(w, h);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = uint8_t(i * 37 + seed * 101);
  return img;
}

// One line, naming the problem, exit 2, and the output file never appears.
void expect_bad_input(const std::string &args, const std::string &message_part, const std::string &out = "") {
  if (!out.empty()) std::remove(out.c_str());
  CliRun r = bfbench(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(message_part), std::string::npos) << args << ": " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  if (!out.empty()) {
    EXPECT_FALSE(exists(out)) << out << " was written";
  }
}

TEST(Cli, RunWritesWhatTheHostReferenceComputes) {
  const std::string a = dir() + "a.pgm", b = dir() + "b.pgm", out = dir() + "sum.pgm", host = dir() + "host.pgm";
  Image ia = frame(37, 11, 1), ib = frame(37, 11, 2);
  write_pnm(a, ia);
  write_pnm(b, ib);
  CliRun r = bfbench("run add_sat_u8 --in " + a + " --in " + b + " --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("cycles"), std::string::npos) << r.out;
  Image got = read_pnm(out);
  Image want(37, 11);
  bvb_add_sat_u8_c(ia.data.data(), ib.data.data(), want.data.data(), 37, 11, 37, 37);
  EXPECT_EQ(got.data, want.data);
  ASSERT_EQ(bfbench("run add_sat_u8 --impl host --in " + a + " --in " + b + " --out " + host).status, 0);
  EXPECT_EQ(read_pnm(host).data, want.data);
}

TEST(Cli, BadFramesAreRejected) {
  const std::string ok = dir() + "ok.pgm", out = dir() + "never.pgm";
  write_pnm(ok, frame(8, 8, 3));
  const std::string trunc = dir() + "trunc.pgm", magic = dir() + "magic.pgm", huge = dir() + "huge.pgm",
                    small = dir() + "small.pgm";
  write(trunc, "P5\n8 8\n255\nabc");
  write(magic, "P9\n8 8\n255\n");
  write(huge, "P5\n99999 99999\n255\n");
  write_pnm(small, frame(4, 8, 1));
  expect_bad_input("run add_sat_u8 --in " + trunc + " --in " + ok + " --out " + out, "truncated", out);
  expect_bad_input("run add_sat_u8 --in " + magic + " --in " + ok + " --out " + out, "bad magic", out);
  expect_bad_input("run add_sat_u8 --in " + huge + " --in " + ok + " --out " + out, "larger than", out);
  expect_bad_input("run add_sat_u8 --in " + small + " --in " + ok + " --out " + out, "differ in size", out);
  expect_bad_input("run add_sat_u8 --in " + dir() + "missing.pgm --in " + ok + " --out " + out, "cannot open", out);
  const std::string raw = dir() + "f.uyvy";
  write(raw, std::string(8 * 8 * 2 - 1, 'x'));
  expect_bad_input("run add_sat_u8 --size 8x8 --in " + raw + " --in " + raw + " --out " + out, "UYVY", out);
}

TEST(Cli, BadUsageIsRejected) {
  const std::string ok = dir() + "ok2.pgm", out = dir() + "never2.pgm";
  write_pnm(ok, frame(8, 8, 3));
  expect_bad_input("frobnicate", "unknown command");
  expect_bad_input("run no_such_kernel --in " + ok + " --out " + out, "unknown kernel", out);
  expect_bad_input("run add_sat_u8 --in " + ok + " --in " + ok + " --out " + out + " --param gain=2",
                   "unknown parameter", out);
  expect_bad_input("run add_sat_u8 --in " + ok + " --in " + ok + " --out " + out + " --impl fast",
                   "unknown implementation", out);
  expect_bad_input("run add_sat_u8 --in " + ok + " --out " + out, "two --in", out);
  expect_bad_input("bench --size 0x5", "--size");
  expect_bad_input("check -k no_such_kernel", "no kernel matches");
  expect_bad_input("check --seed banana", "--seed");
  expect_bad_input("check --bogus", "unknown option");
  CliRun none = bfbench("");
  EXPECT_EQ(none.status, 2);
}

TEST(Cli, MalformedBudgetsAndMissingSimulator) {
  const std::string bad = dir() + "bad.json", nokey = dir() + "nokey.json";
  write(bad, "{\"budgets\": {\"add_sat_u8/asm/160x120\": {\"cycles\": }}}");
  write(nokey, "{\"budgets\": {\"add_sat_u8\": {\"cycles\": 5}}}");
  expect_bad_input("budgets --file " + bad, "malformed JSON");
  expect_bad_input("budgets --file " + nokey, "kernel/impl/case");
  CliRun r = bfbench("check -k add_sat_u8 --seed 1", "BFBENCH_SIM=/nonexistent/bfin-elf-run");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("simulator not found"), std::string::npos) << r.err;
}

TEST(Cli, BudgetsFailWhenOverOrMissing) {
  const std::string tight = dir() + "tight.json", empty = dir() + "empty.json";
  write(tight, "{\"budgets\": {\"add_sat_u8/asm/160x120\": {\"cycles\": 1000}}}");
  CliRun over = bfbench("budgets -k add_sat_u8 --file " + tight);
  EXPECT_EQ(over.status, 1) << over.out << over.err;
  EXPECT_NE(over.out.find("OVER BUDGET"), std::string::npos) << over.out;
  EXPECT_NE(over.out.find("NO BUDGET"), std::string::npos) << over.out;  // 320x240, 640x480
  write(empty, "{\"budgets\": {}}");
  CliRun upd = bfbench("budgets --update -k add_sat_u8 --file " + empty);
  EXPECT_EQ(upd.status, 0) << upd.err;
  EXPECT_NE(upd.out.find("add_sat_u8/asm/160x120                   new -> "), std::string::npos) << upd.out;
  EXPECT_EQ(bfbench("budgets -k add_sat_u8 --file " + empty).status, 0);
}

}  // namespace
}  // namespace bvb
