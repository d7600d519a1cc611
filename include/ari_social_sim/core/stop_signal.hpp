#pragma once

#include <csignal>

namespace ari_social_sim::core {

/// The signal, SIGINT or SIGTERM, that asked the batch tools to stop; 0 until one arrives. Set by
/// the handler install_stop_handler puts in place and read between two steps of work: a signal
/// handler may do nothing but set a flag of this type, hence a global.
extern volatile std::sig_atomic_t g_stop_signal;

/// Makes SIGINT and SIGTERM set g_stop_signal instead of killing the process, so that a tool can
/// finish the file it is writing, drop the unit of work under way and say what it kept. Installed
/// whatever the disposition was, ignored included: a non-interactive shell starts background jobs
/// with SIGINT ignored, and a tool started from a script must stop on Ctrl-C all the same. A
/// second SIGINT kills at once (SA_RESETHAND), for a user who does not want to wait; a second
/// SIGTERM does not, since schedulers send it more than once.
void install_stop_handler();

/// `SIGINT` or `SIGTERM` for g_stop_signal's values, for the tools' messages.
const char* stop_signal_name(int signal);

/// The exit code of a run stopped by `signal`: 128 + its number, as a shell reports a process
/// killed by it (130 for SIGINT, 143 for SIGTERM).
inline int stopped_exit_code(int signal) {
  return 128 + signal;
}

}  // namespace ari_social_sim::core
