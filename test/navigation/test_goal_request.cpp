#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/navigation/goal_request.hpp"

namespace ari_social_sim::navigation {
namespace {

// The text of the core::RequestError `body` throws ("" if it throws none).
template <class F>
std::string request_error(F body) {
  try {
    body();
  } catch (const core::RequestError& e) {
    return e.what();
  }
  return "";
}

// (2, 3) in map, facing 90 degrees: quaternion (0, 0, sin 45, cos 45).
PoseGoalRequest goal_at_2_3_facing_left() {
  PoseGoalRequest goal;
  goal.frame_id = "map";
  goal.x = 2.0;
  goal.y = 3.0;
  goal.qz = std::sin(M_PI / 4);
  goal.qw = std::cos(M_PI / 4);
  return goal;
}

TEST(GoalRequest, AWellFormedGoalGivesItsPlanarPose) {
  const core::Pose2 pose = planar_goal(goal_at_2_3_facing_left(), "target_pose.");
  EXPECT_EQ(pose.position, Eigen::Vector2d(2.0, 3.0));
  EXPECT_NEAR(pose.theta, M_PI / 2, 1e-12);
  // Within the tolerance a norm of 1.0005 (a float-normalised quaternion is far closer) is
  // accepted and its yaw unchanged: 0.70746 / 0.70746 still gives 90 degrees.
  PoseGoalRequest loose = goal_at_2_3_facing_left();
  loose.qz *= 1.0005;
  loose.qw *= 1.0005;
  EXPECT_NEAR(planar_goal(loose, "").theta, M_PI / 2, 1e-12);
}

TEST(GoalRequest, NonFiniteNumbersAreRejectedNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  PoseGoalRequest goal = goal_at_2_3_facing_left();
  goal.x = nan;
  EXPECT_EQ(request_error([&] { planar_goal(goal, "target_pose."); }),
            "target_pose.pose.position.x: expected a finite number, got nan");
  goal = goal_at_2_3_facing_left();
  goal.y = -inf;
  EXPECT_EQ(request_error([&] { planar_goal(goal, ""); }),
            "pose.position.y: expected a finite number, got -inf");
  goal = goal_at_2_3_facing_left();
  goal.qw = nan;  // a NaN yaw was once reported as a goal outside the floor
  EXPECT_EQ(request_error([&] { planar_goal(goal, "target_pose."); }),
            "target_pose.pose.orientation.w: expected a finite number, got nan");
}

TEST(GoalRequest, AQuaternionNotNormalisedIsRejectedWithItsNorm) {
  PoseGoalRequest goal = goal_at_2_3_facing_left();
  goal.qz = 0.0;
  goal.qw = 0.0;
  EXPECT_EQ(request_error([&] { planar_goal(goal, "target_pose."); }),
            "target_pose.pose.orientation: expected a unit quaternion (norm within 0.001 of 1), "
            "got (0, 0, 0, 0) of norm 0");
  // Yaw 1.2 rad written straight into z and w: norm sqrt(1.2^2 + 1) = 1.56205.
  goal.qz = 1.2;
  goal.qw = 1.0;
  EXPECT_NE(request_error([&] { planar_goal(goal, "target_pose."); }).find("of norm 1.56205"),
            std::string::npos);
  // 1.002 is off by 0.002 > 0.001.
  goal = goal_at_2_3_facing_left();
  goal.qz *= 1.002;
  goal.qw *= 1.002;
  EXPECT_NE(request_error([&] { planar_goal(goal, ""); }).find("of norm 1.002"), std::string::npos);
}

TEST(GoalRequest, AnEmptyFrameIsRejectedAndOnlyMapIsTheMap) {
  PoseGoalRequest goal = goal_at_2_3_facing_left();
  goal.frame_id = "";
  EXPECT_EQ(request_error([&] { planar_goal(goal, "target_pose."); }),
            "target_pose.header.frame_id: expected a tf frame such as map, got ''");
  EXPECT_TRUE(names_map_frame("map"));
  EXPECT_TRUE(names_map_frame("/map"));
  EXPECT_FALSE(names_map_frame("odom"));
  EXPECT_FALSE(names_map_frame("map "));
}

TEST(GoalRequest, AGoalOutsideTheMapIsRejectedWithTheBounds) {
  // A 248 x 168 grid at 0.05 m from (-0.2, -0.2): x [-0.2, 12.2], y [-0.2, 8.2].
  model::OccupancyGrid grid;
  grid.origin = {-0.2, -0.2};
  grid.resolution_m = 0.05;
  grid.width = 248;
  grid.height = 168;
  grid.cells.assign(248 * 168, model::OccupancyGrid::kFree);
  const MapBounds bounds = MapBounds::of(GridField(grid, 0.0f));
  EXPECT_NEAR(bounds.max.x(), 12.2, 1e-12);
  EXPECT_NEAR(bounds.max.y(), 8.2, 1e-12);
  EXPECT_EQ(request_error([&] {
              check_inside_map({{25.0, 3.0}, 0.0}, bounds, "target_pose.pose.position");
            }),
            "target_pose.pose.position: (25.00, 3.00) in map is outside the map, which spans x "
            "[-0.20, 12.20] and y [-0.20, 8.20]");
  EXPECT_EQ(request_error([&] { check_inside_map({{12.2, -0.2}, 0.0}, bounds, "p"); }), "");
  EXPECT_NE(request_error([&] { check_inside_map({{3.0, -0.21}, 0.0}, bounds, "p"); }), "");
}

TEST(GoalRequest, TargetIdsAreNonEmptyWithoutWhitespace) {
  EXPECT_EQ(request_error([] { check_target_id("anonymous_person_qkzvd", "target_id"); }), "");
  EXPECT_EQ(request_error([] { check_target_id("", "target_id"); }),
            "target_id: expected a person or group id (not empty, no whitespace), got ''");
  for (const char* bad : {"human 3", " g1", "g1\n", "a\tb"}) {
    EXPECT_NE(request_error([&] { check_target_id(bad, "target_id"); }), "") << bad;
  }
}

}  // namespace
}  // namespace ari_social_sim::navigation
