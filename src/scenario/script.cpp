#include "ari_social_sim/scenario/script.hpp"

#include <algorithm>
#include <stdexcept>

namespace ari_social_sim::scenario {
namespace {

void note(const Action& action, ScriptInterfaces& uses) {
  if (const auto* say = std::get_if<SayAction>(&action)) {
    uses.text_to_speech = uses.text_to_speech || say->speaker.is_ari();
  } else if (const auto* goal = std::get_if<SetGoalAction>(&action)) {
    uses.move_base = uses.move_base || goal->who.is_ari();
  } else if (std::holds_alternative<ApproachAction>(action) ||
             std::holds_alternative<JoinGroupAction>(action)) {
    uses.approach = true;
  } else if (std::holds_alternative<ConverseAction>(action)) {
    uses.dialogue = true;
    uses.text_to_speech = true;
  }
}

}  // namespace

size_t Script::state_index(const std::string& name) const {
  for (size_t i = 0; i < states.size(); ++i) {
    if (states[i].name == name) {
      return i;
    }
  }
  throw std::out_of_range("no state named " + name);
}

bool act_matches(const std::string& pattern, const std::string& act) {
  if (!pattern.empty() && pattern.back() == '*') {
    return act.compare(0, pattern.size() - 1, pattern, 0, pattern.size() - 1) == 0;
  }
  return act == pattern;
}

void Script::for_each_action(const std::function<void(const Action&)>& visit) const {
  for (const State& state : states) {
    std::for_each(state.on_enter.begin(), state.on_enter.end(), visit);
    for (const Transition& transition : state.transitions) {
      std::for_each(transition.actions.begin(), transition.actions.end(), visit);
    }
  }
}

ScriptInterfaces Script::interfaces() const {
  ScriptInterfaces uses;
  for_each_action([&uses](const Action& action) { note(action, uses); });
  for (const State& state : states) {
    for (const Transition& transition : state.transitions) {
      for (const Condition& condition : transition.when) {
        uses.perceived_groups =
            uses.perceived_groups || std::holds_alternative<PerceivedGroupCondition>(condition);
        uses.dialogue =
            uses.dialogue || std::holds_alternative<DialogueFinishedCondition>(condition);
        uses.speech_recognition = uses.speech_recognition ||
                                  std::holds_alternative<HeardCondition>(condition) ||
                                  std::holds_alternative<NotUnderstoodCondition>(condition);
      }
    }
  }
  return uses;
}

}  // namespace ari_social_sim::scenario
