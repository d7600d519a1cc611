#pragma once

#include <vector>

#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::perception {

/// The people GroupPerception considers in a perception frame: one candidate per perceived body,
/// named by the body's person id, at the body's noisy position and facing in the map (metres,
/// rad), in the frame's body order. What group_detection_node reads from tf (`body_<id>` of each
/// tracked person) the in-process engines read here, so both feed GroupPerception the same
/// people. ARI is not a body, so it is never a candidate.
std::vector<GcffPerson> group_candidates_of(const PerceptionFrame& frame);

}  // namespace ari_social_sim::perception
