#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>

#include "../frames.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::nodes {

/// map -> odom: identity in 2D mode, where the base pose is exact.
geometry_msgs::TransformStamped map_to_odom(double stamp_s);
/// odom -> base_footprint from ARI's 2D body.
geometry_msgs::TransformStamped odom_to_base(const world::AriSnapshot& ari, double stamp_s);
/// /mobile_base_controller/odom from ARI's 2D body (pose in odom, twist in base_footprint).
nav_msgs::Odometry to_odometry(const world::AriSnapshot& ari, double stamp_s);

}  // namespace ari_social_sim::nodes
