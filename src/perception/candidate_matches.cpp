#include "ari_social_sim/perception/candidate_matches.hpp"

#include <algorithm>

#include "ari_social_sim/perception/observations_by_human.hpp"

namespace ari_social_sim::perception {

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
  const double now = frame.time_s;
  for (auto it = recognised_.begin(); it != recognised_.end();) {
    const double age_s = now - it->second.last_seen_s;
    it = age_s > kVerdictMemory_s || age_s < 0.0 ? recognised_.erase(it) : std::next(it);
  }
  std::vector<CandidateMatch> matches;
  const auto bodies = observations_by_human(frame.bodies);
  for (const PerceivedFace& face : frame.faces) {
    auto [verdict, is_new] = recognised_.try_emplace(face.face_id);
    if (is_new) {
      verdict->second.recognised = rng_.uniform() < config_.recognition_rate;
    }
    verdict->second.last_seen_s = now;
    if (verdict->second.recognised) {
      send(matches, {face.person_id, IdKind::kPerson, face.face_id, IdKind::kFace,
                     noisy(config_.recognition_confidence)});
    }
    if (const PerceivedBody* body = observation_of(bodies, face.human)) {
      send(matches, {body->body_id, IdKind::kBody, face.face_id, IdKind::kFace,
                     noisy(config_.face_body_confidence)});
    }
  }
  for (const PerceivedVoice& voice : frame.voices) {
    if (const PerceivedBody* body = observation_of(bodies, voice.human)) {
      send(matches, {body->body_id, IdKind::kBody, voice.voice_id, IdKind::kVoice,
                     noisy(config_.voice_body_confidence)});
    }
  }
  return matches;
}

}  // namespace ari_social_sim::perception
