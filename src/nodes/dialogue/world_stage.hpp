#pragma once

#include <ros/node_handle.h>
#include <ros/service_client.h>
#include <ros/subscriber.h>

#include <functional>
#include <vector>

#include "ari_social_sim/WorldState.h"
#include "dialogue/speech_stage.hpp"

namespace ari_social_sim::nodes {

/// Mode 1: utterances voiced by the world's speakers through world_node's /sim/say, followed on
/// /sim/world_state (sim time). An utterance counts as started when the world shows its speaker
/// saying that content with a start time at or after the call, and as played when the world shows
/// the speaker silent or saying something else.
class WorldStage : public SpeechStage {
 public:
  /// `on_state` runs after each world state (the node's tick). `human_ids` follows the roles.
  WorldStage(ros::NodeHandle& nh, uint32_t robot_id, std::vector<uint32_t> human_ids,
             std::function<void()> on_state);

  double now_s() const override { return now_s_; }
  bool has_listener() const override { return true; }
  void start_human(const dialogue::Utterance& utterance, size_t human) override;
  bool human_done() override { return human_.done; }
  void start_robot(const std::string& text) override;
  size_t robot_words_started() override { return robot_.words_started; }
  bool robot_done() override { return robot_.done; }
  uint32_t human_id(size_t human) const override { return human_ids_.at(human); }
  uint32_t robot_id() const override { return robot_id_; }

 private:
  /// One utterance handed to the world and followed there.
  struct Playback {
    uint32_t speaker_id{0};
    std::string content;
    double called_s{0.0};  ///< sim time of the say call
    bool started{false};
    double start_time_s{0.0};  ///< the world's start time of the act
    size_t words_started{0};
    bool done{true};
  };

  void say(Playback& playback, uint32_t speaker_id, const std::string& act,
           const std::string& content);
  void follow(Playback& playback, const SpeechState& speech);
  void on_state(const WorldState::ConstPtr& state);

  uint32_t robot_id_;
  std::vector<uint32_t> human_ids_;
  std::function<void()> on_state_;
  double now_s_{0.0};
  Playback human_, robot_;
  ros::ServiceClient say_client_;
  ros::Subscriber state_sub_;
};

}  // namespace ari_social_sim::nodes
