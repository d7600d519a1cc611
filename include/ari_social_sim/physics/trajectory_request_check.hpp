#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/physics/trajectory_controller.hpp"

namespace ari_social_sim::physics {

/// Longest time a trajectory request may name (a point's time_from_start, goal_time_tolerance):
/// an hour, longer than any scenario runs; a goal for 1e9 s would never end.
constexpr double kMaxTrajectoryTimeS = 3600.0;
/// Largest acceleration a trajectory point may give. The URDF gives ARI's joints no acceleration
/// limit; this is far above what its servos follow (3 rad/s in 3 ms) and keeps the quintic
/// splines' coefficients finite.
constexpr double kMaxJointAccelerationRps2 = 1000.0;

/// Checks every number of a trajectory request whose joint names the controller has accepted,
/// before anything moves, in the request's own order; throws TrajectoryRejected (INVALID_GOAL)
/// naming the field, what it expects and what it got, e.g.
///   `head_controller: goal_tolerance[0].position: expected -1 (none), 0 (the default) or a
///   finite number > 0, got nan`,
///   `head_controller: trajectory.points[0].velocities[1] (head_2_joint): expected a finite
///   number [-3, 3] rad/s, got 1e+308`.
/// Positions must lie within the joint's limits, velocities within its velocity limit,
/// accelerations within kMaxJointAccelerationRps2, times within [0, kMaxTrajectoryTimeS] and
/// increasing strictly; tolerances must name the controller's joints.
/// `bounds_by_column[c]` are the limits of `request.joint_names[c]`; `trajectory_field` is
/// "trajectory." for a FollowJointTrajectory goal, "" for a /command message.
void check_trajectory_request(const TrajectoryRequest& request, const ControllerSpec& spec,
                              const std::vector<JointBounds>& bounds_by_column,
                              const std::string& trajectory_field);

}  // namespace ari_social_sim::physics
