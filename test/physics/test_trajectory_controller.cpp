// TrajectoryController: JointTrajectoryController semantics on two joints.

#include <gtest/gtest.h>

#include "ari_social_sim/physics/trajectory_controller.hpp"

namespace ari_social_sim::physics {
namespace {

// A pan/tilt pair like ARI's head: limits +-1.309 and -0.262..0.436 rad, 3 rad/s.
TrajectoryController head() {
  ControllerSpec spec{"head_controller", {"head_1_joint", "head_2_joint"}, 0.5, 2.0, 5.0};
  return TrajectoryController(spec, {{-1.309, 1.309, 3.0}, {-0.262, 0.436, 3.0}}, {0.0, 0.0});
}

TrajectoryRequest to(double pan, double tilt, double seconds) {
  TrajectoryRequest request;
  request.joint_names = {"head_1_joint", "head_2_joint"};
  request.points = {{{pan, tilt}, {}, {}, seconds}};
  return request;
}

TrajectoryErrorCode rejection(TrajectoryController& controller, const TrajectoryRequest& request,
                              double now_s, std::string* message = nullptr) {
  try {
    controller.follow(request, now_s, true);
  } catch (const TrajectoryRejected& e) {
    if (message != nullptr) {
      *message = e.what();
    }
    return e.code();
  }
  return TrajectoryErrorCode::kSuccessful;
}

TEST(TrajectoryController, RejectsWhatJointTrajectoryControllerRejects) {
  TrajectoryController controller = head();
  std::string message;
  TrajectoryRequest unknown = to(0.1, 0.1, 1.0);
  unknown.joint_names[1] = "neck";
  EXPECT_EQ(rejection(controller, unknown, 0.0, &message), TrajectoryErrorCode::kInvalidJoints);
  EXPECT_NE(message.find("neck"), std::string::npos) << message;
  TrajectoryRequest missing = to(0.1, 0.1, 1.0);
  missing.joint_names.pop_back();
  missing.points[0].positions.pop_back();
  EXPECT_EQ(rejection(controller, missing, 0.0), TrajectoryErrorCode::kInvalidJoints);
  // Beyond head_1_joint's +1.309 rad: INVALID_GOAL naming the joint and the limit.
  EXPECT_EQ(rejection(controller, to(1.4, 0.0, 1.0), 0.0, &message),
            TrajectoryErrorCode::kInvalidGoal);
  EXPECT_NE(
      message.find(
          "positions[0] (head_1_joint): expected a finite number [-1.309, 1.309] rad, got 1.4"),
      std::string::npos)
      << message;
  TrajectoryRequest backwards = to(0.1, 0.1, 2.0);
  backwards.points.push_back({{0.2, 0.1}, {}, {}, 1.0});
  EXPECT_EQ(rejection(controller, backwards, 0.0), TrajectoryErrorCode::kInvalidGoal);
  // Timed from t = 1 and over by t = 2, received at t = 5.
  TrajectoryRequest old = to(0.1, 0.1, 1.0);
  old.start_time_s = 1.0;
  EXPECT_EQ(rejection(controller, old, 5.0), TrajectoryErrorCode::kOldHeaderTimestamp);
  EXPECT_EQ(controller.goal().state, GoalState::kNone);  // nothing was accepted
}

TEST(TrajectoryController, ReordersJointsToItsOwn) {
  TrajectoryController controller = head();
  TrajectoryRequest request = to(0.3, 0.2, 0.0);
  std::swap(request.joint_names[0], request.joint_names[1]);  // tilt first: tilt 0.3, pan 0.2
  controller.follow(request, 0.0, false);
  controller.update(0.0, 0.001, {0.0, 0.0}, {0.0, 0.0});
  EXPECT_DOUBLE_EQ(controller.desired().positions[0], 0.2);
  EXPECT_DOUBLE_EQ(controller.desired().positions[1], 0.3);
}

TEST(TrajectoryController, SaturatesTheCommandAtTheVelocityLimit) {
  // A step of 1 rad: the command moves 3 rad/s x 1 ms per tick, so 0.3 rad after 100 ticks.
  TrajectoryController controller = head();
  controller.follow(to(1.0, 0.0, 0.0), 0.0, false);
  for (int i = 0; i < 100; ++i) {
    controller.update(i * 0.001, 0.001, controller.command(), {0.0, 0.0});
  }
  EXPECT_NEAR(controller.command()[0], 0.3, 1e-9);
  EXPECT_DOUBLE_EQ(controller.desired().positions[0], 1.0);
}

TEST(TrajectoryController, GoalSucceedsOnceReachedAndStopped) {
  TrajectoryController controller = head();
  const uint64_t id = controller.follow(to(0.5, 0.1, 1.0), 0.0, true);
  controller.update(0.5, 0.001, {0.25, 0.05}, {0.5, 0.1});
  EXPECT_EQ(controller.goal().state, GoalState::kActive);
  controller.update(1.0, 0.001, {0.3, 0.1}, {0.0, 0.0});  // 0.2 rad off: within 0.5
  EXPECT_EQ(controller.goal().state, GoalState::kSucceeded);
  EXPECT_EQ(controller.goal().goal_id, id);
}

TEST(TrajectoryController, GoalAbortsPastGoalTime) {
  // Stuck 0.6 rad short (tolerance 0.5) until end + goal_time (1 + 2 s).
  TrajectoryController controller = head();
  controller.follow(to(0.6, 0.0, 1.0), 0.0, true);
  controller.update(2.9, 0.001, {0.0, 0.0}, {0.0, 0.0});
  EXPECT_EQ(controller.goal().state, GoalState::kActive);
  controller.update(3.01, 0.001, {0.0, 0.0}, {0.0, 0.0});
  EXPECT_EQ(controller.goal().state, GoalState::kAborted);
  EXPECT_EQ(controller.goal().code, TrajectoryErrorCode::kGoalToleranceViolated);
  EXPECT_NE(controller.goal().message.find("head_1_joint"), std::string::npos);
}

TEST(TrajectoryController, PathToleranceAbortsOnTheWay) {
  TrajectoryController controller = head();
  TrajectoryRequest request = to(1.0, 0.0, 1.0);
  request.path_tolerance = {{"head_1_joint", 0.1, 0.0, 0.0}};
  controller.follow(request, 0.0, true);
  controller.update(0.5, 0.001, {0.0, 0.0}, {0.0, 0.0});  // desired 0.5, actual 0: 0.5 off
  EXPECT_EQ(controller.goal().code, TrajectoryErrorCode::kPathToleranceViolated);
}

TEST(TrajectoryController, NewerTrajectoryPreemptsTheGoal) {
  TrajectoryController controller = head();
  controller.follow(to(0.5, 0.0, 1.0), 0.0, true);
  controller.follow(to(-0.5, 0.0, 1.0), 0.2, false);  // a /command message
  EXPECT_EQ(controller.goal().state, GoalState::kPreempted);
  // query_state: the new trajectory halfway between the spliced start (0) and -0.5.
  EXPECT_NEAR(controller.sample(0.7).positions[0], -0.25, 1e-12);
}

}  // namespace
}  // namespace ari_social_sim::physics
