// bfbench's contract with its users: bad input gets one clear line and exit 2, never a crash or
// a half-written output; a good run writes what the host reference computes.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "bvb/add_sat.h"
#include "bfbench_run.h"
#include "io.h"
#include "json.h"
#include "tempdir.h"

namespace bvb {
namespace {

// Each test its own directory (tempdir.h): the files below have fixed names.
std::string dir() { return test_dir(); }

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
  bvb_add_sat_u8_c(ia.data.data(), ib.data.data(), want.data.data(), 37, 11, 37, 37, nullptr);
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

// A budget far above what the kernel takes passes but is reported as loose.
TEST(Cli, LooseBudgetsAreReported) {
  const std::string loose = dir() + "loose.json";
  write(loose, "{\"timing\": \"bf537\", \"budgets\": {\"add_sat_u8/asm/160x120\": {\"cycles\": 900000000}}}");
  CliRun r = bfbench("budgets -k add_sat_u8 -j 2 --file " + loose);
  EXPECT_EQ(r.status, 1) << r.out << r.err;  // 320x240 and 640x480 have none
  EXPECT_NE(r.out.find("add_sat_u8/asm/160x120"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(loose: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 loose by more than 2%"), std::string::npos) << r.out;
}

// --case re-runs one call; a case that names no call is no pass; the id must be KERNEL:N.
TEST(Cli, CheckCaseRunsExactlyOneCall) {
  CliRun one = bfbench("check --seed 3 --case add_sat_u8:5 -j 1");
  EXPECT_EQ(one.status, 0) << one.out << one.err;
  EXPECT_NE(one.out.find("asm: 1/1 ok   c: 1/1 ok   host: 1/1 ok"), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("all 2 calls bit-exact"), std::string::npos) << one.out;
  CliRun none = bfbench("check --seed 3 --case add_sat_u8:999999 -j 1");
  EXPECT_EQ(none.status, 1) << none.out << none.err;
  EXPECT_NE(none.out.find("NOT CHECKED add_sat_u8 (asm): no call judged"), std::string::npos) << none.out;
  expect_bad_input("check --seed 3 --case add_sat_u8", "--case wants KERNEL:N");
  expect_bad_input("check --case add_sat_u8:1", "--case needs the --seed");
  expect_bad_input("check --seed 1 --case nosuchkernel:1", "nosuchkernel");
  expect_bad_input("check -k 'sobel*' --seed 1 --case add_sat_u8:1", "not of a kernel");
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

// A budget's size must be one its kernel can take: 0x0 divided by zero, -5x-5 ran for half a
// minute into a hardware error, huge sizes ran out of memory.
TEST(Cli, BudgetKeysWithImpossibleSizes) {
  const std::string f = dir() + "badsize.json";
  for (const char *key : {"add_sat_u8/asm/0x0", "add_sat_u8/asm/-5x-5", "add_sat_u8/asm/99999x99999",
                          "add_sat_u8/asm/160x", "uyvy_to_grey/asm/3x2"}) {
    write(f, std::string("{\"budgets\": {\"") + key + "\": {\"cycles\": 5}}}");
    expect_bad_input("budgets -k add_sat_u8 --file " + f, std::string("budget key '") + key + "'");
  }
}

// Two updates at once with different -k: each keeps the other's entries (the file's directory is
// locked from load to rewrite; without it the later rename dropped the earlier update).
TEST(Cli, ConcurrentBudgetUpdatesKeepBoth) {
  const std::string sub = dir() + "budget_lock/", f = sub + "budgets.json";
  std::system(("rm -rf " + sub + " && mkdir -p " + sub).c_str());
  write(f, "{\"budgets\": {}}");
  const std::string cmd = std::string(BFBENCH_EXE) + " budgets --update -j 1 --file " + f;
  const int rc = std::system(("(" + cmd + " -k add_sat_u8 >" + sub + "a.out 2>&1 & " + cmd +
                              " -k erode3x3_u8 >" + sub + "b.out 2>&1 & wait)")
                                 .c_str());
  ASSERT_EQ(rc, 0);
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  for (const char *key : {"add_sat_u8/asm/160x120", "add_sat_u8/asm/640x480", "erode3x3_u8/asm/160x120",
                          "erode3x3_u8/asm/640x480"})
    EXPECT_NE(text.find(key), std::string::npos) << key << " lost:\n" << text;
}

// Frames larger than the Blackfin's memory are bad input, not the kernel's failure.
TEST(Cli, RunOnFramesTooLargeForTheBlackfin) {
  const std::string big = dir() + "big4096.pgm", out = dir() + "never_big.pgm";
  Image img(4096, 4096);
  write_pnm(big, img);
  expect_bad_input("run add_sat_u8 --in " + big + " --in " + big + " --out " + out, "too large for the Blackfin", out);
  std::remove(big.c_str());
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

std::vector<pid_t> children_of(pid_t pid) {
  std::vector<pid_t> out;
  const std::string task = "/proc/" + std::to_string(pid) + "/task";
  std::string cmd = "cat " + task + "/*/children 2>/dev/null";
  FILE *p = popen(cmd.c_str(), "r");
  if (!p) return out;
  int c;
  while (std::fscanf(p, "%d", &c) == 1) out.push_back(c);
  pclose(p);
  return out;
}

// A simulator killed from outside mid-check is no kernel's failure: a set-up error, exit 2.
TEST(Cli, SimulatorKilledFromOutsideIsNotBlamedOnTheKernel) {
  const std::string o = dir() + "killed.out", e = dir() + "killed.err";
  pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    freopen(o.c_str(), "w", stdout);
    freopen(e.c_str(), "w", stderr);
    execl(BFBENCH_EXE, BFBENCH_EXE, "check", "-k", "add_sat_u8", "--seed", "1", "-j", "1", (char *)nullptr);
    _exit(127);
  }
  std::vector<pid_t> kids;
  for (int i = 0; i < 400 && kids.empty(); ++i) {
    usleep(25000);
    kids = children_of(pid);
  }
  ASSERT_FALSE(kids.empty()) << "no simulator started";
  usleep(200000);
  // The simulator found first may have finished by now and another be running: kill whatever
  // simulators bfbench has, again and again, until bfbench has ended.
  int status = 0;
  bool ended = false;
  for (int i = 0; i < 400 && !ended; ++i) {
    for (pid_t k : children_of(pid)) kill(k, SIGKILL);
    usleep(25000);
    ended = waitpid(pid, &status, WNOHANG) == pid;
  }
  if (!ended) waitpid(pid, &status, 0);
  std::ifstream ef(e);
  std::stringstream err;
  err << ef.rdbuf();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2) << err.str();
  EXPECT_NE(err.str().find("killed from outside"), std::string::npos) << err.str();
}

// bfbench profile: the profile accounts for every cycle of the call bench measures, and no more.
std::string slurp_file(const std::string &p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

uint64_t num(const json::Value &v, const std::string &key) {
  const json::Value *x = v.get(key);
  return x ? uint64_t(x->num) : ~0ull;
}

uint64_t cause_sum(const json::Value &v) {
  uint64_t s = 0;
  for (const auto &kv : v.get("causes")->obj) s += uint64_t(kv.second.num);
  return s;
}

// The value gdb's `info registers` shows for a register ("r0  0xff800040  -8388544").
uint32_t gdb_register(const std::string &out, const std::string &reg) {
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream w(line);
    std::string name, value;
    if (w >> name >> value && name == reg && value.rfind("0x", 0) == 0) return uint32_t(std::stoul(value, nullptr, 16));
  }
  ADD_FAILURE() << "no register " << reg << " in:\n" << out;
  return 0;
}

// The address bfbench debug printed for a buffer ("  a (in, 19200 bytes, SDRAM) at 0x00012340").
uint32_t printed_address(const std::string &out, const std::string &buffer) {
  const size_t at = out.find("\n  " + buffer + " (");
  const size_t addr = at == std::string::npos ? at : out.find(" at 0x", at);
  if (addr == std::string::npos) {
    ADD_FAILURE() << "no address for buffer " << buffer << " in:\n" << out;
    return 0;
  }
  return uint32_t(std::stoul(out.substr(addr + 4, 10), nullptr, 16));
}

// A scripted gdb session (only where emu/bootstrap.sh --with-gdb built the gdb): bfbench debug
// stops at the kernel's entry, its PC the entry bfbench names, and R0-R2 (add_sat_u8's a, b
// and dst) the addresses it printed for those buffers, which came from a bfin-elf-run of the
// same window.
TEST(Debug, StopsAtTheKernelEntryWithItsBuffers) {
  const char *env = std::getenv("BFBENCH_GDB");
  const std::string gdb = env && *env ? env : BVB_DEFAULT_GDB;
  if (access(gdb.c_str(), X_OK) != 0) GTEST_SKIP() << "no " << gdb << " (emu/bootstrap.sh --with-gdb builds it)";
  for (const char *impl : {"asm", "c"}) {
    CliRun r = bfbench(std::string("debug add_sat_u8 --case add_sat_u8:3 --seed 7 --batch --impl ") + impl);
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    const std::string entry = std::string("bvb_add_sat_u8_") + impl;
    const size_t at = r.out.find("stopping at " + entry + " (0x");
    ASSERT_NE(at, std::string::npos) << r.out;
    const uint32_t pc = uint32_t(std::stoul(r.out.substr(at + 13 + entry.size() + 1, 10), nullptr, 16));
    EXPECT_NE(r.out.find("Breakpoint 1, "), std::string::npos) << r.out;
    EXPECT_EQ(gdb_register(r.out, "pc"), pc) << r.out;
    EXPECT_EQ(gdb_register(r.out, "r0"), printed_address(r.out, "a")) << r.out;
    EXPECT_EQ(gdb_register(r.out, "r1"), printed_address(r.out, "b")) << r.out;
    EXPECT_EQ(gdb_register(r.out, "r2"), printed_address(r.out, "dst")) << r.out;
  }
}

TEST(Profile, AccountsForEveryCycleTheBenchMeasures) {
  const std::string j = dir() + "prof.json", csv = dir() + "prof.csv";
  CliRun r = bfbench("profile add_sat_u8 --size 64x48 --json " + j);
  ASSERT_EQ(r.status, 0) << r.err;
  json::Value p = json::parse(slurp_file(j), j);
  const uint64_t measured = num(p, "measured_cycles"), total = num(p, "profile_cycles");
  ASSERT_GT(measured, 0u);
  EXPECT_EQ(measured + num(p, "call_overhead"), total);
  EXPECT_EQ(num(p, "issue_cycles") + cause_sum(p), total);
  uint64_t insn_cycles = 0, insn_count = 0;
  for (const auto &in : p.get("instructions")->arr) {
    insn_cycles += num(in, "cycles");
    insn_count += num(in, "count");
    EXPECT_EQ(num(in, "cycles"), num(in, "count") + cause_sum(in)) << in.get("pc")->str;
  }
  EXPECT_EQ(insn_cycles, total);
  EXPECT_EQ(insn_count, num(p, "issue_cycles"));
  // The kernel's own lines are there, with the assembly source's text.
  bool asm_line = false;
  for (const auto &l : p.get("lines")->arr)
    asm_line |= l.get("file")->str.find("firmware/asm/add_sat.S") != std::string::npos &&
                !l.get("source")->str.empty() && num(l, "cycles") > 0;
  EXPECT_TRUE(asm_line);
  ASSERT_FALSE(p.get("loops")->arr.empty());
  EXPECT_GT(num(p.get("loops")->arr[0], "issue_bound"), 0u);
  // The same call as the bench's: the same cycles.
  CliRun b = bfbench("bench -k add_sat_u8 --size 64x48 --asm-only --csv " + csv);
  ASSERT_EQ(b.status, 0) << b.err;
  std::string c = slurp_file(csv);
  EXPECT_NE(c.find("," + std::to_string(measured) + ","), std::string::npos)
      << "profile measured " << measured << ", bench:\n" << c;
}

TEST(Profile, RefusesWhatItCannotProfile) {
  CliRun none = bfbench("profile no_such_kernel");
  EXPECT_EQ(none.status, 2) << none.err;
  CliRun c_only = bfbench("profile blobs_uyvy --size 32x16");
  EXPECT_EQ(c_only.status, 2);
  EXPECT_NE(c_only.err.find("no assembly"), std::string::npos) << c_only.err;
  CliRun plain = bfbench("profile add_sat_u8 --timing none");
  EXPECT_EQ(plain.status, 2);
  EXPECT_NE(plain.err.find("bf537"), std::string::npos) << plain.err;
}

// The page renders in a browser: headless Chromium runs its script, and the DOM it dumps has a
// row per profiled source line, the hottest in the strongest red.
TEST(Profile, PageShowsTheAnnotatedSourceInABrowser) {
  const char *browser = nullptr;
  for (const char *b : {"/usr/bin/chromium", "/usr/bin/chromium-browser"})
    if (access(b, X_OK) == 0) browser = b;
  if (!browser) GTEST_SKIP() << "no Chromium (apt-get install chromium): the page is not checked";
  const std::string j = dir() + "page.json", h = dir() + "page.html", dom = dir() + "page.dom";
  CliRun r = bfbench("profile add_sat_u8 --size 64x48 --json " + j + " --html " + h);
  ASSERT_EQ(r.status, 0) << r.err;
  json::Value p = json::parse(slurp_file(j), j);
  const size_t lines = p.get("lines")->arr.size();
  uint64_t hottest = 0;
  for (const auto &l : p.get("lines")->arr) hottest = std::max(hottest, num(l, "cycles"));
  const std::string cmd = std::string(browser) +
                          " --headless --no-sandbox --disable-gpu --dump-dom file://" + h + " >" + dom +
                          " 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string d = slurp_file(dom);
  EXPECT_NE(d.find("data-rendered=\"" + std::to_string(lines) + "\""), std::string::npos) << d.substr(0, 2000);
  size_t rows = 0;
  for (size_t k = 0; (k = d.find("<tr class=\"line\"", k)) != std::string::npos; ++k) ++rows;
  EXPECT_EQ(rows, lines);
  // The hottest line carries the most intense colour: alpha 0.08 + 0.72 (as the browser writes it).
  const std::string hot = "data-cycles=\"" + std::to_string(hottest) + "\"";
  size_t at = d.find(hot);
  ASSERT_NE(at, std::string::npos);
  EXPECT_NE(d.substr(at, 200).find("0.8)"), std::string::npos) << d.substr(at, 200);
  EXPECT_NE(d.find("add_sat_u8 (asm)"), std::string::npos);
}

}  // namespace
}  // namespace bvb
