#include "ari_social_sim/dialogue/reward.hpp"

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::dialogue {

void RewardConfig::validate() const {
  if (max_turns == 0) {
    throw core::ConfigError("RewardConfig: max_turns: expected an integer >= 1, got 0");
  }
  if (!(success_reward >= 0.0) || !(failure_penalty >= 0.0) || !(turn_cost >= 0.0)) {
    throw core::ConfigError(
        "RewardConfig: success_reward, failure_penalty, turn_cost: expected numbers >= 0");
  }
}

RewardConfig RewardConfig::from_yaml(const core::YamlMap& map) {
  RewardConfig c;
  c.max_turns = map.optional<unsigned>("max_turns", c.max_turns, core::positive());
  c.success_reward = map.optional<double>("success_reward", c.success_reward, core::non_negative());
  c.failure_penalty =
      map.optional<double>("failure_penalty", c.failure_penalty, core::non_negative());
  c.turn_cost = map.optional<double>("turn_cost", c.turn_cost, core::non_negative());
  map.finish();
  return c;
}

DialogueOutcome judge(const Agenda& agenda, bool truncated) {
  DialogueOutcome outcome;
  bool resolved = !truncated;
  bool satisfied = true;
  for (const TrackedGoal& g : agenda.goals()) {
    resolved = resolved && (g.status == GoalStatus::kResolved || g.status == GoalStatus::kClosed);
    satisfied = satisfied && g.satisfied;
  }
  outcome.complete = resolved;
  outcome.success = resolved && satisfied;
  return outcome;
}

double step_reward(const RewardConfig& config, bool episode_over, const DialogueOutcome& outcome) {
  double reward = -config.turn_cost;
  if (episode_over) {
    reward += outcome.success ? config.success_reward : -config.failure_penalty;
  }
  return reward;
}

}  // namespace ari_social_sim::dialogue
