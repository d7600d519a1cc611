#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "ari_social_sim/dialogue/utterance.hpp"

namespace ari_social_sim::nodes {

/// Where a live dialogue is voiced: the world's speakers (mode 1, WorldStage) or ASR-like
/// ROS4HRI speech (mode 3, AsrStage). One human utterance and one robot utterance at a time; the
/// caller (LiveDialogueNode) polls on every tick, so a stage needs no thread of its own.
class SpeechStage {
 public:
  virtual ~SpeechStage() = default;

  /// The stage's clock (s): sim time of the world, or ROS time.
  virtual double now_s() const = 0;
  /// Someone can hear the humans, so a dialogue may start (the world always; a system listening
  /// to a voice in mode 3).
  virtual bool has_listener() const = 0;

  /// Starts playing a human utterance; `human` indexes the roles of the dialogue settings.
  virtual void start_human(const dialogue::Utterance& utterance, size_t human) = 0;
  /// True once the human utterance started last has been played to its end.
  virtual bool human_done() = 0;

  /// Starts ARI saying `text`.
  virtual void start_robot(const std::string& text) = 0;
  /// Words of ARI's current text started so far (0 before the first).
  virtual size_t robot_words_started() = 0;
  /// True once ARI's current text has been played to its end.
  virtual bool robot_done() = 0;

  /// World id of human `human` and of ARI (0 when the stage has no world).
  virtual uint32_t human_id(size_t human) const = 0;
  virtual uint32_t robot_id() const = 0;
};

/// The ROS4HRI permanent person id of the simulated human with world id `id` (project convention).
inline std::string person_id(uint32_t id) {
  return "human" + std::to_string(id);
}

}  // namespace ari_social_sim::nodes
