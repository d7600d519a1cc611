#include "ari_social_sim/model/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::model {

bool OccupancyGrid::cell_of(const Eigen::Vector2d& point, int& x, int& y) const {
  x = static_cast<int>(std::floor((point.x() - origin.x()) / resolution_m));
  y = static_cast<int>(std::floor((point.y() - origin.y()) / resolution_m));
  return x >= 0 && y >= 0 && x < width && y < height;
}

Eigen::Vector2d OccupancyGrid::cell_centre(int x, int y) const {
  return origin + resolution_m * Eigen::Vector2d(x + 0.5, y + 0.5);
}

size_t OccupancyGrid::occupied_count() const {
  return static_cast<size_t>(std::count(cells.begin(), cells.end(), kOccupied));
}

}  // namespace ari_social_sim::model
