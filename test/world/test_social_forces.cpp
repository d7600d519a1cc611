#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/world/social_forces.hpp"
#include "ari_social_sim/world/step_motion.hpp"

namespace ari_social_sim::world {
namespace {

using Eigen::Vector2d;
using social_forces::Positions;

constexpr double kTol = 1e-9;

void expect_vector(const Vector2d& actual, double x, double y, double tol = kTol) {
  EXPECT_NEAR(actual.x(), x, tol);
  EXPECT_NEAR(actual.y(), y, tol);
}

TEST(SocialForces, Eq3_5GoalForceHasUnitMagnitudeBeyondGoalDistance) {
  // Goal 5 m away along (0.6, 0.8): min(1, 5 / 0.5) = 1.
  expect_vector(social_forces::goal_force({0, 0}, {3, 4}, 0.5), 0.6, 0.8);
}

TEST(SocialForces, Eq3_5GoalForceFadesLinearlyInsideGoalDistance) {
  // Goal 0.25 m away: min(1, 0.25 / 0.5) = 0.5 times the unit direction (0.6, 0.8).
  expect_vector(social_forces::goal_force({0, 0}, {0.15, 0.2}, 0.5), 0.3, 0.4);
  expect_vector(social_forces::goal_force({1, 1}, {1, 1}, 0.5), 0.0, 0.0);
}

TEST(SocialForces, Eq3_6And3_7RepulsionFromAgentsInsidePersonalArea) {
  // Inside Delta_p = 0.8: (0.3, 0) and (0, 0.4); (2, 0) is outside and ignored.
  // R = (0.3, 0.4), |R| = 0.5, d_min = 0.3, (0.8 - 0.3)^2 = 0.25: f = -0.25 (0.6, 0.8).
  const Positions others{{0.3, 0.0}, {0.0, 0.4}, {2.0, 0.0}};
  expect_vector(social_forces::repulsion_force({0, 0}, others, 0.8), -0.15, -0.2);
}

TEST(SocialForces, Eq3_6RepulsionIsZeroWithNobodyClose) {
  expect_vector(social_forces::repulsion_force({0, 0}, {{1.0, 0.0}}, 0.8), 0.0, 0.0);
}

TEST(SocialForces, Eq3_2TurnsTowardMovementThenGoalOrientation) {
  // 2 m from the goal (> Delta_G = 0.5): toward the movement direction pi/2.
  EXPECT_NEAR(social_forces::navigation_rotation(0.0, M_PI / 2, 3 * M_PI / 4, 2.0, 0.5), M_PI / 2,
              kTol);
  // 0.3 m from the goal: toward the goal orientation 3 pi / 4.
  EXPECT_NEAR(social_forces::navigation_rotation(0.0, M_PI / 2, 3 * M_PI / 4, 0.3, 0.5),
              3 * M_PI / 4, kTol);
  // The shorter way round: from 3 rad to -3 rad is +0.283 rad, not -6.
  EXPECT_NEAR(social_forces::navigation_rotation(3.0, -3.0, 0.0, 2.0, 0.5), 2 * M_PI - 6.0, kTol);
}

TEST(SocialForces, Eq3_3And3_4StepAlongTheForceWithinMaxSpeed) {
  HumanMotionParams params;  // walking 1.0 m/s, max 1.3 m/s, turn gain 4 /s
  // Unit force: eta f / dt = 1.0 m/s * (0.6, 0.8).
  expect_vector(step_motion({0.6, 0.8}, params).velocity_mps, 0.6, 0.8);
  // |f| = 5 would walk at 5 m/s: capped at 1.3 m/s along (0.6, 0.8).
  expect_vector(step_motion({3.0, 4.0}, params).velocity_mps, 0.78, 1.04);
  // Rotation step min(1, 4 * 0.05) = 0.2 of the remaining 1 rad.
  EXPECT_NEAR(rotation_step(1.0, params, 0.05), 0.2, kTol);
  // A step longer than the time constant turns all the way, never past it.
  EXPECT_NEAR(rotation_step(1.0, params, 0.5), 1.0, kTol);
}

TEST(SocialForces, Eq3_13LocalCentreIncludesTheAgent) {
  // (0,0), (2,0), (0,2): centre (2/3, 2/3).
  expect_vector(social_forces::local_group_centre({0, 0}, {{2, 0}, {0, 2}}), 2.0 / 3, 2.0 / 3);
}

TEST(SocialForces, Eq3_14MeanDistanceToCentre) {
  // |p - c| = sqrt(8)/3 = 0.942809; |(2,0) - c| = |(0,2) - c| = sqrt(20)/3 = 1.490712;
  // m = (0.942809 + 2 * 1.490712) / 3 = 1.308078.
  const Vector2d c(2.0 / 3, 2.0 / 3);
  EXPECT_NEAR(social_forces::mean_distance_to_centre({0, 0}, {{2, 0}, {0, 2}}, c),
              (std::sqrt(8.0) + 2 * std::sqrt(20.0)) / 9.0, kTol);
}

TEST(SocialForces, Eq3_15EqualityForcePushesACloseAgentOut) {
  // m / |c - p| = 1.308078 / 0.942809 = 1.387426: f = (1 - 1.387426)(2/3, 2/3) = -0.258284 each.
  const double m = (std::sqrt(8.0) + 2 * std::sqrt(20.0)) / 9.0;
  const double scale = (1.0 - m / (std::sqrt(8.0) / 3.0)) * 2.0 / 3.0;
  expect_vector(social_forces::equality_force({0, 0}, {{2, 0}, {0, 2}}), scale, scale);
  EXPECT_NEAR(scale, -0.258284, 1e-6);
  // Alone in its social space: no equality force.
  expect_vector(social_forces::equality_force({0, 0}, {}), 0.0, 0.0);
}

TEST(SocialForces, Eq3_16EqualityOrientationSumsDirectionsToNeighbours) {
  expect_vector(social_forces::equality_orientation({1, 1}, {{3, 1}, {1, 4}}), 2.0, 3.0);
}

TEST(SocialForces, Eq3_17CohesionPullsOntoTheOspaceCircle) {
  // p = (3, 0), o = (0, 0), s = 1, N_a = 3, N_s = 1: alpha = 3 / 2,
  // f = 1.5 (1 - 1/3) (-3, 0) = (-3, 0).
  expect_vector(social_forces::cohesion_force({3, 0}, {0, 0}, 1.0, 3, 1), -3.0, 0.0);
  // Inside the circle it pushes out: p = (0.5, 0), alpha = 1: (1 - 2)(-0.5, 0) = (0.5, 0).
  expect_vector(social_forces::cohesion_force({0.5, 0}, {0, 0}, 1.0, 2, 1), 0.5, 0.0);
  // On the circle it vanishes.
  expect_vector(social_forces::cohesion_force({0, 1}, {0, 0}, 1.0, 3, 2), 0.0, 0.0);
}

TEST(SocialForces, Eq3_18CohesionOrientationSumsDirectionsToAllMembers) {
  expect_vector(social_forces::cohesion_orientation({0, 0}, {{1, 0}, {-1, 2}, {0, -1}}), 0.0, 1.0);
}

}  // namespace
}  // namespace ari_social_sim::world
