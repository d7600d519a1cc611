#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "ari_social_sim/core/bounds.hpp"

namespace ari_social_sim::model {

/// Cell sizes (m) the suite's occupancy maps take: world_node's /map and ARI's map sensor, and the
/// voxels of the 3D mapping, whose 2D projection is /map too.
inline const core::Bounds kMapResolutionBounds = core::between(0.01, 1.0);

/// A 2D occupancy grid in the ROS convention: row-major from the lower-left cell at `origin`,
/// values 0 (free), 100 (occupied), -1 (unknown).
struct OccupancyGrid {
  static constexpr int8_t kFree = 0;
  static constexpr int8_t kOccupied = 100;
  static constexpr int8_t kUnknown = -1;

  Eigen::Vector2d origin{Eigen::Vector2d::Zero()};  // m, lower-left corner of cell (0, 0)
  double resolution_m{0.05};
  int width{0};   // cells along x
  int height{0};  // cells along y
  std::vector<int8_t> cells;

  int8_t at(int x, int y) const { return cells[static_cast<size_t>(y) * width + x]; }
  /// Cell holding a point, or false when the point is outside the grid.
  bool cell_of(const Eigen::Vector2d& point, int& x, int& y) const;
  Eigen::Vector2d cell_centre(int x, int y) const;
  size_t occupied_count() const;
};

}  // namespace ari_social_sim::model
