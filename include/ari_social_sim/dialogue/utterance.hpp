#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/dialogue/goal.hpp"

namespace ari_social_sim::dialogue {

/// The robot's name as speaker and addressee.
constexpr const char* kRobot = "ARI";

/// What ARI's perception reports about a human utterance once the error layer has run.
struct Perception {
  bool dropped{false};                  ///< missed entirely; the fields below are then empty
  std::string speaker;                  ///< attributed speaker (may be the wrong human)
  std::vector<std::string> addressees;  ///< perceived addressee(s)
  std::string text;                     ///< ASR-like text
  std::vector<DialogueAct> acts;        ///< acts as understood (may be confused)
  double confidence{1.0};               ///< ASR confidence in [0, 1]
  int word_errors{0};                   ///< substitutions + deletions + insertions
};

/// One utterance of a simulated dialogue, as it really happened (ground truth) plus, for human
/// utterances, what ARI perceived.
struct Utterance {
  int turn{0};                          ///< index in the dialogue, from 0
  std::string speaker;                  ///< ARI or a role (patient, companion, ...)
  std::vector<std::string> addressees;  ///< ARI and/or roles
  std::string text;
  std::vector<DialogueAct> acts;  ///< empty for an unannotated utterance
  std::vector<GoalLabel> goals;
  double start_s{0.0};  ///< s since the dialogue started
  double end_s{0.0};
  Perception heard;  ///< human utterances only

  bool is_robot() const { return speaker == kRobot; }
  std::string first_intent() const { return acts.empty() ? "none" : acts.front().intent; }
};

}  // namespace ari_social_sim::dialogue
