#include "ari_social_sim/scenario/group_memory.hpp"

#include <utility>

namespace ari_social_sim::scenario {

void GroupMemory::report(const std::string& group_id, double stamp_s,
                         std::vector<std::string> person_ids) {
  groups_[group_id] = {stamp_s, std::move(person_ids)};
}

std::vector<PerceivedGroup> GroupMemory::believed_at(double now_s,
                                                     const PersonIdentities& identities) {
  std::vector<PerceivedGroup> believed;
  for (auto group = groups_.begin(); group != groups_.end();) {
    if (now_s - group->second.stamp_s > timeout_s_) {
      group = groups_.erase(group);
    } else {
      believed.push_back(perceived_group(group->first, group->second.person_ids, identities));
      ++group;
    }
  }
  return believed;
}

}  // namespace ari_social_sim::scenario
