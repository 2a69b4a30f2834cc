// Every bfbench command's command line through the real binary: --help (exit 0), and the same
// one-line "bfbench CMD: ..." with exit 2 for an unknown option, a missing value, a malformed
// size or a repeated option, and for a set-up that cannot run; exit 1 for a failed verdict.
// No simulator runs here (a simulator that does not exist is one of the set-ups).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "bfbench_run.h"

namespace bvb {
namespace {

const std::vector<std::string> kCommands = {"list",    "check", "bench",    "run",         "budgets", "profile",
                                            "debug",   "scene", "pipeline", "hs-accuracy", "heldout"};

// Exit 2 and exactly one line on stderr, "bfbench CMD: " then the message, which has `part`.
void expect_usage_error(const std::string &cmd, const std::string &args, const std::string &part,
                        const std::string &env = "") {
  const CliRun r = bfbench(cmd + " " + args, env);
  EXPECT_EQ(r.status, 2) << cmd << " " << args << "\n" << r.err;
  EXPECT_EQ(r.err.rfind("bfbench " + cmd + ": ", 0), 0u) << cmd << " " << args << ": " << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << cmd << " " << args << ": " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

struct Mistake {
  std::string cmd, args, part;
};
void expect_usage_errors(const std::vector<Mistake> &mistakes) {
  for (const auto &m : mistakes) expect_usage_error(m.cmd, m.args, m.part);
}

TEST(Commands, EveryCommandHasHelp) {
  for (const auto &cmd : kCommands)
    for (const char *h : {"--help", "-h"}) {
      const CliRun r = bfbench(cmd + " " + h);
      EXPECT_EQ(r.status, 0) << cmd << " " << h << ": " << r.err;
      EXPECT_EQ(r.out.rfind("usage: bfbench " + cmd + " ", 0), 0u) << r.out;
      EXPECT_NE(r.out.find("\n  -h, --help"), std::string::npos) << cmd << ":\n" << r.out;
      EXPECT_NE(r.out.find("Exit status"), std::string::npos) << cmd << ":\n" << r.out;
      EXPECT_EQ(r.err, "") << cmd;
    }
  // The top level lists every command.
  const CliRun top = bfbench("--help");
  EXPECT_EQ(top.status, 0);
  for (const auto &cmd : kCommands) EXPECT_NE(top.out.find("\n  " + cmd + " "), std::string::npos) << cmd;
}

TEST(Commands, HelpListsEachDeclaredOption) {
  // A few options per command, as the README and the scripts spell them.
  const std::vector<std::pair<std::string, std::vector<std::string>>> want = {
      {"check", {"-k, --kernel GLOB", "--seed N", "--seeds COUNT", "-j N", "--campaign", "--case KERNEL:N", "-v"}},
      {"bench", {"--size WxH", "--json FILE", "--csv FILE", "--markdown FILE", "--asm-only", "--no-sim"}},
      {"run", {"--in FILE", "--out FILE", "--impl asm|c|host", "--param K=V", "--grey", "--out-buffer NAME"}},
      {"budgets", {"--update", "--file FILE", "--timing none|bf537"}},
      {"profile", {"--size WxH", "--lines N", "--json FILE", "--html FILE"}},
      {"debug", {"--case KERNEL:N", "--seed S", "--batch"}},
      {"scene", {"--spec SPEC", "--out DIR", "--force", "--check DIR", "--list-arenas"}},
      {"pipeline", {"--scene DIR", "--spec SPEC", "--closed-loop", "--frames N", "--svg PREFIX", "--compare-host"}},
      {"hs-accuracy", {"--alpha A", "--iterations N", "--sequence NAME", "--frames DIR"}},
      {"heldout", {"--seed N", "--runs N", "--run K", "--save DIR", "--builds-only", "--ss N", "--size WxH"}},
  };
  for (const auto &w : want) {
    const CliRun r = bfbench(w.first + " --help");
    for (const auto &opt : w.second) EXPECT_NE(r.out.find("\n  " + opt), std::string::npos) << w.first << ": " << opt;
  }
}

TEST(Commands, UnknownOptionIsExitTwo) {
  for (const auto &cmd : kCommands) expect_usage_error(cmd, "--no-such-option", "unknown option --no-such-option");
  expect_usage_error("check", "--seed=1 --bogus=2", "unknown option --bogus");
}

TEST(Commands, MissingValueIsExitTwo) {
  const std::vector<std::pair<std::string, std::string>> last = {
      {"check", "--seed"},       {"bench", "--size"},         {"run", "add_sat_u8 --in"}, {"budgets", "--file"},
      {"profile", "x --lines"},  {"debug", "x --case"},       {"scene", "--spec"},        {"pipeline", "x --frames"},
      {"hs-accuracy", "--alpha"}, {"heldout", "--runs"}};
  for (const auto &c : last) {
    const std::string option = c.second.substr(c.second.rfind(' ') + 1);
    expect_usage_error(c.first, c.second, option + " needs a value");
  }
}

TEST(Commands, MalformedValuesAreExitTwo) {
  expect_usage_errors({
      {"bench", "--size 12x", "--size wants WxH (1..4096), got '12x'"},
      {"bench", "--size 160x120 --size=0x5", "--size wants WxH"},
      {"run", "add_sat_u8 --in a.uyvy --in b.uyvy --out c.pgm --size 8x8x8", "--size wants WxH"},
      {"profile", "add_sat_u8 --size 3x", "--size wants WxH"},
      {"heldout", "--size x120", "--size wants WxH"},
      {"check", "--seed banana", "--seed wants an integer in 0..4294967295, got 'banana'"},
      {"check", "-j 0", "-j wants an integer in 1..256"},
      {"pipeline", "seg_avoid --frames 0", "--frames wants an integer in 1..1000000"},
      {"heldout", "--seed x", "--seed wants an integer"},
      {"hs-accuracy", "--alpha 7.9", "--alpha wants a number in 8..256"},
      {"bench", "--timing fast", "--timing wants none or bf537, got 'fast'"},
      {"profile", "add_sat_u8 --timing none", "--timing wants bf537, got 'none'"},
      {"check", "--campaign=yes", "--campaign takes no value"},
  });
}

TEST(Commands, RepeatedOptionIsExitTwo) {
  expect_usage_errors({
      {"check", "--seeds 1 --seeds 2", "--seeds given more than once"},
      {"check", "-k a --kernel b", "--kernel given more than once"},
      {"run", "add_sat_u8 --in a.pgm --out b.pgm --out c.pgm", "--out given more than once"},
      {"profile", "add_sat_u8 --size 8x8 --size 16x16", "--size given more than once"},
      {"pipeline", "seg_avoid --csv a --csv b", "--csv given more than once"},
      {"scene", "--out a --out b", "--out given more than once"},
      {"heldout", "--quiet --quiet", "--quiet given more than once"},
  });
}

TEST(Commands, OperandsAndRequiredOptionsAreExitTwo) {
  expect_usage_errors({
      {"list", "extra", "unexpected argument 'extra'"},
      {"check", "sobel", "unexpected argument 'sobel'"},
      {"profile", "", "profile takes one KERNEL (bfbench list)"},
      {"run", "a b --in x.pgm --out y.pgm", "run takes one KERNEL"},
      {"run", "add_sat_u8 --out y.pgm", "run needs --in FILE"},
      {"debug", "add_sat_u8 --case add_sat_u8:1", "debug needs --seed S"},
      {"pipeline", "", "pipeline takes one NAME"},
      {"scene", "", "--spec is required"},
  });
}

TEST(Commands, BadInputAndSetUpAreExitTwo) {
  expect_usage_errors({
      {"run", "no_such_kernel --in a.pgm --out b.pgm", "unknown kernel"},
      {"pipeline", "no_such --spec path=F1", "unknown pipeline 'no_such'"},
      {"heldout", "no_such", "unknown pipeline 'no_such'"},
      {"scene", "--spec frames=x --out " + test_dir() + "never", "frames"},
  });
  // No simulator where one is named: a set-up that cannot run, exit 2 like bad usage.
  const std::string no_sim = "BFBENCH_SIM=/nonexistent/bfin-elf-run";
  for (const std::string &c : {std::string("check -k add_sat_u8 --seed 1"), std::string("bench -k add_sat_u8 --size 8x8"),
                               std::string("budgets -k add_sat_u8"), std::string("profile add_sat_u8 --size 8x8")}) {
    const std::string cmd = c.substr(0, c.find(' '));
    expect_usage_error(cmd, c.substr(c.find(' ') + 1), "", no_sim);
  }
  const CliRun unknown = bfbench("frobnicate");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_EQ(unknown.err, "bfbench: unknown command 'frobnicate' (bfbench --help)\n");
  EXPECT_EQ(bfbench("").status, 2);
}

TEST(Commands, SuccessIsExitZero) {
  const CliRun list = bfbench("list");
  EXPECT_EQ(list.status, 0) << list.err;
  EXPECT_NE(list.out.find("add_sat_u8"), std::string::npos);
  const CliRun arenas = bfbench("scene --list-arenas");
  EXPECT_EQ(arenas.status, 0) << arenas.err;
  EXPECT_NE(arenas.out.find("boxes"), std::string::npos) << arenas.out;
}

TEST(Commands, FailedVerdictIsExitOne) {
  // go_rows=120: the whole view must be free to drive on, so the robot never goes forward and
  // the verdict (at least a quarter forward) fails, on any scene.
  const CliRun r = bfbench("heldout seg_avoid --runs 1 --frames 40 --seed 1 --quiet --param go_rows=120");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("0% forward (at least 25%): FAIL"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");
  const CliRun ok = bfbench("heldout seg_avoid --runs 1 --frames 40 --seed 1 --quiet");
  EXPECT_EQ(ok.status, 0) << ok.out << ok.err;
}

}  // namespace
}  // namespace bvb
