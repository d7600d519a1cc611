#include "dialogue/world_stage.hpp"

#include <ros/console.h>

#include <optional>

#include "ari_social_sim/Say.h"

namespace ari_social_sim::nodes {
namespace {

dialogue::SpeakerState speaker_state(const SpeechState& speech) {
  return {speech.is_speaking != 0, speech.content, speech.start_time, speech.word_index};
}

}  // namespace

WorldStage::WorldStage(ros::NodeHandle& nh, uint32_t robot_id, std::vector<uint32_t> human_ids,
                       std::function<void()> on_state)
    : PlaybackStage(std::move(human_ids)), robot_id_(robot_id), on_state_(std::move(on_state)) {
  say_client_ = nh.serviceClient<Say>("/sim/say", /*persistent=*/true);
  // Every state counts: a word lasts 8 steps at 150 wpm and 0.05 s, an act at least that.
  state_sub_ = nh.subscribe("/sim/world_state", 100, &WorldStage::on_state, this);
}

bool WorldStage::play(uint32_t speaker_id, const std::string& act, const std::string& content) {
  Say say;
  say.request.speaker_id = speaker_id;
  say.request.act = act;
  say.request.content = content;
  if (!say_client_.isValid()) {
    say_client_ = ros::NodeHandle().serviceClient<Say>("/sim/say", /*persistent=*/true);
  }
  if (!say_client_.call(say) || !say.response.success) {
    ROS_ERROR("/sim/say for %u failed: %s", speaker_id, say.response.message.c_str());
    return false;
  }
  return true;
}

void WorldStage::on_state(const WorldState::ConstPtr& state) {
  std::optional<dialogue::SpeakerState> robot, human;
  if (state->has_ari && state->ari.id == robot_speaker()) {
    robot = speaker_state(state->ari.speech);
  }
  for (const HumanState& h : state->humans) {
    if (h.id == human_speaker()) {
      human = speaker_state(h.speech);
    }
  }
  follow(state->header.stamp.toSec(), robot ? &*robot : nullptr, human ? &*human : nullptr);
  on_state_();
}

}  // namespace ari_social_sim::nodes
