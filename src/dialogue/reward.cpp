#include "ari_social_sim/dialogue/reward.hpp"

#include "ari_social_sim/core/config_check.hpp"

namespace ari_social_sim::dialogue {

void RewardConfig::validate() const {
  core::check_fields(*this, "RewardConfig");
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
