#include "rl_env_services.hpp"

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/robot_action_request.hpp"
#include "dialogue_conversions/dialogue.hpp"

namespace ari_social_sim::nodes {

RlEnvServices::RlEnvServices(ros::NodeHandle& nh, const dialogue::DialogueSetup& setup)
    : setup_(setup), env_(setup) {
  reset_service_ = nh.advertiseService("/sim/dialogue/reset", &RlEnvServices::reset, this);
  step_service_ = nh.advertiseService("/sim/dialogue/step", &RlEnvServices::step, this);
}

bool RlEnvServices::reset(DialogueReset::Request& req, DialogueReset::Response& res) {
  const dialogue::Observation observation = env_.reset(req.seed);
  started_ = true;
  res.success = true;
  res.observation = to_msg(observation);
  res.info = to_msg(env_.current_info(), setup_.config.users.roles);
  return true;
}

bool RlEnvServices::step(DialogueStep::Request& req, DialogueStep::Response& res) {
  try {
    if (!started_) {
      throw core::RequestError("no episode: call /sim/dialogue/reset first");
    }
    if (env_.episode_over()) {
      throw core::RequestError("the episode is over: call /sim/dialogue/reset");
    }
    const std::vector<std::string>& roles = setup_.config.users.roles;
    const dialogue::StepResult result =
        env_.step(dialogue::robot_action_from(req.acts, req.addressees, req.text, roles));
    res.success = true;
    res.observation = to_msg(result.observation);
    res.reward = result.reward;
    res.terminated = result.terminated;
    res.truncated = result.truncated;
    res.info = to_msg(result.info, roles);
  } catch (const core::Error& e) {
    res.success = false;
    res.message = e.what();
    ROS_WARN("%s", e.what());
  }
  return true;
}

}  // namespace ari_social_sim::nodes
