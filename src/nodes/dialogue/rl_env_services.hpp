#pragma once

#include <ros/node_handle.h>
#include <ros/service_server.h>

#include "ari_social_sim/DialogueReset.h"
#include "ari_social_sim/DialogueStep.h"
#include "ari_social_sim/dialogue/dialogue_env.hpp"

namespace ari_social_sim::nodes {

/// Mode 2: the dialogue RL environment as two services, /sim/dialogue/reset (seed -> observation,
/// info) and /sim/dialogue/step (robot acts -> observation, reward, terminated, truncated, info).
/// A bad request (unknown intent, more than 16 acts, an unknown or repeated addressee, text over
/// 4 KiB or not UTF-8, no episode) gets success = false and the reason, naming the field; the
/// episode is left as it was.
class RlEnvServices {
 public:
  /// Holds a reference to the setup, which must outlive it.
  RlEnvServices(ros::NodeHandle& nh, const dialogue::DialogueSetup& setup);

 private:
  bool reset(DialogueReset::Request& req, DialogueReset::Response& res);
  bool step(DialogueStep::Request& req, DialogueStep::Response& res);

  const dialogue::DialogueSetup& setup_;
  dialogue::DialogueEnv env_;
  bool started_{false};
  ros::ServiceServer reset_service_, step_service_;
};

}  // namespace ari_social_sim::nodes
