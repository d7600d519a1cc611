#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/dialogue/dialogue_run_config.hpp"
#include "ari_social_sim/dialogue/live_dialogue.hpp"
#include "ari_social_sim/dialogue/speech_stage.hpp"

namespace ari_social_sim::dialogue {

/// ARI started a word of its current utterance (a /tts feedback event).
struct RobotWordEvent {
  double since_start_s{0.0};  // since ARI started the utterance
  std::string text_said;      // the words so far, this one included
};

/// An utterance of the dialogue started playing (a /sim/dialogue/utterances message).
struct UtteranceEvent {
  int index{0};            // in the dialogue's transcript
  uint32_t dialogue{0};    // index of the dialogue since the start
  double stamp_s{0.0};     // when it started playing
  uint32_t speaker_id{0};  // world id of the speaker (the stage's ids)
};

/// A dialogue ended (a /sim/dialogue/outcome message).
struct OutcomeEvent {
  uint32_t dialogue{0};
  uint64_t seed{0};
  double stamp_s{0.0};
  bool complete{false};
  bool success{false};
  bool truncated{false};
  int robot_turns{0};
  int utterances{0};
  double total_reward{0.0};
  std::vector<std::string> goals;
};

/// What happened since the adapter last took the events.
struct SpokenDialogueEvents {
  std::vector<RobotWordEvent> robot_words;
  std::optional<std::string> robot_done;  // ARI's utterance played to its end: its text
  std::vector<UtteranceEvent> utterances;
  std::vector<OutcomeEvent> outcomes;
};

/// Simulated humans in dialogues with a live robot (dialogue_node's modes 1 and 3, and the batch
/// tool): ARI's utterances (/tts goals) wait for the floor and are voiced by the stage word by
/// word; what ARI said goes to the LiveDialogue, whose human replies the stage voices in turn.
/// Runs `dialogues` dialogues (0 = forever), `dialogue_pause` apart, each once the stage has a
/// listener and, with `start: robot_speaks`, once ARI speaks (ARI then opens it). Without
/// `humans` nothing but ARI's utterances is voiced. Events are buffered for the adapter, which
/// publishes them. Single-threaded; holds references to the setup, NLU, run config and stage,
/// which must outlive it.
class SpokenDialogue {
 public:
  /// Throws core::ConfigError for an invalid run config (DialogueRunConfig::validate).
  SpokenDialogue(const DialogueSetup& setup, const RobotNlu& nlu, const DialogueRunConfig& run,
                 SpeechStage& stage);

  /// A new utterance for ARI: cuts off the one it is saying, then waits for the floor. Returns
  /// why it is refused (empty text, a negative or non-finite wait), or "" when it is queued.
  std::string request_robot(const std::string& text, double wait_before_speaking_s);
  /// Cancels ARI's current utterance; returns the words said so far ("" when none).
  std::string cancel_robot();
  /// Advances everything to the stage's clock; call on every tick of the stage. A clock that
  /// went back (the world was reset) ends the dialogue under way as truncated and restarts the
  /// waits from the new time.
  void tick();

  /// The events since the previous call, which this call clears.
  SpokenDialogueEvents take_events();

  const LiveDialogue& live() const { return live_; }
  bool dialogue_active() const { return dialogue_active_; }

 private:
  void start_dialogue(double now_s, Opening opening);
  void finish_robot(const std::string& said, double now_s);
  void report_utterance(int index, double stamp_s);
  /// Ends the dialogue under way; `cut_off` (by a reset) reports it truncated, neither complete
  /// nor successful.
  void end_dialogue(double now_s, bool cut_off);
  void restart_clock(double now_s);
  void report_outcome(double now_s, bool cut_off);
  std::string robot_words(size_t count) const;

  const DialogueSetup& setup_;
  const DialogueRunConfig& run_;
  SpeechStage& stage_;
  LiveDialogue live_;
  SpokenDialogueEvents events_;

  uint32_t dialogue_index_{0};
  bool dialogue_active_{false};
  double next_start_s_{0.0};  ///< when the next dialogue may start; < 0 = none left
  bool human_playing_{false};

  // ARI's current utterance: waiting for the floor, then speaking.
  bool robot_waiting_{false};
  bool robot_speaking_{false};
  std::string robot_text_;
  std::vector<std::string> robot_word_list_;
  double robot_not_before_s_{0.0};
  double robot_start_s_{0.0};
  size_t robot_words_reported_{0};

  /// Less than a world step: a clock that goes back by more was reset.
  static constexpr double kTimeBackToleranceS = 1e-3;
  double last_tick_s_{0.0};
};

}  // namespace ari_social_sim::dialogue
