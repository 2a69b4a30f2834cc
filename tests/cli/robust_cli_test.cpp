// bfbench on bad input and hostile paths, where no simulator is needed: one clear line and
// exit 2, never a crash, a hang, or a file destroyed or half-written.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "bfbench_run.h"
#include "io.h"
#include "tempdir.h"

namespace bvb {
namespace {

// Each test its own directory (tempdir.h): the files below have fixed names.
std::string dir() { return test_dir(); }

Image frame(int w, int h, int seed) {
  Image img(w, h);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = uint8_t(i * 37 + seed * 101);
  return img;
}

void write(const std::string &path, const std::string &bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string slurp_cmd(const std::string &cmd) {
  const std::string o = dir() + "rcli." + std::to_string(getpid()) + ".cmd";
  std::system((cmd + " >" + o + " 2>&1").c_str());
  return slurp(o);
}

bool is_fifo(const std::string &p) {
  struct stat st;
  return lstat(p.c_str(), &st) == 0 && S_ISFIFO(st.st_mode);
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

// Without its gdb (emu/bootstrap.sh --with-gdb builds it on request), bfbench debug says so in
// one line and exits 2, before it looks for a firmware or simulator.
TEST(Debug, WithoutGdbSaysHowToBuildIt) {
  CliRun r = bfbench("debug add_sat_u8 --case add_sat_u8:0 --seed 1", "BFBENCH_GDB=" + dir() + "no-such-gdb");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("emu/bootstrap.sh --with-gdb"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.out, "");
}

// --out names what the user wants written, and a device, FIFO or symbolic link stays what it
// was (issue: a character device became a 59-byte regular file).
TEST(OutputPaths, DeviceIsWrittenNotReplaced) {
  const std::string in = dir() + "dev_in.pgm", dev = dir() + "mynull";
  write_pnm(in, frame(16, 16, 1));
  std::remove(dev.c_str());
  if (mknod(dev.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) GTEST_SKIP() << "mknod needs privileges";
  CliRun r = bfbench("run erode3x3_u8 --impl host --in " + in + " --out " + dev);
  EXPECT_EQ(r.status, 0) << r.err;
  struct stat st;
  ASSERT_EQ(lstat(dev.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << dev << " is no longer a character device";
  std::remove(dev.c_str());
}

TEST(OutputPaths, FifoIsWrittenNotReplaced) {
  const std::string in = dir() + "fifo_in.pgm", fifo = dir() + "out_fifo.pgm";  // a FIFO named for the format sent through it
  write_pnm(in, frame(16, 16, 1));
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // Held open for reading and writing, so bfbench's open for writing does not wait for a reader
  // and what it writes (a few hundred bytes) sits in the pipe.
  int fd = open(fifo.c_str(), O_RDWR | O_NONBLOCK);
  ASSERT_GE(fd, 0);
  CliRun r = bfbench("run erode3x3_u8 --impl host --in " + in + " --out " + fifo);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(is_fifo(fifo)) << fifo << " is no longer a FIFO";
  char buf[4096];
  ssize_t n = read(fd, buf, sizeof buf);
  close(fd);
  ASSERT_GT(n, 0) << "nothing was written into the FIFO";
  Image got = parse_pnm(std::vector<uint8_t>(buf, buf + n), fifo);
  EXPECT_EQ(got.width, 16);
  std::remove(fifo.c_str());
}

TEST(OutputPaths, SymlinkIsFollowedDanglingOneRefused) {
  const std::string in = dir() + "sl_in.pgm", real = dir() + "sl_real.pgm", link = dir() + "sl_link.pgm",
                    dangling = dir() + "sl_dangling.pgm", nowhere = dir() + "sl_nowhere/x.pgm";
  write_pnm(in, frame(16, 16, 1));
  write(real, "old");
  std::remove(link.c_str());
  std::remove(dangling.c_str());
  ASSERT_EQ(symlink(real.c_str(), link.c_str()), 0);
  ASSERT_EQ(symlink(nowhere.c_str(), dangling.c_str()), 0);
  CliRun r = bfbench("run erode3x3_u8 --impl host --in " + in + " --out " + link);
  EXPECT_EQ(r.status, 0) << r.err;
  struct stat st;
  ASSERT_EQ(lstat(link.c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode)) << link << " was replaced by a regular file";
  EXPECT_EQ(read_pnm(real).width, 16) << "the file the link names was not written";
  expect_bad_input("run erode3x3_u8 --impl host --in " + in + " --out " + dangling, "symbolic link");
  ASSERT_EQ(lstat(dangling.c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode));
}

TEST(OutputPaths, DirectoryIsRefused) {
  const std::string in = dir() + "d_in.pgm", d = dir() + "an_out_dir";
  write_pnm(in, frame(16, 16, 1));
  mkdir(d.c_str(), 0700);
  expect_bad_input("run erode3x3_u8 --impl host --in " + in + " --out " + d, "is a directory");
}

// Inputs: a directory is named as one, never "internal error: basic_filebuf::underflow"; a
// device that never ends is cut off at the largest input size instead of filling memory.
TEST(InputPaths, DirectoryAsInput) {
  const std::string d = dir() + "an_in_dir", out = dir() + "never3.pgm";
  mkdir(d.c_str(), 0700);
  std::remove(out.c_str());
  expect_bad_input("run erode3x3_u8 --impl host --in " + d + " --out " + out, d + ": is a directory");
  struct stat st;
  EXPECT_NE(stat(out.c_str(), &st), 0) << out << " was written";
}

TEST(InputPaths, EndlessDeviceIsCutOff) {
  // The address-space limit turns the old unbounded read into a quick failure instead of an
  // exhausted machine.
  const std::string out = dir() + "never4.pgm";
  CliRun r = bfbench("run erode3x3_u8 --impl host --in /dev/zero --out " + out, "ulimit -v 4000000;");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("/dev/zero: more than"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(InputPaths, SceneWithADirectoryOrAHugeNumber) {
  const std::string sc = dir() + "scene_bad";
  std::system(("rm -rf " + sc).c_str());
  CliRun made = bfbench("scene --spec arena=boxes,path=straight,frames=2,size=32x24 --out " + sc);
  ASSERT_EQ(made.status, 0) << made.err;
  // A 19-digit tick count: too large for 64 bits.
  std::string truth = slurp(sc + "/truth.csv");
  std::vector<std::string> lines;
  std::istringstream in(truth);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  ASSERT_GE(lines.size(), 2u);
  std::string &row = lines[1];
  size_t c = 0;
  for (int k = 0; k < 9; ++k) c = row.find(',', c) + 1;
  row = row.substr(0, c) + "9999999999999999999" + row.substr(row.find(',', c));
  std::string text;
  for (auto &l : lines) text += l + "\n";
  write(sc + "/truth.csv", text);
  expect_bad_input("scene --check " + sc, "truth.csv:2: left_ticks");
  // scene.txt a directory.
  std::remove((sc + "/scene.txt").c_str());
  mkdir((sc + "/scene.txt").c_str(), 0700);
  expect_bad_input("scene --check " + sc, "scene.txt: is a directory");
}

TEST(InputPaths, HsAccuracyFramesThatAreDirectories) {
  const std::string fr = dir() + "frames_bad";
  std::system(("rm -rf " + fr).c_str());
  mkdir(fr.c_str(), 0700);
  mkdir((fr + "/Yosemite").c_str(), 0700);
  mkdir((fr + "/Yosemite/yos9.pgm").c_str(), 0700);
  expect_bad_input("hs-accuracy --frames " + fr + " --sequence Yosemite", "yos9.pgm: is a directory");
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

// A simulator that starts but runs no firmware is a set-up problem: exit 2 in pipeline too.
TEST(SetupErrors, PipelineWithASimulatorThatDoesNotRun) {
  const std::string sim = dir() + "sim_exits.sh";
  write(sim, "#!/bin/sh\nexit 0\n");
  chmod(sim.c_str(), 0755);
  CliRun r = bfbench("pipeline seg_avoid --spec arena=boxes,path=straight,frames=2 --impl c --frames 1",
                     "BFBENCH_SIM=" + sim + " BFBENCH_FIRMWARE=" + sim);
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("simulator"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

// Sizes below a kernel's minimum are the user's mistake, named with the minimum, before anything
// runs: they used to divide by zero (1x1, Wx1), read past a buffer (odd UYVY widths) or run the
// assembly where it faults and blame it.
TEST(BenchSizes, BelowAKernelsMinimumIsAUsageError) {
  expect_bad_input("bench --size 1x1", "needs at least");
  expect_bad_input("bench -k scanline_profile_u8 --size 8x1", "scanline_profile_u8 needs at least 1x2");
  expect_bad_input("bench -k uyvy_to_rgb24 --size 1x1", "uyvy_to_rgb24 needs at least 2x1 and an even width");
  expect_bad_input("bench -k uyvy_to_rgb24 --size 33x8", "even width");
  expect_bad_input("bench -k 'harris_*' --size 4x40", "harris_");
  expect_bad_input("bench -k ncc_match --size 26x64", "ncc_match needs at least 27x27");
}

// A -k that selects no budgets would judge nothing and pass a CI gate.
TEST(Budgets, PatternMatchingNoAssemblyKernelIsAnError) {
  expect_bad_input("budgets -k no_such_kernel", "no assembly kernel matches 'no_such_kernel'");
  expect_bad_input("budgets -k canny", "no assembly kernel matches 'canny'");  // C only
  expect_bad_input("budgets --update -k 'add_sat_u9*'", "no assembly kernel matches");
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

bool alive(pid_t pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(f, line)) return false;
  const size_t close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

// Interrupted, bfbench removes its window files (up to 64 MB each) and kills its simulators
// (they used to run on as orphans after SIGTERM or SIGHUP), then dies of the signal.
TEST(Interrupts, RemoveWindowFilesAndKillSimulators) {
  const std::string a = dir() + "int_a.pgm", out = dir() + "int_out.pgm";
  write_pnm(a, frame(16, 16, 1));
  for (int sig : {SIGTERM, SIGHUP, SIGINT}) {
    const std::string tmp = dir() + "int_tmp_" + std::to_string(sig), pidfile = tmp + ".pid";
    std::system(("rm -rf " + tmp + " " + pidfile).c_str());
    mkdir(tmp.c_str(), 0700);
    const std::string sim = dir() + "int_sim.sh";
    write(sim, "#!/bin/sh\necho $$ > \"$SIM_PIDFILE\"\nexec sleep 60\n");
    chmod(sim.c_str(), 0755);
    pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      setenv("TMPDIR", tmp.c_str(), 1);
      setenv("BFBENCH_SIM", sim.c_str(), 1);
      setenv("BFBENCH_FIRMWARE", sim.c_str(), 1);
      setenv("SIM_PIDFILE", pidfile.c_str(), 1);
      // The test runner may have set these ignored or blocked; bfbench must see them.
      signal(sig, SIG_DFL);
      sigset_t none;
      sigemptyset(&none);
      sigprocmask(SIG_SETMASK, &none, nullptr);
      execl(BFBENCH_EXE, BFBENCH_EXE, "run", "add_sat_u8", "--impl", "c", "--in", a.c_str(), "--in", a.c_str(),
            "--out", out.c_str(), (char *)nullptr);
      _exit(127);
    }
    pid_t sim_pid = 0;
    for (int i = 0; i < 200 && sim_pid <= 0; ++i) {
      usleep(50000);
      std::ifstream(pidfile) >> sim_pid;
    }
    ASSERT_GT(sim_pid, 0) << "the stand-in simulator never started";
    kill(pid, sig);
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "signal " << sig << ": status " << status;
    for (int i = 0; i < 40 && alive(sim_pid); ++i) usleep(50000);
    EXPECT_FALSE(alive(sim_pid)) << "signal " << sig << ": the simulator outlived bfbench";
    if (alive(sim_pid)) kill(sim_pid, SIGKILL);
    std::string left = slurp_cmd("ls -A " + tmp);
    EXPECT_EQ(left, "") << "signal " << sig << ": left in TMPDIR: " << left;
  }
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

// Ground truth with no known vector: EPE and AE are undefined, never a perfect 0.0000.
TEST(InputPaths, HsAccuracyWithNoKnownGroundTruth) {
  const std::string fr = dir() + "frames_unknown";
  std::system(("rm -rf " + fr).c_str());
  mkdir(fr.c_str(), 0700);
  mkdir((fr + "/Yosemite").c_str(), 0700);
  write_pnm(fr + "/Yosemite/yos9.pgm", frame(8, 8, 1));
  write_pnm(fr + "/Yosemite/yos10.pgm", frame(8, 8, 2));
  FlowField unknown(8, 8);
  for (auto &u : unknown.u) u = 1e10f;
  for (auto &v : unknown.v) v = 1e10f;
  write_flo(fr + "/Yosemite/flow9.flo", unknown);
  expect_bad_input("hs-accuracy --frames " + fr + " --sequence Yosemite --iterations 1",
                   "no pixel has a known ground-truth vector");
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

// An unknown --param says which the kernel takes.
TEST(Messages, UnknownParamListsTheKnownOnes) {
  const std::string a = dir() + "par_a.pgm", out = dir() + "par_out.pgm";
  write_pnm(a, frame(16, 16, 1));
  expect_bad_input("run add_sat_u8 --impl host --in " + a + " --in " + a + " --out " + out + " --param gain=2",
                   "unknown parameter 'gain' for this kernel (it takes none)");
  expect_bad_input("run erode3x3_u8 --impl host --in " + a + " --out " + out + " --param gain=2",
                   "(it takes none)");
  const std::string big = dir() + "par_big.pgm";
  write_pnm(big, frame(64, 64, 2));
  expect_bad_input("run ncc_match --impl host --in " + big + " --in " + big + " --out " + out + " --param gain=2",
                   "unknown parameter 'gain' for this kernel (it takes cols, r, rows, s)");
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

// A path of pauses, each within the million-step cap, is refused as a whole before it is
// expanded (a 13 KB spec of S1000000 moves once took 8 GB in 20 s). The address-space limit
// turns an unbounded expansion into a quick failure instead of an exhausted machine.
TEST(Limits, PathOfManyPausesIsRefusedBeforeExpanding) {
  std::string path = "S1000000";
  for (int i = 0; i < 1500; ++i) path += "+S1000000";
  const std::string out = dir() + "pauses_scene";
  std::system(("rm -rf " + out).c_str());
  CliRun r = bfbench("scene --spec path=" + path + ",size=32x24 --out " + out, "ulimit -v 2000000;");
  EXPECT_EQ(r.status, 2) << r.err.substr(0, 300);
  EXPECT_NE(r.err.find("more than a million steps"), std::string::npos) << r.err.substr(0, 300);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err.substr(0, 300);
  struct stat st;
  EXPECT_NE(stat(out.c_str(), &st), 0) << out << " was written";
}

// Binary PGM/PPM samples above maxval used to wrap when scaled; ASCII ones were refused. A "P55"
// magic is no P5 header. Both are bad input naming the file, at the command line too.
TEST(InputPaths, PnmSamplesAboveMaxvalAndBadMagic) {
  const std::string out = dir() + "pnm_out.pgm";
  const std::string above = dir() + "above.pgm", above_rgb = dir() + "above.ppm", magic = dir() + "magic.pgm";
  write(above, std::string("P5\n2 2\n15\n") + char(3) + char(16) + char(0) + char(15));
  write(above_rgb, std::string("P6\n2 1\n100\n") + char(1) + char(2) + char(3) + char(4) + char(101) + char(6));
  write(magic, std::string("P55\n2 2\n255\n") + std::string(4, char(7)));
  expect_bad_input("run erode3x3_u8 --impl host --in " + above + " --out " + out,
                   above + ": pixel value 16 above maxval 15");
  expect_bad_input("run uyvy_to_grey --impl host --in " + above_rgb + " --out " + out, above_rgb + ": pixel value 101 above maxval 100");
  expect_bad_input("run erode3x3_u8 --impl host --in " + magic + " --out " + out, magic + ": not a PGM/PPM file (bad magic)");
  struct stat st;
  EXPECT_NE(stat(out.c_str(), &st), 0) << out << " was written";
}

}  // namespace
}  // namespace bvb

#include "bvb/sobel.h"
#include "formats.h"

namespace bvb {
namespace {

bool exists(const std::string &p) {
  struct stat st;
  return lstat(p.c_str(), &st) == 0;
}

// The output's name says its format (--out x.png used to get PGM bytes), the input's name too;
// an extension nobody knows is refused before anything runs.
TEST(Formats, OutputsAndInputsFollowTheirNames) {
  const std::string in = dir() + "fmt_in.pgm", pgm = dir() + "fmt_out.pgm", png = dir() + "fmt_out.png",
                    npy = dir() + "fmt_out.npy";
  write_pnm(in, frame(16, 12, 3));
  ASSERT_EQ(bfbench("run erode3x3_u8 --impl host --in " + in + " --out " + pgm).status, 0);
  CliRun r = bfbench("run erode3x3_u8 --impl host --in " + in + " --out " + png);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string bytes = slurp(png);
  EXPECT_EQ(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n"), 0) << "not a PNG: " << bytes.substr(0, 8);
  EXPECT_EQ(read_image(png).data, read_pnm(pgm).data);
  ASSERT_EQ(bfbench("run erode3x3_u8 --impl host --in " + in + " --out " + npy).status, 0);
  const NpyArray a = parse_npy(read_file(npy), npy);
  EXPECT_EQ(a.dtype, "|u1");
  EXPECT_EQ(a.shape, (std::vector<size_t>{12, 16}));
  EXPECT_EQ(a.data, read_pnm(pgm).data);
  // A PNG in gives what the same frame as a PGM gives.
  const std::string png_in = dir() + "fmt_in.png", from_png = dir() + "fmt_from_png.pgm";
  write_image(png_in, frame(16, 12, 3));
  ASSERT_EQ(bfbench("run erode3x3_u8 --impl host --in " + png_in + " --out " + from_png).status, 0);
  EXPECT_EQ(read_pnm(from_png).data, read_pnm(pgm).data);

  const std::string jpg = dir() + "fmt_out.jpg", flo = dir() + "fmt_out.flo";
  expect_bad_input("run erode3x3_u8 --impl host --in " + in + " --out " + jpg, "unknown extension '.jpg'");
  expect_bad_input("run erode3x3_u8 --impl host --in " + in + " --out " + flo, "an image is written as");
  expect_bad_input("run hornschunck --impl host --param iterations=1 --in " + in + " --in " + in + " --out " + png,
                   "a flow field is written as .flo or .npy");
  expect_bad_input("run erode3x3_u8 --impl host --in " + dir() + "fmt_in.bmp --out " + pgm, "unknown extension '.bmp'");
  EXPECT_FALSE(exists(jpg));
  EXPECT_FALSE(exists(flo));
}

// A colour frame given to a kernel of grey frames was greyed silently; now it is refused naming
// the kernel and what it takes, and --grey converts on request.
TEST(Formats, ColourFrameToAGreyKernel) {
  Image rgb(16, 12, 3);
  for (size_t i = 0; i < rgb.data.size(); ++i) rgb.data[i] = uint8_t(i * 13);
  const std::string ppm = dir() + "col_in.ppm", png = dir() + "col_in.png", out = dir() + "col_out.pgm";
  write_pnm(ppm, rgb);
  write_image(png, rgb);
  std::remove(out.c_str());
  expect_bad_input("run erode3x3_u8 --impl host --in " + ppm + " --out " + out,
                   ppm + ": a colour image, and erode3x3_u8 takes grey frames");
  expect_bad_input("run sobel3x3_u8 --impl host --in " + png + " --out " + out, "sobel3x3_u8 takes grey frames");
  EXPECT_FALSE(exists(out));
  CliRun r = bfbench("run erode3x3_u8 --impl host --grey --in " + ppm + " --out " + out);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_pnm(out).channels, 1);
  // A kernel of colour frames still takes them.
  EXPECT_EQ(bfbench("run uyvy_to_grey --impl host --in " + png + " --out " + out).status, 0);
}

// --out F.npy writes the kernel's buffer itself: int16 gradients as <i2 (H, W), the one
// --out-buffer names; compared with the C reference run here.
TEST(Formats, NpyWritesAnOutputBufferWithItsTypeAndShape) {
  const int w = 20, h = 10;
  const Image img = frame(w, h, 5);
  const std::string in = dir() + "npy_in.pgm", gx = dir() + "npy_gx.npy", gy = dir() + "npy_gy.npy";
  write_pnm(in, img);
  ASSERT_EQ(bfbench("run sobel3x3_s16 --impl host --in " + in + " --out " + gx).status, 0);
  CliRun r = bfbench("run sobel3x3_s16 --impl host --in " + in + " --out " + gy + " --out-buffer gy");
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<int16_t> rx(size_t(w) * h), ry(size_t(w) * h);
  std::vector<uint8_t> mag(size_t(w) * h), scratch(BVB_SOBEL3X3_S16_SCRATCH_SIZE(w));
  bvb_sobel3x3_s16_c(img.data.data(), w, rx.data(), ry.data(), w, mag.data(), w, w, h, scratch.data());
  const NpyArray ax = parse_npy(read_file(gx), gx), ay = parse_npy(read_file(gy), gy);
  EXPECT_EQ(ax.dtype, "<i2");
  EXPECT_EQ(ax.shape, (std::vector<size_t>{size_t(h), size_t(w)}));
  ASSERT_EQ(ax.data.size(), rx.size() * 2);
  ASSERT_EQ(ay.data.size(), ry.size() * 2);
  EXPECT_EQ(std::memcmp(ax.data.data(), rx.data(), ax.data.size()), 0) << "gx differs from the reference";
  EXPECT_EQ(std::memcmp(ay.data.data(), ry.data(), ay.data.size()), 0) << "gy differs from the reference";
  expect_bad_input("run sobel3x3_s16 --impl host --in " + in + " --out " + gy + " --out-buffer gz",
                   "no such output buffer (this call has gx, gy, mag)");
  expect_bad_input("run sobel3x3_s16 --impl host --in " + in + " --out " + dir() + "x.pgm --out-buffer gy",
                   "--out-buffer picks the buffer of an --out F.npy");
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

// An error names what the user gave, but control characters in it (a terminal escape, a
// newline in a file name) are shown escaped: the message stays one line and cannot rewrite
// the terminal.
TEST(Messages, ControlCharactersInErrorsAreEscaped) {
  const std::string odd = dir() + "esc\x1b[31m\nname.pgm";
  write(odd, "P9\n");
  CliRun r = bfbench("run erode3x3_u8 --impl host --in '" + odd + "' --out " + dir() + "esc_out.pgm");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("esc\\x1b[31m\\x0aname.pgm: not a PGM/PPM file"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  r = bfbench("run \"$(printf '\\007bell')\" --impl host --in " + dir() + "esc_in.pgm --out " + dir() + "esc_out.pgm");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.find('\x07'), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\\x07bell"), std::string::npos) << r.err;
  std::remove(odd.c_str());
}

}  // namespace
}  // namespace bvb

namespace bvb {
namespace {

// scene --force deleted any directory holding a scene.txt, the user's other files and
// subdirectories with it; now such a directory is refused whole and left as it was.
TEST(SceneForce, RefusesADirectoryHoldingMoreThanAScene) {
  const std::string sc = dir() + "force_scene", spec = "--spec path=F1,size=32x24,flow=0 --out " + dir() + "force_scene";
  std::system(("rm -rf " + sc).c_str());
  ASSERT_EQ(bfbench("scene " + spec).status, 0);
  ASSERT_EQ(bfbench("scene " + spec + " --force").status, 0) << "a scene over a scene";
  write(sc + "/notes.txt", "mine");
  mkdir((sc + "/keep").c_str(), 0700);
  write(sc + "/keep/data.bin", "mine too");
  expect_bad_input("scene " + spec + " --force", "which a scene does not write; not replacing it");
  EXPECT_EQ(slurp(sc + "/notes.txt"), "mine");
  EXPECT_EQ(slurp(sc + "/keep/data.bin"), "mine too");
  EXPECT_TRUE(exists(sc + "/scene.txt"));
}

}  // namespace
}  // namespace bvb
