#include "cleanup.h"

#include <atomic>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>

#include <unistd.h>

namespace bvb {

namespace {

// Fixed slots, no allocation: the signal handler walks them as they are. A slot's state is
// 0 free, 1 being written, 2 live; the handler only reads live ones.
constexpr int kFileSlots = 256;
constexpr int kChildSlots = 256;

struct FileSlot {
  std::atomic<int> state{0};
  char path[PATH_MAX];
};
FileSlot g_files[kFileSlots];
std::atomic<pid_t> g_children[kChildSlots];

void on_signal(int sig) {
  for (auto &c : g_children) {
    pid_t p = c.load();
    if (p > 0) kill(-p, SIGKILL);
  }
  for (auto &f : g_files)
    if (f.state.load() == 2) unlink(f.path);
  // Die of the signal, as without the handler: the caller's shell sees the usual status.
  signal(sig, SIG_DFL);
  raise(sig);
}

}  // namespace

void register_temp_file(const std::string &path) {
  if (path.size() >= PATH_MAX) return;
  for (auto &f : g_files) {
    int expected = 0;
    if (f.state.compare_exchange_strong(expected, 1)) {
      std::memcpy(f.path, path.c_str(), path.size() + 1);
      f.state.store(2);
      return;
    }
  }
  // Every slot taken: the file is still removed normally, just not on an interrupt.
}

void unregister_temp_file(const std::string &path) {
  for (auto &f : g_files) {
    int expected = 2;
    if (f.state.load() == 2 && std::strcmp(f.path, path.c_str()) == 0 &&
        f.state.compare_exchange_strong(expected, 1)) {
      f.state.store(0);
      return;
    }
  }
}

void remove_temp_file(const std::string &path) {
  std::remove(path.c_str());
  unregister_temp_file(path);
}

void register_child_group(pid_t pgid) {
  for (auto &c : g_children) {
    pid_t expected = 0;
    if (c.compare_exchange_strong(expected, pgid)) return;
  }
}

void unregister_child_group(pid_t pgid) {
  for (auto &c : g_children) {
    pid_t expected = pgid;
    if (c.compare_exchange_strong(expected, 0)) return;
  }
}

void install_interrupt_cleanup() {
  static std::atomic<bool> done{false};
  if (done.exchange(true)) return;
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, s);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old;
    // A signal the caller ignores (nohup) stays ignored.
    if (sigaction(s, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    sigaction(s, &sa, nullptr);
  }
}

}  // namespace bvb
