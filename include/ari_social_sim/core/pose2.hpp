#pragma once

#include <Eigen/Core>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::core {

/// Largest heading (rad, either sign) a file or request may give. Box2D keeps angles as float,
/// and an angle beyond float's range would turn every body it touches into NaN; a million radians
/// is far beyond any heading a caller means, yet still within float's range.
constexpr double kMaxHeadingRad = 1e6;

/// A planar pose: position (m) and heading (rad, counter-clockwise from +x) in one frame.
struct Pose2 {
  Eigen::Vector2d position{Eigen::Vector2d::Zero()};
  double theta{0.0};

  /// Unit vector of the heading.
  Eigen::Vector2d heading() const { return {std::cos(theta), std::sin(theta)}; }
  /// A point given in this pose's frame, expressed in the parent frame.
  Eigen::Vector2d transform(const Eigen::Vector2d& point_local) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return position + Eigen::Vector2d(c * point_local.x() - s * point_local.y(),
                                      s * point_local.x() + c * point_local.y());
  }
  /// This pose expressed in `frame`, both given in the same parent frame:
  /// X_frame_this = X_parent_frame^-1 * X_parent_this.
  Pose2 relative_to(const Pose2& frame) const {
    const Eigen::Vector2d offset = position - frame.position;
    const double c = std::cos(frame.theta), s = std::sin(frame.theta);
    return {{c * offset.x() + s * offset.y(), -s * offset.x() + c * offset.y()},
            wrap_angle(theta - frame.theta)};
  }

  /// The pose as files write it (config_fields.hpp): `position: [x, y]`, required, and
  /// `orientation`. An entry that is a pose lists these among its own fields.
  template <class V>
  void visit(V& v) {
    v.field(required("position"), position, "m, [x, y] in the map frame");
    v.field("orientation", theta, "rad, heading in the map frame, counter-clockwise from +x",
            between(-kMaxHeadingRad, kMaxHeadingRad));
  }
};

}  // namespace ari_social_sim::core
