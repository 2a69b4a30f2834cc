// Every bfbench command's command line: options declared once with their type (flag, integer,
// number, text, size WxH, or a repeatable text or size), which both parses the arguments and
// writes the command's --help. One convention for all: `--name value` or `--name=value`,
// options and operands in any order, -h or --help anywhere prints the help (exit 0), and a
// mistake (an unknown option, a missing or malformed value, an option given twice that is not
// repeatable, operands missing or too many) is one line "bfbench CMD: ..." and exit 2.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "io.h"
#include "names.h"

namespace bvb {

// The exit status of every bfbench command.
enum ExitStatus : int {
  kExitOk = 0,      // done: every check, budget and verdict passed
  kExitFailed = 1,  // a check, budget or verdict failed
  kExitUsage = 2,   // bad usage, bad input, or a set-up that cannot run (no simulator, no firmware)
};
// The sentence each command's --help ends with, unless it states its own.
extern const char *const kExitStatusHelp;

// A mistake on the command line: exit 2, as bad input is.
struct UsageError : InputError {
  using InputError::InputError;
};

class CommandLine {
 public:
  // command is how the user names it ("check", "pipeline"); the help names the program too.
  explicit CommandLine(std::string command);
  ~CommandLine();
  CommandLine(const CommandLine &) = delete;
  CommandLine &operator=(const CommandLine &) = delete;

  // The help's text: prose after the usage lines, a tail after the options, and the exit-status
  // sentence (kExitStatusHelp unless given).
  CommandLine &about(std::string text);
  CommandLine &tail(std::string text);
  CommandLine &exit_status(std::string text);
  // Usage lines in place of the ones generated from the declarations (for a command with
  // several forms); each is prefixed with "PROGRAM COMMAND ".
  CommandLine &forms(std::vector<std::string> lines);

  // names: "--seed", or "-k,--kernel" (the first is the one the help shows first). help: one
  // line or a few words; it is wrapped.
  CommandLine &flag(const std::string &names, bool *out, const std::string &help);
  // A whole number in lo..hi, into any integer type that holds the range.
  template <typename T>
  CommandLine &integer(const std::string &names, const std::string &metavar, long long lo, long long hi, T *out,
                       const std::string &help) {
    return add_integer(names, metavar, lo, hi, [out](long long v) { *out = T(v); }, help);
  }
  CommandLine &number(const std::string &names, const std::string &metavar, double lo, double hi, double *out,
                      const std::string &help);
  CommandLine &text(const std::string &names, const std::string &metavar, std::string *out, const std::string &help);
  // One of a few words; anything else is "--x wants a or b, got 'c'".
  CommandLine &choice(const std::string &names, const std::vector<std::string> &choices, std::string *out,
                      const std::string &help);
  CommandLine &size(const std::string &names, Size *out, const std::string &help, int max_dim = kMaxFrameDim);
  // Repeatable: each occurrence adds one value, in order.
  CommandLine &texts(const std::string &names, const std::string &metavar, std::vector<std::string> *out,
                     const std::string &help);
  CommandLine &sizes(const std::string &names, std::vector<Size> *out, const std::string &help,
                     int max_dim = kMaxFrameDim);
  // The option declared last must be given ("CMD needs --in FILE").
  CommandLine &required();
  // The operands (arguments that are not options), between min and max of them; hint follows
  // the error ("profile takes one KERNEL (bfbench list)"). Without it, any operand is an error.
  CommandLine &operands(const std::string &metavar, std::vector<std::string> *out, size_t min, size_t max,
                        const std::string &hint = "");

  // Parses argv[1..argc) (argv[0] is the command's name). Returns false when -h or --help was
  // given: the help is printed to stdout and nothing else is looked at. Throws UsageError.
  bool parse(int argc, char **argv);
  bool parse(const std::vector<std::string> &args);
  // Whether the option (by any of its names) was on the command line.
  bool given(const std::string &name) const;
  std::string help() const;
  const std::string &command() const { return command_; }

 private:
  struct Option;
  // Takes one value of an option, given under the name `as`; throws UsageError naming it.
  using Take = std::function<void(const std::string &as, const std::string &value)>;
  CommandLine &add(const std::string &names, const std::string &metavar, const std::string &help, Take take,
                   bool repeatable = false);
  CommandLine &add_integer(const std::string &names, const std::string &metavar, long long lo, long long hi,
                           std::function<void(long long)> set, const std::string &help);
  Option *find(const std::string &name) const;
  std::string usage_lines() const;

  std::string command_, about_, tail_, exit_status_;
  std::vector<std::string> forms_;
  std::vector<std::unique_ptr<Option>> options_;
  std::string operand_metavar_, operand_hint_;
  std::vector<std::string> *operands_ = nullptr;
  size_t operand_min_ = 0, operand_max_ = 0;
};

// Runs a command and turns what it throws into the exit status, with one line "PROGRAM COMMAND:
// message" on stderr: a CallFailed is exit 1; a UsageError, InputError or sim::SetupError exit
// 2, as is anything else (as "internal error: ..."). The one place bfbench's commands report
// errors.
int run_command(const std::string &command, const std::function<int()> &body);

}  // namespace bvb
