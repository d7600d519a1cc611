#include "ari_social_sim/scenario/world_speech_stage.hpp"

#include <optional>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::scenario {
namespace {

dialogue::SpeakerState speaker_state(const world::SpeechSnapshot& speech) {
  return {speech.is_speaking, speech.content, speech.start_s, speech.word_index};
}

}  // namespace

WorldSpeechStage::WorldSpeechStage(world::Simulation& simulation, std::vector<uint32_t> human_ids)
    : PlaybackStage(std::move(human_ids)), simulation_(simulation) {}

uint32_t WorldSpeechStage::robot_id() const {
  return simulation_.ari() != nullptr ? simulation_.ari()->id() : 0;
}

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
  try {
    simulation_.say(speaker_id, act, content);
  } catch (const core::RequestError&) {
    return false;  // as /sim/say refusing
  }
  return true;
}

}  // namespace ari_social_sim::scenario
