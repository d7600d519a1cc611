// PhysicsConfig and PhysicsRunConfig: defaults valid, every bad field named.

#include <gtest/gtest.h>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/physics/physics_run_config.hpp"

namespace ari_social_sim::physics {
namespace {

PhysicsRunConfig read(const std::string& yaml) {
  return PhysicsRunConfig::from_yaml(core::YamlMap::parse(yaml, "/ari_physics_node parameter"));
}

void expect_rejected(const std::string& yaml, const std::vector<std::string>& fragments) {
  try {
    read(yaml);
    FAIL() << "accepted " << yaml;
  } catch (const core::ConfigError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("/ari_physics_node parameter"), std::string::npos) << message;
    for (const std::string& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos) << fragment << " not in " << message;
    }
  }
}

TEST(PhysicsConfig, DefaultsAreAriAndValid) {
  const PhysicsRunConfig config = read("{}");
  EXPECT_DOUBLE_EQ(config.physics.step_s, 0.001);  // 1 kHz, as PAL's Gazebo
  EXPECT_DOUBLE_EQ(config.publish_rate_hz, 50.0);
  EXPECT_EQ(config.clock, ClockSource::kOwn);
  EXPECT_FALSE(config.initial_pose.has_value());
  EXPECT_NO_THROW(config.physics.validate());
}

TEST(PhysicsConfig, ReadsEveryParameter) {
  const PhysicsRunConfig config = read(
      "{world: w.yaml, initial_pose: [1, 2, 0.5], clock: world, real_time_factor: 0, "
      "publish_rate: 100, ground_truth_rate: 50, step: 0.002, seed: 4, imu_rate: 200, "
      "imu_gyro_noise: 0.01, imu_accel_noise: 0.1, imu_gyro_bias: 0.001, imu_accel_bias: 0.01}");
  EXPECT_EQ(config.clock, ClockSource::kWorld);
  EXPECT_DOUBLE_EQ(config.start_pose()->theta, 0.5);
  EXPECT_DOUBLE_EQ(config.physics.step_s, 0.002);
  EXPECT_EQ(config.physics.seed, 4u);
  EXPECT_DOUBLE_EQ(config.physics.imu_noise.accel_bias_std_mps2, 0.01);
}

TEST(PhysicsConfig, NamesEachBadField) {
  expect_rejected("{step: 0.02}", {"step", "0.01"});
  expect_rejected("{clock: wall}", {"clock", "own or world", "wall"});
  expect_rejected("{scene: s.yaml, world: w.yaml}", {"world", "scene"});
  expect_rejected("{scene: s.yaml, initial_pose: [0, 0, 0]}", {"initial_pose"});
  expect_rejected("{initial_pose: [1, 2]}", {"initial_pose", "[x, y, theta]", "2 numbers"});
  expect_rejected("{imu_rate: 5000}", {"imu_rate", "1/step"});
  expect_rejected("{imu_gyro_noise: -1}", {"imu_gyro_noise"});
  expect_rejected("{publsh_rate: 50}", {"publsh_rate"});
}

// Expects `check` to throw core::ConfigError with exactly `message`.
template <class Check>
void expect_message(Check check, const std::string& message) {
  try {
    check();
    ADD_FAILURE() << "accepted; expected " << message;
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(PhysicsConfig, ValidateRefusesABadValueBuiltInCode) {
  PhysicsConfig config;
  config.person.head_centre_height_m = 1.0;
  expect_message([&] { config.validate(); },
                 "PhysicsConfig: person.head_centre_height: expected a height above "
                 "shoulder_height (1.45), got 1");
  config = PhysicsConfig{};
  config.imu_rate_hz = 2000.0;
  expect_message([&] { config.validate(); },
                 "PhysicsConfig: imu_rate: expected a rate at most 1/step (1000 Hz), got 2000");
}

TEST(PhysicsRunConfig, ValidateRefusesABadValueBuiltInCode) {
  PhysicsRunConfig config;
  EXPECT_NO_THROW(config.validate());
  config.initial_pose = std::vector<double>{1.0, 2.0};
  expect_message([&] { config.validate(); },
                 "PhysicsRunConfig: initial_pose: expected [x, y, theta] (m, m, rad), got 2 "
                 "numbers");
  config.initial_pose.reset();
  config.physics.step_s = 0.1;
  expect_message([&] { config.validate(); },
                 "PhysicsRunConfig: step: expected a number (0, 0.01], got 0.1");
}

}  // namespace
}  // namespace ari_social_sim::physics
