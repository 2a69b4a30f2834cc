#include "options.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>

#include "registry.h"
#include "simdriver.h"

namespace bvb {

const char *const kExitStatusHelp =
    "Exit status: 0 ok, 1 a check or budget failed, 2 bad usage, bad input or set-up.";

struct CommandLine::Option {
  std::vector<std::string> names;  // "-k", "--kernel"
  std::string metavar;             // empty for a flag
  std::string help;
  bool repeatable = false, required = false;
  int seen = 0;
  // Takes one value (never called for a flag); throws UsageError naming `as`, the name used.
  Take take;
  bool *flag = nullptr;

  std::string shown() const {
    std::string s;
    for (const auto &n : names) s += (s.empty() ? "" : ", ") + n;
    return metavar.empty() ? s : s + " " + metavar;
  }
  std::string in_usage() const {
    const std::string s = metavar.empty() ? names.back() : names.front() + " " + metavar;
    return (required ? s : "[" + s + "]") + (repeatable ? "..." : "");
  }
};

namespace {

// The words of text in lines of at most width characters (a longer word stands alone), the
// first starting at first_column, the others after indent spaces.
std::string wrap(const std::string &text, size_t first_column, size_t indent, size_t width = 96) {
  std::string out;
  size_t column = first_column;
  for (size_t a = text.find_first_not_of(' '); a != std::string::npos; a = text.find_first_not_of(' ', a)) {
    size_t b = text.find(' ', a);
    if (b == std::string::npos) b = text.size();
    const size_t len = b - a;
    if (!out.empty() && column + 1 + len > width) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    } else if (!out.empty()) {
      out += ' ';
      ++column;
    }
    out.append(text, a, len);
    column += len;
    a = b;
  }
  return out;
}

std::string program() { return bfbench_name(); }

}  // namespace

CommandLine::CommandLine(std::string command) : command_(std::move(command)), exit_status_(kExitStatusHelp) {}
CommandLine::~CommandLine() = default;

CommandLine &CommandLine::about(std::string text) {
  about_ = std::move(text);
  return *this;
}
CommandLine &CommandLine::tail(std::string text) {
  tail_ = std::move(text);
  return *this;
}
CommandLine &CommandLine::exit_status(std::string text) {
  exit_status_ = std::move(text);
  return *this;
}
CommandLine &CommandLine::forms(std::vector<std::string> lines) {
  forms_ = std::move(lines);
  return *this;
}

CommandLine &CommandLine::add(const std::string &names, const std::string &metavar, const std::string &help,
                              Take take, bool repeatable) {
  auto o = std::make_unique<Option>();
  o->names = split_list(names);
  o->metavar = metavar;
  o->help = help;
  o->take = std::move(take);
  o->repeatable = repeatable;
  for (const auto &n : o->names)
    if (n.size() < 2 || n[0] != '-' || n == "-h" || n == "--help" || find(n))
      throw std::logic_error(command_ + ": option name '" + n + "' is malformed, reserved or declared twice");
  options_.push_back(std::move(o));
  return *this;
}

CommandLine &CommandLine::flag(const std::string &names, bool *out, const std::string &help) {
  add(names, "", help, nullptr);
  options_.back()->flag = out;
  return *this;
}

CommandLine &CommandLine::add_integer(const std::string &names, const std::string &metavar, long long lo,
                                      long long hi, std::function<void(long long)> set, const std::string &help) {
  return add(names, metavar, help, [lo, hi, set](const std::string &as, const std::string &v) {
    char *end = nullptr;
    errno = 0;
    const long long n = std::strtoll(v.c_str(), &end, 10);
    // Digits only (an optional minus): strtoll alone would take " 7" and "+7".
    const bool plain = !v.empty() && (std::isdigit(uint8_t(v[0])) || (v[0] == '-' && v.size() > 1));
    if (!plain || *end || errno == ERANGE || n < lo || n > hi)
      throw UsageError(as + " wants an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got '" +
                       v + "'");
    set(n);
  });
}

CommandLine &CommandLine::number(const std::string &names, const std::string &metavar, double lo, double hi,
                                 double *out, const std::string &help) {
  return add(names, metavar, help, [lo, hi, out](const std::string &as, const std::string &v) {
    char *end = nullptr;
    errno = 0;
    const double n = v.empty() || std::isspace(uint8_t(v[0])) ? NAN : std::strtod(v.c_str(), &end);
    if (!std::isfinite(n) || *end || errno == ERANGE || n < lo || n > hi) {
      char range[64];
      std::snprintf(range, sizeof range, "%g..%g", lo, hi);
      throw UsageError(as + " wants a number in " + range + ", got '" + v + "'");
    }
    *out = n;
  });
}

CommandLine &CommandLine::text(const std::string &names, const std::string &metavar, std::string *out,
                               const std::string &help) {
  return add(names, metavar, help, [out](const std::string &, const std::string &v) { *out = v; });
}

CommandLine &CommandLine::choice(const std::string &names, const std::vector<std::string> &choices,
                                 std::string *out, const std::string &help) {
  std::string metavar, listed;
  for (size_t i = 0; i < choices.size(); ++i) {
    metavar += (i ? "|" : "") + choices[i];
    listed += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  }
  return add(names, metavar, help, [choices, listed, out](const std::string &as, const std::string &v) {
    for (const auto &c : choices)
      if (v == c) {
        *out = v;
        return;
      }
    throw UsageError(as + " wants " + listed + ", got '" + v + "'");
  });
}

namespace {
Size size_value(const std::string &as, const std::string &v, int max_dim) {
  Size s{0, 0};
  if (!parse_size(v, max_dim, &s))
    throw UsageError(as + " wants WxH (1.." + std::to_string(max_dim) + "), got '" + v + "'");
  return s;
}
}  // namespace

CommandLine &CommandLine::size(const std::string &names, Size *out, const std::string &help, int max_dim) {
  return add(names, "WxH", help, [out, max_dim](const std::string &as, const std::string &v) { *out = size_value(as, v, max_dim); });
}

CommandLine &CommandLine::texts(const std::string &names, const std::string &metavar, std::vector<std::string> *out,
                                const std::string &help) {
  return add(names, metavar, help, [out](const std::string &, const std::string &v) { out->push_back(v); }, true);
}

CommandLine &CommandLine::sizes(const std::string &names, std::vector<Size> *out, const std::string &help,
                                int max_dim) {
  return add(names, "WxH", help, [out, max_dim](const std::string &as, const std::string &v) { out->push_back(size_value(as, v, max_dim)); }, true);
}

CommandLine &CommandLine::required() {
  if (options_.empty()) throw std::logic_error(command_ + ": required() before any option");
  options_.back()->required = true;
  return *this;
}

CommandLine &CommandLine::operands(const std::string &metavar, std::vector<std::string> *out, size_t min,
                                   size_t max, const std::string &hint) {
  operand_metavar_ = metavar;
  operands_ = out;
  operand_min_ = min;
  operand_max_ = max;
  operand_hint_ = hint;
  return *this;
}

CommandLine::Option *CommandLine::find(const std::string &name) const {
  for (const auto &o : options_)
    for (const auto &n : o->names)
      if (n == name) return o.get();
  return nullptr;
}

bool CommandLine::given(const std::string &name) const {
  const Option *o = find(name);
  if (!o) throw std::logic_error(command_ + ": no option " + name + " declared");
  return o->seen > 0;
}

bool CommandLine::parse(int argc, char **argv) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) args.push_back(argv[i]);
  return parse(args);
}

bool CommandLine::parse(const std::vector<std::string> &args) {
  // --help wins over every mistake (and is never a value: "--out --help" asks for help too,
  // as bfbench always did).
  for (const auto &a : args)
    if (a == "-h" || a == "--help") {
      std::fputs(help().c_str(), stdout);
      return false;
    }
  const std::string more = " (" + program() + " " + command_ + " --help)";
  std::vector<std::string> operands;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string &a = args[i];
    if (a.size() < 2 || a[0] != '-') {
      operands.push_back(a);
      continue;
    }
    const size_t eq = a.find('=');  // --name=value, and -k=value as bfbench always took it
    const std::string name = a.substr(0, eq);
    Option *o = find(name);
    if (!o) throw UsageError("unknown option " + name + more);
    if (o->seen && !o->repeatable) throw UsageError(name + " given more than once");
    ++o->seen;
    if (o->flag) {
      if (eq != std::string::npos) throw UsageError(name + " takes no value");
      *o->flag = true;
      continue;
    }
    if (eq != std::string::npos) {
      o->take(name, a.substr(eq + 1));
    } else {
      if (i + 1 >= args.size()) throw UsageError(name + " needs a value (" + o->metavar + ")");
      o->take(name, args[++i]);
    }
  }
  for (const auto &o : options_)
    if (o->required && !o->seen) throw UsageError(command_ + " needs " + o->names.front() + " " + o->metavar);
  const std::string hint = operand_hint_.empty() ? "" : " " + operand_hint_;
  if (!operands_ && !operands.empty()) throw UsageError("unexpected argument '" + operands[0] + "'" + more);
  if (operands_) {
    if (operands.size() < operand_min_ || operands.size() > operand_max_) {
      if (operand_min_ == operand_max_)
        throw UsageError(command_ + " takes " + (operand_min_ == 1 ? std::string("one") : std::to_string(operand_min_)) +
                         " " + operand_metavar_ + hint);
      if (operands.size() < operand_min_)
        throw UsageError(command_ + " takes at least " + std::to_string(operand_min_) + " " + operand_metavar_ + hint);
      throw UsageError(command_ + " takes at most " + std::to_string(operand_max_) + " " + operand_metavar_ + hint);
    }
    *operands_ = operands;
  }
  return true;
}

std::string CommandLine::usage_lines() const {
  const std::string lead = "usage: " + program() + " " + command_ + " ";
  if (!forms_.empty()) {
    std::string s;
    for (size_t i = 0; i < forms_.size(); ++i)
      s += (i ? std::string(7, ' ') + program() + " " + command_ + " " : lead) + forms_[i] + "\n";
    return s;
  }
  std::string words;
  if (operands_) {
    std::string m = operand_metavar_ + (operand_max_ > 1 ? "..." : "");
    words += operand_min_ ? m : "[" + m + "]";
  }
  // An option and its value stay on one line: their space is held as \x01 while wrapping.
  for (const auto &o : options_) {
    std::string item = o->in_usage();
    std::replace(item.begin(), item.end(), ' ', '\x01');
    words += " " + item;
  }
  std::string lines = wrap(words, lead.size(), lead.size());
  std::replace(lines.begin(), lines.end(), '\x01', ' ');
  return lead + lines + "\n";
}

std::string CommandLine::help() const {
  std::string s = usage_lines();
  if (!about_.empty()) s += "\n" + about_ + (about_.back() == '\n' ? "" : "\n");
  size_t column = 0;
  for (const auto &o : options_) column = std::max(column, o->shown().size());
  column = std::min<size_t>(column, 24) + 4;
  s += "\noptions:\n";
  auto line = [&](const std::string &left, const std::string &help) {
    std::string l = "  " + left;
    if (l.size() + 2 > column) l += "\n" + std::string(column, ' ');
    else l += std::string(column - l.size(), ' ');
    s += l + wrap(help, column, column) + "\n";
  };
  for (const auto &o : options_) line(o->shown(), o->help + (o->repeatable ? " (repeatable)" : ""));
  line("-h, --help", "this text");
  if (!tail_.empty()) s += "\n" + tail_ + (tail_.back() == '\n' ? "" : "\n");
  if (!exit_status_.empty()) s += "\n" + wrap(exit_status_, 0, 0) + "\n";
  return s;
}

int run_command(const std::string &command, const std::function<int()> &body) {
  const std::string who = program() + (command.empty() ? "" : " " + command) + ": ";
  auto say = [&](const std::string &what) {
    std::fprintf(stderr, "%s%s\n", who.c_str(), sim::printable(what, 2000).c_str());
    return int(kExitUsage);
  };
  try {
    return body();
  } catch (const CallFailed &e) {
    say(e.what());
    return int(kExitFailed);
  } catch (const InputError &e) {  // a UsageError too
    return say(e.what());
  } catch (const sim::SetupError &e) {
    return say(e.what());
  } catch (const std::exception &e) {
    return say(std::string("internal error: ") + e.what());
  }
}

}  // namespace bvb
