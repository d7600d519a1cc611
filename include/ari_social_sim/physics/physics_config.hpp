#pragma once

#include <cstdint>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/model/ari_limits.hpp"
#include "ari_social_sim/physics/imu_model.hpp"
#include "ari_social_sim/physics/person_shape.hpp"

namespace ari_social_sim::physics {

/// Everything AriPhysics needs besides the robot model and the world. Defaults are ARI's
/// (ari_robot) or, where it is silent, the project's own, explained in docs/physics.md.
struct PhysicsConfig {
  double step_s{0.001};  // PAL's Gazebo runs physics and ros_control at 1 kHz
  double gravity_mps2{9.81};
  int solver_iterations{6};
  double wheel_friction{1.0};
  double caster_friction{0.0};
  double body_friction{0.3};
  double joint_position_gain{0.2};
  double joint_velocity_gain{1.0};
  model::AriLimits base_limits;  // mobile_base_controller's limits and cmd_vel timeout
  double imu_rate_hz{100.0};
  ImuNoise imu_noise;
  PersonShapeConfig person;
  uint64_t seed{0};

  /// Also ari_physics_node's parameters of the same names.
  template <class V>
  void visit(V& v) {
    v.field("step", step_s, "s of sim time per physics step", core::Bounds{0.0, 0.01, true});
    v.field("seed", seed, "the IMU's and the cameras' noise",
            core::Bounds{0.0, 2147483647.0, false});
    v.field("gravity", gravity_mps2, "m/s^2", core::non_negative());
    // Fewer let a parked ARI creep (docs/physics.md).
    v.field("solver_iterations", solver_iterations, "contact solver iterations per step, at most",
            core::between(1.0, 1000.0));
    // Bullet multiplies the two bodies' friction coefficients.
    v.field("wheel_friction", wheel_friction, "contact friction of the drive wheels",
            core::non_negative());
    v.field("caster_friction", caster_friction,
            "of the casters: 0 stands in for swivel casters that never resist turning",
            core::non_negative());
    v.field("body_friction", body_friction, "of ARI's shell, walls, furniture and people",
            core::non_negative());
    // Bullet's multibody joint motor; effort is capped at the URDF's effort limit.
    v.field("joint_position_gain", joint_position_gain,
            "share of a joint servo's position error corrected per step",
            core::Bounds{0.0, 1.0, true});
    v.field("joint_velocity_gain", joint_velocity_gain,
            "share of a joint servo's velocity error corrected per step", core::between(0.0, 1.0));
    v.field("imu_rate", imu_rate_hz, "Hz of /torso_front_camera/imu", core::positive());
    v.rule("imu_rate", imu_rate_hz <= 1.0 / step_s,
           "a rate at most 1/step (" + core::number_text(1.0 / step_s) + " Hz)",
           core::number_text(imu_rate_hz));
    v.field("imu_gyro_noise", imu_noise.gyro_std_rps, "rad/s, standard deviation",
            core::non_negative());
    v.field("imu_accel_noise", imu_noise.accel_std_mps2, "m/s^2, standard deviation",
            core::non_negative());
    v.field("imu_gyro_bias", imu_noise.gyro_bias_std_rps,
            "rad/s, standard deviation of the constant bias drawn per axis at start",
            core::non_negative());
    v.field("imu_accel_bias", imu_noise.accel_bias_std_mps2,
            "m/s^2, standard deviation of the constant bias drawn per axis at start",
            core::non_negative());
    v.section("person", person,
              "the person-shaped bodies standing in for the 2D world's humans: a cylinder from "
              "the floor to the shoulders, a sphere for the head");
  }

  /// Throws core::ConfigError naming the first field outside what visit allows.
  void validate() const;
};

}  // namespace ari_social_sim::physics
