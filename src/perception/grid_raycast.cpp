#include "ari_social_sim/perception/grid_raycast.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>

namespace ari_social_sim::perception {

bool segment_is_clear(const model::OccupancyGrid& grid, int occupied_threshold,
                      const Eigen::Vector2d& from_map, const Eigen::Vector2d& to_map) {
  if (grid.width <= 0 || grid.height <= 0) {
    return true;
  }
  // In cell units, so that cell (i, j) spans [i, i+1) x [j, j+1).
  const Eigen::Vector2d from = (from_map - grid.origin) / grid.resolution_m;
  const Eigen::Vector2d to = (to_map - grid.origin) / grid.resolution_m;
  const Eigen::Vector2d delta = to - from;
  int x = static_cast<int>(std::floor(from.x()));
  int y = static_cast<int>(std::floor(from.y()));
  const int end_x = static_cast<int>(std::floor(to.x()));
  const int end_y = static_cast<int>(std::floor(to.y()));

  // Parameter t in [0, 1] along the segment at which the next x (y) cell border is crossed, and
  // the increase of t from one border to the next.
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const int step_x = delta.x() > 0.0 ? 1 : -1;
  const int step_y = delta.y() > 0.0 ? 1 : -1;
  double next_x = kNever, next_y = kNever, every_x = kNever, every_y = kNever;
  if (delta.x() != 0.0) {
    every_x = 1.0 / std::abs(delta.x());
    next_x = (step_x > 0 ? x + 1.0 - from.x() : from.x() - x) * every_x;
  }
  if (delta.y() != 0.0) {
    every_y = 1.0 / std::abs(delta.y());
    next_y = (step_y > 0 ? y + 1.0 - from.y() : from.y() - y) * every_y;
  }

  const int steps = std::abs(end_x - x) + std::abs(end_y - y);
  for (int i = 1; i < steps; ++i) {
    if (next_x < next_y) {
      x += step_x;
      next_x += every_x;
    } else {
      y += step_y;
      next_y += every_y;
    }
    if (x >= 0 && y >= 0 && x < grid.width && y < grid.height &&
        grid.at(x, y) >= occupied_threshold) {
      return false;
    }
  }
  return true;
}

}  // namespace ari_social_sim::perception
