#include "ari_social_sim/perception/field_of_view.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::perception {

double FieldOfView::bearing_of(const Eigen::Vector2d& point_map) const {
  const Eigen::Vector2d offset = point_map - X_map_sensor.position;
  return core::angle_difference(std::atan2(offset.y(), offset.x()), X_map_sensor.theta);
}

bool FieldOfView::contains(const Eigen::Vector2d& point_map) const {
  return distance_to(point_map) <= range_m && angle_inside(bearing_of(point_map)) >= 0.0;
}

double FieldOfView::angle_inside(double bearing_rad) const {
  return half_angle_rad - std::abs(bearing_rad);
}

}  // namespace ari_social_sim::perception
