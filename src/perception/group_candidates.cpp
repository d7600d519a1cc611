#include "ari_social_sim/perception/group_candidates.hpp"

#include "ari_social_sim/perception/tracked_persons.hpp"

namespace ari_social_sim::perception {

std::vector<GcffPerson> group_candidates_of(const model::TrackedPersons& persons) {
  std::vector<GcffPerson> candidates;
  for (const model::PlacedPerson& person :
       model::place_at_bodies(persons.persons, persons.locate_body)) {
    candidates.push_back(
        {person.person_id, person.pose.position.x(), person.pose.position.y(), person.pose.theta});
  }
  return candidates;
}

std::vector<GcffPerson> group_candidates_of(const PerceptionFrame& frame) {
  return group_candidates_of(tracked_persons_of(frame));
}

}  // namespace ari_social_sim::perception
