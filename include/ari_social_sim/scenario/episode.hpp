#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/scenario/episode_metrics.hpp"
#include "ari_social_sim/scenario/scenario.hpp"
#include "ari_social_sim/scenario/script_runner.hpp"
#include "ari_social_sim/world/occupancy_grid.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::scenario {

/// What the batch tool runs every episode with; the defaults are those of the live nodes.
struct EpisodeConfig {
  world::SimulationConfig simulation;  // step and map resolution (world_node's ~step, ...)
};

/// Something ARI said through its text-to-speech, as the batch records it (a /tts goal live).
struct SpokenByAri {
  double time_s{0.0};
  std::string text;
};

/// One run of a scenario with the suite's cores composed in one process, as fast as the machine
/// allows (the batch tool's engine): each step advances the world, then runs the script on what
/// the step produced, exactly as scenario_node does on each /sim/world_state. Seeded: the same
/// scenario, configuration and seed give the same run.
class Episode {
 public:
  /// `seed` replaces the scene's seed and draws the script's random groups. Throws
  /// core::ConfigError when the scene cannot be built.
  Episode(const Scenario& scenario, uint64_t seed, const EpisodeConfig& config = {});
  ~Episode();
  Episode(const Episode&) = delete;
  Episode& operator=(const Episode&) = delete;

  /// One world step and everything that follows it. Does nothing once the script has ended.
  void step();
  bool finished() const { return runner_.finished(); }

  const world::Simulation& simulation() const { return *simulation_; }
  /// The world after the last step (before the first: the initial state).
  const world::WorldSnapshot& snapshot() const { return observations_.world; }
  const world::OccupancyGrid& map() const { return map_; }
  const ScriptRunner& runner() const { return runner_; }
  const EpisodeMetrics& metrics() const { return metrics_.metrics(); }
  uint64_t seed() const { return seed_; }
  /// /tts goals sent during the last step.
  const std::vector<SpokenByAri>& ari_speech() const { return ari_speech_; }

 private:
  class InProcessCommands;

  const Scenario& scenario_;
  uint64_t seed_;
  std::unique_ptr<world::Simulation> simulation_;
  world::OccupancyGrid map_;
  std::unique_ptr<InProcessCommands> commands_;
  ScriptRunner runner_;
  MetricsRecorder metrics_;
  Observations observations_;
  std::vector<SpokenByAri> ari_speech_;
};

}  // namespace ari_social_sim::scenario
