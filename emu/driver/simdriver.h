// Runs a Blackfin ELF in the GNU simulator (bfin-elf-run) as the SRV-1 board: a BF537 in the
// simulator's operating environment with the board's 32 MB of SDRAM at 0, plus host files mapped
// into the address space. Knows nothing of kernels: it maps, runs, and reports how the run ended.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace bvb::sim {

// The simulator or the ELF is missing or cannot be started: a set-up problem, not a kernel's.
struct SetupError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct MappedFile {
  std::string path;  // host file; the simulator maps it shared, so writes land in it
  uint32_t address;
  uint32_t size;     // bytes, at most the file's size
};

struct RunSpec {
  std::string simulator;  // path of bfin-elf-run
  std::string elf;
  std::vector<MappedFile> maps;
  // Further simulator options, before the ELF (e.g. "--timing", "bf537").
  std::vector<std::string> options;
  // Backstop only: firmware enforces cycle limits itself; this catches a simulator that never
  // returns (e.g. a kernel that masked the watchdog). Never a measurement.
  double wall_timeout_s = 600;
};

enum class Ending { Exited, Signalled, TimedOut };

struct RunResult {
  Ending ending = Ending::Exited;
  int exit_code = -1;   // Exited
  int signal = 0;       // Signalled: the host signal that ended bfin-elf-run
  std::string output;   // what the simulator printed (stdout and stderr), capped
};

// SDRAM on the SRV-1 board.
constexpr uint32_t kSdramSize = 32u << 20;

RunResult run(const RunSpec &spec);

// A simulator run the caller talks to while it runs (through a mapped file).
class Process {
 public:
  explicit Process(const RunSpec &spec);  // starts it; throws SetupError
  ~Process();                             // kills it if still running
  Process(const Process &) = delete;
  Process &operator=(const Process &) = delete;
  bool running();                         // also drains its output
  RunResult finish(double timeout_s);     // waits (kills after timeout_s) and reports
  const std::string &output() const { return result_.output; }

 private:
  void drain(int timeout_ms);
  void kill_group();  // kills the simulator's process group and reaps the simulator
  int pid_ = -1, fd_ = -1;
  bool exited_ = false;
  bool group_gone_ = false;
  int status_ = 0;
  RunResult result_;
};
std::vector<std::string> command_line(const RunSpec &spec);
std::string describe(const RunResult &r);
// Text for a one-line report: bytes outside printable ASCII (control characters, a newline, a
// program's binary output) as \xNN, cut after max_chars with "...".
std::string printable(const std::string &text, size_t max_chars = 200);

// The simulator named by $BFBENCH_SIM, else the given default; checked to be executable.
std::string find_simulator(const std::string &default_path);

}  // namespace bvb::sim
