#include "ari_social_sim/physics/imu_model.hpp"

namespace ari_social_sim::physics {
namespace {

Eigen::Vector3d gaussian(core::Rng& rng, double stddev) {
  return {rng.normal(0.0, stddev), rng.normal(0.0, stddev), rng.normal(0.0, stddev)};
}

}  // namespace

ImuModel::ImuModel(const ImuNoise& noise, double gravity_mps2, core::Rng rng)
    : noise_(noise), gravity_world_(0.0, 0.0, -gravity_mps2), rng_(rng) {
  gyro_bias_ = gaussian(rng_, noise_.gyro_bias_std_rps);
  accel_bias_ = gaussian(rng_, noise_.accel_bias_std_mps2);
}

ImuReading ImuModel::measure(double time_s, const Eigen::Isometry3d& X_world_imu,
                             const Eigen::Vector3d& velocity_world,
                             const Eigen::Vector3d& angular_velocity_world) {
  Eigen::Vector3d acceleration_world = Eigen::Vector3d::Zero();
  if (has_previous_ && time_s > previous_time_s_) {
    acceleration_world = (velocity_world - previous_velocity_) / (time_s - previous_time_s_);
  }
  has_previous_ = true;
  previous_time_s_ = time_s;
  previous_velocity_ = velocity_world;

  const Eigen::Matrix3d R_imu_world = X_world_imu.linear().transpose();
  ImuReading reading;
  reading.time_s = time_s;
  reading.angular_velocity_rps =
      R_imu_world * angular_velocity_world + gyro_bias_ + gaussian(rng_, noise_.gyro_std_rps);
  // An accelerometer measures specific force: acceleration minus gravity.
  reading.linear_acceleration_mps2 = R_imu_world * (acceleration_world - gravity_world_) +
                                     accel_bias_ + gaussian(rng_, noise_.accel_std_mps2);
  return reading;
}

}  // namespace ari_social_sim::physics
