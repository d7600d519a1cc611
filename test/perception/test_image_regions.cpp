#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/image_regions.hpp"

namespace ari_social_sim::perception {
namespace {

TEST(ImageRegions, FisheyeMapsBearingLinearly) {
  const FieldOfView fisheye{{{0.0, 0.0}, 0.0}, core::kPi / 2, 10.0};
  // 45 deg to the left of 180: a quarter of the width from the left edge.
  const ImageRegion left = fisheye_region(
      fisheye, 1.3, {2.0 * std::cos(core::kPi / 4), 2.0 * std::sin(core::kPi / 4)}, 0.2, 1.7);
  EXPECT_NEAR(0.5 * (left.xmin + left.xmax), 0.25, 1e-9);
  // Feet at atan(1.3 / 2) = 33.0 deg below the axis, of a 135 deg vertical span: y = 0.744.
  EXPECT_NEAR(left.ymax, 0.5 + std::atan2(1.3, 2.0) / (0.75 * core::kPi), 1e-9);
  // Top 0.4 m above the camera: atan(0.2) = 11.3 deg above: y = 0.416.
  EXPECT_NEAR(left.ymin, 0.5 - std::atan2(0.4, 2.0) / (0.75 * core::kPi), 1e-9);
}

TEST(ImageRegions, PinholeFaceShrinksWithDistanceAndIsClipped) {
  const FieldOfView camera{{{0.0, 0.0}, 0.0}, core::deg_to_rad(31.0), 2.0};
  const ImageRegion near = pinhole_region(camera, 1.6, {1.0, 0.0}, 1.6, 0.16, 0.22);
  const ImageRegion far = pinhole_region(camera, 1.6, {2.0, 0.0}, 1.6, 0.16, 0.22);
  // Width fraction: (0.16 / depth) / (2 tan 31 deg) = 0.1331 at 1 m, half at 2 m.
  EXPECT_NEAR(near.xmax - near.xmin, 0.16 / (2.0 * std::tan(core::deg_to_rad(31.0))), 1e-9);
  EXPECT_NEAR(far.xmax - far.xmin, 0.5 * (near.xmax - near.xmin), 1e-9);
  EXPECT_NEAR(0.5 * (near.ymin + near.ymax), 0.5, 1e-9);
  // At the left edge of the view, half the face is cut off.
  const double edge = std::tan(core::deg_to_rad(31.0));
  const ImageRegion cut = pinhole_region(camera, 1.6, {1.0, edge}, 1.6, 0.16, 0.22);
  EXPECT_DOUBLE_EQ(cut.xmin, 0.0);
  EXPECT_NEAR(cut.xmax, 0.5 * (near.xmax - near.xmin), 1e-9);
}

}  // namespace
}  // namespace ari_social_sim::perception
