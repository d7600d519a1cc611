#include "ari_social_sim/dialogue/playback_stage.hpp"

namespace ari_social_sim::dialogue {

void PlaybackStage::start_human(const Utterance& utterance, size_t human) {
  say(human_, human_ids_.at(human), world_act(utterance), utterance.text);
}

void PlaybackStage::start_robot(const std::string& text) {
  say(robot_, robot_id(), kRobotSpeechAct, text);
}

void PlaybackStage::say(SpeechPlayback& playback, uint32_t speaker_id, const std::string& act,
                        const std::string& content) {
  playback.begin(speaker_id, content, now_s_);
  if (!play(speaker_id, act, content)) {
    playback.fail();  // the world refused (speaker removed, world gone): the dialogue goes on
  }
}

void PlaybackStage::follow(double now_s, const SpeakerState* robot, const SpeakerState* human) {
  now_s_ = now_s;
  robot_.follow(robot);
  human_.follow(human);
}

}  // namespace ari_social_sim::dialogue
