#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace ari_social_sim::dialogue {

/// What a world reports of one speaker at one step (world_node's SpeechState, the world core's
/// SpeechSnapshot).
struct SpeakerState {
  bool is_speaking{false};
  std::string content;
  double start_s{0.0};  // when the current act started
  size_t word_index{0};
};

/// One utterance handed to a world and followed there, step by step: it counts as started when the
/// world shows its speaker saying that content with a start time at or after the hand-over, and
/// as played when the world then shows the speaker silent, saying something else, or gone.
class SpeechPlayback {
 public:
  /// The utterance was handed over at `called_s`.
  void begin(uint32_t speaker_id, const std::string& content, double called_s);
  /// Nothing can play it (the world refused it): it counts as played.
  void fail() { done_ = true; }
  /// The speaker's state after a step, or none when the speaker is not in the world.
  void follow(const SpeakerState* speaker);

  uint32_t speaker_id() const { return speaker_id_; }
  bool done() const { return done_; }
  size_t words_started() const { return words_started_; }

 private:
  uint32_t speaker_id_{0};
  std::string content_;
  double called_s_{0.0};
  bool started_{false};
  double start_s_{0.0};
  size_t words_started_{0};
  bool done_{true};
};

}  // namespace ari_social_sim::dialogue
