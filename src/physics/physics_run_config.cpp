#include "ari_social_sim/physics/physics_run_config.hpp"

#include <vector>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::physics {

PhysicsRunConfig PhysicsRunConfig::from_yaml(const core::YamlMap& map) {
  PhysicsRunConfig config;
  config.urdf = map.optional<std::string>("urdf", config.urdf);
  config.scene = map.optional<std::string>("scene", config.scene);
  config.world = map.optional<std::string>("world", config.world);
  if (!config.scene.empty() && !config.world.empty()) {
    map.fail("world", "no world when a scene is given (the scene names its world)",
             "'" + config.world + "'");
  }
  if (map.has("initial_pose")) {
    if (!config.scene.empty()) {
      map.fail("initial_pose", "no initial_pose when a scene is given (the scene places ARI)",
               "a pose");
    }
    const std::vector<double> pose = map.required<std::vector<double>>("initial_pose");
    if (pose.size() != 3) {
      map.fail("initial_pose", "[x, y, theta] (m, m, rad)",
               std::to_string(pose.size()) + " numbers");
    }
    config.initial_pose = core::Pose2{{pose[0], pose[1]}, pose[2]};
  }
  const std::string clock = map.optional<std::string>("clock", "own");
  if (clock == "own") {
    config.clock = ClockSource::kOwn;
  } else if (clock == "world") {
    config.clock = ClockSource::kWorld;
  } else {
    map.fail("clock", "own or world", "'" + clock + "'");
  }
  config.real_time_factor =
      map.optional<double>("real_time_factor", config.real_time_factor, core::non_negative());
  config.publish_rate_hz =
      map.optional<double>("publish_rate", config.publish_rate_hz, core::between(1.0, 1000.0));
  config.ground_truth_rate_hz = map.optional<double>(
      "ground_truth_rate", config.ground_truth_rate_hz, core::between(1.0, 1000.0));

  config.cameras_enabled = map.optional<bool>("cameras_enabled", config.cameras_enabled);
  if (map.has("cameras")) {
    config.cameras = map.map("cameras");
  }
  config.mapping = map.optional<bool>("mapping", config.mapping);
  if (map.has("mapping_params")) {
    config.mapping_params = map.map("mapping_params");
  }
  config.map_file = map.optional<std::string>("map_file", config.map_file);

  PhysicsConfig& physics = config.physics;
  physics.step_s = map.optional<double>("step", physics.step_s, {0.0, 0.01, true});
  physics.seed =
      static_cast<uint64_t>(map.optional<int>("seed", 0, core::Bounds{0.0, 2147483647.0, false}));
  physics.imu_rate_hz = map.optional<double>("imu_rate", physics.imu_rate_hz, core::positive());
  physics.imu_noise.gyro_std_rps =
      map.optional<double>("imu_gyro_noise", physics.imu_noise.gyro_std_rps, core::non_negative());
  physics.imu_noise.accel_std_mps2 = map.optional<double>(
      "imu_accel_noise", physics.imu_noise.accel_std_mps2, core::non_negative());
  physics.imu_noise.gyro_bias_std_rps = map.optional<double>(
      "imu_gyro_bias", physics.imu_noise.gyro_bias_std_rps, core::non_negative());
  physics.imu_noise.accel_bias_std_mps2 = map.optional<double>(
      "imu_accel_bias", physics.imu_noise.accel_bias_std_mps2, core::non_negative());
  map.finish();
  try {
    physics.validate();
  } catch (const core::ConfigError& error) {
    throw core::ConfigError(map.source() + ": " + error.what());
  }
  return config;
}

}  // namespace ari_social_sim::physics
