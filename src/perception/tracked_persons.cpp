#include "ari_social_sim/perception/tracked_persons.hpp"

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ari_social_sim::perception {

model::TrackedPersons tracked_persons_of(const PerceptionFrame& frame) {
  model::TrackedPersons tracked;
  tracked.persons.reserve(frame.persons.size());
  for (const PersonReport& person : frame.persons) {
    if (person.tracked) {
      tracked.persons.push_back({person.person_id, person.body_id});
    }
  }
  // Sorted by body id for the lookups; one allocation per frame rather than a node per body.
  using Placed = std::pair<std::string, model::BodyPlacement>;
  auto bodies = std::make_shared<std::vector<Placed>>();
  bodies->reserve(frame.bodies.size());
  for (const PerceivedBody& body : frame.bodies) {
    bodies->push_back({body.body_id, model::BodyPlacement{frame.time_s, body.X_map_body}});
  }
  const auto by_id = [](const Placed& a, const Placed& b) { return a.first < b.first; };
  // Stable: were a body id repeated, the first body in the frame would be found.
  std::stable_sort(bodies->begin(), bodies->end(), by_id);
  tracked.locate_body = [bodies = std::shared_ptr<const std::vector<Placed>>(bodies)](
                            const std::string& body_id) -> std::optional<model::BodyPlacement> {
    const auto body = std::lower_bound(
        bodies->begin(), bodies->end(), body_id,
        [](const Placed& placed, const std::string& id) { return placed.first < id; });
    if (body == bodies->end() || body->first != body_id) {
      return std::nullopt;
    }
    return body->second;
  };
  return tracked;
}

}  // namespace ari_social_sim::perception
