#include <gtest/gtest.h>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/field_of_view.hpp"

namespace ari_social_sim::perception {
namespace {

using core::deg_to_rad;

TEST(FieldOfView, BearingIsMeasuredFromTheSensorAxis) {
  const FieldOfView fov{{{1.0, 1.0}, core::kPi / 2}, deg_to_rad(31.0), 2.0};
  EXPECT_NEAR(fov.bearing_of({1.0, 2.0}), 0.0, 1e-12);             // straight ahead (+y)
  EXPECT_NEAR(fov.bearing_of({0.0, 1.0}), core::kPi / 2, 1e-12);   // to its left (-x)
  EXPECT_NEAR(fov.bearing_of({2.0, 2.0}), -core::kPi / 4, 1e-12);  // ahead right
  EXPECT_NEAR(fov.distance_to({1.0, 3.0}), 2.0, 1e-12);
}

TEST(FieldOfView, ContainsTheWedgeWithinRange) {
  const FieldOfView fov{{{0.0, 0.0}, 0.0}, deg_to_rad(31.0), 2.0};  // ARI's head camera, 62 deg
  EXPECT_TRUE(fov.contains({1.9, 0.0}));
  EXPECT_FALSE(fov.contains({2.1, 0.0}));  // beyond range
  // tan(30 deg) = 0.577 inside, tan(32 deg) = 0.625 outside.
  EXPECT_TRUE(fov.contains({1.0, 0.577}));
  EXPECT_FALSE(fov.contains({1.0, 0.625}));
  EXPECT_FALSE(fov.contains({-1.0, 0.0}));
  EXPECT_NEAR(fov.angle_inside(deg_to_rad(21.0)), deg_to_rad(10.0), 1e-12);
  EXPECT_NEAR(fov.angle_inside(deg_to_rad(-41.0)), deg_to_rad(-10.0), 1e-12);
}

TEST(FieldOfView, HalfPlaneOfTheFisheye) {
  const FieldOfView fisheye{{{0.0, 0.0}, 0.0}, deg_to_rad(90.0), 10.0};
  EXPECT_TRUE(fisheye.contains({0.01, 5.0}));
  EXPECT_TRUE(fisheye.contains({0.0, -5.0}));  // the edge belongs to the view
  EXPECT_FALSE(fisheye.contains({-0.01, 5.0}));
}

}  // namespace
}  // namespace ari_social_sim::perception
