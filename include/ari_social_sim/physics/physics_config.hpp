#pragma once

#include <cstdint>

#include "ari_social_sim/model/ari_limits.hpp"
#include "ari_social_sim/physics/imu_model.hpp"
#include "ari_social_sim/physics/person_shape.hpp"

namespace ari_social_sim::physics {

/// Everything AriPhysics needs besides the robot model and the world. Defaults are ARI's
/// (ari_robot) or, where it is silent, the project's own, explained in docs/physics.md.
struct PhysicsConfig {
  double step_s{0.001};  // s; PAL's Gazebo runs physics and ros_control at 1 kHz
  double gravity_mps2{9.81};
  int solver_iterations{6};  // at most, per step; fewer let a parked ARI creep (docs/physics.md)
  // Contact friction coefficients (Bullet multiplies the two bodies' values).
  double wheel_friction{1.0};
  double caster_friction{0.0};  // stands in for swivel casters that never resist turning
  double body_friction{0.3};    // ARI's shell, walls, furniture, people
  // Joint servos (Bullet's multibody joint motor): the share of the position error and of the
  // velocity error corrected per step. Effort is capped at the URDF's effort limit.
  double joint_position_gain{0.2};
  double joint_velocity_gain{1.0};
  model::AriLimits base_limits;  // mobile_base_controller's limits and cmd_vel timeout
  double imu_rate_hz{100.0};
  ImuNoise imu_noise;
  PersonShapeConfig person;
  uint64_t seed{0};  // the IMU's noise

  /// Throws core::ConfigError naming the first field out of its range.
  void validate() const;
};

}  // namespace ari_social_sim::physics
