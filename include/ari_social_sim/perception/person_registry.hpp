#pragma once

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/perception/ari_sensors.hpp"
#include "ari_social_sim/perception/engagement.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/perception/transient_ids.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::perception {

/// The person manager (hri_person_manager's role): one permanent person per simulated human,
/// named by PersonConfig::id_style, linked to that human's face, body and voice of the frame. A
/// person is tracked while any of the three is, and known from the first time it is. Its location
/// is the face if seen, else the body, else the voice; once untracked it stays at the last place
/// while location_confidence falls linearly from 1 to 0 over location_decay. Engagement is scored
/// from the perceived face and ARI's head (no face: score 0) and reset to UNKNOWN when untracked;
/// so is the proxemic zone, from the distance between ARI's base and the person's location.
class PersonRegistry {
 public:
  /// `id_rng` draws the ids of the "random" id style.
  PersonRegistry(const PersonConfig& persons, const EngagementConfig& engagement, core::Rng id_rng);

  /// Updates every person from this frame's observations (each list ordered by human id) and
  /// writes a report per known person, ordered by human id. `sensors` is null without ARI.
  void update(const world::WorldSnapshot& snapshot, const AriSensors* sensors,
              const std::vector<PerceivedBody>& bodies, const std::vector<PerceivedFace>& faces,
              const std::vector<PerceivedVoice>& voices, std::vector<PersonReport>& reports);

  bool is_known(world::ObjectId human) const { return persons_.count(human) > 0; }
  /// The person id of a known human; throws std::out_of_range for an unknown one.
  const std::string& person_id(world::ObjectId human) const {
    return persons_.at(human).report.person_id;
  }
  /// Forgets everyone (a world reset). Their ids stay theirs: a person met again after a reset is
  /// recognised as the same person.
  void clear() { persons_.clear(); }

 private:
  struct Person {
    PersonReport report;
    double last_tracked_s{0.0};
    EngagementTracker engagement;
  };

  const std::string& id_of(world::ObjectId human);

  PersonConfig config_;
  EngagementConfig engagement_config_;
  std::map<world::ObjectId, Person> persons_;
  TransientIds random_ids_;
  std::map<world::ObjectId, std::string> ids_;  ///< Every person id handed out in this run.
};

}  // namespace ari_social_sim::perception
