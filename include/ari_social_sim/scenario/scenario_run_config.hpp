#pragma once

#include <cstdint>
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

  /// Reads every field; unknown keys and out-of-range values throw core::ConfigError naming the
  /// parameter.
  static ScenarioRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::scenario
