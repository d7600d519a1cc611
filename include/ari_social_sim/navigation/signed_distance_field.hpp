#pragma once

#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/navigation/grid_field.hpp"

namespace ari_social_sim::navigation {

/// Distance (m) from every cell centre of `grid` to the nearest edge between free and occupied
/// cells: positive in free space, negative inside walls and furniture, +-resolution/2 next to the
/// edge. Unknown cells count as occupied, so the planner never relies on unmapped space. Exact
/// Euclidean distances (OpenCV's precise distance transform). A grid with no occupied cell reads
/// as far from everything (its diagonal).
GridField signed_distance_field(const model::OccupancyGrid& grid);

}  // namespace ari_social_sim::navigation
