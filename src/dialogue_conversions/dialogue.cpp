#include "dialogue.hpp"

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::nodes {

std::vector<std::string> to_strings(const std::vector<dialogue::DialogueAct>& acts) {
  std::vector<std::string> out;
  out.reserve(acts.size());
  for (const dialogue::DialogueAct& act : acts) {
    out.push_back(act.to_string());
  }
  return out;
}

std::vector<std::string> to_strings(const std::vector<dialogue::GoalLabel>& goals) {
  std::vector<std::string> out;
  out.reserve(goals.size());
  for (const dialogue::GoalLabel& goal : goals) {
    out.push_back(goal.to_string());
  }
  return out;
}

DialoguePerception to_msg(const dialogue::Perception& heard) {
  DialoguePerception msg;
  msg.dropped = heard.dropped;
  msg.speaker = heard.speaker;
  msg.addressees = heard.addressees;
  msg.text = heard.text;
  msg.acts = to_strings(heard.acts);
  msg.confidence = heard.confidence;
  msg.word_errors = heard.word_errors;
  return msg;
}

dialogue::Perception from_msg(const DialoguePerception& msg) {
  dialogue::Perception heard;
  heard.dropped = msg.dropped;
  heard.speaker = msg.speaker;
  heard.addressees = msg.addressees;
  heard.text = msg.text;
  heard.acts = acts_from_msg(msg.acts, "heard.acts");
  heard.confidence = msg.confidence;
  heard.word_errors = msg.word_errors;
  return heard;
}

DialogueObservation to_msg(const dialogue::Observation& observation) {
  DialogueObservation msg;
  for (const dialogue::Perception& heard : observation.heard) {
    msg.heard.push_back(to_msg(heard));
  }
  msg.robot_turn = observation.robot_turn;
  return msg;
}

DialogueInfo to_msg(const dialogue::StepInfo& info, const std::vector<std::string>& roles) {
  DialogueInfo msg;
  msg.complete = info.complete;
  msg.success = info.success;
  msg.robot_turns = info.robot_turns;
  msg.utterances = info.utterances;
  msg.patience = info.patience;
  msg.roles = roles;
  msg.goals = info.goals;
  return msg;
}

DialogueUtterance to_msg(const dialogue::Utterance& utterance,
                         const dialogue::UtteranceEvent& event) {
  DialogueUtterance msg;
  msg.header.stamp = ros::Time(event.stamp_s);
  msg.dialogue = event.dialogue;
  msg.speaker_id = event.speaker_id;
  msg.turn = static_cast<uint32_t>(utterance.turn);
  msg.speaker = utterance.speaker;
  msg.addressees = utterance.addressees;
  msg.text = utterance.text;
  msg.acts = to_strings(utterance.acts);
  msg.goals = to_strings(utterance.goals);
  msg.planned_start = utterance.start_s;
  msg.planned_end = utterance.end_s;
  if (!utterance.is_robot()) {
    msg.person_id = perception::person_id_of(event.speaker_id);
    msg.heard = to_msg(utterance.heard);
  }
  return msg;
}

DialogueOutcome to_msg(const dialogue::OutcomeEvent& outcome) {
  DialogueOutcome msg;
  msg.header.stamp = ros::Time(outcome.stamp_s);
  msg.dialogue = outcome.dialogue;
  msg.seed = outcome.seed;
  msg.complete = outcome.complete;
  msg.success = outcome.success;
  msg.truncated = outcome.truncated;
  msg.robot_turns = outcome.robot_turns;
  msg.utterances = outcome.utterances;
  msg.total_reward = outcome.total_reward;
  msg.goals = outcome.goals;
  return msg;
}

dialogue::OutcomeEvent from_msg(const DialogueOutcome& msg) {
  dialogue::OutcomeEvent outcome;
  outcome.stamp_s = msg.header.stamp.toSec();
  outcome.dialogue = msg.dialogue;
  outcome.seed = msg.seed;
  outcome.complete = msg.complete;
  outcome.success = msg.success;
  outcome.truncated = msg.truncated;
  outcome.robot_turns = msg.robot_turns;
  outcome.utterances = msg.utterances;
  outcome.total_reward = msg.total_reward;
  outcome.goals = msg.goals;
  return outcome;
}

std::vector<dialogue::DialogueAct> acts_from_msg(const std::vector<std::string>& acts,
                                                 const std::string& field) {
  std::vector<dialogue::DialogueAct> out;
  for (size_t i = 0; i < acts.size(); ++i) {
    try {
      out.push_back(dialogue::parse_act(acts[i], field + "[" + std::to_string(i) + "]"));
    } catch (const core::ConfigError& e) {
      throw core::RequestError(e.what());
    }
  }
  return out;
}

}  // namespace ari_social_sim::nodes
