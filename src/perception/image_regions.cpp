#include "ari_social_sim/perception/image_regions.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::perception {
namespace {

constexpr double kAspect = 0.75;  // image height / width

ImageRegion clipped(double xmin, double ymin, double xmax, double ymax) {
  return {std::clamp(xmin, 0.0, 1.0), std::clamp(ymin, 0.0, 1.0), std::clamp(xmax, 0.0, 1.0),
          std::clamp(ymax, 0.0, 1.0)};
}

}  // namespace

ImageRegion fisheye_region(const FieldOfView& camera, double camera_height_m,
                           const Eigen::Vector2d& centre_map, double radius_m, double top_m) {
  const double distance = std::max(camera.distance_to(centre_map), radius_m);
  const double bearing = camera.bearing_of(centre_map);
  const double half_width = std::asin(std::min(1.0, radius_m / distance));
  // Equidistant: image position proportional to the angle from the optical axis.
  const double full_angle = 2.0 * camera.half_angle_rad;
  const double vertical_angle = kAspect * full_angle;
  const double top = std::atan2(top_m - camera_height_m, distance);
  const double bottom = std::atan2(-camera_height_m, distance);
  return clipped(0.5 - (bearing + half_width) / full_angle, 0.5 - top / vertical_angle,
                 0.5 - (bearing - half_width) / full_angle, 0.5 - bottom / vertical_angle);
}

ImageRegion pinhole_region(const FieldOfView& camera, double camera_height_m,
                           const Eigen::Vector2d& centre_map, double centre_height_m,
                           double width_m, double height_m) {
  // Image-plane coordinates: lateral and vertical offsets over depth, scaled so the image edge
  // is at tan(half field of view).
  const Eigen::Vector2d offset = centre_map - camera.X_map_sensor.position;
  const double c = std::cos(camera.X_map_sensor.theta), s = std::sin(camera.X_map_sensor.theta);
  const double depth = std::max(c * offset.x() + s * offset.y(), 1e-3);
  const double left = -s * offset.x() + c * offset.y();
  const double half_span = std::tan(camera.half_angle_rad);
  const double half_span_vertical = kAspect * half_span;
  const double x_centre = 0.5 - 0.5 * (left / depth) / half_span;
  const double y_centre =
      0.5 - 0.5 * ((centre_height_m - camera_height_m) / depth) / half_span_vertical;
  const double half_w = 0.25 * (width_m / depth) / half_span;
  const double half_h = 0.25 * (height_m / depth) / half_span_vertical;
  return clipped(x_centre - half_w, y_centre - half_h, x_centre + half_w, y_centre + half_h);
}

}  // namespace ari_social_sim::perception
