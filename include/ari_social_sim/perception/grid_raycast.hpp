#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "ari_social_sim/model/occupancy_grid.hpp"

namespace ari_social_sim::perception {

/// True when the straight segment between two map points crosses no cell whose value is at least
/// `occupied_threshold`. Walks the crossed cells in order (Amanatides & Woo, 1987); the cells
/// holding the two end points are not tested, so a sensor or a person touching a cell that a wall
/// only partly fills still sees past it. Cells outside the grid, unknown cells (-1) and an empty
/// grid are free.
bool segment_is_clear(const model::OccupancyGrid& grid, int occupied_threshold,
                      const Eigen::Vector2d& from_map, const Eigen::Vector2d& to_map);

}  // namespace ari_social_sim::perception
