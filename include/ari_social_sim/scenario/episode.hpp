#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"
#include "ari_social_sim/scenario/episode_metrics.hpp"
#include "ari_social_sim/scenario/scenario.hpp"
#include "ari_social_sim/scenario/script_runner.hpp"
#include "ari_social_sim/world/occupancy_grid.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::scenario {

/// What the batch tool runs every episode with; the defaults are those of the live nodes.
struct EpisodeConfig {
  world::SimulationConfig simulation;  // step and map resolution (world_node's ~step, ...)
  /// hri_perception_node's config/perception.yaml; its seed is replaced by the episode's.
  perception::PerceptionConfig perception;
  double perception_max_rate_hz{30.0};  // hri_perception_node's ~max_rate

  /// The live nodes' defaults, read from the package's config files under `config_dir`.
  /// Throws core::ConfigError naming the file and field.
  static EpisodeConfig load(const std::string& config_dir);
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
  /// What perception reported in the last step; null when it skipped the step (its ~max_rate).
  const perception::PerceptionFrame* perception_frame() const { return perceived_; }
  const perception::PerceptionConfig& perception_config() const { return perception_.config(); }

 private:
  class InProcessCommands;

  void perceive();

  const Scenario& scenario_;
  uint64_t seed_;
  EpisodeConfig config_;
  std::unique_ptr<world::Simulation> simulation_;
  world::OccupancyGrid map_;
  perception::PerceptionPipeline perception_;
  std::optional<double> last_perceived_s_;
  const perception::PerceptionFrame* perceived_{nullptr};
  std::unique_ptr<InProcessCommands> commands_;
  ScriptRunner runner_;
  MetricsRecorder metrics_;
  Observations observations_;
  std::vector<SpokenByAri> ari_speech_;
};

}  // namespace ari_social_sim::scenario
