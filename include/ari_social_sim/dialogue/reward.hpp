#pragma once

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/dialogue/agenda.hpp"

namespace ari_social_sim::dialogue {

/// Episode reward (the project's own choice: +2 x cap on success, -cap on failure, -1 a turn)
/// and the turn cap, counted in robot turns (RL steps).
struct RewardConfig {
  unsigned max_turns{40};
  double success_reward{80.0};   // 2 x max_turns, as TC-Bot and ConvLab
  double failure_penalty{40.0};  // max_turns
  double turn_cost{1.0};

  template <class V>
  void visit(V& v) {
    v.field("max_turns", max_turns, "robot turns before the episode is truncated",
            core::positive());
    v.field("success_reward", success_reward, "reward when the dialogue succeeds",
            core::non_negative());
    v.field("failure_penalty", failure_penalty, "penalty when it fails", core::non_negative());
    v.field("turn_cost", turn_cost, "penalty per robot turn", core::non_negative());
  }

  /// Throws core::ConfigError naming the field when max_turns is 0 or a value is negative.
  void validate() const;
};

/// Complete and success, judged separately (ConvLab): complete when every goal was resolved (the
/// users' agendas are exhausted, none failed, not truncated); success when, in addition, every
/// answer was the right one (the right information, or cant-help only where ARI cannot know).
struct DialogueOutcome {
  bool complete{false};
  bool success{false};
};

DialogueOutcome judge(const Agenda& agenda, bool truncated);

/// Reward of one step: -turn_cost, plus success_reward or -failure_penalty when the episode ends.
double step_reward(const RewardConfig& config, bool episode_over, const DialogueOutcome& outcome);

}  // namespace ari_social_sim::dialogue
