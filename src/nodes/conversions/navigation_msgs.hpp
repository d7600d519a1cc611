#pragma once

#include <geometry_msgs/Pose.h>
#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>

#include <optional>
#include <string>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/navigation/navigator.hpp"

namespace ari_social_sim::nodes {

/// A planar pose from a 3D one: position x, y and the yaw of the quaternion. Empty when the
/// quaternion is not finite or has no length.
std::optional<core::Pose2> planar_pose(const geometry_msgs::Pose& pose);
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
