#include "ari_social_sim/perception/candidate_matches.hpp"

#include <algorithm>

namespace ari_social_sim::perception {
namespace {

// The observation of `human` in a list ordered by human id, or null.
template <class Observation>
const Observation* observation_of(const std::vector<Observation>& observations,
                                  world::ObjectId human) {
  const auto it = std::lower_bound(
      observations.begin(), observations.end(), human,
      [](const Observation& observation, world::ObjectId id) { return observation.human < id; });
  return it != observations.end() && it->human == human ? &*it : nullptr;
}

}  // namespace

std::vector<CandidateMatch> person_links(const PerceptionFrame& frame) {
  std::vector<CandidateMatch> matches;
  for (const PerceivedBody& body : frame.bodies) {
    matches.push_back({body.body_id, IdKind::kBody, body.person_id, IdKind::kPerson, 1.0});
  }
  for (const PerceivedFace& face : frame.faces) {
    matches.push_back({face.face_id, IdKind::kFace, face.person_id, IdKind::kPerson, 1.0});
  }
  for (const PerceivedVoice& voice : frame.voices) {
    matches.push_back({voice.voice_id, IdKind::kVoice, voice.person_id, IdKind::kPerson, 1.0});
  }
  return matches;
}

double CandidateMatcher::noisy(double confidence) {
  if (config_.confidence_noise <= 0.0) {
    return confidence;
  }
  return std::clamp(confidence + rng_.normal(0.0, config_.confidence_noise), 0.0, 1.0);
}

void CandidateMatcher::send(std::vector<CandidateMatch>& matches, CandidateMatch match) const {
  if (match.confidence > config_.threshold) {
    matches.push_back(std::move(match));
  }
}

std::vector<CandidateMatch> CandidateMatcher::update(const PerceptionFrame& frame) {
  std::vector<CandidateMatch> matches;
  std::unordered_map<std::string, bool> recognised;
  for (const PerceivedFace& face : frame.faces) {
    const auto known = recognised_.find(face.face_id);
    const bool is_recognised =
        known != recognised_.end() ? known->second : rng_.uniform() < config_.recognition_rate;
    recognised.emplace(face.face_id, is_recognised);
    if (is_recognised) {
      send(matches, {face.person_id, IdKind::kPerson, face.face_id, IdKind::kFace,
                     noisy(config_.recognition_confidence)});
    }
    if (const PerceivedBody* body = observation_of(frame.bodies, face.human)) {
      send(matches, {body->body_id, IdKind::kBody, face.face_id, IdKind::kFace,
                     noisy(config_.face_body_confidence)});
    }
  }
  recognised_ = std::move(recognised);
  for (const PerceivedVoice& voice : frame.voices) {
    if (const PerceivedBody* body = observation_of(frame.bodies, voice.human)) {
      send(matches, {body->body_id, IdKind::kBody, voice.voice_id, IdKind::kVoice,
                     noisy(config_.voice_body_confidence)});
    }
  }
  return matches;
}

}  // namespace ari_social_sim::perception
