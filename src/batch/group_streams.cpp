#include "ari_social_sim/batch/group_streams.hpp"

#include <map>
#include <set>
#include <vector>

#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/perception/group_candidates.hpp"

namespace ari_social_sim::batch {

GroupStreams::GroupStreams()
    : features_("frame,person_id,x,y,theta\n"),
      truth_("frame,group,person_id\n"),
      frames_("frame\n") {}

void GroupStreams::add(const world::WorldSnapshot& world,
                       const perception::PerceptionFrame& frame) {
  const long long number = static_cast<long long>(counts_.frames);
  frames_ += std::to_string(number) + "\n";
  ++counts_.frames;

  // What GCFF is given: the tracked persons at their bodies.
  std::set<std::string> placed;
  for (const perception::GcffPerson& person : perception::group_candidates_of(frame)) {
    features_ += core::format_text("%lld,%s,%.4f,%.4f,%.5f\n", number, person.id.c_str(), person.x,
                                   person.y, person.theta);
    placed.insert(person.id);
    ++counts_.feature_rows;
  }

  // Who each placed person is: the person manager's link from person to human.
  std::map<model::ObjectId, std::string> person_of_human;
  for (const perception::PersonReport& person : frame.persons) {
    if (placed.count(person.person_id) > 0) {
      person_of_human[person.human] = person.person_id;
    }
  }
  for (const world::GroupSnapshot& group : world.groups) {
    if (group.members.size() < 2) {
      continue;
    }
    ++counts_.world_groups;
    std::vector<std::string> seen;
    for (model::ObjectId member : group.members) {
      const auto person = person_of_human.find(member);
      if (person != person_of_human.end()) {
        seen.push_back(person->second);
      }
    }
    if (seen.size() < 2) {
      continue;
    }
    ++counts_.truth_groups;
    for (const std::string& person : seen) {
      truth_ += std::to_string(number) + "," + std::to_string(group.id) + "," + person + "\n";
      ++counts_.truth_rows;
    }
  }
}

}  // namespace ari_social_sim::batch
