#include "dialogue/rl_env_services.hpp"

#include <algorithm>

#include "ari_social_sim/core/error.hpp"
#include "conversions/dialogue.hpp"
#include "dialogue/request_checks.hpp"

namespace ari_social_sim::nodes {
namespace {

// More acts than any MPGT utterance holds (at most 4) with room to spare; a list beyond it is a
// client's bug, refused before the NLG realises it.
constexpr size_t kMaxActs = 16;

// The action a step request asks for, every field checked first, so that a refused step leaves
// the episode as it was. Throws core::RequestError naming the field.
dialogue::RobotAction action_from(const DialogueStep::Request& req,
                                  const std::vector<std::string>& roles) {
  if (req.acts.size() > kMaxActs) {
    throw core::RequestError("acts: expected at most " + std::to_string(kMaxActs) + " acts, got " +
                             std::to_string(req.acts.size()));
  }
  for (size_t i = 0; i < req.acts.size(); ++i) {
    check_spoken_text(req.acts[i], "acts[" + std::to_string(i) + "]");
  }
  dialogue::RobotAction action;
  action.acts = acts_from_msg(req.acts, "acts");
  for (size_t i = 0; i < req.addressees.size(); ++i) {
    const std::string& addressee = req.addressees[i];
    const std::string field = "addressees[" + std::to_string(i) + "]";
    if (std::find(roles.begin(), roles.end(), addressee) == roles.end()) {
      check_spoken_text(addressee, field);  // so that the message below prints it safely
      throw core::RequestError(field + ": expected one of the humans' roles, got '" + addressee +
                               "'");
    }
    if (std::find(req.addressees.begin(), req.addressees.begin() + i, addressee) !=
        req.addressees.begin() + i) {
      throw core::RequestError(field + ": expected each role once, got '" + addressee + "' again");
    }
  }
  action.addressees = req.addressees;
  check_spoken_text(req.text, "text");
  action.text = req.text;
  return action;
}

}  // namespace

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
    const dialogue::StepResult result = env_.step(action_from(req, roles));
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
