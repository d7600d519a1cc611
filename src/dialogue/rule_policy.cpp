#include "ari_social_sim/dialogue/rule_policy.hpp"

#include <algorithm>

namespace ari_social_sim::dialogue {
namespace {

DialogueAct bare(const std::string& intent) {
  return DialogueAct{intent, {}, ""};
}

void add_unique(std::vector<DialogueAct>& acts, const DialogueAct& act) {
  if (std::find(acts.begin(), acts.end(), act) == acts.end()) {
    acts.push_back(act);
  }
}

}  // namespace

RulePolicy::RulePolicy(const Domain& domain) : domain_(domain) {}

void RulePolicy::reset() {
  greeted_ = false;
  last_acts_.clear();
}

RobotAction RulePolicy::act(const Observation& observation) {
  RobotAction action;
  const Perception* addressed = nullptr;
  for (auto it = observation.heard.rbegin(); it != observation.heard.rend(); ++it) {
    if (!it->dropped &&
        std::find(it->addressees.begin(), it->addressees.end(), kRobot) != it->addressees.end()) {
      addressed = &*it;
      break;
    }
  }
  const auto greeting = [this, &action] {
    action.acts = {bare("greet"), DialogueAct::from_path("inform", {"ari", "name"}),
                   bare("offer-help")};
    greeted_ = true;
  };
  if (addressed == nullptr) {
    if (!greeted_ && observation.robot_turn == 0) {
      greeting();
    }
    last_acts_ = action.acts.empty() ? last_acts_ : action.acts;
    return action;
  }
  // Requests first: every request heard gets its answer.
  for (const DialogueAct& act : addressed->acts) {
    if (act.intent != "request") {
      continue;
    }
    const auto goal = domain_.goal_of_request(act);
    const DomainObject* object = goal ? domain_.find_object(*goal) : nullptr;
    add_unique(action.acts, object != nullptr && object->ari_knows ? domain_.answer_act(*goal)
                                                                   : bare("cant-help"));
  }
  if (action.acts.empty() && !addressed->acts.empty()) {
    const std::string& intent = addressed->acts.front().intent;
    if (intent == "greet") {
      if (greeted_) {
        action.acts = {bare("offer-help")};
      } else {
        greeting();
      }
    } else if (intent == "thank") {
      action.acts = {bare("thank")};
    } else if (intent == "bye") {
      action.acts = {bare("thank"), bare("bye")};
    } else if (intent == "r-repet" || intent == "cant-hear" || intent == "r-paraph") {
      for (const DialogueAct& act : last_acts_) {
        action.acts.push_back(act.path().empty() ? act
                                                 : DialogueAct::from_path("p-repet", act.path()));
      }
    } else if (intent == "r-confirm") {
      action.acts = {bare("affirm")};
    } else if (intent == "change-volume") {
      action.acts = {bare("cant-help")};
    }
  }
  if (action.acts.empty() && !greeted_ && observation.robot_turn == 0) {
    greeting();
  }
  if (!action.acts.empty()) {
    last_acts_ = action.acts;
  }
  return action;
}

}  // namespace ari_social_sim::dialogue
