#include "ari_social_sim/perception/person_registry.hpp"

#include <algorithm>

#include "ari_social_sim/perception/observations_by_human.hpp"

namespace ari_social_sim::perception {
namespace {

ProxemicSpace zone_of(const PersonConfig& config, double distance_m) {
  if (distance_m <= config.personal_distance_m) {
    return ProxemicSpace::kPersonal;
  }
  if (distance_m <= config.social_distance_m) {
    return ProxemicSpace::kSocial;
  }
  return distance_m <= config.public_distance_m ? ProxemicSpace::kPublic : ProxemicSpace::kUnknown;
}

}  // namespace

PersonRegistry::PersonRegistry(const PersonConfig& persons, const EngagementConfig& engagement,
                               core::Rng id_rng)
    : config_(persons), engagement_config_(engagement), random_ids_(id_rng) {}

std::string PersonRegistry::id_of(model::ObjectId human) {
  if (config_.id_style != "random") {
    return person_id_of(human);
  }
  auto [it, is_new] = random_ids_by_human_.try_emplace(human);
  if (is_new) {
    it->second = "anonymous_person_" + random_ids_.next();
  }
  return it->second;
}

size_t PersonRegistry::engagement_samples() const {
  size_t samples = 0;
  for (const auto& [human, person] : persons_) {
    samples += person.engagement.history_size();
  }
  return samples;
}

void PersonRegistry::forget(const world::WorldSnapshot& snapshot) {
  const double now = snapshot.time_s;
  for (auto it = persons_.begin(); it != persons_.end();) {
    const bool forgotten =
        !it->second.report.tracked && now - it->second.last_tracked_s > config_.forget_after_s;
    it = forgotten ? persons_.erase(it) : std::next(it);
  }
  if (random_ids_by_human_.empty()) {
    return;
  }
  std::vector<model::ObjectId> in_world;
  in_world.reserve(snapshot.humans.size());
  for (const world::HumanSnapshot& human : snapshot.humans) {
    in_world.push_back(human.id);
  }
  std::sort(in_world.begin(), in_world.end());
  for (auto it = random_ids_by_human_.begin(); it != random_ids_by_human_.end();) {
    const bool released = persons_.count(it->first) == 0 &&
                          !std::binary_search(in_world.begin(), in_world.end(), it->first);
    it = released ? random_ids_by_human_.erase(it) : std::next(it);
  }
}

void PersonRegistry::update(const world::WorldSnapshot& snapshot, const AriSensors* sensors,
                            const std::vector<PerceivedBody>& bodies,
                            const std::vector<PerceivedFace>& faces,
                            const std::vector<PerceivedVoice>& voices,
                            std::vector<PersonReport>& reports) {
  const double now = snapshot.time_s;
  // Untracked unless something of theirs is seen or heard below (removed humans included).
  for (auto& [human, person] : persons_) {
    person.report.tracked = false;
  }
  const auto bodies_by_human = observations_by_human(bodies);
  const auto faces_by_human = observations_by_human(faces);
  const auto voices_by_human = observations_by_human(voices);
  for (const world::HumanSnapshot& human : snapshot.humans) {
    const PerceivedBody* body = observation_of(bodies_by_human, human.id);
    const PerceivedFace* face = observation_of(faces_by_human, human.id);
    const PerceivedVoice* voice = observation_of(voices_by_human, human.id);
    if (body == nullptr && face == nullptr && voice == nullptr) {
      continue;
    }
    auto it = persons_.find(human.id);
    if (it == persons_.end()) {
      it = persons_.emplace(human.id, Person{{}, now, EngagementTracker(engagement_config_)}).first;
      it->second.report.human = human.id;
      it->second.report.person_id = id_of(human.id);
    }
    Person& person = it->second;
    PersonReport& report = person.report;
    report.name = human.name;
    report.tracked = true;
    person.last_tracked_s = now;
    report.face_id = face != nullptr ? face->face_id : "";
    report.body_id = body != nullptr ? body->body_id : "";
    report.voice_id = voice != nullptr ? voice->voice_id : "";
    report.location = face != nullptr   ? face->X_map_face.position
                      : body != nullptr ? body->X_map_body.position
                                        : voice->position;
    report.engagement_score =
        face != nullptr && sensors != nullptr
            ? engagement_score(engagement_config_, sensors->face_camera.X_map_sensor,
                               {face->X_map_face.position, face->gaze_rad})
            : 0.0;
    report.engagement = person.engagement.update(now, report.engagement_score);
    report.proxemic_space =
        snapshot.ari ? zone_of(config_, (report.location - snapshot.ari->pose.position).norm())
                     : ProxemicSpace::kUnknown;
  }

  forget(snapshot);
  reports.clear();
  for (auto& [human, person] : persons_) {
    PersonReport& report = person.report;
    if (!report.tracked) {
      report.face_id.clear();
      report.body_id.clear();
      report.voice_id.clear();
      report.engagement_score = 0.0;
      person.engagement.reset();
      report.engagement = EngagementLevel::kUnknown;
      report.proxemic_space = ProxemicSpace::kUnknown;
    }
    report.location_confidence =
        std::max(0.0, 1.0 - (now - person.last_tracked_s) / config_.location_decay_s);
    reports.push_back(report);
  }
}

}  // namespace ari_social_sim::perception
