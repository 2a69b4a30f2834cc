// What a run leaves behind if it is interrupted: temporary files (the simulator's window files,
// up to 64 MB each, and the temporaries of atomic writes) and simulator processes. Both are
// registered while they exist; on SIGINT, SIGTERM or SIGHUP the handler removes the files, kills
// the simulators' process groups, and lets the signal end the process as it would have.
// Everything here is thread-safe, and the handler uses only async-signal-safe calls.
#pragma once

#include <string>

#include <sys/types.h>

namespace bvb {

void register_temp_file(const std::string &path);
void unregister_temp_file(const std::string &path);
// Removes the file and forgets it.
void remove_temp_file(const std::string &path);

// A child that leads its own process group (the simulator and anything it starts).
void register_child_group(pid_t pgid);
void unregister_child_group(pid_t pgid);

// Installs the handlers for SIGINT, SIGTERM and SIGHUP (once; later calls do nothing).
void install_interrupt_cleanup();

}  // namespace bvb
