#include "ari_social_sim/dialogue/dialogue_env.hpp"

#include <algorithm>

namespace ari_social_sim::dialogue {

DialogueEnv::DialogueEnv(const DialogueSetup& setup)
    : setup_(setup),
      users_(setup.config.users, setup.domain, setup.model, setup.config.model_file, *setup.nlg,
             *setup.errors, *setup.timing) {}

Observation DialogueEnv::reset(uint64_t seed, Opening opening) {
  rng_ = core::Rng(seed);
  transcript_.clear();
  robot_turns_ = 0;
  humans_finished_ = false;
  over_ = false;
  users_.reset(rng_);
  // The draw is made either way, so that the rest of the episode's draws do not depend on it.
  const bool robot_opens = rng_.bernoulli(setup_.model.robot_opens);
  if (!robot_opens && opening == Opening::kDrawn) {
    users_.open(transcript_, rng_);
  }
  return observe(0);
}

StepResult DialogueEnv::step(const RobotAction& action) {
  ++robot_turns_;
  const size_t first_new = transcript_.size();
  bool terminated = false;
  bool robot_said_bye = false;
  if (!action.acts.empty() || !action.text.empty()) {
    Utterance u;
    u.turn = static_cast<int>(transcript_.size());
    u.speaker = kRobot;
    u.addressees = action.addressees;
    if (u.addressees.empty()) {
      // The human who last spoke to ARI, else everyone.
      for (auto it = transcript_.rbegin(); it != transcript_.rend() && u.addressees.empty(); ++it) {
        if (!it->is_robot() && std::find(it->addressees.begin(), it->addressees.end(), kRobot) !=
                                   it->addressees.end()) {
          u.addressees.push_back(it->speaker);
        }
      }
      if (u.addressees.empty()) {
        u.addressees = setup_.config.users.roles;
      }
    }
    u.acts = action.acts;
    u.text = action.text.empty() ? setup_.nlg->realise(true, u.acts, rng_) : action.text;
    u.start_s =
        transcript_.empty() ? 0.0 : setup_.timing->next_start(transcript_.back().end_s, rng_);
    u.end_s = u.start_s + setup_.timing->duration(u.text);
    transcript_.push_back(std::move(u));
    users_.hear_robot(transcript_.back());
    robot_said_bye = std::any_of(action.acts.begin(), action.acts.end(),
                                 [](const DialogueAct& a) { return a.intent == "bye"; });
  }
  // ARI's bye ends the dialogue once the humans have finished (a human with goals left speaks
  // up instead); after the humans finished, ARI's reply (or silence) ends it.
  if (robot_said_bye && users_.finished()) {
    users_.farewell(transcript_, rng_);
    terminated = true;
  } else if (humans_finished_) {
    terminated = true;
  } else {
    users_.respond(transcript_, rng_);
    humans_finished_ = users_.finished();
  }
  const bool truncated =
      !terminated && robot_turns_ >= static_cast<int>(setup_.config.reward.max_turns);
  over_ = terminated || truncated;
  const DialogueOutcome outcome = judge(users_.agenda(), truncated);
  StepResult result;
  result.observation = observe(first_new);
  result.reward = step_reward(setup_.config.reward, over_, outcome);
  result.terminated = terminated;
  result.truncated = truncated;
  result.info = info(outcome);
  return result;
}

Observation DialogueEnv::observe(size_t from) const {
  Observation observation;
  observation.robot_turn = robot_turns_;
  for (size_t i = from; i < transcript_.size(); ++i) {
    if (!transcript_[i].is_robot()) {
      observation.heard.push_back(transcript_[i].heard);
    }
  }
  return observation;
}

StepInfo DialogueEnv::current_info() const {
  return info(judge(users_.agenda(), false));
}

StepInfo DialogueEnv::info(const DialogueOutcome& outcome) const {
  StepInfo info;
  info.complete = outcome.complete;
  info.success = outcome.success;
  info.robot_turns = robot_turns_;
  info.utterances = static_cast<int>(transcript_.size());
  for (const HumanAgent& human : users_.humans()) {
    info.patience.push_back(human.patience);
  }
  for (const TrackedGoal& g : users_.agenda().goals()) {
    info.goals.push_back(GoalLabel{GoalLabelKind::kStated, g.goal}.to_string());
  }
  return info;
}

}  // namespace ari_social_sim::dialogue
