#include <gtest/gtest.h>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/visibility.hpp"
#include "perception_scenes.hpp"

namespace ari_social_sim::perception {
namespace {

const FieldOfView kFisheye{{{0.0, 0.0}, 0.0}, core::kPi / 2, 10.0};

double fraction(const std::vector<Eigen::Vector2d>& people, size_t target,
                const model::OccupancyGrid* grid = nullptr, const FieldOfView& fov = kFisheye,
                int rays = 100, const std::vector<bool>* seated = nullptr) {
  return visible_fraction(fov, {grid, 50, &people, 0.2, seated}, target, rays);
}

TEST(Visibility, AnOpenViewSeesAll) {
  EXPECT_DOUBLE_EQ(fraction({{3.0, 0.0}}, 0), 1.0);
  EXPECT_DOUBLE_EQ(fraction({{0.1, 0.0}}, 0), 1.0);  // sensor inside the circle
}

TEST(Visibility, APersonStraightInFrontHidesOneBehind) {
  // Same bearing, twice the distance: the front circle (angular radius asin(0.2/2)) covers the
  // whole back one (asin(0.2/4)).
  EXPECT_DOUBLE_EQ(fraction({{2.0, 0.0}, {4.0, 0.0}}, 1), 0.0);
  EXPECT_DOUBLE_EQ(fraction({{2.0, 0.0}, {4.0, 0.0}}, 0), 1.0);
}

TEST(Visibility, HalfHiddenGivesAboutHalf) {
  // The front person shifted sideways by one radius covers the back one's rays whose offset
  // angle is below the front edge: by symmetry of two equal angular widths at the same
  // distance, half of them.
  const double fraction_half = fraction({{3.0, 0.2}, {3.6, 0.0}}, 1);
  // Back circle: half width asin(0.2/3.6) = 3.18 deg at bearing 0; front circle covers bearings
  // atan(0.2/3) +- asin(0.2/3.006) = 3.81 +- 3.81 deg, i.e. 0..7.6 deg: the upper half.
  EXPECT_NEAR(fraction_half, 0.5, 0.02);
}

TEST(Visibility, AWallHidesWhatIsBehindIt) {
  const model::OccupancyGrid grid = test::map_with_wall({2.0, -1.0}, {2.0, 1.0});
  EXPECT_DOUBLE_EQ(fraction({{3.0, 0.0}}, 0, &grid), 0.0);
  EXPECT_DOUBLE_EQ(fraction({{1.5, 0.0}}, 0, &grid), 1.0);  // in front of the wall
  // Past the wall's end at y = 1 (+ up to 5 cm of raster): the rays to (4, 2.1) cross x = 2 at
  // y = 1.05 +- 0.1: about the upper half passes.
  const double edge = fraction({{4.0, 2.1}}, 0, &grid);
  EXPECT_GT(edge, 0.2);
  EXPECT_LT(edge, 0.8);
}

TEST(Visibility, OnlyASeatedPersonIsSeenPastTheMapWithinOneRadiusOfThem) {
  // A wall 0.1 m thick over x = 2.70..2.80, a person at x = 3.05. A ray at u (-1..1) of the
  // person's half width meets the circle at x = 3.05 - 0.2 sqrt(1 - u^2): 2.85 for the centre
  // ray, 3.05 at the rim. A standing person is checked up to there, past the wall: hidden.
  // A seated one up to 0.2 m less, 2.65..2.85: only rays checked past the wall's raster, which
  // starts at about 2.76, are hidden: 3.05 - 0.2 sqrt(1 - u^2) - 0.2 > 2.76 for |u| > 0.9,
  // the outer tenth of the rays.
  const model::OccupancyGrid grid = test::map_with_wall({2.75, -1.0}, {2.75, 1.0});
  const std::vector<bool> standing{false};
  const std::vector<bool> seated{true};
  EXPECT_DOUBLE_EQ(fraction({{3.05, 0.0}}, 0, &grid, kFisheye, 100, &standing), 0.0);
  EXPECT_DOUBLE_EQ(fraction({{3.05, 0.0}}, 0, &grid, kFisheye, 100, nullptr), 0.0);
  EXPECT_NEAR(fraction({{3.05, 0.0}}, 0, &grid, kFisheye, 100, &seated), 0.9, 0.02);
  // Seated 0.5 m behind the wall (circle from x = 3.3, map checked up to 3.1 or more): hidden.
  EXPECT_DOUBLE_EQ(fraction({{3.5, 0.0}}, 0, &grid, kFisheye, 100, &seated), 0.0);
}

TEST(Visibility, RaysOutsideTheWedgeDoNotCount) {
  const FieldOfView narrow{{{0.0, 0.0}, 0.0}, core::deg_to_rad(10.0), 10.0};
  // Centred on the wedge's edge: half of the person is inside.
  const double angle = core::deg_to_rad(10.0);
  EXPECT_NEAR(fraction({{3.0 * std::cos(angle), 3.0 * std::sin(angle)}}, 0, nullptr, narrow), 0.5,
              0.01);
}

}  // namespace
}  // namespace ari_social_sim::perception
