#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/JointState.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <optional>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"
#include "node_support/frames.hpp"

namespace ari_social_sim::nodes {

/// map -> odom: the odom frame's origin in the map. Identity (the default) in 2D mode, where the
/// base pose is exact; in 3D mode what ARI's localisation knows of the odometry's drift.
geometry_msgs::TransformStamped map_to_odom(double stamp_s,
                                            const core::Pose2& odom_in_map = core::Pose2{});
/// odom -> base_footprint: ARI's base as its odometry has it.
geometry_msgs::TransformStamped odom_to_base(const core::Pose2& base_in_odom, double stamp_s);
/// /mobile_base_controller/odom from ARI's 2D body (pose in odom, twist in base_footprint).
nav_msgs::Odometry to_odometry(const world::AriSnapshot& ari, double stamp_s);
/// /joint_states of ARI's 2D body, as ARI's joint_state_controller reports every joint: the head
/// pans (its tilt stays level), the rest stays at rest (kJointsAtRest).
sensor_msgs::JointState joint_states_of(const world::AriSnapshot& ari, double stamp_s);
/// The head_1_joint position a /head_controller/command asks for (its last point's), or nothing
/// when it names none.
std::optional<double> head_pan_target(const trajectory_msgs::JointTrajectory& command);

}  // namespace ari_social_sim::nodes
