#include "dialogue/world_stage.hpp"

#include <ros/console.h>

#include "ari_social_sim/Say.h"
#include "ari_social_sim/dialogue/dialogue_act.hpp"
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
  const std::string act =
      utterance.acts.empty() ? "none" : dialogue::acts_to_string(utterance.acts);
  say(human_, human_ids_.at(human), act, utterance.text);
}

void WorldStage::start_robot(const std::string& text) {
  say(robot_, robot_id_, "tts", text);
}

void WorldStage::say(Playback& playback, uint32_t speaker_id, const std::string& act,
                     const std::string& content) {
  playback = Playback{};
  playback.speaker_id = speaker_id;
  playback.content = content;
  playback.called_s = now_s_;
  playback.done = false;
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
    playback.done = true;
  }
}

void WorldStage::follow(Playback& playback, const SpeechState& speech) {
  if (playback.done) {
    return;
  }
  const bool saying_it = speech.is_speaking && speech.content == playback.content &&
                         speech.start_time >= playback.called_s - 1e-9;
  if (!playback.started) {
    if (saying_it) {
      playback.started = true;
      playback.start_time_s = speech.start_time;
      playback.words_started = speech.word_index + 1;
    }
    return;
  }
  if (saying_it && speech.start_time == playback.start_time_s) {
    playback.words_started = speech.word_index + 1;
  } else {
    // Played to its end: every word was started, including any whose states this node missed.
    playback.words_started = dialogue::split_words(playback.content).size();
    playback.done = true;
  }
}

void WorldStage::on_state(const WorldState::ConstPtr& state) {
  now_s_ = state->header.stamp.toSec();
  if (state->has_ari && state->ari.id == robot_.speaker_id) {
    follow(robot_, state->ari.speech);
  } else {
    robot_.done = true;  // no ARI in the world (any more): nothing can play
  }
  bool human_found = false;
  for (const HumanState& human : state->humans) {
    if (human.id == human_.speaker_id) {
      follow(human_, human.speech);
      human_found = true;
    }
  }
  // A speaker removed from the world mid-utterance has stopped speaking.
  human_.done = human_.done || !human_found;
  on_state_();
}

}  // namespace ari_social_sim::nodes
