#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/dialogue/speech_playback.hpp"
#include "ari_social_sim/dialogue/speech_stage.hpp"

namespace ari_social_sim::dialogue {

/// A stage whose utterances a world plays (ARI's with the act `tts`, a human's with its acts) and
/// whose progress is read from the world's states, one SpeechPlayback per speaker. Subclasses hand
/// the words to their world (world_node's /sim/say, or the world core in-process) and report each
/// state the world reaches.
class PlaybackStage : public SpeechStage {
 public:
  /// `human_ids` follows the roles of the dialogue settings (empty without simulated humans).
  explicit PlaybackStage(std::vector<uint32_t> human_ids) : human_ids_(std::move(human_ids)) {}

  double now_s() const override { return now_s_; }
  bool has_listener() const override { return true; }
  void start_human(const Utterance& utterance, size_t human) override;
  bool human_done() override { return human_.done(); }
  void start_robot(const std::string& text) override;
  size_t robot_words_started() override { return robot_.words_started(); }
  bool robot_done() override { return robot_.done(); }
  uint32_t human_id(size_t human) const override { return human_ids_.at(human); }

 protected:
  /// Hands an utterance to the world; false when the world refuses it (nothing plays then).
  virtual bool play(uint32_t speaker_id, const std::string& act, const std::string& content) = 0;
  /// A state of the world at `now_s`: the states of the speakers the playbacks follow, each null
  /// when that speaker is not in the world.
  void follow(double now_s, const SpeakerState* robot, const SpeakerState* human);
  uint32_t robot_speaker() const { return robot_.speaker_id(); }
  uint32_t human_speaker() const { return human_.speaker_id(); }

 private:
  void say(SpeechPlayback& playback, uint32_t speaker_id, const std::string& act,
           const std::string& content);

  std::vector<uint32_t> human_ids_;
  double now_s_{0.0};
  SpeechPlayback human_, robot_;
};

}  // namespace ari_social_sim::dialogue
