#pragma once

#include <trajectory_msgs/JointTrajectory.h>

#include "ari_social_sim/FollowJointTrajectoryGoal.h"
#include "ari_social_sim/physics/trajectory_controller.hpp"

namespace ari_social_sim::nodes {

/// A /command message: its points timed from header.stamp (0 = on receipt), no tolerances.
physics::TrajectoryRequest from_msg(const trajectory_msgs::JointTrajectory& trajectory);
/// A FollowJointTrajectory goal: the trajectory with its path and goal tolerances.
physics::TrajectoryRequest from_msg(const FollowJointTrajectoryGoal& goal);
/// A setpoint as a trajectory point (time_from_start 0).
trajectory_msgs::JointTrajectoryPoint to_msg(const physics::JointSetpoint& setpoint);

}  // namespace ari_social_sim::nodes
