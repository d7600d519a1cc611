#pragma once

#include <optional>
#include <string>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/physics/physics_config.hpp"

namespace ari_social_sim::physics {

/// Who owns simulated time: ari_physics_node alone publishes /clock at its real-time factor; in
/// a full run it follows world_node's /clock.
enum class ClockSource { kOwn, kWorld };

/// How ari_physics_node runs: its private parameters, read and checked in one place. Documented
/// in the README's parameter table.
struct PhysicsRunConfig {
  std::string urdf;   // ARI's URDF; empty = the package's urdf/ari.urdf
  std::string scene;  // a scene file: its world and ARI's start pose (as world_node's ~scene)
  std::string world;  // a world file, when no scene; empty = the package's worlds/room_6x6.yaml
  std::optional<core::Pose2> initial_pose;  // with ~world: base_footprint in the map frame;
                                            // absent = the floor's centre, facing +x
  ClockSource clock{ClockSource::kOwn};
  double real_time_factor{1.0};        // own clock: sim s per wall s; 0 = as fast as possible
  double publish_rate_hz{50.0};        // /joint_states, odometry, controller states
  double ground_truth_rate_hz{100.0};  // /ground_truth_odom, as PAL's Gazebo p3d plugin
  PhysicsConfig physics;
  // Cameras and mapping (docs/cameras.md): read here only as far as this node's own keys go;
  // the sub-mappings are handed unread to CameraRigConfig::from_yaml and MappingConfig::from_yaml.
  bool cameras_enabled{true};                   // render ARI's cameras for their subscribers
  std::optional<core::YamlMap> cameras;         // CameraRigConfig overrides
  bool mapping{false};                          // OctoMap from the torso depth, /map from it
  std::optional<core::YamlMap> mapping_params;  // MappingConfig overrides
  std::string map_file{"ari_octomap.bt"};       // where ~save_map writes the .bt file

  /// Reads every field from a mapping (parameter server or file); unknown keys, out-of-range
  /// values and contradictions (scene and world both given) throw core::ConfigError naming the
  /// parameter.
  static PhysicsRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::physics
