#pragma once

#include <string>

#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::perception {

/// How group_detection_node runs: its private parameters (~config, ~reference_frame, ~rate),
/// read and checked in one place. Documented in the README's parameter table.
struct GroupDetectionRunConfig {
  /// Perception config file whose `groups:` section configures GCFF; empty = the package's
  /// config/perception.yaml.
  std::string config;
  /// The fixed tf frame people are placed in and groups are reported in: a tf2 frame name, not
  /// empty, without a leading slash.
  std::string reference_frame{"map"};
  /// Detections per second of (sim) time on the latest tracked persons, (0, 1000]; 20 Hz is the
  /// perception's frame rate with the world's default step, which the membership window assumes.
  double rate_hz{20.0};

  /// Reads every field from a mapping (parameter server or file); unknown keys and out-of-range
  /// values throw core::ConfigError naming the parameter.
  static GroupDetectionRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::perception
