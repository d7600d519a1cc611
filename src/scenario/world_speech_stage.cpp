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
    : simulation_(simulation), human_ids_(std::move(human_ids)), now_s_(simulation.time_s()) {}

uint32_t WorldSpeechStage::robot_id() const {
  return simulation_.ari() != nullptr ? simulation_.ari()->id() : 0;
}

void WorldSpeechStage::follow(const world::WorldSnapshot& snapshot) {
  now_s_ = snapshot.time_s;
  std::optional<dialogue::SpeakerState> robot, human;
  if (snapshot.ari && snapshot.ari->id == robot_.speaker_id()) {
    robot = speaker_state(snapshot.ari->speech);
  }
  for (const world::HumanSnapshot& h : snapshot.humans) {
    if (h.id == human_.speaker_id()) {
      human = speaker_state(h.speech);
    }
  }
  robot_.follow(robot ? &*robot : nullptr);
  human_.follow(human ? &*human : nullptr);
}

void WorldSpeechStage::start_human(const dialogue::Utterance& utterance, size_t human) {
  say(human_, human_ids_.at(human), dialogue::world_act(utterance), utterance.text);
}

void WorldSpeechStage::start_robot(const std::string& text) {
  say(robot_, robot_id(), dialogue::kRobotSpeechAct, text);
}

void WorldSpeechStage::say(dialogue::SpeechPlayback& playback, uint32_t speaker_id,
                           const std::string& act, const std::string& content) {
  playback.begin(speaker_id, content, now_s_);
  try {
    simulation_.speech_of(speaker_id).say(act, content, simulation_.time_s());
  } catch (const core::RequestError&) {
    playback.fail();  // as /sim/say refusing: nothing plays, the dialogue goes on
  }
}

}  // namespace ari_social_sim::scenario
