#pragma once

#include "ari_social_sim/model/object_id.hpp"

namespace ari_social_sim::world {

/// Where a human looks for one gaze event, when a behaviour other than the human's own gaze
/// model decides it: the reaction to ARI, or the conversation of the human's group.
struct GazeEvent {
  model::ObjectId target{model::kNoObject};  // looked at; none: along `direction_rad`
  double direction_rad{0.0};                 // map frame
  double since_s{0.0};                       // sim time the gaze event started
};

}  // namespace ari_social_sim::world
