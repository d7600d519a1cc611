#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/model/occupancy_grid.hpp"

namespace ari_social_sim::navigation {

/// A scalar field sampled at the cell centres of a grid laid like an OccupancyGrid (row-major from
/// the lower-left cell at `origin`), read back by bilinear interpolation so that the MPC gets a
/// continuous value and gradient anywhere. Points outside the grid read the nearest border value.
class GridField {
 public:
  GridField() = default;
  /// A field the size of `grid`, every cell `fill`.
  GridField(const model::OccupancyGrid& grid, float fill);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution_m() const { return resolution_m_; }
  const Eigen::Vector2d& origin() const { return origin_; }
  bool empty() const { return values_.empty(); }

  float at(int x, int y) const { return values_[index(x, y)]; }
  float& at(int x, int y) { return values_[index(x, y)]; }
  size_t index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }
  const std::vector<float>& values() const { return values_; }
  std::vector<float>& values() { return values_; }

  /// Cell holding a point, or false when the point is outside the grid.
  bool cell_of(const Eigen::Vector2d& point, int& x, int& y) const;
  Eigen::Vector2d cell_centre(int x, int y) const;

  /// Bilinear value at `point` (m, map frame); when `gradient` is given, also the gradient of that
  /// interpolant (per m), and when `cross` is given its only non-zero second derivative
  /// d2f/dxdy (per m^2; d2f/dx2 = d2f/dy2 = 0 inside a cell). Outside the grid, the border value
  /// and zero derivatives across the border.
  double sample(const Eigen::Vector2d& point, Eigen::Vector2d* gradient = nullptr,
                double* cross = nullptr) const;

 private:
  Eigen::Vector2d origin_{Eigen::Vector2d::Zero()};
  double resolution_m_{0.05};
  int width_{0};
  int height_{0};
  std::vector<float> values_;
};

}  // namespace ari_social_sim::navigation
