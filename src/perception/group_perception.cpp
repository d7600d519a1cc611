#include "ari_social_sim/perception/group_perception.hpp"

namespace ari_social_sim::perception {

void GroupPerception::update(const std::vector<GcffPerson>& people,
                             std::vector<PerceivedGroup>& groups) {
  detector_.detect(people, result_);
  ids_.clear();
  for (const GcffPerson& person : people) {
    ids_.push_back(person.id);
  }
  detected_.clear();
  for (const GcffGroup& group : result_.groups) {
    detected_.push_back(group.members);
  }
  const std::vector<std::vector<size_t>> steady = membership_.update(ids_, detected_);
  // Names, and the o-space centre as GCFF computes it: the mean of the members' candidate
  // centres.
  grouping_.assign(steady.size(), {});
  std::vector<Eigen::Vector2d> centres(steady.size(), Eigen::Vector2d::Zero());
  for (size_t g = 0; g < steady.size(); ++g) {
    for (size_t member : steady[g]) {
      const GcffPerson& person = people[member];
      grouping_[g].push_back(person.id);
      centres[g] += gcff_candidate_centre(person, stride_);
    }
    centres[g] /= static_cast<double>(steady[g].size());
  }
  const std::vector<std::string> ids = tracker_.update(grouping_);
  groups.clear();
  for (size_t g = 0; g < ids.size(); ++g) {
    groups.push_back({ids[g], grouping_[g], centres[g]});
  }
}

}  // namespace ari_social_sim::perception
