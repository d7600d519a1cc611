#pragma once

#include <ros/node_handle.h>
#include <ros/service_client.h>
#include <ros/subscriber.h>

#include <functional>
#include <vector>

#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/dialogue/speech_playback.hpp"
#include "ari_social_sim/dialogue/speech_stage.hpp"

namespace ari_social_sim::nodes {

/// Mode 1: utterances voiced by the world's speakers through world_node's /sim/say (ARI's with the
/// act `tts`), followed on /sim/world_state (sim time) by dialogue::SpeechPlayback.
class WorldStage : public dialogue::SpeechStage {
 public:
  /// `on_state` runs after each world state (the node's tick). `human_ids` follows the roles.
  WorldStage(ros::NodeHandle& nh, uint32_t robot_id, std::vector<uint32_t> human_ids,
             std::function<void()> on_state);

  double now_s() const override { return now_s_; }
  bool has_listener() const override { return true; }
  void start_human(const dialogue::Utterance& utterance, size_t human) override;
  bool human_done() override { return human_.done(); }
  void start_robot(const std::string& text) override;
  size_t robot_words_started() override { return robot_.words_started(); }
  bool robot_done() override { return robot_.done(); }
  uint32_t human_id(size_t human) const override { return human_ids_.at(human); }
  uint32_t robot_id() const override { return robot_id_; }

 private:
  void say(dialogue::SpeechPlayback& playback, uint32_t speaker_id, const std::string& act,
           const std::string& content);
  void on_state(const WorldState::ConstPtr& state);

  uint32_t robot_id_;
  std::vector<uint32_t> human_ids_;
  std::function<void()> on_state_;
  double now_s_{0.0};
  dialogue::SpeechPlayback human_, robot_;
  ros::ServiceClient say_client_;
  ros::Subscriber state_sub_;
};

}  // namespace ari_social_sim::nodes
