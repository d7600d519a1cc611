#pragma once

#include <visualization_msgs/MarkerArray.h>

#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::nodes {

/// Everything rviz shows of the world in one MarkerArray (one message per display tick, never one
/// per entity): walls and furniture, each human's body, heading, gaze and label (id, name, age,
/// gender, emotion, mask), ARI's footprint and head direction, groups' o-space circles and the
/// utterances being spoken. Starts with DELETEALL so removed entities disappear.
visualization_msgs::MarkerArray world_markers(const world::WorldSnapshot& snapshot,
                                              const model::WorldDescription& world,
                                              const std::string& frame_id);

}  // namespace ari_social_sim::nodes
