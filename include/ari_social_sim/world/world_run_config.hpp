#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {

/// Who moves ARI's base: world_node itself from cmd_vel (2D mode), or ari_physics_node, whose
/// ground truth world_node follows (3D mode, docs/physics.md).
enum class AriSource { kInternal, kPhysics };

inline constexpr core::Choice<AriSource> kAriSources[] = {{AriSource::kInternal, "internal"},
                                                          {AriSource::kPhysics, "physics"}};

/// How world_node runs a scene: its private parameters (~scene, ~step, ...), listed once in visit
/// (config_fields.hpp; docs/parameters.md is generated from it).
struct WorldRunConfig {
  std::string scene;
  SimulationConfig simulation;  // ~step and ~map_resolution; the seed is the scene's
  double real_time_factor{1.0};
  std::optional<uint64_t> seed;
  double duration_s{0.0};
  double marker_rate_hz{30.0};
  bool start_paused{false};
  AriSource ari_source{AriSource::kInternal};

  template <class V>
  void visit(V& v) {
    v.field("scene", scene,
            "the scene file (world, people, groups, ARI); empty: the package's "
            "scenes/waiting_room.yaml");
    simulation.visit(v);
    v.field("real_time_factor", real_time_factor,
            "sim seconds per wall second (1e-3: one 0.05 s step every 50 s); 0 = as fast as "
            "possible. Pacing restarts after a pause and after /sim/reset",
            core::non_negative());
    v.field(core::unset_by_minus_one("seed"), seed, "overrides the scene's seed when set",
            core::kParameterSeedBounds);
    v.field("duration", duration_s,
            "stop after this many sim seconds and print a group report; 0 = run until shut down",
            core::non_negative());
    v.field("marker_rate", marker_rate_hz, "Hz of /sim/markers (wall clock)",
            core::Bounds{0.0, 30.0, true});
    v.field("start_paused", start_paused, "wait for /sim/pause false or /sim/step");
    v.choice("ari_source", ari_source,
             "physics: 3D mode, ARI's base is ari_physics_node's (world_node follows "
             "/ground_truth_odom and head_1_joint from /joint_states, takes no cmd_vel and "
             "publishes no odometry)",
             kAriSources);
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
  /// Reads every field from a mapping (parameter server or file); unknown keys and out-of-range
  /// values throw core::ConfigError naming the parameter.
  static WorldRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::world
