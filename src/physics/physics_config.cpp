#include "ari_social_sim/physics/physics_config.hpp"

#include <string>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::physics {
namespace {

void require(bool ok, const std::string& field, const std::string& expectation, double value) {
  if (!ok) {
    throw core::ConfigError("physics config: " + field + ": expected " + expectation + ", got " +
                            std::to_string(value));
  }
}

}  // namespace

void PhysicsConfig::validate() const {
  require(step_s > 0.0 && step_s <= 0.01, "step", "a number in (0, 0.01] s", step_s);
  require(gravity_mps2 >= 0.0, "gravity", "a number >= 0", gravity_mps2);
  require(solver_iterations >= 1 && solver_iterations <= 1000, "solver_iterations",
          "an integer in [1, 1000]", solver_iterations);
  require(wheel_friction >= 0.0, "wheel_friction", "a number >= 0", wheel_friction);
  require(caster_friction >= 0.0, "caster_friction", "a number >= 0", caster_friction);
  require(body_friction >= 0.0, "body_friction", "a number >= 0", body_friction);
  require(joint_position_gain > 0.0 && joint_position_gain <= 1.0, "joint_position_gain",
          "a number in (0, 1]", joint_position_gain);
  require(joint_velocity_gain >= 0.0 && joint_velocity_gain <= 1.0, "joint_velocity_gain",
          "a number in [0, 1]", joint_velocity_gain);
  require(imu_rate_hz > 0.0 && imu_rate_hz <= 1.0 / step_s, "imu_rate",
          "a number in (0, 1/step] Hz", imu_rate_hz);
  require(imu_noise.gyro_std_rps >= 0.0, "imu_gyro_noise", "a number >= 0", imu_noise.gyro_std_rps);
  require(imu_noise.accel_std_mps2 >= 0.0, "imu_accel_noise", "a number >= 0",
          imu_noise.accel_std_mps2);
  require(imu_noise.gyro_bias_std_rps >= 0.0, "imu_gyro_bias", "a number >= 0",
          imu_noise.gyro_bias_std_rps);
  require(imu_noise.accel_bias_std_mps2 >= 0.0, "imu_accel_bias", "a number >= 0",
          imu_noise.accel_bias_std_mps2);
  require(person.body_radius_m > 0.0, "person.body_radius", "a number > 0", person.body_radius_m);
  require(person.head_radius_m > 0.0, "person.head_radius", "a number > 0", person.head_radius_m);
  require(person.shoulder_height_m > 0.0 && person.head_centre_height_m > person.shoulder_height_m,
          "person.head_centre_height", "a height above the shoulders", person.head_centre_height_m);
}

}  // namespace ari_social_sim::physics
