#include "ari_social_sim/core/stop_signal.hpp"

namespace ari_social_sim::core {

volatile std::sig_atomic_t g_stop_signal = 0;

namespace {

void on_stop_signal(int signal) {
  g_stop_signal = signal;
}

}  // namespace

void install_stop_handler() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  // SA_RESTART: a read or write under way when the signal comes (a pipe, a slow disk) goes on
  // rather than failing with EINTR, which would turn a clean stop into a write error.
  sigemptyset(&action.sa_mask);
  // sigaction replaces SIG_IGN too, unlike the `if (signal(...) != SIG_IGN)` idiom.
  // SA_RESETHAND on SIGINT only: a second Ctrl-C is a user who will not wait, but a scheduler
  // may send SIGTERM more than once (SLURM's scancel signals every process of a job, and a
  // wrapper passes it on too) and sends SIGKILL itself when it will wait no longer.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  action.sa_flags = SA_RESTART;
  sigaction(SIGTERM, &action, nullptr);
}

const char* stop_signal_name(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal";
}

}  // namespace ari_social_sim::core
