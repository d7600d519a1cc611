// PointHead goals: field checks, PAL's head_action timing, and the tf frame watch.

#include <gtest/gtest.h>

#include <limits>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/physics/point_head_goal.hpp"

namespace ari_social_sim::physics {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kHeadTopSpeed = 3.0;  // ARI's head_1 and head_2 joints, rad/s

PointHeadGoal ordinary() {
  PointHeadGoal goal;
  goal.target_frame = "base_footprint";
  goal.target_point = {2.0, 0.5, 1.2};
  goal.pointing_axis = {0.0, 0.0, 1.0};
  goal.pointing_frame = "head_front_camera_color_optical_frame";
  goal.min_duration_s = 0.5;
  goal.max_velocity_rps = 1.0;
  return goal;
}

std::string refusal(const PointHeadGoal& goal) {
  try {
    check_point_head_goal(goal, kHeadTopSpeed);
  } catch (const core::RequestError& e) {
    return e.what();
  }
  return "";
}

TEST(PointHeadGoalCheck, PassesAnOrdinaryGoal) {
  EXPECT_EQ(refusal(ordinary()), "");
  PointHeadGoal defaults = ordinary();
  defaults.max_velocity_rps = 0.0;  // the joints' own limits
  defaults.min_duration_s = 0.0;
  EXPECT_EQ(refusal(defaults), "");
}

TEST(PointHeadGoalCheck, NamesTheTargetsField) {
  PointHeadGoal goal = ordinary();
  goal.target_point.x() = kNan;
  EXPECT_EQ(refusal(goal), "target.point.x: expected a finite number, got nan");
  goal = ordinary();
  goal.target_point.z() = -INFINITY;
  EXPECT_EQ(refusal(goal), "target.point.z: expected a finite number, got -inf");
  goal = ordinary();
  goal.pointing_axis.y() = kNan;
  EXPECT_EQ(refusal(goal), "pointing_axis.y: expected a finite number, got nan");
}

TEST(PointHeadGoalCheck, HoldsMaxVelocityToTheHeadsLimit) {
  PointHeadGoal goal = ordinary();
  goal.max_velocity_rps = -1.0;
  EXPECT_EQ(
      refusal(goal),
      "max_velocity: expected 0 (the joints' limits) or a finite number (0, 3] rad/s, got -1");
  goal.max_velocity_rps = 1e308;
  EXPECT_EQ(refusal(goal),
            "max_velocity: expected 0 (the joints' limits) or a finite number (0, 3] rad/s, got "
            "1e+308");
  goal.max_velocity_rps = kNan;
  EXPECT_NE(refusal(goal).find("got nan"), std::string::npos);
  goal.max_velocity_rps = 3.0;
  EXPECT_EQ(refusal(goal), "");
}

TEST(PointHeadGoalCheck, CapsMinDuration) {
  PointHeadGoal goal = ordinary();
  goal.min_duration_s = 1e9;
  EXPECT_EQ(refusal(goal), "min_duration: expected a finite number [0, 60] s, got 1e+09");
  goal.min_duration_s = -0.5;
  EXPECT_EQ(refusal(goal), "min_duration: expected a finite number [0, 60] s, got -0.5");
}

TEST(PointHeadDuration, TimesTheMoveAsPalsHeadAction) {
  PointHeadGoal goal = ordinary();
  goal.min_duration_s = 0.0;
  goal.max_velocity_rps = 0.5;
  // The larger rotation (pan 1.0 rad) at 0.5 rad/s: 2 s.
  EXPECT_DOUBLE_EQ(point_head_duration(goal, 1.0, 0.2, 3.0, 3.0), 2.0);
  goal.min_duration_s = 4.0;  // min_duration is a floor
  EXPECT_DOUBLE_EQ(point_head_duration(goal, 1.0, 0.2, 3.0, 3.0), 4.0);
  goal.min_duration_s = 0.0;
  goal.max_velocity_rps = 0.0;  // the joints' limits: 1.2 rad of tilt at 3 rad/s
  EXPECT_DOUBLE_EQ(point_head_duration(goal, 0.3, 1.2, 3.0, 3.0), 0.4);
  EXPECT_DOUBLE_EQ(point_head_duration(goal, 0.0, 0.0, 3.0, 3.0), kMinPointHeadDurationS);
}

TEST(PointHeadDuration, RefusesAMoveThatWouldNeverEnd) {
  PointHeadGoal goal = ordinary();
  goal.max_velocity_rps = 1e-300;
  try {
    point_head_duration(goal, 0.5, 0.1, 3.0, 3.0);
    FAIL() << "a move of 5e+299 s was accepted";
  } catch (const core::RequestError& e) {
    EXPECT_STREQ(e.what(),
                 "max_velocity: expected a speed that moves the head 0.5 rad within 60 s, got "
                 "1e-300 rad/s (5e+299 s)");
  }
}

TEST(FrameWatch, GivesAnUnknownFrameHalfASecondOfWallTime) {
  FrameWatch watch(0.5);
  watch.start(100.0);
  EXPECT_EQ(watch.look(std::nullopt, 100.0, 7.0), FrameWatch::Status::kWaiting);
  EXPECT_EQ(watch.look(std::nullopt, 100.49, 7.0), FrameWatch::Status::kWaiting);
  // Sim time may stand still (the stepping thread asks): the wall clock alone decides.
  EXPECT_EQ(watch.look(std::nullopt, 100.5, 7.0), FrameWatch::Status::kNeverSeen);
}

TEST(FrameWatch, AFrameThatArrivesLateIsFresh) {
  FrameWatch watch(0.5);
  watch.start(100.0);
  EXPECT_EQ(watch.look(std::nullopt, 100.2, 7.2), FrameWatch::Status::kWaiting);
  EXPECT_EQ(watch.look(7.2, 100.3, 7.3), FrameWatch::Status::kFresh);
  EXPECT_EQ(watch.look(7.2, 100.6, 7.6), FrameWatch::Status::kFresh);  // 0.4 s old on both
}

TEST(FrameWatch, AFrameThatStopsComingGoesStaleAfterHalfASecondOnBothClocks) {
  FrameWatch watch(0.5);
  watch.start(100.0);
  EXPECT_EQ(watch.look(7.0, 100.0, 7.0), FrameWatch::Status::kFresh);
  EXPECT_EQ(watch.look(7.5, 100.5, 7.5), FrameWatch::Status::kFresh);  // still coming
  // The last transform was stamped 7.5 s; none since.
  EXPECT_EQ(watch.look(7.5, 100.9, 7.9), FrameWatch::Status::kFresh);
  EXPECT_EQ(watch.look(7.5, 101.0, 8.0), FrameWatch::Status::kStale);
  // A lookup that fails (the buffer forgot the frame) keeps the newest stamp seen.
  EXPECT_EQ(watch.look(std::nullopt, 101.1, 8.1), FrameWatch::Status::kStale);
}

TEST(FrameWatch, APausedWorldDoesNotMakeALiveFrameStale) {
  FrameWatch watch(0.5);
  watch.start(100.0);
  EXPECT_EQ(watch.look(7.0, 100.0, 7.0), FrameWatch::Status::kFresh);
  // Five wall seconds, but sim time stood at 7.1 s: the publisher had nothing newer to stamp.
  EXPECT_EQ(watch.look(7.0, 105.0, 7.1), FrameWatch::Status::kFresh);
}

TEST(FrameWatch, AnOldFrameGoesStaleHalfASecondAfterTheGoal) {
  // A person who left 5 s ago: tf still holds the last transform.
  FrameWatch watch(0.5);
  watch.start(100.0);
  EXPECT_EQ(watch.look(2.0, 100.0, 7.0), FrameWatch::Status::kFresh);
  EXPECT_EQ(watch.look(2.0, 100.5, 7.5), FrameWatch::Status::kStale);
}

TEST(FrameWatch, StaticFramesNeverAge) {
  FrameWatch watch(0.5);
  watch.start(100.0);
  EXPECT_EQ(watch.look(0.0, 200.0, 90.0), FrameWatch::Status::kFresh);
}

}  // namespace
}  // namespace ari_social_sim::physics
