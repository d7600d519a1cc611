#pragma once

#include <vector>

#include "ari_social_sim/dialogue/speech_playback.hpp"
#include "ari_social_sim/dialogue/speech_stage.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::scenario {

/// dialogue_node's world stage in-process: utterances voiced by the world core's speakers (as
/// /sim/say does; ARI's with the act `tts`) and followed in the snapshot of each step by
/// dialogue::SpeechPlayback. Holds a reference to the simulation, which must outlive it.
class WorldSpeechStage : public dialogue::SpeechStage {
 public:
  /// `human_ids` follows the roles of the dialogue settings (empty without simulated humans).
  WorldSpeechStage(world::Simulation& simulation, std::vector<uint32_t> human_ids);

  /// Follows the playbacks in the state after a step; call before the dialogue's tick.
  void follow(const world::WorldSnapshot& snapshot);

  double now_s() const override { return now_s_; }
  bool has_listener() const override { return true; }
  void start_human(const dialogue::Utterance& utterance, size_t human) override;
  bool human_done() override { return human_.done(); }
  void start_robot(const std::string& text) override;
  size_t robot_words_started() override { return robot_.words_started(); }
  bool robot_done() override { return robot_.done(); }
  uint32_t human_id(size_t human) const override { return human_ids_.at(human); }
  uint32_t robot_id() const override;

 private:
  void say(dialogue::SpeechPlayback& playback, uint32_t speaker_id, const std::string& act,
           const std::string& content);

  world::Simulation& simulation_;
  std::vector<uint32_t> human_ids_;
  double now_s_{0.0};
  dialogue::SpeechPlayback human_, robot_;
};

}  // namespace ari_social_sim::scenario
