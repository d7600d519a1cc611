// JointTrajectory: ros_controllers' spline segments between waypoints.

#include <gtest/gtest.h>

#include "ari_social_sim/physics/joint_trajectory.hpp"

namespace ari_social_sim::physics {
namespace {

JointSetpoint rest(double q) {
  return JointSetpoint::at_rest({q});
}

TEST(JointTrajectory, PositionsOnlyInterpolateLinearly) {
  // 0 -> 1 rad over 2 s: halfway at 1 s, constant 0.5 rad/s.
  const JointTrajectory trajectory(rest(0.0), 0.0, 0.0, {{{1.0}, {}, {}, 2.0}});
  EXPECT_DOUBLE_EQ(trajectory.sample(1.0).positions[0], 0.5);
  EXPECT_DOUBLE_EQ(trajectory.sample(1.0).velocities[0], 0.5);
  EXPECT_DOUBLE_EQ(trajectory.end_time_s(), 2.0);
}

TEST(JointTrajectory, VelocitiesMakeACubic) {
  // Rest to rest over T = 2 s, distance 1: the cubic peaks at 1.5 * 1 / 2 = 0.75 rad/s halfway.
  const JointTrajectory trajectory(rest(0.0), 0.0, 0.0, {{{1.0}, {0.0}, {}, 2.0}});
  EXPECT_NEAR(trajectory.sample(1.0).positions[0], 0.5, 1e-12);
  EXPECT_NEAR(trajectory.sample(1.0).velocities[0], 0.75, 1e-12);
  EXPECT_NEAR(trajectory.sample(2.0 - 1e-9).velocities[0], 0.0, 1e-6);
}

TEST(JointTrajectory, AccelerationsMakeAQuintic) {
  // Rest to rest with zero accelerations: peak speed 15/8 * 1 / 2 = 0.9375 rad/s halfway and no
  // acceleration at either end.
  const JointTrajectory trajectory(rest(0.0), 0.0, 0.0, {{{1.0}, {0.0}, {0.0}, 2.0}});
  EXPECT_NEAR(trajectory.sample(1.0).velocities[0], 0.9375, 1e-12);
  EXPECT_NEAR(trajectory.sample(0.0).accelerations[0], 0.0, 1e-12);
  EXPECT_NEAR(trajectory.sample(2.0 - 1e-9).accelerations[0], 0.0, 1e-6);
}

TEST(JointTrajectory, SeveralWaypointsPassThroughEach) {
  const JointTrajectory trajectory(rest(0.0), 10.0, 10.0,
                                   {{{1.0}, {}, {}, 1.0}, {{-1.0}, {}, {}, 3.0}});
  EXPECT_NEAR(trajectory.sample(11.0).positions[0], 1.0, 1e-12);
  EXPECT_NEAR(trajectory.sample(12.0).positions[0], 0.0, 1e-12);  // halfway from 1 to -1
  // After the end: the last waypoint, at rest.
  EXPECT_DOUBLE_EQ(trajectory.sample(20.0).positions[0], -1.0);
  EXPECT_DOUBLE_EQ(trajectory.sample(20.0).velocities[0], 0.0);
  // Before the start: the start state.
  EXPECT_DOUBLE_EQ(trajectory.sample(5.0).positions[0], 0.0);
}

TEST(JointTrajectory, WaypointAtTheStartIsAStep) {
  const JointTrajectory trajectory(rest(0.0), 4.0, 4.0, {{{0.7}, {}, {}, 0.0}});
  EXPECT_DOUBLE_EQ(trajectory.sample(4.0).positions[0], 0.7);
}

TEST(JointTrajectory, PastWaypointsArePassedOver) {
  // Points timed from t = 0, spliced in at t = 1.5: the 1 s point is gone, the 2 s point is
  // reached from the start state in the remaining 0.5 s.
  const JointTrajectory trajectory(rest(0.0), 1.5, 0.0,
                                   {{{5.0}, {}, {}, 1.0}, {{1.0}, {}, {}, 2.0}});
  EXPECT_NEAR(trajectory.sample(1.75).positions[0], 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(trajectory.end_time_s(), 2.0);
}

}  // namespace
}  // namespace ari_social_sim::physics
