#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/reward.hpp"
#include "ari_social_sim/dialogue/user_simulation.hpp"

namespace ari_social_sim::dialogue {

/// What the robot does in one step: acts to say (none = stay silent and let the humans go on), to
/// whom (empty = the human who last spoke to ARI) and in which words (empty = the NLG's; a live
/// robot's own text in modes 1 and 3).
struct RobotAction {
  std::vector<DialogueAct> acts;
  std::vector<std::string> addressees;
  std::string text;
};

/// What the robot perceives since its previous turn: human utterances after the error layer
/// (dropped ones included, flagged, so that a policy cannot see the truth through the gaps).
struct Observation {
  std::vector<Perception> heard;
  int robot_turn{0};  ///< robot turns taken so far
};

struct StepInfo {
  bool complete{false};
  bool success{false};
  int robot_turns{0};
  int utterances{0};
  std::vector<int> patience;       ///< per human, in role order
  std::vector<std::string> goals;  ///< the dialogue's goals, `G(owner, predicate)`
};

struct StepResult {
  Observation observation;
  double reward{0.0};
  bool terminated{false};  ///< the dialogue ended (goals done, humans left, or ARI said bye)
  bool truncated{false};   ///< the turn cap was hit first
  StepInfo info;
};

/// Who opens a dialogue: drawn from the fitted model (P(robot opens), the corpus's share), or
/// ARI (a live robot that walked up to the humans and spoke first).
enum class Opening { kDrawn, kRobot };

/// The RL environment (Gymnasium-style, docs/dialogue.md): reset(seed) / step(robot
/// action). One seed reproduces an episode exactly. Holds a reference to the setup, which must
/// outlive it.
class DialogueEnv {
 public:
  explicit DialogueEnv(const DialogueSetup& setup);

  Observation reset(uint64_t seed, Opening opening = Opening::kDrawn);
  /// Precondition: reset was called and the episode has not ended.
  StepResult step(const RobotAction& action);

  /// Everything said so far, ground truth plus perception.
  const std::vector<Utterance>& transcript() const { return transcript_; }
  const UserSimulation& users() const { return users_; }
  bool episode_over() const { return over_; }
  /// The info of the episode as it stands (Gymnasium's reset info: goals, patience, no turn yet).
  StepInfo current_info() const;

 private:
  Observation observe(size_t from) const;
  StepInfo info(const DialogueOutcome& outcome) const;

  const DialogueSetup& setup_;
  UserSimulation users_;
  core::Rng rng_{0};
  std::vector<Utterance> transcript_;
  int robot_turns_{0};
  bool humans_finished_{false};
  bool over_{false};
};

}  // namespace ari_social_sim::dialogue
