#pragma once

#include <vector>

#include "ari_social_sim/model/tracked_person.hpp"
#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::perception {

/// The people GroupPerception considers, the one way group_detection_node (bodies placed by tf)
/// and the in-process engines (bodies placed by the perception frame) both choose them: each
/// tracked person at their body (model::place_at_bodies: GCFF needs the body's facing, which a
/// face or voice does not give), named by their person id, at the body's position and facing in
/// the map (metres, rad), in the order the persons are reported. ARI is not a person, so it is
/// never a candidate.
std::vector<GcffPerson> group_candidates_of(model::TrackedPersons persons);
/// The same for the persons a perception frame reports (tracked_persons_of).
std::vector<GcffPerson> group_candidates_of(const PerceptionFrame& frame);

}  // namespace ari_social_sim::perception
