#include "ari_social_sim/navigation/perceived_scene.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::navigation {

GroupEstimate estimate_group(const std::string& id, const std::vector<PersonEstimate>& members,
                             double stride_m) {
  ARI_CHECK(!members.empty());
  GroupEstimate group;
  group.id = id;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const PersonEstimate& member : members) {
    group.members.push_back(member.id);
    sum += member.position +
           stride_m * Eigen::Vector2d(std::cos(member.heading), std::sin(member.heading));
  }
  group.centre = sum / static_cast<double>(members.size());
  double radius_sum = 0.0;
  for (const PersonEstimate& member : members) {
    radius_sum += (member.position - group.centre).norm();
  }
  group.radius_m = radius_sum / static_cast<double>(members.size());
  return group;
}

const PersonEstimate* PerceivedScene::find_person(const std::string& id) const {
  const auto it = std::find_if(people.begin(), people.end(),
                               [&](const PersonEstimate& person) { return person.id == id; });
  return it == people.end() ? nullptr : &*it;
}

const GroupEstimate* PerceivedScene::find_group(const std::string& id) const {
  const auto it = std::find_if(groups.begin(), groups.end(),
                               [&](const GroupEstimate& group) { return group.id == id; });
  return it == groups.end() ? nullptr : &*it;
}

const GroupEstimate* PerceivedScene::group_of(const std::string& person_id) const {
  for (const GroupEstimate& group : groups) {
    if (std::find(group.members.begin(), group.members.end(), person_id) != group.members.end()) {
      return &group;
    }
  }
  return nullptr;
}

}  // namespace ari_social_sim::navigation
