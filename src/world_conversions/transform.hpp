#pragma once

#include <geometry_msgs/Transform.h>

#include <Eigen/Geometry>

namespace ari_social_sim::nodes {

/// A tf transform as an isometry (its quaternion normalised).
Eigen::Isometry3d isometry_of(const geometry_msgs::Transform& transform);

}  // namespace ari_social_sim::nodes
