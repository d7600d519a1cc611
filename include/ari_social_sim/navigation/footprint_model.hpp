#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/ari_footprint.hpp"

namespace ari_social_sim::navigation {

/// ARI's footprint as the planner and the metrics see it, in base_footprint (x forward, at the
/// wheel axle at the front of the robot): the rectangle of model::AriFootprint, covered by equal
/// circles along the body axis so that clearance costs are smooth, and the head pan axis, from
/// which the head camera looks.
struct FootprintModel {
  model::AriFootprint rectangle;
  std::vector<double> circle_offsets_x_m;  // circle centres on the body axis
  double circle_radius_m{0.0};             // covers the rectangle's corners
  double head_offset_x_m{-0.2255};         // head_1_joint axis (ari_robot's URDF)

  /// `circle_count` circles, each covering an equal slice of the rectangle's length.
  static FootprintModel covering(const model::AriFootprint& rectangle, int circle_count);

  /// Rectangle outline in base_footprint: corners and points at most `spacing_m` apart.
  std::vector<Eigen::Vector2d> outline(double spacing_m) const;
  /// Distance (m) from `point` to the rectangle placed at `base` (map frame); 0 inside.
  double distance_to(const core::Pose2& base, const Eigen::Vector2d& point) const;
  /// Centre of the rectangle at `base`, in the map frame (ARI's body centre).
  Eigen::Vector2d centre(const core::Pose2& base) const {
    return base.transform(rectangle.centre_local());
  }
};

}  // namespace ari_social_sim::navigation
