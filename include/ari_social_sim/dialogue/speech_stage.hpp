#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/dialogue/utterance.hpp"

namespace ari_social_sim::dialogue {

/// The act a world's speaker plays ARI's /tts text with: a text-to-speech goal carries no act.
constexpr char kRobotSpeechAct[] = "tts";

/// The act a world's speaker plays a simulated human's utterance with: its acts in MPGT notation,
/// `none` for an unannotated one.
inline std::string world_act(const Utterance& utterance) {
  return utterance.acts.empty() ? "none" : acts_to_string(utterance.acts);
}

/// Where a spoken dialogue is voiced: the world's speakers (dialogue_node's mode 1 over ROS, or
/// the batch tool's world in-process) or ASR-like ROS4HRI speech (mode 3). One human utterance and
/// one robot utterance at a time; SpokenDialogue polls it on every tick, so a stage needs no
/// thread of its own.
class SpeechStage {
 public:
  virtual ~SpeechStage() = default;

  /// The stage's clock (s): sim time of the world, or ROS time.
  virtual double now_s() const = 0;
  /// Someone hears the humans (a dialogue starts only then: the users do not talk to an empty
  /// room).
  virtual bool has_listener() const = 0;

  /// Starts playing a human utterance; `human` indexes the roles of the dialogue settings.
  virtual void start_human(const Utterance& utterance, size_t human) = 0;
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

}  // namespace ari_social_sim::dialogue
