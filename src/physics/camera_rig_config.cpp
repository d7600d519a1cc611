#include "ari_social_sim/physics/camera_rig_config.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::physics {

std::string config_key_of(const CameraSpec& spec) {
  std::string key = spec.name;
  std::replace(key.begin(), key.end(), '/', '_');
  return key;
}

CameraRigConfig CameraRigConfig::from_yaml(const core::YamlMap& map) {
  CameraRigConfig config;
  if (map.has("depth_encoding")) {
    config.depth_encoding = parse_depth_encoding(map.required<std::string>("depth_encoding"),
                                                 map.field_name("depth_encoding"));
  }
  if (map.has("cameras")) {
    const core::YamlMap cameras = map.map("cameras");
    for (CameraSpec& spec : config.cameras) {
      const std::string key = config_key_of(spec);
      if (!cameras.has(key)) {
        continue;
      }
      const core::YamlMap entry = cameras.map(key);
      spec.enabled = entry.optional<bool>("enabled", spec.enabled);
      spec.width = entry.optional<int>("width", spec.width, core::between(16, 8192));
      spec.height = entry.optional<int>("height", spec.height, core::between(16, 8192));
      spec.rate_hz = entry.optional<double>("rate_hz", spec.rate_hz, {0.0, 100.0, true});
      // A pinhole cannot see 180 degrees; a fisheye can see all around.
      const double max_fov_deg = spec.kind == CameraKind::kFisheye ? 360.0 : 170.0;
      spec.hfov_rad = entry.optional<double>("hfov_deg", spec.hfov_rad * 180.0 / M_PI,
                                             {1.0, max_fov_deg, false}) *
                      M_PI / 180.0;
      entry.finish();
    }
    cameras.finish();
  }
  map.finish();
  return config;
}

}  // namespace ari_social_sim::physics
