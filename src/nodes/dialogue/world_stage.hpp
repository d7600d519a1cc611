#pragma once

#include <ros/node_handle.h>
#include <ros/service_client.h>
#include <ros/subscriber.h>

#include <functional>
#include <vector>

#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/dialogue/playback_stage.hpp"

namespace ari_social_sim::nodes {

/// Mode 1: utterances voiced by the world's speakers through world_node's /sim/say (ARI's with the
/// act `tts`), followed on /sim/world_state (sim time).
class WorldStage : public dialogue::PlaybackStage {
 public:
  /// `on_state` runs after each world state (the node's tick). `human_ids` follows the roles.
  WorldStage(ros::NodeHandle& nh, uint32_t robot_id, std::vector<uint32_t> human_ids,
             std::function<void()> on_state);

  uint32_t robot_id() const override { return robot_id_; }

 private:
  bool play(uint32_t speaker_id, const std::string& act, const std::string& content) override;
  void on_state(const WorldState::ConstPtr& state);

  uint32_t robot_id_;
  std::function<void()> on_state_;
  ros::ServiceClient say_client_;
  ros::Subscriber state_sub_;
};

}  // namespace ari_social_sim::nodes
