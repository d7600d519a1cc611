#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/navigation/goal_request.hpp"
#include "ari_social_sim/navigation/navigator.hpp"

namespace ari_social_sim::nodes {

/// A goal pose as the navigation core checks it (navigation::planar_goal).
navigation::PoseGoalRequest goal_request_of(const geometry_msgs::PoseStamped& goal);
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
