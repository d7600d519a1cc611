#include "ari_social_sim/navigation/grid_field.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::navigation {

GridField::GridField(const model::OccupancyGrid& grid, float fill)
    : origin_(grid.origin),
      resolution_m_(grid.resolution_m),
      width_(grid.width),
      height_(grid.height),
      values_(static_cast<size_t>(grid.width) * grid.height, fill) {}

bool GridField::cell_of(const Eigen::Vector2d& point, int& x, int& y) const {
  x = static_cast<int>(std::floor((point.x() - origin_.x()) / resolution_m_));
  y = static_cast<int>(std::floor((point.y() - origin_.y()) / resolution_m_));
  return x >= 0 && y >= 0 && x < width_ && y < height_;
}

Eigen::Vector2d GridField::cell_centre(int x, int y) const {
  return origin_ + resolution_m_ * Eigen::Vector2d(x + 0.5, y + 0.5);
}

double GridField::sample(const Eigen::Vector2d& point, Eigen::Vector2d* gradient,
                         double* cross) const {
  ARI_DCHECK(!values_.empty());
  // Continuous cell coordinates with cell centres at integers.
  double fx = (point.x() - origin_.x()) / resolution_m_ - 0.5;
  double fy = (point.y() - origin_.y()) / resolution_m_ - 0.5;
  const bool clamped_x = fx < 0.0 || fx > width_ - 1;
  const bool clamped_y = fy < 0.0 || fy > height_ - 1;
  fx = std::clamp(fx, 0.0, static_cast<double>(width_ - 1));
  fy = std::clamp(fy, 0.0, static_cast<double>(height_ - 1));
  const int x0 = std::min(static_cast<int>(fx), std::max(width_ - 2, 0));
  const int y0 = std::min(static_cast<int>(fy), std::max(height_ - 2, 0));
  const int x1 = std::min(x0 + 1, width_ - 1);
  const int y1 = std::min(y0 + 1, height_ - 1);
  const double tx = fx - x0;
  const double ty = fy - y0;
  const double v00 = at(x0, y0), v10 = at(x1, y0), v01 = at(x0, y1), v11 = at(x1, y1);
  const double bottom = v00 + tx * (v10 - v00);
  const double top = v01 + tx * (v11 - v01);
  if (gradient != nullptr) {
    const double dx = ((1.0 - ty) * (v10 - v00) + ty * (v11 - v01)) / resolution_m_;
    const double dy = (top - bottom) / resolution_m_;
    *gradient = {clamped_x ? 0.0 : dx, clamped_y ? 0.0 : dy};
  }
  if (cross != nullptr) {
    *cross =
        clamped_x || clamped_y ? 0.0 : (v11 - v01 - v10 + v00) / (resolution_m_ * resolution_m_);
  }
  return bottom + ty * (top - bottom);
}

}  // namespace ari_social_sim::navigation
