#include "ari_social_sim/model/tracked_person.hpp"

#include <utility>

namespace ari_social_sim::model {

std::vector<PlacedPerson> place_at_bodies(std::vector<TrackedPerson> persons,
                                          const BodyLocator& locate_body) {
  std::vector<PlacedPerson> placed;
  placed.reserve(persons.size());
  for (TrackedPerson& person : persons) {
    if (person.body_id.empty()) {
      continue;
    }
    if (const std::optional<BodyPlacement> body = locate_body(person.body_id)) {
      placed.push_back({std::move(person.person_id), body->stamp_s, body->pose});
    }
  }
  return placed;
}

}  // namespace ari_social_sim::model
