#pragma once

#include "ari_social_sim/world/occupancy_grid.hpp"
#include "ari_social_sim/world/world_description.hpp"

namespace ari_social_sim::perception {

/// The map that blocks sound (seed 3.5.4: people in another room are not heard): the world's
/// walls rasterised like the occupancy map, without furniture, which sound passes over.
world::OccupancyGrid rasterize_walls(const world::WorldDescription& world, double resolution_m);

}  // namespace ari_social_sim::perception
