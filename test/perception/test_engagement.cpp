#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/engagement.hpp"

namespace ari_social_sim::perception {
namespace {

const core::Pose2 kRobot{{0.0, 0.0}, 0.0};

TEST(EngagementScore, MutualGazeAtDistance) {
  const EngagementConfig config;  // 4 m, 60 deg
  // Face to face at 1 m: both gazes 1, distance factor log(4) / log(5) = 0.861.
  EXPECT_NEAR(engagement_score(config, kRobot, {{1.0, 0.0}, core::kPi}),
              std::log(4.0) / std::log(5.0), 1e-12);
  // At 3 m: log(2) / log(5) = 0.431.
  EXPECT_NEAR(engagement_score(config, kRobot, {{3.0, 0.0}, core::kPi}),
              std::log(2.0) / std::log(5.0), 1e-12);
  EXPECT_EQ(engagement_score(config, kRobot, {{4.5, 0.0}, core::kPi}), 0.0);  // beyond 4 m
}

TEST(EngagementScore, GazeOffTheAxisLowersTheScore) {
  const EngagementConfig config;
  // The person looks 30 deg away from ARI at 1 m: lateral/forward of ARI in the person's gaze
  // frame = tan(30 deg), gaze = 1 - tan(30) / tan(60) = 2/3.
  const double score = engagement_score(config, kRobot, {{1.0, 0.0}, core::kPi + core::kPi / 6});
  EXPECT_NEAR(score, (2.0 / 3.0) * std::log(4.0) / std::log(5.0), 1e-12);
  // Looking away entirely, or ARI looking away: 0.
  EXPECT_EQ(engagement_score(config, kRobot, {{1.0, 0.0}, 0.0}), 0.0);
  EXPECT_EQ(engagement_score(config, {{0.0, 0.0}, core::kPi}, {{1.0, 0.0}, core::kPi}), 0.0);
}

TEST(EngagementTracker, FollowsHriEngagementsLevels) {
  EngagementConfig config;
  config.window_s = 2.0;
  EngagementTracker tracker(config);
  int frame = 0;  // at 10 Hz
  auto run = [&](int frames, double score) {
    EngagementLevel level = tracker.level();
    for (int end = frame + frames; frame < end; ++frame) {
      level = tracker.update(0.1 * frame, score);
    }
    return level;
  };
  EXPECT_EQ(run(10, 0.9), EngagementLevel::kUnknown);  // up to 0.9 s: less than half a window
  // At 1 s the history spans half the window: DISENGAGED first, then the mean of +1 makes it
  // ENGAGING and ENGAGED on the next frames.
  EXPECT_EQ(run(1, 0.9), EngagementLevel::kDisengaged);
  EXPECT_EQ(run(1, 0.9), EngagementLevel::kEngaging);
  EXPECT_EQ(run(1, 0.9), EngagementLevel::kEngaged);
  EXPECT_EQ(run(20, 0.9), EngagementLevel::kEngaged);
  // Looking away: with 21 frames in the window, k frames of -1 give a mean of (21 - 2k) / 21:
  // below 0.4 from k = 7 (DISENGAGING), below -0.5 from k = 16 (DISENGAGED).
  EXPECT_EQ(run(6, 0.0), EngagementLevel::kEngaged);
  EXPECT_EQ(run(1, 0.0), EngagementLevel::kDisengaging);
  EXPECT_EQ(run(8, 0.0), EngagementLevel::kDisengaging);
  EXPECT_EQ(run(1, 0.0), EngagementLevel::kDisengaged);
  tracker.reset();
  EXPECT_EQ(tracker.level(), EngagementLevel::kUnknown);
}

}  // namespace
}  // namespace ari_social_sim::perception
