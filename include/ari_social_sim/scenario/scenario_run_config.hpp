#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::scenario {

/// How scenario_node runs a scenario: its private parameters, read and checked in one place
/// (README's parameter table).
struct ScenarioRunConfig {
  std::string scenario;           // scenario file (required)
  int64_t seed{-1};               // draws of the script (random groups); -1 = the scene's seed
  double server_timeout_s{60.0};  // wall seconds to wait for the services and actions it needs
  /// Sim seconds after which a perceived group that was not published again counts as gone
  /// (ROS4HRI publishes one message per group, repeatedly, and no "gone" message).
  double group_timeout_s{1.0};
  /// The dialogue settings ARI's `converse` uses (its policy's domain and NLG); empty = the
  /// package's config/dialogue/simulation.yaml. Read only by scripts that converse.
  std::string dialogue_config;
  /// Unpause the world once the suite is up; false leaves that to another node (a test that
  /// must see every state from the first, a user's rqt).
  bool start_world{true};
  /// Wall seconds after which the run ends as a failure whatever it is doing, waiting for servers
  /// and the world included: the script's time_limit counts sim time, which stands still when
  /// the world is paused or gone. Unset: wall_time_limit_for's default; 0: no limit.
  std::optional<double> wall_time_limit_s;
  /// Wall seconds without a /sim/world_state, while the world should be running (after the node
  /// unpaused it, or from the first state when another node starts it), after which the run ends
  /// as a failure naming the wait: world_node died, or the world stays paused.
  double world_timeout_s{10.0};

  /// The wall-time limit for a script with this sim-time limit: the parameter if set (0 = none),
  /// else 3 x the script's limit (the script at a third of real time) + server_timeout (the
  /// wait for the suite).
  double wall_time_limit_for(double script_time_limit_s) const;

  /// Reads every field; unknown keys and out-of-range values throw core::ConfigError naming the
  /// parameter.
  static ScenarioRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::scenario
