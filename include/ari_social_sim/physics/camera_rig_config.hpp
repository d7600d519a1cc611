#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/physics/ari_cameras.hpp"
#include "ari_social_sim/physics/depth_image.hpp"

namespace ari_social_sim::physics {

/// Which of ARI's cameras render, at what size and rate, and how depth is encoded.
struct CameraRigConfig {
  std::vector<CameraSpec> cameras{ari_camera_specs()};
  DepthEncoding depth_encoding{DepthEncoding::kMetres32F};

  /// Reads overrides of the defaults:
  ///   depth_encoding: 32FC1            # or 16UC1
  ///   cameras:
  ///     head_front_camera: {enabled: true, width: 1280, height: 960, rate_hz: 10, hfov_deg: 62.2}
  ///     torso_back_camera_fisheye1: {enabled: true}    # a '/' in a name becomes '_'
  /// Every key is optional; unknown cameras or keys and out-of-range values throw
  /// core::ConfigError naming the field.
  static CameraRigConfig from_yaml(const core::YamlMap& map);
};

/// The key naming a camera in the configuration: its name with '/' replaced by '_'.
std::string config_key_of(const CameraSpec& spec);

}  // namespace ari_social_sim::physics
