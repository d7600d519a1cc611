#pragma once

#include <cstdint>
#include <deque>
#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/dialogue/dialogue_env.hpp"
#include "ari_social_sim/dialogue/robot_nlu.hpp"

namespace ari_social_sim::dialogue {

/// Timing of a dialogue with a live robot.
struct LiveDialogueConfig {
  double robot_silence_s{3.0};

  template <class V>
  void visit(V& v) {
    v.field("robot_silence", robot_silence_s,
            "s the humans wait for ARI after their turn before they go on", core::positive());
  }

  /// Throws core::ConfigError naming the field when robot_silence_s <= 0.
  void validate() const;
};

/// A DialogueEnv driven by a clock and a live robot (modes 1 and 3): ARI speaks whenever it
/// likes (its text is understood by RobotNlu and becomes the env's step); the humans' replies
/// come out one at a time, each after the previous utterance really ended plus the gap the turn
/// timing drew for it, so the dialogue keeps its turn-taking whatever the playback takes. When
/// ARI says nothing for `robot_silence_s` after the humans' turn, the env steps with silence and
/// the humans go on. ARI waits for the floor: it may start once no human utterance is playing or
/// queued. Times are seconds on the caller's clock (sim time in mode 1, ROS time in mode 3).
/// Not thread-safe; holds references to the setup and the NLU, which must outlive it.
class LiveDialogue {
 public:
  LiveDialogue(const DialogueSetup& setup, const RobotNlu& nlu, LiveDialogueConfig config);

  /// Starts a dialogue: reset(seed); the humans' opening (if they open) is queued.
  void start(uint64_t seed, double now_s, Opening opening = Opening::kDrawn);

  /// ARI wants to speak: the silence timer stops until robot_finished.
  void request_floor();
  /// ARI gave up speaking before it started (its request was cancelled): the silence timer runs
  /// again from the last utterance's end.
  void release_floor() { robot_wants_floor_ = false; }
  /// ARI may start now: no human utterance is playing or waiting.
  bool robot_may_speak() const { return !human_playing_ && queue_.empty(); }
  /// ARI finished saying `text` at `now_s`. Returns the transcript index of its utterance, or -1
  /// when the dialogue is already over (nothing is simulated then).
  int robot_finished(const std::string& text, double now_s);

  /// The transcript index of the next human utterance due at `now_s`, or -1. The caller plays it
  /// and reports its end with human_finished. Steps the env with ARI's silence when it is due.
  int next_due(double now_s);
  /// The human utterance returned by next_due ended at `now_s`.
  void human_finished(double now_s);

  /// The episode ended and every utterance has been played.
  bool over() const { return env_.episode_over() && queue_.empty() && !human_playing_; }
  const DialogueEnv& env() const { return env_; }
  /// The latest step's result (reward summed over the episode in total_reward()).
  const StepResult& last_result() const { return last_result_; }
  double total_reward() const { return total_reward_; }
  uint64_t seed() const { return seed_; }

 private:
  void step(const RobotAction& action);
  void enqueue_humans(size_t from);

  const RobotNlu& nlu_;
  LiveDialogueConfig config_;
  DialogueEnv env_;
  uint64_t seed_{0};
  std::deque<size_t> queue_;  ///< transcript indices of human utterances not yet played
  bool human_playing_{false};
  bool robot_wants_floor_{false};
  bool gap_done_{false};    ///< the next utterance follows a silence already waited
  double last_end_s_{0.0};  ///< when the last utterance (ARI's or a human's) ended
  StepResult last_result_;
  double total_reward_{0.0};
};

}  // namespace ari_social_sim::dialogue
