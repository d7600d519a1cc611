#include "ari_social_sim/rendering/camera_rig_config.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

namespace ari_social_sim::rendering {

std::string config_key_of(const CameraSpec& spec) {
  std::string key = spec.name;
  std::replace(key.begin(), key.end(), '/', '_');
  return key;
}

CameraSettings CameraSettings::of(const CameraSpec& spec) {
  return {spec.enabled,
          spec.width,
          spec.height,
          spec.rate_hz,
          spec.hfov_rad * 180.0 / M_PI,
          spec.kind == CameraKind::kFisheye ? 360.0 : 170.0};
}

void CameraSettings::apply_to(CameraSpec& spec) const {
  spec.enabled = enabled;
  spec.width = width;
  spec.height = height;
  spec.rate_hz = rate_hz;
  // Only a changed angle is converted back, so that an untouched camera keeps its exact field of
  // view rather than one rounded through degrees.
  if (hfov_deg != of(spec).hfov_deg) {
    spec.hfov_rad = hfov_deg * M_PI / 180.0;
  }
}

void CameraRigConfig::validate() const {
  core::check_fields(*this, "CameraRigConfig");
}

CameraRigConfig CameraRigConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<CameraRigConfig>(map);
}

}  // namespace ari_social_sim::rendering
