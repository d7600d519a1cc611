#include "ari_social_sim/scenario/observations.hpp"

namespace ari_social_sim::scenario {

PerceivedGroup perceived_group(const std::string& group_id,
                               const std::vector<std::string>& person_ids,
                               const PersonIdentities& identities) {
  PerceivedGroup group{group_id, {}};
  for (const std::string& person : person_ids) {
    if (const std::optional<model::ObjectId> human = identities.human_of(person)) {
      group.members.push_back(AgentRef::human(*human));
    }
  }
  return group;
}

}  // namespace ari_social_sim::scenario
