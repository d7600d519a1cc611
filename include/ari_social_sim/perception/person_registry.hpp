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

/// The person manager (hri_person_manager's role): one person per simulated human, named by
/// PersonConfig::id_style, linked to that human's face, body and voice of the frame. A person is
/// tracked while any of the three is, and known from the first time it is until it has gone
/// unseen for forget_after (then it is forgotten and its state released; a human seen again is a
/// person again). Its location is the face if seen, else the body, else the voice; once untracked
/// it stays at the last place while location_confidence falls linearly from 1 to 0 over
/// location_decay. Engagement is scored from the perceived face and ARI's head (no face: score 0)
/// and reset to UNKNOWN when untracked; so is the proxemic zone, from the distance between ARI's
/// base and the person's location.
///
/// Ids: in the "human" style a person id is a function of the human (`human<N>`), so a forgotten
/// human comes back under the same id. In the "random" style the registry remembers the id drawn
/// for each human while the human is in the world or known, so a forgotten human still in the
/// world comes back under the same id too; the id of a human gone from the world and forgotten is
/// released (a later human reusing the world id gets a new person id). Memory thus grows with the
/// humans in the world plus those unseen for less than forget_after, not with the run's length.
class PersonRegistry {
 public:
  /// `id_rng` draws the ids of the "random" id style.
  PersonRegistry(const PersonConfig& persons, const EngagementConfig& engagement, core::Rng id_rng);

  /// Updates every person from this frame's observations (each list ordered by human id) and
  /// writes a report per known person, ordered by human id. `sensors` is null without ARI.
  void update(const world::WorldSnapshot& snapshot, const AriSensors* sensors,
              const std::vector<PerceivedBody>& bodies, const std::vector<PerceivedFace>& faces,
              const std::vector<PerceivedVoice>& voices, std::vector<PersonReport>& reports);

  bool is_known(model::ObjectId human) const { return persons_.count(human) > 0; }
  /// The person id of a known human; throws std::out_of_range for an unknown one.
  const std::string& person_id(model::ObjectId human) const {
    return persons_.at(human).report.person_id;
  }
  /// Forgets everyone (a world reset). Their ids stay theirs: a person met again after a reset is
  /// recognised as the same person.
  void clear() { persons_.clear(); }

  /// Persons known now.
  size_t known_count() const { return persons_.size(); }
  /// "random" style: person ids remembered (humans in the world or known); 0 in the "human" style.
  size_t remembered_id_count() const { return random_ids_by_human_.size(); }
  /// Frames in the engagement histories of all known persons.
  size_t engagement_samples() const;

 private:
  struct Person {
    PersonReport report;
    double last_tracked_s{0.0};
    EngagementTracker engagement;
  };

  std::string id_of(model::ObjectId human);
  /// Forgets persons unseen for more than forget_after, then the random ids of humans that are
  /// neither in `snapshot` nor known.
  void forget(const world::WorldSnapshot& snapshot);

  PersonConfig config_;
  EngagementConfig engagement_config_;
  std::map<model::ObjectId, Person> persons_;
  TransientIds random_ids_;
  std::map<model::ObjectId, std::string> random_ids_by_human_;  ///< "random" style only.
};

}  // namespace ari_social_sim::perception
