#include "joint_trajectory.hpp"

namespace ari_social_sim::nodes {
namespace {

std::vector<physics::JointTolerance> from_msg(const std::vector<JointTolerance>& tolerances) {
  std::vector<physics::JointTolerance> out;
  out.reserve(tolerances.size());
  for (const JointTolerance& tolerance : tolerances) {
    out.push_back({tolerance.name, tolerance.position, tolerance.velocity, tolerance.acceleration});
  }
  return out;
}

}  // namespace

physics::TrajectoryRequest from_msg(const trajectory_msgs::JointTrajectory& trajectory) {
  physics::TrajectoryRequest request;
  request.joint_names = trajectory.joint_names;
  request.start_time_s = trajectory.header.stamp.toSec();
  for (const trajectory_msgs::JointTrajectoryPoint& point : trajectory.points) {
    request.points.push_back(
        {point.positions, point.velocities, point.accelerations, point.time_from_start.toSec()});
  }
  return request;
}

physics::TrajectoryRequest from_msg(const FollowJointTrajectoryGoal& goal) {
  physics::TrajectoryRequest request = from_msg(goal.trajectory);
  request.path_tolerance = from_msg(goal.path_tolerance);
  request.goal_tolerance = from_msg(goal.goal_tolerance);
  request.goal_time_tolerance_s = goal.goal_time_tolerance.toSec();
  return request;
}

trajectory_msgs::JointTrajectoryPoint to_msg(const physics::JointSetpoint& setpoint) {
  trajectory_msgs::JointTrajectoryPoint point;
  point.positions = setpoint.positions;
  point.velocities = setpoint.velocities;
  point.accelerations = setpoint.accelerations;
  return point;
}

}  // namespace ari_social_sim::nodes
