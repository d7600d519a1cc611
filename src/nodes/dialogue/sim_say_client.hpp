#pragma once

#include <ros/node_handle.h>
#include <ros/service_client.h>

#include <cstdint>
#include <string>

namespace ari_social_sim::nodes {

/// world_node's /sim/say as dialogue_node's world stage voices through it: one persistent
/// connection, made again when it broke (world_node restarted).
class SimSayClient {
 public:
  explicit SimSayClient(ros::NodeHandle& nh);

  /// Has `speaker_id` say `content` with `act`; false, logged, when the call fails or world_node
  /// refuses it.
  bool operator()(uint32_t speaker_id, const std::string& act, const std::string& content);

 private:
  ros::ServiceClient client_;
};

}  // namespace ari_social_sim::nodes
