#pragma once

#include <optional>
#include <string>

#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::perception {

/// How hri_perception_node runs: its private parameters (~config, ~seed, ...), read and checked
/// in one place. Documented in the README's parameter table.
struct PerceptionRunConfig {
  /// What the node stands in for: the whole stack up to persons (kSim), or only the face, body
  /// and voice detectors and the matchers, leaving persons to a real person manager (kDetectors).
  enum class Mode { kSim, kDetectors };

  Mode mode{Mode::kSim};
  std::string config;                  ///< Perception config file; empty = the package's default.
  int64_t seed{-1};                    ///< Overrides the config's seed when >= 0.
  std::optional<bool> errors_enabled;  ///< Overrides the config's errors_enabled when given.
  std::optional<std::string> person_ids;  ///< Overrides persons.id_style (human or random).
  std::string world;            ///< World file whose walls block sound; empty = /map does.
  double max_rate_hz{30.0};     ///< World states closer in sim time are skipped, (0, 1000].
  double id_linger_s{1.0};      ///< Per-id topics outlive their id by this (sim s), [0, 60].
  double marker_rate_hz{10.0};  ///< Wall-clock rate of ~markers, (0, 30].

  /// Reads every field from a mapping (parameter server or file); unknown keys and out-of-range
  /// values throw core::ConfigError naming the parameter.
  static PerceptionRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::perception
