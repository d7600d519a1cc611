#include "ari_social_sim/perception/group_candidates.hpp"

namespace ari_social_sim::perception {

std::vector<GcffPerson> group_candidates_of(const PerceptionFrame& frame) {
  std::vector<GcffPerson> candidates;
  candidates.reserve(frame.bodies.size());
  for (const PerceivedBody& body : frame.bodies) {
    candidates.push_back({body.person_id, body.X_map_body.position.x(),
                          body.X_map_body.position.y(), body.X_map_body.theta});
  }
  return candidates;
}

}  // namespace ari_social_sim::perception
