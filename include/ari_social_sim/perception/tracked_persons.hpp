#pragma once

#include "ari_social_sim/model/tracked_person.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::perception {

/// What hri_perception_node publishes of `frame` for the nodes that act on persons
/// (group_detection_node, social_mpc_node, scenario_node), for the in-process engines to read in
/// their place: the tracked persons in the frame's order with their body ids
/// (/humans/persons/tracked, /humans/persons/<id>/body_id), and the frame's bodies, each at its
/// pose in the map at the frame's time (tf body_<id>). The locator holds its own copy of the
/// bodies.
model::TrackedPersons tracked_persons_of(const PerceptionFrame& frame);

}  // namespace ari_social_sim::perception
