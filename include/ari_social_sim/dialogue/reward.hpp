#pragma once

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/agenda.hpp"

namespace ari_social_sim::dialogue {

/// Episode reward (the project's own choice: +2 x cap on success, -cap on failure, -1 a turn)
/// and the turn cap, counted in robot turns (RL steps).
struct RewardConfig {
  unsigned max_turns{40};        ///< robot turns before the episode is truncated
  double success_reward{80.0};   ///< 2 x max_turns, as TC-Bot and ConvLab
  double failure_penalty{40.0};  ///< max_turns
  double turn_cost{1.0};         ///< per robot turn

  template <class V>
  void visit(V& v) {
    v("max_turns", max_turns, core::positive());
    v("success_reward", success_reward, core::non_negative());
    v("failure_penalty", failure_penalty, core::non_negative());
    v("turn_cost", turn_cost, core::non_negative());
  }

  /// Throws core::ConfigError naming the field when max_turns is 0 or a value is negative.
  void validate() const;
  static RewardConfig from_yaml(const core::YamlMap& map);
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
