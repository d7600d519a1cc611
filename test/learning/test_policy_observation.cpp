#include <gtest/gtest.h>

#include <vector>

#include "ari_social_sim/navigation/policy_observation.hpp"

namespace ari_social_sim::navigation {
namespace {

// A 10 x 10 m free map with a wall from x = 5.9 to 6.2 m.
model::OccupancyGrid map_with_wall() {
  model::OccupancyGrid map;
  map.resolution_m = 0.1;
  map.width = 100;
  map.height = 100;
  map.cells.assign(100 * 100, model::OccupancyGrid::kFree);
  for (int y = 0; y < 100; ++y) {
    for (int x = 59; x <= 61; ++x) {
      map.cells[y * 100 + x] = model::OccupancyGrid::kOccupied;
    }
  }
  return map;
}

TEST(PolicyObservation, PeopleGoalAndMapAreInAriFrameNearestFirst) {
  PolicyObservationConfig config;
  config.nearest_people = 2;
  config.patch_cells = 9;
  config.patch_resolution_m = 0.5;
  const PolicyObservation observation(config);
  ASSERT_EQ(observation.size(), 3 + 6 + 4 + 2 * 9 + 81);

  RobotObservation robot;
  robot.pose.position = {4.0, 5.0};
  robot.pose.theta = core::kPi / 2;  // facing +y
  robot.linear_mps = 0.3;
  PerceivedScene scene;
  scene.people.push_back({"far", {4.0, 9.0}, 0.0, {0.0, 0.0}});
  scene.people.push_back({"near", {3.0, 5.0}, -core::kPi / 2, {0.0, 1.0}});
  scene.people.push_back({"farther", {4.0, 12.0}, 0.0, {0.0, 0.0}});
  Goal goal;
  goal.pose.position = {4.0, 7.0};
  goal.pose.theta = core::kPi / 2;
  goal.target_people = {"far"};
  std::vector<float> out(observation.size());
  observation.build(robot, scene, goal, true, map_with_wall(), out.data());

  EXPECT_FLOAT_EQ(out[0], 0.3f);
  const float* g = out.data() + 3;
  EXPECT_EQ(g[0], 1.0f);
  EXPECT_NEAR(g[1], 2.0, 1e-6);  // 2 m ahead
  EXPECT_NEAR(g[2], 0.0, 1e-6);
  EXPECT_NEAR(g[3], 1.0, 1e-6);  // same heading
  EXPECT_NEAR(g[5], 2.0, 1e-6);
  const float* p = out.data() + 13;
  EXPECT_EQ(p[0], 1.0f);  // "near": 1 m to ARI's left, walking forward, facing backward
  EXPECT_NEAR(p[1], 0.0, 1e-6);
  EXPECT_NEAR(p[2], 1.0, 1e-6);
  EXPECT_NEAR(p[3], 1.0, 1e-6);
  EXPECT_NEAR(p[5], -1.0, 1e-6);
  EXPECT_EQ(p[7], 0.0f);
  EXPECT_NEAR(p[9 + 1], 4.0, 1e-6);  // then "far", the target
  EXPECT_EQ(p[9 + 7], 1.0f);
  // The wall at x = 6 m is 2 m to ARI's right (y = -2 in ARI's frame): column j = 0 at -2 m.
  const float* patch = out.data() + 31;
  for (int i = 0; i < 9; ++i) {
    EXPECT_EQ(patch[i * 9 + 0], 1.0f) << i;
    EXPECT_EQ(patch[i * 9 + 4], 0.0f) << i;
  }
}

}  // namespace
}  // namespace ari_social_sim::navigation
