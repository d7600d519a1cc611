#pragma once

#include <unordered_map>
#include <vector>

#include "ari_social_sim/model/object_id.hpp"

namespace ari_social_sim::perception {

/// Each human's first observation (body, face or voice) in `observations`, by human id. The
/// detectors list observations in the world state's order of humans, which only world_node keeps
/// sorted by id: another publisher's /sim/world_state may list them in any order.
template <class Observation>
std::unordered_map<model::ObjectId, const Observation*> observations_by_human(
    const std::vector<Observation>& observations) {
  std::unordered_map<model::ObjectId, const Observation*> found;
  for (const Observation& observation : observations) {
    found.emplace(observation.human, &observation);
  }
  return found;
}

/// The observation of `human` in an index of observations_by_human, or null.
template <class Observation>
const Observation* observation_of(
    const std::unordered_map<model::ObjectId, const Observation*>& observations,
    model::ObjectId human) {
  const auto it = observations.find(human);
  return it == observations.end() ? nullptr : it->second;
}

}  // namespace ari_social_sim::perception
