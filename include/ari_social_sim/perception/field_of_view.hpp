#pragma once

#include <Eigen/Core>

#include "ari_social_sim/core/pose2.hpp"

namespace ari_social_sim::perception {

/// A sensor's planar field of view: a wedge of `half_angle_rad` either side of the sensor's x
/// axis, out to `range_m`, from the sensor pose in the map frame.
struct FieldOfView {
  core::Pose2 X_map_sensor;
  double half_angle_rad{0.0};
  double range_m{0.0};

  /// Angle (rad, counter-clockwise, in [-pi, pi)) of a map point seen from the sensor's axis.
  double bearing_of(const Eigen::Vector2d& point_map) const;
  double distance_to(const Eigen::Vector2d& point_map) const {
    return (point_map - X_map_sensor.position).norm();
  }
  /// True when the point is within range and inside the wedge (edges included).
  bool contains(const Eigen::Vector2d& point_map) const;
  /// Angle (rad) from the bearing to the nearer edge of the wedge; negative outside it.
  double angle_inside(double bearing_rad) const;
};

}  // namespace ari_social_sim::perception
