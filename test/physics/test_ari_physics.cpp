// AriPhysics: ARI's multibody on Bullet, driven and steered through its controllers.

#include <gtest/gtest.h>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/physics/ari_physics.hpp"

namespace ari_social_sim::physics {
namespace {

const RobotModel& ari() {
  static const RobotModel model = RobotModel::from_urdf_file(ARI_URDF);
  return model;
}

// A 10 x 10 m floor with one wall across x = 6 (its near face at x = 5.95).
model::WorldDescription walled_floor() {
  return model::parse_world(core::YamlMap::parse(
      "name: test\norigin: [-5, -5]\nsize: [15, 10]\n"
      "objects:\n  - {type: wall, from: [6, -4], to: [6, 4], thickness: 0.1}\n",
      "inline world"));
}

void run(AriPhysics& physics, double seconds) {
  const int steps = static_cast<int>(std::lround(seconds / physics.config().step_s));
  for (int i = 0; i < steps; ++i) {
    physics.step();
  }
}

TEST(AriPhysics, StandsStillOnItsWheels) {
  AriPhysics physics(ari(), walled_floor(), {{0.0, 0.0}, 0.0}, PhysicsConfig{});
  run(physics, 2.0);
  const Eigen::Isometry3d base = physics.frame_pose("base_footprint");
  // Settled on wheels and casters: base_footprint on the floor, level, where it started.
  EXPECT_NEAR(base.translation().z(), 0.0, 0.005);
  EXPECT_NEAR(base.translation().head<2>().norm(), 0.0, 0.005);
  EXPECT_GT(base.linear()(2, 2), std::cos(0.01));
  EXPECT_EQ(physics.diagnostics().nan_resets, 0u);
}

// A person's walked distance goes on from their report at their reported speed, as
// rendering::DrawnPeople takes it to (the cameras' gait phase); a seated person's stays. Their
// velocity stays the reported one (the stride's length) while their body glides to catch up.
TEST(AriPhysics, PeopleWalkOnTheirWalkedDistanceFromTheirReport) {
  AriPhysics physics(ari(), walled_floor(), {{0.0, 0.0}, 0.0}, PhysicsConfig{});
  PersonState walker;
  walker.id = 10;
  walker.pose = {{2.0, 2.0}, 0.0};
  walker.velocity_mps = {0.6, 0.8};  // 1 m/s
  walker.walked_m = 3.0;
  physics.set_people({walker});
  walker.pose.position.x() += 0.1;  // the next report 0.1 m ahead: the body glides to it
  walker.walked_m = 3.0;
  PersonState sitter = walker;
  sitter.id = 11;
  sitter.pose.position.y() = -2.0;
  sitter.seated_fraction = 0.5;  // sitting down: the feet stay put
  physics.set_people({walker, sitter});
  run(physics, 0.2);
  const std::vector<PersonState> people = physics.people_states();
  ASSERT_EQ(people.size(), 2u);
  EXPECT_NEAR(people[0].walked_m, 3.2, 1e-9);
  EXPECT_EQ(people[1].walked_m, 3.0);
  EXPECT_NEAR((people[0].velocity_mps - walker.velocity_mps).norm(), 0.0, 1e-12);
}

TEST(AriPhysics, StaysParked) {
  // Ten seconds without commands after settling: the wheels hold their angles (odometry does not
  // move) and the base stays within a millimetre and a milliradian of where it stood.
  AriPhysics physics(ari(), walled_floor(), {{0.0, 0.0}, 0.0}, PhysicsConfig{});
  run(physics, 1.0);
  const core::Pose2 odom = physics.odometry().pose();
  const core::Pose2 truth = physics.base_pose();
  run(physics, 10.0);
  EXPECT_LT((physics.odometry().pose().position - odom.position).norm(), 1e-4);
  EXPECT_LT((physics.base_pose().position - truth.position).norm(), 1e-3);
  EXPECT_LT(std::abs(physics.base_pose().theta - truth.theta), 1e-3);
}

TEST(AriPhysics, MatchesTheModelsKinematics) {
  // Bullet's link frames equal RobotModel's forward kinematics at the joints' positions.
  AriPhysics physics(ari(), walled_floor(), {{1.0, 2.0}, 0.5}, PhysicsConfig{});
  TrajectoryRequest request;
  request.joint_names = {"head_1_joint", "head_2_joint"};
  request.points = {{{0.6, 0.3}, {}, {}, 0.5}};
  physics.controller("head_controller").follow(request, physics.time_s(), false);
  run(physics, 1.0);
  std::unordered_map<std::string, double> q;
  for (size_t j = 0; j < physics.joint_names().size(); ++j) {
    q[physics.joint_names()[j]] = physics.joint_positions()[j];
  }
  const Eigen::Isometry3d X_map_base = physics.frame_pose("base_footprint");
  for (const std::string frame : {"head_front_camera_color_optical_frame", "arm_left_tool_link",
                                  "torso_front_camera_link", "wheel_right_link"}) {
    const Eigen::Isometry3d expected = X_map_base * ari().link_pose(frame, q);
    const Eigen::Isometry3d actual = physics.frame_pose(frame);
    EXPECT_LT((expected.translation() - actual.translation()).norm(), 1e-6) << frame;
    EXPECT_TRUE(expected.linear().isApprox(actual.linear(), 1e-6)) << frame;
  }
  EXPECT_NEAR(physics.joint_position("head_1_joint"), 0.6, 0.005);
  EXPECT_NEAR(physics.joint_position("head_2_joint"), 0.3, 0.005);
}

TEST(AriPhysics, DrivesTwoAndAHalfMetresInFiveSeconds) {
  // 0.5 m/s for 5 s, then 0: the 1 m/s^2 ramps lose 0.125 m starting and give it back stopping.
  AriPhysics physics(ari(), walled_floor(), {{-3.0, 0.0}, 0.0}, PhysicsConfig{});
  for (int i = 0; i < 100; ++i) {
    physics.command_base(0.5, 0.0);
    run(physics, 0.05);
  }
  for (int i = 0; i < 40; ++i) {
    physics.command_base(0.0, 0.0);
    run(physics, 0.05);
  }
  EXPECT_NEAR(physics.odometry().pose().position.x() + 3.0, 2.5, 0.02);
  EXPECT_NEAR(physics.base_pose().position.x() + 3.0, 2.5, 0.02);
  EXPECT_NEAR(physics.base_pose().position.y(), 0.0, 0.01);
}

TEST(AriPhysics, TurnsInPlace) {
  // 1 rad/s for pi s after a 1 s ramp (1 rad/s / 2.094 rad/s^2 each way): about pi rad.
  AriPhysics physics(ari(), walled_floor(), {{0.0, 0.0}, 0.0}, PhysicsConfig{});
  for (int i = 0; i < 63; ++i) {
    physics.command_base(0.0, 1.0);
    run(physics, 0.05);
  }
  for (int i = 0; i < 30; ++i) {
    physics.command_base(0.0, 0.0);
    run(physics, 0.05);
  }
  EXPECT_NEAR(std::abs(physics.base_pose().theta), 3.15, 0.05);
  EXPECT_NEAR(std::abs(physics.odometry().pose().theta), std::abs(physics.base_pose().theta), 0.02);
  // It turned about the wheel axle, which stayed put.
  EXPECT_LT(physics.base_pose().position.norm(), 0.02);
}

TEST(AriPhysics, StopsAtAWall) {
  // Driving at 1 m/s toward the wall at x = 5.95: the base's front (0.16 m ahead of the axle)
  // stops at the wall's face and stays there.
  AriPhysics physics(ari(), walled_floor(), {{2.0, 0.0}, 0.0}, PhysicsConfig{});
  double furthest = -1e9;
  for (int i = 0; i < 200; ++i) {
    physics.command_base(1.0, 0.0);
    run(physics, 0.05);
    furthest = std::max(furthest, physics.base_pose().position.x());
  }
  EXPECT_LT(furthest + 0.16, 5.95 + 0.01);
  EXPECT_GT(physics.base_pose().position.x() + 0.16, 5.95 - 0.05);
  EXPECT_LT(std::abs(physics.base_linear_mps()), 0.05);
}

TEST(AriPhysics, SameSeedSameRunOtherSeedOtherImuNoise) {
  // One second of driving and turning: the same seed repeats the pose and the IMU bit for bit;
  // another seed changes only the IMU's noise.
  const auto run_with_seed = [](uint64_t seed) {
    PhysicsConfig config;
    config.seed = seed;
    AriPhysics physics(ari(), walled_floor(), {{0.0, 0.0}, 0.0}, config);
    for (int i = 0; i < 20; ++i) {
      physics.command_base(0.3, 0.4);
      run(physics, 0.05);
    }
    return std::make_pair(physics.base_pose(), physics.imu());
  };
  const auto first = run_with_seed(3);
  const auto again = run_with_seed(3);
  const auto other = run_with_seed(4);
  EXPECT_EQ(first.first.position, again.first.position);
  EXPECT_EQ(first.first.theta, again.first.theta);
  EXPECT_EQ(first.second.linear_acceleration_mps2, again.second.linear_acceleration_mps2);
  EXPECT_EQ(first.first.position, other.first.position);
  EXPECT_NE(first.second.angular_velocity_rps, other.second.angular_velocity_rps);
}

}  // namespace
}  // namespace ari_social_sim::physics
