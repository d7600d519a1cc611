#include "ari_social_sim/learning/ground_truth.hpp"

#include <algorithm>

#include "ari_social_sim/learning/navigation_episodes.hpp"
#include "ari_social_sim/perception/gcff.hpp"

namespace ari_social_sim::learning {

navigation::PerceivedScene true_scene(const world::Simulation& sim, double stride_m) {
  navigation::PerceivedScene scene;
  scene.people.reserve(sim.humans().size());
  for (const auto& human : sim.humans()) {
    navigation::PersonEstimate person;
    person.id = person_id(human->id());
    person.position = human->pose().position;
    person.heading = human->pose().theta;
    person.velocity = human->velocity();
    scene.people.push_back(std::move(person));
  }
  std::vector<navigation::PersonEstimate> members;
  for (const auto& group : sim.groups()) {
    members.clear();
    for (model::ObjectId id : group->members()) {
      if (const auto* person = scene.find_person(person_id(id))) {
        members.push_back(*person);
      }
    }
    if (!members.empty()) {
      scene.groups.push_back(navigation::estimate_group(group_id(group->id()), members, stride_m));
    }
  }
  return scene;
}

bool gcff_includes_ari(const world::Simulation& sim, const navigation::FootprintModel& footprint,
                       const std::vector<std::string>& members) {
  std::vector<perception::GcffPerson> persons;
  for (const auto& human : sim.humans()) {
    persons.push_back({person_id(human->id()), human->pose().position.x(),
                       human->pose().position.y(), human->pose().theta});
  }
  const Eigen::Vector2d ari_centre = footprint.centre(sim.ari()->pose());
  persons.push_back({"ari", ari_centre.x(), ari_centre.y(), sim.ari()->pose().theta});
  perception::GcffDetector detector{perception::GcffParams{}};
  const perception::GcffResult result = detector.detect(persons);
  const int ari_label = result.labels.back();
  int together = 0;
  for (size_t i = 0; i + 1 < persons.size(); ++i) {
    const bool is_member =
        std::find(members.begin(), members.end(), persons[i].id) != members.end();
    together += is_member && result.labels[i] == ari_label ? 1 : 0;
  }
  return 3 * together >= 2 * static_cast<int>(members.size());
}

}  // namespace ari_social_sim::learning
