#include "ari_social_sim/perception/tracked_persons.hpp"

#include <map>
#include <memory>

namespace ari_social_sim::perception {

model::TrackedPersons tracked_persons_of(const PerceptionFrame& frame) {
  model::TrackedPersons tracked;
  for (const PersonReport& person : frame.persons) {
    if (person.tracked) {
      tracked.persons.push_back({person.person_id, person.body_id});
    }
  }
  auto bodies = std::make_shared<std::map<std::string, model::BodyPlacement>>();
  for (const PerceivedBody& body : frame.bodies) {
    bodies->emplace(body.body_id, model::BodyPlacement{frame.time_s, body.X_map_body});
  }
  tracked.locate_body =
      [bodies = std::shared_ptr<const std::map<std::string, model::BodyPlacement>>(bodies)](
          const std::string& body_id) -> std::optional<model::BodyPlacement> {
    const auto body = bodies->find(body_id);
    if (body == bodies->end()) {
      return std::nullopt;
    }
    return body->second;
  };
  return tracked;
}

}  // namespace ari_social_sim::perception
