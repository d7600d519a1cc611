// WheelOdometry: dead reckoning from ARI's wheel angles.

#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/physics/wheel_odometry.hpp"

namespace ari_social_sim::physics {
namespace {

TEST(WheelOdometry, StraightLine) {
  // 10 rad on both wheels of radius 0.125 m: 1.25 m along the heading (45 degrees here).
  WheelOdometry odometry({0.125, 0.44}, {{1.0, 2.0}, M_PI / 4});
  odometry.update(0.0, 0.0, 0.0, 0.0);
  odometry.update(10.0, 10.0, 4.0, 4.0);
  EXPECT_NEAR(odometry.pose().position.x(), 1.0 + 1.25 * std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(odometry.pose().position.y(), 2.0 + 1.25 * std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(odometry.linear_mps(), 0.5, 1e-12);
}

TEST(WheelOdometry, QuarterCircle) {
  // Radius 1 m, quarter turn, in 1000 small steps: wheels travel pi/2 x (1 -+ 0.22) m.
  WheelOdometry odometry({0.125, 0.44}, {});
  const double left_total = M_PI / 2 * (1.0 - 0.22) / 0.125;
  const double right_total = M_PI / 2 * (1.0 + 0.22) / 0.125;
  for (int i = 0; i <= 1000; ++i) {
    odometry.update(left_total * i / 1000.0, right_total * i / 1000.0, 0.0, 0.0);
  }
  EXPECT_NEAR(odometry.pose().theta, M_PI / 2, 1e-9);
  EXPECT_NEAR(odometry.pose().position.x(), 1.0, 1e-6);
  EXPECT_NEAR(odometry.pose().position.y(), 1.0, 1e-6);
}

}  // namespace
}  // namespace ari_social_sim::physics
