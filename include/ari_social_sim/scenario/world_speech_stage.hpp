#pragma once

#include <vector>

#include "ari_social_sim/dialogue/playback_stage.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::scenario {

/// dialogue_node's world stage in-process: utterances voiced by the world core's speakers (as
/// /sim/say does) and followed in the snapshot of each step. Holds a reference to the simulation,
/// which must outlive it.
class WorldSpeechStage : public dialogue::PlaybackStage {
 public:
  /// `human_ids` follows the roles of the dialogue settings (empty without simulated humans).
  WorldSpeechStage(world::Simulation& simulation, std::vector<uint32_t> human_ids);

  /// Follows the playbacks in the state after a step; call before the dialogue's tick.
  void follow(const world::WorldSnapshot& snapshot);

  uint32_t robot_id() const override;

 private:
  bool play(uint32_t speaker_id, const std::string& act, const std::string& content) override;

  world::Simulation& simulation_;
};

}  // namespace ari_social_sim::scenario
