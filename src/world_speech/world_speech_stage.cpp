#include "ari_social_sim/world_speech/world_speech_stage.hpp"

#include <optional>

namespace ari_social_sim::world_speech {
namespace {

dialogue::SpeakerState speaker_state(const world::SpeechSnapshot& speech) {
  return {speech.is_speaking, speech.content, speech.start_s, speech.word_index};
}

}  // namespace

WorldSpeechStage::WorldSpeechStage(uint32_t robot_id, std::vector<uint32_t> human_ids, Voice voice)
    : PlaybackStage(std::move(human_ids)), robot_id_(robot_id), voice_(std::move(voice)) {}

void WorldSpeechStage::follow(const world::WorldSnapshot& snapshot) {
  std::optional<dialogue::SpeakerState> robot, human;
  if (snapshot.ari && snapshot.ari->id == robot_speaker()) {
    robot = speaker_state(snapshot.ari->speech);
  }
  for (const world::HumanSnapshot& h : snapshot.humans) {
    if (h.id == human_speaker()) {
      human = speaker_state(h.speech);
    }
  }
  PlaybackStage::follow(snapshot.time_s, robot ? &*robot : nullptr, human ? &*human : nullptr);
}

bool WorldSpeechStage::play(uint32_t speaker_id, const std::string& act,
                            const std::string& content) {
  return voice_(speaker_id, act, content);
}

}  // namespace ari_social_sim::world_speech
