#pragma once

// What the episodes are scored on: the simulation as it is, not as perception reports it.

#include <string>
#include <vector>

#include "ari_social_sim/navigation/footprint_model.hpp"
#include "ari_social_sim/navigation/perceived_scene.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::learning {

/// Every human under the id perception would give them, at their true pose and velocity, and
/// every group's o-space from its members' poses (GCFF's `stride_m`).
navigation::PerceivedScene true_scene(const world::Simulation& sim, double stride_m);

/// Whether GCFF (perception core, default parameters), run on the true scene with ARI as one
/// more participant at its body centre facing its heading, puts ARI with at least two thirds of
/// `members` (person ids).
bool gcff_includes_ari(const world::Simulation& sim, const navigation::FootprintModel& footprint,
                       const std::vector<std::string>& members);

}  // namespace ari_social_sim::learning
