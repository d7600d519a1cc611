#include "ari_social_sim/perception/speech_listener.hpp"

#include <algorithm>

#include "ari_social_sim/perception/grid_raycast.hpp"

namespace ari_social_sim::perception {

SpeechListener::SpeechListener(const PerceptionConfig& config, TransientIds& ids, core::Rng rng)
    : config_(config),
      ids_(ids),
      rng_(rng.next_u64()),
      asr_(config.speech_errors, core::Rng(rng.next_u64())) {}

void SpeechListener::clear() {
  utterances_.clear();
  voices_.clear();
}

SpeechListener::VoiceTrack& SpeechListener::voice_of(model::ObjectId human) {
  VoiceTrack& voice = voices_[human];
  if (voice.id.empty()) {
    voice.id = ids_.next();
  }
  return voice;
}

void SpeechListener::finish(const Utterance& utterance, double now_s) {
  VoiceTrack& voice = voice_of(utterance.voice_owner);
  voice.last_active_s = now_s;
  if (!utterance.transcript.empty()) {
    voice.results.push_back(
        {"", join_words(utterance.transcript), 1.0 - config_.speech_errors.word_error_rate});
  }
}

SpeechListener::Hearing SpeechListener::hearing(const std::vector<world::HumanSnapshot>& humans,
                                                const AriSensors& sensors,
                                                const model::OccupancyGrid* sound_map,
                                                int occupied_threshold) const {
  Hearing hearing;
  hearing.audible.assign(humans.size(), false);
  const double radius_m = config_.occlusion.person_radius_m;
  for (size_t i = 0; i < humans.size(); ++i) {
    const Eigen::Vector2d& position = humans[i].pose.position;
    hearing.index_of[humans[i].id] = i;
    const Eigen::Vector2d to_speaker = position - sensors.microphone;
    const double distance_m = to_speaker.norm();
    // As for sight (visibility.hpp): a seated speaker sits on a chair the map holds (it has no
    // heights) and the voice rises over it, so the map is read only up to one body radius
    // short of their circle; a standing speaker's voice is checked all the way.
    const double margin_m = humans[i].posture.is_standing() ? 0.0 : 2.0 * radius_m;
    const Eigen::Vector2d heard_from =
        distance_m > margin_m ? position - margin_m / distance_m * to_speaker : sensors.microphone;
    hearing.audible[i] = distance_m <= sensors.listening_range_m &&
                         (sound_map == nullptr || segment_is_clear(*sound_map, occupied_threshold,
                                                                   sensors.microphone, heard_from));
  }
  return hearing;
}

void SpeechListener::finish_ended_utterances(const std::vector<world::HumanSnapshot>& humans,
                                             const Hearing& hearing, double now_s) {
  for (auto it = utterances_.begin(); it != utterances_.end();) {
    const auto found = hearing.index_of.find(it->first);
    const bool goes_on = found != hearing.index_of.end() && hearing.audible[found->second] &&
                         humans[found->second].speech.is_speaking &&
                         humans[found->second].speech.start_s == it->second.start_s;
    if (goes_on) {
      ++it;
    } else {
      finish(it->second, now_s);
      it = utterances_.erase(it);
    }
  }
}

void SpeechListener::begin_utterance(const std::vector<world::HumanSnapshot>& humans,
                                     const Hearing& hearing, size_t speaker, Utterance& utterance) {
  const world::SpeechSnapshot& speech = humans[speaker].speech;
  utterance.start_s = speech.start_s;
  utterance.words = split_words(speech.content);
  // Words said before the speaker came within hearing are lost.
  utterance.last_heard = static_cast<int>(speech.word_index) - 1;
  utterance.voice_owner = humans[speaker].id;
  const double misattribution = config_.speech_errors.misattribution_rate;
  if (misattribution > 0.0 && rng_.bernoulli(misattribution)) {
    std::vector<model::ObjectId> others;
    for (size_t j = 0; j < humans.size(); ++j) {
      if (j != speaker && hearing.audible[j]) {
        others.push_back(humans[j].id);
      }
    }
    if (!others.empty()) {
      utterance.voice_owner = others[rng_.uniform_index(others.size())];
    }
  }
}

void SpeechListener::hear_new_words(const std::vector<world::HumanSnapshot>& humans,
                                    const Hearing& hearing, double now_s) {
  const double confidence = 1.0 - config_.speech_errors.word_error_rate;
  for (size_t i = 0; i < humans.size(); ++i) {
    const world::SpeechSnapshot& speech = humans[i].speech;
    if (!hearing.audible[i] || !speech.is_speaking) {
      continue;
    }
    auto [it, is_new] = utterances_.try_emplace(humans[i].id);
    Utterance& utterance = it->second;
    if (is_new) {
      begin_utterance(humans, hearing, i, utterance);
    }
    const size_t before = utterance.transcript.size();
    const int current =
        std::min(static_cast<int>(speech.word_index), static_cast<int>(utterance.words.size()) - 1);
    for (int word = utterance.last_heard + 1; word <= current; ++word) {
      asr_.hear(utterance.words[static_cast<size_t>(word)], utterance.transcript);
    }
    utterance.last_heard = std::max(utterance.last_heard, current);
    VoiceTrack& voice = voice_of(utterance.voice_owner);
    voice.active = true;
    voice.last_active_s = now_s;
    if (utterance.transcript.size() != before) {
      voice.transcript = join_words(utterance.transcript);
      voice.results.push_back({voice.transcript, "", confidence});
    }
  }
}

void SpeechListener::report_voices(const std::vector<world::HumanSnapshot>& humans,
                                   const Hearing& hearing, double now_s,
                                   std::vector<PerceivedVoice>& voices) {
  for (auto it = voices_.begin(); it != voices_.end();) {
    const auto found = hearing.index_of.find(it->first);
    if (found == hearing.index_of.end()) {
      it = voices_.erase(it);
      continue;
    }
    VoiceTrack& voice = it->second;
    if (voice.active || now_s - voice.last_active_s <= config_.microphone.voice_timeout_s) {
      PerceivedVoice perceived;
      perceived.human = it->first;
      perceived.voice_id = voice.id;
      perceived.position = humans[found->second].pose.position;
      perceived.is_speaking = voice.active;
      perceived.speech = std::move(voice.results);
      perceived.transcript = voice.transcript;
      voices.push_back(std::move(perceived));
    }
    ++it;
  }
}

void SpeechListener::update(const world::WorldSnapshot& snapshot, const AriSensors& sensors,
                            const model::OccupancyGrid* sound_map, int occupied_threshold,
                            std::vector<PerceivedVoice>& voices) {
  const Hearing heard = hearing(snapshot.humans, sensors, sound_map, occupied_threshold);
  for (auto& [owner, voice] : voices_) {
    voice.active = false;
    voice.results.clear();
  }
  // Utterances end with their act, when another act starts, or when the speaker goes out of
  // hearing or out of the world.
  finish_ended_utterances(snapshot.humans, heard, snapshot.time_s);
  hear_new_words(snapshot.humans, heard, snapshot.time_s);
  // Report the voices in use; forget those whose owner left the world.
  report_voices(snapshot.humans, heard, snapshot.time_s, voices);
}

}  // namespace ari_social_sim::perception
