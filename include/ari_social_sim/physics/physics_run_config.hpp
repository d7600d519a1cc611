#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/physics/physics_config.hpp"

namespace ari_social_sim::physics {

/// Who owns simulated time: ari_physics_node alone publishes /clock at its real-time factor; in
/// a full run it follows world_node's /clock.
enum class ClockSource { kOwn, kWorld };

inline constexpr core::Choice<ClockSource> kClockSources[] = {{ClockSource::kOwn, "own"},
                                                              {ClockSource::kWorld, "world"}};

/// How ari_physics_node runs: its private parameters, listed once in visit
/// (core/config_fields.hpp; docs/parameters.md is generated from it).
struct PhysicsRunConfig {
  std::string urdf;
  std::string scene;
  std::string world;
  std::optional<std::vector<double>> initial_pose;  // [x, y, theta]
  ClockSource clock{ClockSource::kOwn};
  double real_time_factor{1.0};
  double publish_rate_hz{50.0};
  double ground_truth_rate_hz{100.0};
  PhysicsConfig physics;
  bool cameras_enabled{true};
  uint64_t appearance_seed{1};
  // Cameras and mapping (docs/cameras.md) are read by the node's camera interface, which links
  // the renderer: their mappings are handed on unread.
  std::optional<core::YamlMap> cameras;
  bool mapping{false};
  std::optional<core::YamlMap> mapping_params;
  std::string map_file{"ari_octomap.bt"};

  template <class V>
  void visit(V& v) {
    v.field("urdf", urdf, "ARI's URDF; empty: the package's urdf/ari.urdf");
    v.field("scene", scene,
            "a scene file: its world and ARI's start pose (as world_node's ~scene)");
    v.field("world", world,
            "a world file, when no scene is given; empty: the package's worlds/room_6x6.yaml");
    v.rule("world", scene.empty() || world.empty(),
           "no world when a scene is given (the scene names its world)", "'" + world + "'");
    v.field("initial_pose", initial_pose,
            "[x, y, theta] (m, m, rad) of base_footprint in the map frame, with ~world; unset: "
            "the floor's centre, facing +x");
    v.rule("initial_pose", !initial_pose || scene.empty(),
           "no initial_pose when a scene is given (the scene places ARI)", "a pose");
    v.rule("initial_pose", !initial_pose || initial_pose->size() == 3, "[x, y, theta] (m, m, rad)",
           std::to_string(initial_pose.value_or(std::vector<double>{}).size()) + " numbers");
    v.choice("clock", clock,
             "own: publish /clock at ~real_time_factor; world: follow world_node's /clock",
             kClockSources);
    v.field("real_time_factor", real_time_factor,
            "own clock: sim seconds per wall second; 0 = as fast as possible",
            core::non_negative());
    v.field("publish_rate", publish_rate_hz, "Hz of /joint_states, odometry, controller states",
            core::between(1.0, 1000.0));
    v.field("ground_truth_rate", ground_truth_rate_hz,
            "Hz of /ground_truth_odom, as PAL's Gazebo p3d plugin", core::between(1.0, 1000.0));
    physics.visit(v);
    v.field("cameras_enabled", cameras_enabled, "render ARI's cameras for their subscribers");
    v.field("appearance_seed", appearance_seed,
            "draws each person's look in the cameras (stature, skin, hair, clothes) with their id");
    v.field("cameras", cameras, "overrides of the cameras' settings (camera rig below)");
    v.field("mapping", mapping, "OctoMap from the torso depth camera, and /map from it");
    v.field("mapping_params", mapping_params, "mapping settings (mapping below)");
    v.field("map_file", map_file, "where ~save_map writes the OctoMap (.bt)");
  }

  /// base_footprint's start pose given by initial_pose, if any.
  std::optional<core::Pose2> start_pose() const;

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
  /// Reads every field from a mapping (parameter server or file); unknown keys, out-of-range
  /// values and contradictions (scene and world both given) throw core::ConfigError naming the
  /// parameter.
  static PhysicsRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::physics
