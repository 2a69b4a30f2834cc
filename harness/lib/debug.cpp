#include "debug.h"

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include <sys/wait.h>
#include <unistd.h>

#include "bench.h"
#include "elf_symbols.h"
#include "family.h"
#include "io.h"
#include "patterns.h"
#include "simdriver.h"

namespace bvb {

namespace {

std::string hex32(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08x", v);
  return b;
}

const char *role_name(Role r) {
  switch (r) {
    case Role::In: return "in";
    case Role::Out: return "out";
    case Role::InOut: return "in/out";
    case Role::Scratch: return "scratch";
  }
  return "?";
}

// A gdb convenience variable's name for a buffer: its name with anything else than letters,
// digits and _ made _.
std::string gdb_name(const std::string &s) {
  std::string n;
  for (char c : s) n += (std::isalnum(uint8_t(c)) || c == '_') ? c : '_';
  return n.empty() ? "buf" : n;
}

}  // namespace

std::string default_gdb() {
  const char *env = std::getenv("BFBENCH_GDB");
  if (env && *env) return env;
  return BVB_DEFAULT_GDB;
}

Call case_call(const Target &target, const std::string &case_id, uint32_t seed, uint32_t impl,
               std::string *case_name) {
  const std::string kernel = case_kernel(case_id);
  const KernelInfo &k = target.registry().get(kernel);
  if (impl == BVB_IMPL_ASM && !k.has_asm) throw InputError(kernel + " has no assembly implementation (--impl c)");
  const Family *f = family_of(kernel);
  if (!f) throw InputError(kernel + " has no family: no check makes its calls");
  CheckOptions o;
  o.seed = seed;
  o.kernel_glob = kernel;
  o.only_case = case_id;
  o.frames_real = default_frames_real();
  Checker ck(target, o);
  ck.reseed(f->name);
  f->check(ck);
  const std::vector<const CheckCall *> calls = ck.pending();
  if (calls.empty())
    throw InputError("no call " + case_id + " with seed " + std::to_string(seed) +
                     " (" + bfbench_name() + " check -k " + kernel + " --seed " + std::to_string(seed) + " -v shows the calls)");
  const CheckCall &cc = *calls.front();
  if (case_name) *case_name = cc.case_name;
  return target_call(cc, k.index, impl, canary_seed_of(seed));
}

DebugPlan plan_debug(const Target &target, const Call &call, const std::string &window, const std::string &gdb,
                     bool batch) {
  DebugPlan p;
  const KernelInfo &k = target.registry().kernels().at(call.kernel);
  p.entry_name = call.impl == BVB_IMPL_ASM ? k.asm_entry : k.c_entry;
  if (!symbol_value(target.elf(), p.entry_name, &p.entry))
    throw InputError(target.elf() + " has no symbol " + p.entry_name + " (a firmware image of another build?)");
  const CallResult r = target.run_one(call);
  if (!r.crash.empty()) throw InputError("the call crashed the simulator before its entry could be known: " + r.crash);
  if (r.status == BVB_NO_SPACE) throw InputError("the call's buffers do not fit the firmware's memory");

  const sim::RunSpec spec = target.write_window(call, window);
  std::vector<std::string> sim_args = sim::command_line(spec);
  std::string target_sim = "target sim";
  for (size_t i = 1; i + 1 < sim_args.size(); ++i) target_sim += " " + sim_args[i];  // not the program, not the ELF

  p.argv = {gdb, "-q", "-nx"};
  if (batch) p.argv.push_back("-batch");
  auto ex = [&](const std::string &cmd) {
    p.argv.push_back("-ex");
    p.argv.push_back(cmd);
  };
  ex(target_sim);
  ex("load");
  ex("break *" + hex32(p.entry));
  ex("run");
  for (size_t b = 0; b < call.bufs.size(); ++b) {
    const Buffer &buf = call.bufs[b];
    const std::string addr = hex32(r.buf_addr[b]);
    p.buffers.push_back(buf.name + " (" + role_name(buf.role) + ", " + std::to_string(buf.data.size()) +
                        " bytes, " + place_name(buf.place) + ") at " + addr);
    ex("set $" + gdb_name(buf.name) + " = (unsigned char *) " + addr);
    ex("echo $" + gdb_name(buf.name) + " = " + p.buffers.back() + "\\n");
  }
  if (batch) ex("info registers pc r0 r1 r2 sp");
  p.argv.push_back(target.elf());
  return p;
}

int run_gdb(const std::vector<std::string> &argv) {
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) throw sim::SetupError("fork failed");
  if (pid == 0) {
    std::vector<char *> a;
    for (const auto &s : argv) a.push_back(const_cast<char *>(s.c_str()));
    a.push_back(nullptr);
    execv(a[0], a.data());
    std::fprintf(stderr, "bfbench: cannot run %s\n", a[0]);
    _exit(127);
  }
  struct sigaction ign {}, old_int {}, old_quit {};
  ign.sa_handler = SIG_IGN;
  sigaction(SIGINT, &ign, &old_int);
  sigaction(SIGQUIT, &ign, &old_quit);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGQUIT, &old_quit, nullptr);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace bvb
