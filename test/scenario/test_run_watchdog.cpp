#include <gtest/gtest.h>

#include "ari_social_sim/scenario/run_watchdog.hpp"

namespace ari_social_sim::scenario {
namespace {

const auto kReachable = [] { return true; };
const auto kGone = [] { return false; };

TEST(RunWatchdog, WallTimeLimitCountsTheWaitsToo) {
  // Limit 240 s from a start at wall time 1000 s: fine at 1240, expired after.
  const RunWatchdog watchdog(240.0, 10.0, 1000.0);
  EXPECT_FALSE(watchdog.expired(1240.0, "waiting for the /tts action server", kReachable));
  EXPECT_EQ(watchdog.expired(1240.5, "waiting for the /tts action server", kReachable),
            "wall-time limit of 240 s reached while waiting for the /tts action server");
  // No limit: never.
  EXPECT_FALSE(RunWatchdog(0.0, 10.0, 0.0).expired(1e9, "in state walk", kReachable));
}

TEST(RunWatchdog, WorldSilenceCountsOnlyOnceTheWorldShouldRun) {
  RunWatchdog watchdog(0.0, 10.0, 0.0);
  // Waiting for the suite with the world paused: silence is expected.
  EXPECT_FALSE(watchdog.expired(500.0, "waiting for the world", kGone));
  watchdog.expect_world(500.0);
  EXPECT_FALSE(watchdog.expired(510.0, "in state walk", kGone));
  // States until 520 s, then none: expired 10 s after the last one.
  watchdog.world_state(520.0);
  EXPECT_FALSE(watchdog.expired(530.0, "in state walk", kGone));
  EXPECT_EQ(watchdog.expired(530.1, "in state ask_help", kGone),
            "no /sim/world_state for 10 s (world_node gone?) while in state ask_help");
  EXPECT_EQ(watchdog.expired(530.1, "in state ask_help", kReachable),
            "no /sim/world_state for 10 s (world paused?) while in state ask_help");
}

TEST(RunWatchdog, AWorldStartedByAnotherNodeCountsFromItsFirstState) {
  RunWatchdog watchdog(0.0, 2.5, 0.0);
  EXPECT_FALSE(watchdog.expired(100.0, "in state walk", kGone));  // never started: not counted
  watchdog.world_state(100.0);
  EXPECT_FALSE(watchdog.expired(102.5, "in state walk", kGone));
  EXPECT_EQ(watchdog.expired(102.6, "in state walk", kGone),
            "no /sim/world_state for 2.5 s (world_node gone?) while in state walk");
}

TEST(RunWatchdog, TheWallLimitIsReportedFirst) {
  RunWatchdog watchdog(60.0, 10.0, 0.0);
  watchdog.expect_world(0.0);
  bool asked = false;
  EXPECT_EQ(watchdog.expired(61.0, "in state walk",
                             [&] {
                               asked = true;
                               return false;
                             }),
            "wall-time limit of 60 s reached while in state walk");
  EXPECT_FALSE(asked);  // the probe (a service lookup in the node) is not made for nothing
}

}  // namespace
}  // namespace ari_social_sim::scenario
