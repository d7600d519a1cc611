#include <gtest/gtest.h>

#include "ari_social_sim/scenario/episode_metrics.hpp"

namespace ari_social_sim::scenario {
namespace {

// ARI drives along +x at 1 m/s past a human standing at (5, 1); its footprint spans x -0.60..0.16
// and y +-0.27 around base_footprint.
TEST(EpisodeMetrics, PathClearancePersonalSpaceAndContacts) {
  MetricsRecorder recorder;
  Observations obs;
  obs.world.ari = world::AriSnapshot{};
  world::HumanSnapshot human;
  human.id = 10;
  human.pose.position = {5.0, 1.0};
  obs.world.humans = {human};
  obs.navigation.state = NavigationState::kActive;
  for (int step = 0; step <= 100; ++step) {
    obs.world.time_s = 0.1 * step;
    obs.world.ari->pose.position = {0.1 * step, 0.0};
    recorder.observe(obs);
  }
  const EpisodeMetrics& m = recorder.metrics();
  EXPECT_NEAR(m.ari_path_length_m, 10.0, 1e-9);
  // Closest: the footprint's side at y = 0.27, 0.73 m below the human's centre, minus its 0.2 m.
  EXPECT_NEAR(m.min_clearance_m, 0.53, 1e-9);
  EXPECT_EQ(m.contacts, 0);
  // The centre is within 0.8 m of the footprint when the human is beside it (x from 4.84 to
  // 5.60): dy = 0.73 leaves dx < sqrt(0.8^2 - 0.73^2) = 0.327 m beyond either end, so base x in
  // (4.84 - 0.327, 5.60 + 0.327) = 1.41 m, 14 steps of 0.1 s (+-1 for the sampling).
  EXPECT_NEAR(m.personal_space_time_s, 1.41, 0.1 + 1e-9);
  EXPECT_NEAR(m.navigation_time_s, 10.0, 1e-9);
  EXPECT_EQ(m.navigation_goals, 1);
}

TEST(EpisodeMetrics, EachTouchAndEachFailedGoalCountsOnce) {
  MetricsRecorder recorder;
  Observations obs;
  obs.world.ari = world::AriSnapshot{};
  world::HumanSnapshot human;
  human.pose.position = {0.36, 0.0};  // 0.2 m in front of the footprint: touching
  obs.world.humans = {human};
  const auto tick = [&](double x_m, NavigationState state) {
    obs.world.ari->pose.position = {x_m, 0.0};
    obs.navigation.state = state;
    obs.world.time_s += 0.1;
    recorder.observe(obs);
  };
  tick(0.0, NavigationState::kActive);
  tick(0.0, NavigationState::kActive);
  tick(-1.0, NavigationState::kFailed);
  tick(-1.0, NavigationState::kFailed);
  tick(0.0, NavigationState::kActive);
  tick(0.0, NavigationState::kFailed);
  EXPECT_EQ(recorder.metrics().contacts, 2);
  EXPECT_EQ(recorder.metrics().navigation_goals, 2);
  EXPECT_EQ(recorder.metrics().navigation_failures, 2);
  EXPECT_DOUBLE_EQ(recorder.metrics().min_clearance_m, 0.0);
}

}  // namespace
}  // namespace ari_social_sim::scenario
