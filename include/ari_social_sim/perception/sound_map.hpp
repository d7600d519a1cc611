#pragma once

#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/model/world_description.hpp"

namespace ari_social_sim::perception {

/// The map that blocks sound (D6.4 §3.5.4: people in another room are not heard): the world's
/// walls rasterised like the occupancy map, without furniture, which sound passes over.
model::OccupancyGrid rasterize_walls(const model::WorldDescription& world, double resolution_m);

}  // namespace ari_social_sim::perception
