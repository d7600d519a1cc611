#pragma once

#include <Eigen/Geometry>

#include "ari_social_sim/core/rng.hpp"

namespace ari_social_sim::physics {

/// Noise of the torso IMU (white Gaussian, per axis). The defaults are of the order of a
/// consumer MEMS IMU such as the D435i's BMI055 at 100 Hz.
struct ImuNoise {
  double gyro_std_rps{0.002};     // rad/s
  double accel_std_mps2{0.02};    // m/s^2
  double gyro_bias_std_rps{0.0};  // rad/s, one constant bias per axis drawn at start
  double accel_bias_std_mps2{0.0};
};

/// One reading in the IMU's frame: angular velocity (rad/s) and specific force (m/s^2; +9.81 up
/// when at rest, the convention of sensor_msgs/Imu).
struct ImuReading {
  double time_s{0.0};
  Eigen::Vector3d angular_velocity_rps{Eigen::Vector3d::Zero()};
  Eigen::Vector3d linear_acceleration_mps2{Eigen::Vector3d::Zero()};
};

/// An IMU rigidly mounted on a body: differentiates the mount point's velocity between readings,
/// removes gravity, rotates both into the sensor frame and adds seeded noise.
class ImuModel {
 public:
  ImuModel(const ImuNoise& noise, double gravity_mps2, core::Rng rng);

  /// `X_world_imu`: the sensor's pose; `velocity_world` and `angular_velocity_world`: the mount
  /// point's linear (m/s) and the body's angular (rad/s) velocity, world frame.
  ImuReading measure(double time_s, const Eigen::Isometry3d& X_world_imu,
                     const Eigen::Vector3d& velocity_world,
                     const Eigen::Vector3d& angular_velocity_world);

 private:
  ImuNoise noise_;
  Eigen::Vector3d gravity_world_;
  core::Rng rng_;
  Eigen::Vector3d gyro_bias_;
  Eigen::Vector3d accel_bias_;
  bool has_previous_{false};
  double previous_time_s_{0.0};
  Eigen::Vector3d previous_velocity_{Eigen::Vector3d::Zero()};
};

}  // namespace ari_social_sim::physics
