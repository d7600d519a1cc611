// check_trajectory_request: every number of a FollowJointTrajectory goal refused by field name.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ari_social_sim/physics/trajectory_controller.hpp"
#include "ari_social_sim/physics/trajectory_request_check.hpp"

namespace ari_social_sim::physics {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// ARI's head: pan +-1.309 rad, tilt -0.262..0.436 rad, both 3 rad/s.
const ControllerSpec kHead{"head_controller", {"head_1_joint", "head_2_joint"}, 0.5, 2.0, 5.0};
const std::vector<JointBounds> kHeadBounds{{-1.309, 1.309, 3.0}, {-0.262, 0.436, 3.0}};

TrajectoryRequest pan_to(double pan) {
  TrajectoryRequest request;
  request.joint_names = {"head_1_joint", "head_2_joint"};
  request.points = {{{pan, 0.0}, {0.0, 0.0}, {0.0, 0.0}, 1.0}};
  return request;
}

// The refusal's text ("" when the request passes); every refusal is INVALID_GOAL.
std::string refusal(const TrajectoryRequest& request,
                    const std::vector<JointBounds>& bounds = kHeadBounds) {
  try {
    check_trajectory_request(request, kHead, bounds, "trajectory.");
  } catch (const TrajectoryRejected& e) {
    EXPECT_EQ(e.code(), TrajectoryErrorCode::kInvalidGoal);
    return e.what();
  }
  return "";
}

TEST(TrajectoryRequestCheck, PassesAnOrdinaryGoal) {
  TrajectoryRequest request = pan_to(1.0);
  request.goal_tolerance = {{"head_1_joint", 0.1, 0.0, -1.0}};
  request.path_tolerance = {{"head_2_joint", -1.0, 0.0, 0.0}};
  request.goal_time_tolerance_s = 2.0;
  EXPECT_EQ(refusal(request), "");
}

TEST(TrajectoryRequestCheck, NamesANanGoalTolerance) {
  TrajectoryRequest request = pan_to(0.5);
  request.goal_tolerance = {{"head_1_joint", kNan, 0.0, 0.0}};
  EXPECT_EQ(refusal(request),
            "head_controller: goal_tolerance[0].position: expected -1 (none), 0 (the default) or "
            "a finite number > 0, got nan");
  request.goal_tolerance = {{"head_1_joint", 0.1, -0.5, 0.0}};
  EXPECT_EQ(refusal(request),
            "head_controller: goal_tolerance[0].velocity: expected -1 (none), 0 (the default) or "
            "a finite number > 0, got -0.5");
}

TEST(TrajectoryRequestCheck, NamesPathToleranceOfAJointNotControlled) {
  TrajectoryRequest request = pan_to(0.5);
  request.path_tolerance = {{"head_1_joint", 0.1, 0.0, 0.0}, {"neck", 0.1, 0.0, 0.0}};
  EXPECT_EQ(refusal(request),
            "head_controller: path_tolerance[1].name: expected one of head_1_joint, "
            "head_2_joint, got 'neck'");
  request.path_tolerance = {{"head_2_joint", INFINITY, 0.0, 0.0}};
  EXPECT_EQ(refusal(request),
            "head_controller: path_tolerance[0].position: expected -1 (none), 0 (the default) or "
            "a finite number > 0, got inf");
}

TEST(TrajectoryRequestCheck, CapsGoalTimeTolerance) {
  TrajectoryRequest request = pan_to(0.5);
  request.goal_time_tolerance_s = 1e9;
  EXPECT_EQ(
      refusal(request),
      "head_controller: goal_time_tolerance: expected a finite number [0, 3600] s, got 1e+09");
  request.goal_time_tolerance_s = -1.0;
  EXPECT_NE(refusal(request).find("goal_time_tolerance"), std::string::npos);
}

TEST(TrajectoryRequestCheck, NamesThePositionBeyondItsJointsLimits) {
  EXPECT_EQ(refusal(pan_to(1.6)),
            "head_controller: trajectory.points[0].positions[0] (head_1_joint): expected a "
            "finite number [-1.309, 1.309] rad, got 1.6");
  EXPECT_EQ(refusal(pan_to(kNan)),
            "head_controller: trajectory.points[0].positions[0] (head_1_joint): expected a "
            "finite number [-1.309, 1.309] rad, got nan");
}

TEST(TrajectoryRequestCheck, NamesTheRequestsColumnNotTheControllers) {
  // Tilt first: column 0 is head_2_joint, with its own limits.
  TrajectoryRequest request = pan_to(0.0);
  request.joint_names = {"head_2_joint", "head_1_joint"};
  request.points[0].positions = {0.5, 0.0};
  const std::vector<JointBounds> tilt_first{kHeadBounds[1], kHeadBounds[0]};
  EXPECT_EQ(refusal(request, tilt_first),
            "head_controller: trajectory.points[0].positions[0] (head_2_joint): expected a "
            "finite number [-0.262, 0.436] rad, got 0.5");
}

TEST(TrajectoryRequestCheck, HoldsVelocitiesToTheJointsLimit) {
  TrajectoryRequest request = pan_to(0.5);
  request.points[0].velocities = {0.0, 1e308};
  EXPECT_EQ(refusal(request),
            "head_controller: trajectory.points[0].velocities[1] (head_2_joint): expected a "
            "finite number [-3, 3] rad/s, got 1e+308");
  request.points[0].velocities = {-3.0, 3.0};  // the limit itself is allowed
  EXPECT_EQ(refusal(request), "");
}

TEST(TrajectoryRequestCheck, CapsAccelerations) {
  TrajectoryRequest request = pan_to(0.5);
  request.points[0].accelerations = {1e308, 0.0};
  EXPECT_EQ(refusal(request),
            "head_controller: trajectory.points[0].accelerations[0] (head_1_joint): expected a "
            "finite number [-1000, 1000] rad/s^2, got 1e+308");
}

TEST(TrajectoryRequestCheck, CapsAndOrdersTimes) {
  TrajectoryRequest request = pan_to(0.5);
  request.points[0].time_from_start_s = 1e9;
  EXPECT_EQ(refusal(request),
            "head_controller: trajectory.points[0].time_from_start: expected a finite number "
            "[0, 3600] s, got 1e+09");
  request.points[0].time_from_start_s = 2.0;
  request.points.push_back({{0.4, 0.0}, {}, {}, 2.0});
  EXPECT_EQ(refusal(request),
            "head_controller: trajectory.points[1].time_from_start: expected more than the "
            "previous point's 2 s (times increase strictly), got 2 s");
}

TEST(TrajectoryRequestCheck, NamesWrongValueCounts) {
  TrajectoryRequest request = pan_to(0.5);
  request.points[0].velocities = {0.0};
  EXPECT_EQ(refusal(request),
            "head_controller: trajectory.points[0].velocities: expected none or 2 values (one "
            "per joint name), got 1");
}

TEST(TrajectoryRequestCheck, ControllerRefusesBeforeMovingAndKeepsItsTrajectory) {
  TrajectoryController controller(kHead, kHeadBounds, {0.0, 0.0});
  controller.follow(pan_to(1.0), 0.0, true);
  TrajectoryRequest hostile = pan_to(0.5);
  hostile.goal_tolerance = {{"head_1_joint", kNan, 0.0, 0.0}};
  EXPECT_THROW(controller.follow(hostile, 0.1, true), TrajectoryRejected);
  EXPECT_EQ(controller.goal().state, GoalState::kActive);
  EXPECT_DOUBLE_EQ(controller.sample(1.0).positions[0], 1.0);  // still the first goal
}

TEST(TrajectoryRequestCheck, ControllerCapsTheStartStamp) {
  TrajectoryController controller(kHead, kHeadBounds, {0.0, 0.0});
  TrajectoryRequest late = pan_to(0.5);
  late.start_time_s = 1e9;
  try {
    controller.follow(late, 10.0, true);
    FAIL() << "a start 1e9 s ahead was accepted";
  } catch (const TrajectoryRejected& e) {
    EXPECT_EQ(e.code(), TrajectoryErrorCode::kInvalidGoal);
    EXPECT_STREQ(e.what(),
                 "head_controller: trajectory.header.stamp: expected 0 (now) or at most 3600 s "
                 "after now (10 s), got 1e+09 s");
  }
}

}  // namespace
}  // namespace ari_social_sim::physics
