#include "sim_say_client.hpp"

#include <ros/console.h>

#include "ari_social_sim/Say.h"

namespace ari_social_sim::nodes {

SimSayClient::SimSayClient(ros::NodeHandle& nh)
    : client_(nh.serviceClient<Say>("/sim/say", /*persistent=*/true)) {}

bool SimSayClient::operator()(uint32_t speaker_id, const std::string& act,
                              const std::string& content) {
  Say say;
  say.request.speaker_id = speaker_id;
  say.request.act = act;
  say.request.content = content;
  if (!client_.isValid()) {
    client_ = ros::NodeHandle().serviceClient<Say>("/sim/say", /*persistent=*/true);
  }
  if (!client_.call(say) || !say.response.success) {
    ROS_ERROR("/sim/say for %u failed: %s", speaker_id, say.response.message.c_str());
    return false;
  }
  return true;
}

}  // namespace ari_social_sim::nodes
