#pragma once

#include <Eigen/Geometry>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/physics/ari_physics.hpp"

namespace ari_social_sim::nodes {

/// A planar pose as a 3D one: on the ground (z = 0), turned about z.
Eigen::Isometry3d planar(const core::Pose2& pose);

/// The odom frame in the map as a localised robot knows it: the true planar base pose composed
/// with the inverse of the wheel odometry. The wheels slip (a fast turn on the spot can cost a
/// metre), and ARI's own localisation corrects for it; this stands in for that localisation,
/// without its error.
core::Pose2 odom_in_map(const physics::AriPhysics& physics);

}  // namespace ari_social_sim::nodes
