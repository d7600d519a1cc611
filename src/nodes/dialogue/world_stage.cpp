#include "dialogue/world_stage.hpp"

#include <ros/console.h>

#include <optional>

#include "ari_social_sim/Say.h"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::nodes {

WorldStage::WorldStage(ros::NodeHandle& nh, uint32_t robot_id, std::vector<uint32_t> human_ids,
                       std::function<void()> on_state)
    : robot_id_(robot_id), human_ids_(std::move(human_ids)), on_state_(std::move(on_state)) {
  say_client_ = nh.serviceClient<Say>("/sim/say", /*persistent=*/true);
  // Every state counts: a word lasts 8 steps at 150 wpm and 0.05 s, an act at least that.
  state_sub_ = nh.subscribe("/sim/world_state", 100, &WorldStage::on_state, this);
}

void WorldStage::start_human(const dialogue::Utterance& utterance, size_t human) {
  say(human_, human_ids_.at(human), dialogue::world_act(utterance), utterance.text);
}

void WorldStage::start_robot(const std::string& text) {
  say(robot_, robot_id_, dialogue::kRobotSpeechAct, text);
}

void WorldStage::say(dialogue::SpeechPlayback& playback, uint32_t speaker_id,
                     const std::string& act, const std::string& content) {
  playback.begin(speaker_id, content, now_s_);
  Say say;
  say.request.speaker_id = speaker_id;
  say.request.act = act;
  say.request.content = content;
  if (!say_client_.isValid()) {
    say_client_ = ros::NodeHandle().serviceClient<Say>("/sim/say", /*persistent=*/true);
  }
  if (!say_client_.call(say) || !say.response.success) {
    // The world refused (speaker removed, world gone): nothing plays, the dialogue goes on.
    ROS_ERROR("/sim/say for %u failed: %s", speaker_id, say.response.message.c_str());
    playback.fail();
  }
}

namespace {

dialogue::SpeakerState speaker_state(const SpeechState& speech) {
  return {speech.is_speaking != 0, speech.content, speech.start_time, speech.word_index};
}

}  // namespace

void WorldStage::on_state(const WorldState::ConstPtr& state) {
  now_s_ = state->header.stamp.toSec();
  std::optional<dialogue::SpeakerState> robot, human;
  if (state->has_ari && state->ari.id == robot_.speaker_id()) {
    robot = speaker_state(state->ari.speech);
  }
  for (const HumanState& h : state->humans) {
    if (h.id == human_.speaker_id()) {
      human = speaker_state(h.speech);
    }
  }
  robot_.follow(robot ? &*robot : nullptr);
  human_.follow(human ? &*human : nullptr);
  on_state_();
}

}  // namespace ari_social_sim::nodes
