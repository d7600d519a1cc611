// ImuModel: specific force and angular rate in the sensor frame, seeded noise.

#include <gtest/gtest.h>

#include "ari_social_sim/physics/imu_model.hpp"

namespace ari_social_sim::physics {
namespace {

TEST(ImuModel, AtRestMeasuresGravityUp) {
  ImuModel imu(ImuNoise{0.0, 0.0, 0.0, 0.0}, 9.81, core::Rng(1));
  const ImuReading reading = imu.measure(0.01, Eigen::Isometry3d::Identity(),
                                         Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  EXPECT_TRUE(reading.linear_acceleration_mps2.isApprox(Eigen::Vector3d(0, 0, 9.81)));
}

TEST(ImuModel, RotatesIntoTheSensorFrameAndDifferentiatesVelocity) {
  // A sensor pitched 90 degrees (its x axis pointing down) accelerating at 1 m/s^2 along map x:
  // specific force (1, 0, 9.81) in map is (-9.81, 0, 1) in the sensor; yaw rate 0.5 rad/s about
  // map z is -0.5... about the sensor's x (which points down).
  ImuModel imu(ImuNoise{0.0, 0.0, 0.0, 0.0}, 9.81, core::Rng(1));
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  imu.measure(0.0, X, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 0.5));
  const ImuReading reading =
      imu.measure(0.01, X, Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d(0, 0, 0.5));
  EXPECT_TRUE(reading.linear_acceleration_mps2.isApprox(Eigen::Vector3d(-9.81, 0, 1.0), 1e-9))
      << reading.linear_acceleration_mps2.transpose();
  EXPECT_TRUE(reading.angular_velocity_rps.isApprox(Eigen::Vector3d(-0.5, 0, 0), 1e-9))
      << reading.angular_velocity_rps.transpose();
}

TEST(ImuModel, NoiseHasItsStandardDeviationAndItsSeed) {
  // 20 000 readings at rest: the gyro's sample standard deviation is 0.002 rad/s within 2%.
  const ImuNoise noise{0.002, 0.02, 0.0, 0.0};
  ImuModel imu(noise, 9.81, core::Rng(7));
  ImuModel twin(noise, 9.81, core::Rng(7));
  ImuModel other(noise, 9.81, core::Rng(8));
  double sum = 0.0;
  double sum_sq = 0.0;
  const int n = 20000;
  bool same = true;
  bool differs = false;
  for (int i = 0; i < n; ++i) {
    const Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    const double t = 0.01 * i;
    const double x = imu.measure(t, X, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero())
                         .angular_velocity_rps.x();
    same &= twin.measure(t, X, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero())
                .angular_velocity_rps.x() == x;
    differs |= other.measure(t, X, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero())
                   .angular_velocity_rps.x() != x;
    sum += x;
    sum_sq += x * x;
  }
  const double mean = sum / n;
  EXPECT_NEAR(std::sqrt(sum_sq / n - mean * mean), 0.002, 0.002 * 0.02);
  EXPECT_TRUE(same);
  EXPECT_TRUE(differs);
}

}  // namespace
}  // namespace ari_social_sim::physics
