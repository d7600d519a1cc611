#include "ari_social_sim/perception/group_perception.hpp"

namespace ari_social_sim::perception {

void GroupPerception::update(const std::vector<PerceivedBody>& bodies,
                             std::vector<PerceivedGroup>& groups) {
  persons_.clear();
  for (const PerceivedBody& body : bodies) {
    persons_.push_back({body.person_id, body.X_map_body.position.x(), body.X_map_body.position.y(),
                        body.X_map_body.theta});
  }
  detector_.detect(persons_, result_);
  grouping_.assign(result_.groups.size(), {});
  for (size_t g = 0; g < result_.groups.size(); ++g) {
    for (size_t member : result_.groups[g].members) {
      grouping_[g].push_back(persons_[member].id);
    }
  }
  const std::vector<std::string> ids = tracker_.update(grouping_);
  groups.clear();
  for (size_t g = 0; g < ids.size(); ++g) {
    groups.push_back({ids[g], grouping_[g], result_.groups[g].centre});
  }
}

}  // namespace ari_social_sim::perception
