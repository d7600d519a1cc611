// core::install_stop_handler: SIGINT and SIGTERM set the flag the batch tools read between steps,
// also when the process started with SIGINT ignored (a background job of a script).
#include <gtest/gtest.h>

#include "ari_social_sim/core/stop_signal.hpp"

namespace ari_social_sim::core {
namespace {

TEST(StopSignal, CaughtEvenWhenIgnoredAtStartAndSigintOnlyOnce) {
  std::signal(SIGINT, SIG_IGN);  // as `tool &` in a non-interactive shell starts it
  g_stop_signal = 0;
  install_stop_handler();
  ASSERT_EQ(std::raise(SIGINT), 0);
  EXPECT_EQ(g_stop_signal, SIGINT);
  EXPECT_STREQ(stop_signal_name(g_stop_signal), "SIGINT");
  EXPECT_EQ(stopped_exit_code(g_stop_signal), 130);
  // The default action is back: a second Ctrl-C kills at once.
  struct sigaction now {};
  sigaction(SIGINT, nullptr, &now);
  EXPECT_EQ(now.sa_handler, SIG_DFL);

  g_stop_signal = 0;
  install_stop_handler();
  ASSERT_EQ(std::raise(SIGTERM), 0);
  EXPECT_EQ(g_stop_signal, SIGTERM);
  EXPECT_STREQ(stop_signal_name(g_stop_signal), "SIGTERM");
  EXPECT_EQ(stopped_exit_code(g_stop_signal), 143);
  // A second SIGTERM (a scheduler's, passed on by a wrapper too) is caught again.
  ASSERT_EQ(std::raise(SIGTERM), 0);
  EXPECT_EQ(g_stop_signal, SIGTERM);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  g_stop_signal = 0;
}

}  // namespace
}  // namespace ari_social_sim::core
