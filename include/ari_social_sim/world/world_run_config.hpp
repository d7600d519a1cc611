#pragma once

#include <cstdint>
#include <string>

#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::world {

/// Who moves ARI's base: world_node itself from cmd_vel (2D mode), or ari_physics_node, whose
/// ground truth world_node follows (3D mode, docs/physics.md).
enum class AriSource { kInternal, kPhysics };

/// How world_node runs a scene: its private parameters (~scene, ~step, ...), read and checked in
/// one place. Documented in the README's parameter table.
struct WorldRunConfig {
  std::string scene;              // scene file; empty = the package's scenes/waiting_room.yaml
  double step_s{0.05};            // sim seconds per step, (0, 1]
  double real_time_factor{1.0};   // sim seconds per wall second; 0 = as fast as possible
  int64_t seed{-1};               // overrides the scene's seed when >= 0
  double duration_s{0.0};         // stop after this much sim time (and print a report); 0 = never
  double marker_rate_hz{30.0};    // wall-clock rate of /sim/markers, (0, 30]
  double map_resolution_m{0.05};  // /map cell size, [0.01, 1]
  bool start_paused{false};       // wait for /sim/pause false or /sim/step before stepping
  AriSource ari_source{AriSource::kInternal};  // ~ari_source: internal or physics

  /// Reads every field from a mapping (parameter server or file); unknown keys and out-of-range
  /// values throw core::ConfigError naming the parameter.
  static WorldRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::world
