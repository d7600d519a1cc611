#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ari_social_sim/dialogue/playback_stage.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::world_speech {

/// dialogue_node's world stage: utterances voiced by a world's speakers (ARI's with the act `tts`)
/// and followed in the world's state after each step. The one implementation of it: dialogue_node
/// voices through world_node's /sim/say and follows /sim/world_state, the batch engine voices
/// through the world core and follows its snapshots (in_process_speech_stage, episode.hpp).
class WorldSpeechStage : public dialogue::PlaybackStage {
 public:
  /// Hands an utterance to the world's speaker `speaker_id`; false when the world refuses it
  /// (nothing plays then).
  using Voice =
      std::function<bool(uint32_t speaker_id, const std::string& act, const std::string& content)>;

  /// `robot_id` is ARI's world id; `human_ids` follows the roles of the dialogue settings (empty
  /// without simulated humans).
  WorldSpeechStage(uint32_t robot_id, std::vector<uint32_t> human_ids, Voice voice);

  /// Follows the playbacks in the state after a step; call before the dialogue's tick.
  void follow(const world::WorldSnapshot& snapshot);

  uint32_t robot_id() const override { return robot_id_; }

 private:
  bool play(uint32_t speaker_id, const std::string& act, const std::string& content) override;

  uint32_t robot_id_;
  Voice voice_;
};

}  // namespace ari_social_sim::world_speech
