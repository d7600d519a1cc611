#include "ari_social_sim/navigation/footprint_model.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::navigation {

FootprintModel FootprintModel::covering(const model::AriFootprint& rectangle, int circle_count) {
  ARI_CHECK(circle_count >= 1);
  FootprintModel model;
  model.rectangle = rectangle;
  const double length = rectangle.front_x_m - rectangle.rear_x_m;
  const double slice = length / circle_count;
  for (int i = 0; i < circle_count; ++i) {
    model.circle_offsets_x_m.push_back(rectangle.rear_x_m + (i + 0.5) * slice);
  }
  // Each circle reaches the corners of its slice: half the slice along x, the half width across.
  model.circle_radius_m = std::hypot(0.5 * slice, rectangle.half_width_m);
  return model;
}

std::vector<Eigen::Vector2d> FootprintModel::outline(double spacing_m) const {
  const Eigen::Vector2d corners[4] = {{rectangle.front_x_m, rectangle.half_width_m},
                                      {rectangle.rear_x_m, rectangle.half_width_m},
                                      {rectangle.rear_x_m, -rectangle.half_width_m},
                                      {rectangle.front_x_m, -rectangle.half_width_m}};
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d& from = corners[i];
    const Eigen::Vector2d& to = corners[(i + 1) % 4];
    const int pieces = std::max(1, static_cast<int>(std::ceil((to - from).norm() / spacing_m)));
    for (int k = 0; k < pieces; ++k) {
      points.emplace_back(from + (to - from) * (static_cast<double>(k) / pieces));
    }
  }
  return points;
}

double FootprintModel::distance_to(const core::Pose2& base, const Eigen::Vector2d& point) const {
  const Eigen::Vector2d d = point - base.position;
  const double c = std::cos(base.theta), s = std::sin(base.theta);
  const double local_x = c * d.x() + s * d.y();
  const double local_y = -s * d.x() + c * d.y();
  const double out_x = std::max({rectangle.rear_x_m - local_x, local_x - rectangle.front_x_m, 0.0});
  const double out_y = std::max(std::abs(local_y) - rectangle.half_width_m, 0.0);
  return std::hypot(out_x, out_y);
}

}  // namespace ari_social_sim::navigation
