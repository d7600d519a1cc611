#pragma once

#include <nav_msgs/OccupancyGrid.h>

#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/world/occupancy_grid.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::nodes {

/// /sim/world_state from a snapshot; header stamped with the snapshot's sim time in `frame_id`.
WorldState to_msg(const world::WorldSnapshot& snapshot, const std::string& frame_id);
/// The snapshot a /sim/world_state message carries (its inverse: from_msg(to_msg(s)) == s up
/// to the message's float32 ages).
world::WorldSnapshot from_msg(const WorldState& msg);
/// /map from the rasterised static geometry.
nav_msgs::OccupancyGrid to_msg(const world::OccupancyGrid& grid, const std::string& frame_id,
                               double stamp_s);

}  // namespace ari_social_sim::nodes
