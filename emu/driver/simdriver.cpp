#include "simdriver.h"

#include "cleanup.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <pthread.h>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace bvb::sim {

namespace {

constexpr size_t kMaxOutput = 64 * 1024;

std::string hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%x", v);
  return buf;
}

}  // namespace

std::vector<std::string> command_line(const RunSpec &spec) {
  std::vector<std::string> args = {spec.simulator, "--environment", "operating", "--model", "bf537",
                                   "--memory-region", "0," + hex(kSdramSize)};
  for (const auto &m : spec.maps) {
    args.push_back("--memory-mapfile");
    args.push_back(m.path);
    args.push_back("--memory-region");
    args.push_back(hex(m.address) + "," + hex(m.size));
  }
  for (const auto &o : spec.options) args.push_back(o);
  args.push_back(spec.elf);
  return args;
}

std::string find_simulator(const std::string &default_path) {
  const char *env = std::getenv("BFBENCH_SIM");
  std::string path = env && *env ? env : default_path;
  // A host-only build (BVB_HOST_ONLY) has no simulator of its own to fall back on.
  if (path.empty())
    throw SetupError("this bfbench is a host-only build (BVB_HOST_ONLY=ON): no simulator or firmware; "
                     "use --impl host, or build with the toolchain (emu/bootstrap.sh)");
  if (access(path.c_str(), X_OK) != 0)
    throw SetupError("simulator not found or not executable: " + path +
                     " (run emu/bootstrap.sh, or set BFBENCH_SIM)");
  return path;
}

Process::Process(const RunSpec &spec) {
  if (access(spec.simulator.c_str(), X_OK) != 0)
    throw SetupError("simulator not found or not executable: " + spec.simulator);
  if (access(spec.elf.c_str(), R_OK) != 0) throw SetupError("firmware not found: " + spec.elf);
  auto args = command_line(spec);
  std::vector<char *> argv;
  for (auto &a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int pipefd[2];
  if (pipe2(pipefd, O_CLOEXEC) != 0) throw SetupError(std::string("pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, pipefd[1], 1);
  posix_spawn_file_actions_adddup2(&fa, pipefd[1], 2);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  // The simulator leads its own process group, so a timeout or an interrupt kills whatever it
  // started too (a wrapper script that does not exec, say) and never leaves one holding the pipe.
  // Interrupts are blocked from the spawn until the group is registered for the handler to kill;
  // the child starts with none blocked.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setpgroup(&attr, 0);
  sigset_t none, interrupts, old;
  sigemptyset(&none);
  sigemptyset(&interrupts);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&interrupts, s);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK);
  pthread_sigmask(SIG_BLOCK, &interrupts, &old);
  pid_t pid;
  int rc = posix_spawn(&pid, argv[0], &fa, &attr, argv.data(), environ);
  if (rc == 0) register_child_group(pid);
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&fa);
  close(pipefd[1]);
  if (rc != 0) {
    close(pipefd[0]);
    throw SetupError("cannot start " + spec.simulator + ": " + std::strerror(rc));
  }
  pid_ = pid;
  fd_ = pipefd[0];
}

void Process::kill_group() {
  kill(-pid_, SIGKILL);
  if (!exited_) {
    while (waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
    }
    exited_ = true;
  }
  unregister_child_group(pid_);
}

Process::~Process() {
  if (pid_ > 0 && !group_gone_) kill_group();
  if (fd_ >= 0) close(fd_);
}

void Process::drain(int timeout_ms) {
  if (fd_ < 0) return;
  pollfd p{fd_, POLLIN, 0};
  int n = poll(&p, 1, timeout_ms);
  if (n <= 0) return;
  char buf[4096];
  ssize_t got = read(fd_, buf, sizeof buf);
  if (got > 0) {
    if (result_.output.size() < kMaxOutput) result_.output.append(buf, size_t(got));
  } else if (got == 0) {
    close(fd_);
    fd_ = -1;
  }
}

bool Process::running() {
  drain(0);
  if (exited_) return false;
  pid_t r = waitpid(pid_, &status_, WNOHANG);
  if (r == pid_) exited_ = true;
  return !exited_;
}

RunResult Process::finish(double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::milliseconds(int64_t(timeout_s * 1000));
  bool timed_out = false;
  while (running()) {
    if (std::chrono::steady_clock::now() >= deadline) {
      timed_out = true;
      break;
    }
    drain(fd_ >= 0 ? 100 : 0);
    if (fd_ < 0) usleep(1000);
  }
  // The simulator has exited (or is killed now): what it printed is read for at most a second
  // more, since something it started may hold the pipe open; then the group is killed, which
  // ends anything left.
  const auto drain_until = std::chrono::steady_clock::now() + std::chrono::seconds(timed_out ? 0 : 1);
  while (!timed_out && fd_ >= 0 && std::chrono::steady_clock::now() < drain_until) drain(100);
  kill_group();
  group_gone_ = true;
  if (fd_ >= 0) {
    drain(0);
    close(fd_);
    fd_ = -1;
  }
  if (timed_out) {
    result_.ending = Ending::TimedOut;
  } else if (WIFEXITED(status_)) {
    result_.ending = Ending::Exited;
    result_.exit_code = WEXITSTATUS(status_);
  } else {
    result_.ending = Ending::Signalled;
    result_.signal = WTERMSIG(status_);
  }
  return result_;
}

std::string printable(const std::string &text, size_t max_chars) {
  std::string shown;
  for (unsigned char c : text) {
    if (shown.size() >= max_chars) {
      shown += "...";
      break;
    }
    if (c >= 0x20 && c < 0x7f) {
      shown += char(c);
    } else {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\x%02x", c);
      shown += esc;
    }
  }
  return shown;
}

RunResult run(const RunSpec &spec) {
  Process p(spec);
  return p.finish(spec.wall_timeout_s);
}

std::string describe(const RunResult &r) {
  std::string what;
  switch (r.ending) {
    case Ending::Exited: what = "simulator exited with status " + std::to_string(r.exit_code); break;
    case Ending::Signalled: what = std::string("simulator killed by signal ") + strsignal(r.signal); break;
    case Ending::TimedOut: what = "simulator did not finish in time (killed)"; break;
  }
  // The simulator's own last line says why, e.g. "_cec_raise: double fault at 0x...".
  std::string out = r.output;
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  if (!out.empty()) {
    auto nl = out.rfind('\n');
    std::string last = out.substr(nl == std::string::npos ? 0 : nl + 1);
    // What a simulator prints can be anything (a crashing program's binary output): shown
    // printable and short, so a report stays one readable line on any terminal.
    what += ": " + printable(last);
  }
  return what;
}

}  // namespace bvb::sim
