#include "ari_social_sim/perception/group_candidates.hpp"

#include <utility>

#include "ari_social_sim/perception/tracked_persons.hpp"

namespace ari_social_sim::perception {

std::vector<GcffPerson> group_candidates_of(model::TrackedPersons persons) {
  std::vector<model::PlacedPerson> placed =
      model::place_at_bodies(std::move(persons.persons), persons.locate_body);
  std::vector<GcffPerson> candidates;
  candidates.reserve(placed.size());
  for (model::PlacedPerson& person : placed) {
    candidates.push_back({std::move(person.person_id), person.pose.position.x(),
                          person.pose.position.y(), person.pose.theta});
  }
  return candidates;
}

std::vector<GcffPerson> group_candidates_of(const PerceptionFrame& frame) {
  return group_candidates_of(tracked_persons_of(frame));
}

}  // namespace ari_social_sim::perception
