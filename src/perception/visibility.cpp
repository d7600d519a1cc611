#include "ari_social_sim/perception/visibility.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/perception/grid_raycast.hpp"

namespace ari_social_sim::perception {
namespace {

// Distance along the unit ray (eye, direction) at which it enters a circle, or a negative value
// when it misses it or the circle lies behind the eye.
double ray_entry(const Eigen::Vector2d& eye, const Eigen::Vector2d& direction,
                 const Eigen::Vector2d& centre, double radius) {
  const Eigen::Vector2d to_centre = centre - eye;
  const double along = to_centre.dot(direction);
  const double across_sq = to_centre.squaredNorm() - along * along;
  const double radius_sq = radius * radius;
  if (along <= 0.0 || across_sq >= radius_sq) {
    return -1.0;
  }
  return along - std::sqrt(radius_sq - across_sq);
}

}  // namespace

double visible_fraction(const FieldOfView& sensor, const SightObstacles& obstacles, size_t target,
                        int ray_count) {
  const std::vector<Eigen::Vector2d>& people = *obstacles.people;
  const double radius = obstacles.person_radius_m;
  // A seated person's circle lies on the chair's cells; the map is read only up to one radius
  // before it, or the chair would hide whoever sits on it. A standing person is checked up to
  // their circle: what the map holds that close to them stands between them and the sensor.
  const bool seated = obstacles.seated != nullptr && (*obstacles.seated)[target];
  const double map_margin_m = seated ? radius : 0.0;
  const Eigen::Vector2d& eye = sensor.X_map_sensor.position;
  const Eigen::Vector2d to_target = people[target] - eye;
  const double distance = to_target.norm();
  if (distance <= radius) {
    return 1.0;
  }
  const double centre_angle = std::atan2(to_target.y(), to_target.x());
  const double half_width = std::asin(radius / distance);
  const double centre_bearing = sensor.bearing_of(people[target]);

  int visible = 0;
  for (int ray = 0; ray < ray_count; ++ray) {
    // Evenly over (-half_width, half_width), each ray at the middle of its slice.
    const double offset = half_width * (2.0 * (ray + 0.5) / ray_count - 1.0);
    if (sensor.angle_inside(centre_bearing + offset) < 0.0) {
      continue;
    }
    const Eigen::Vector2d direction(std::cos(centre_angle + offset),
                                    std::sin(centre_angle + offset));
    const double reach = ray_entry(eye, direction, people[target], radius);
    bool blocked = false;
    for (size_t other = 0; other < people.size() && !blocked; ++other) {
      if (other == target || (people[other] - eye).norm() - radius >= reach) {
        continue;
      }
      const double entry = ray_entry(eye, direction, people[other], radius);
      blocked = entry >= 0.0 && entry < reach;
    }
    if (!blocked && obstacles.grid != nullptr) {
      blocked = !segment_is_clear(*obstacles.grid, obstacles.occupied_threshold, eye,
                                  eye + std::max(0.0, reach - map_margin_m) * direction);
    }
    visible += blocked ? 0 : 1;
  }
  return static_cast<double>(visible) / ray_count;
}

}  // namespace ari_social_sim::perception
