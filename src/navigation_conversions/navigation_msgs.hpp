#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Path.h>
#include <trajectory_msgs/JointTrajectory.h>
#include <visualization_msgs/MarkerArray.h>

#include <optional>
#include <string>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/navigation/goal_request.hpp"
#include "ari_social_sim/navigation/navigation_session.hpp"
#include "ari_social_sim/navigation/navigator.hpp"

namespace ari_social_sim::nodes {

/// A goal pose in the map frame as a move_base client sends it (scenario_node): the heading as a
/// rotation about z.
geometry_msgs::PoseStamped map_goal_msg(const core::Pose2& goal, const ros::Time& stamp);
/// A goal pose as the navigation core checks it (navigation::planar_goal).
navigation::PoseGoalRequest goal_request_of(const geometry_msgs::PoseStamped& goal);
/// What social_mpc_node publishes for a command: the twist (/mobile_base_controller/cmd_vel) and,
/// unless the command stops the base, the head's pan target with a level tilt
/// (/head_controller/command), to be reached within one control period of `control_rate_hz`.
struct CommandMessages {
  geometry_msgs::Twist twist;
  std::optional<trajectory_msgs::JointTrajectory> head;
};
CommandMessages to_msgs(const navigation::BaseCommand& command, const ros::Time& stamp,
                        double control_rate_hz);
/// The MPC's predicted base_footprint poses as a path in `frame_id`.
nav_msgs::Path plan_msg(const navigation::MpcSolution& plan, const std::string& frame_id,
                        const ros::Time& stamp);
/// What rviz shows of the navigator: the goal pose and look-at point, the predicted footprint
/// along the plan, each person's personal-space edge, each group's o-space circle (green for the
/// group joined) and the social cost density around ARI as coloured squares. Starts with
/// DELETEALL; empty apart from it when no goal is active.
visualization_msgs::MarkerArray navigation_markers(const navigation::Navigator& navigator,
                                                   bool active, const std::string& frame_id);

}  // namespace ari_social_sim::nodes
