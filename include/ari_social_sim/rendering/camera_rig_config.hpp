#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/rendering/ari_cameras.hpp"
#include "ari_social_sim/rendering/camera_effects.hpp"
#include "ari_social_sim/rendering/depth_image.hpp"

namespace ari_social_sim::rendering {

/// The key naming a camera in the configuration: its name with '/' replaced by '_'.
std::string config_key_of(const CameraSpec& spec);

/// What a user may change of one camera (one entry of the `cameras:` mapping), in the file's
/// units.
struct CameraSettings {
  bool enabled{true};
  int width{0};
  int height{0};
  double rate_hz{0.0};
  double hfov_deg{0.0};
  double max_hfov_deg{0.0};  // 170 for a pinhole, which cannot see 180 degrees; 360 for a fisheye

  static CameraSettings of(const CameraSpec& spec);
  void apply_to(CameraSpec& spec) const;

  template <class V>
  void visit(V& v) {
    v.field("enabled", enabled, "render and publish the camera");
    v.field("width", width, "pixels", core::between(16.0, 8192.0));
    v.field("height", height, "pixels", core::between(16.0, 8192.0));
    v.field("rate_hz", rate_hz, "images per second of sim time", core::Bounds{0.0, 100.0, true});
    v.field("hfov_deg", hfov_deg, "horizontal field of view across the full width",
            core::between(1.0, max_hfov_deg));
  }
};

/// Which of ARI's cameras render, at what size and rate, and how depth is encoded, e.g.
///   depth_encoding: 16UC1
///   cameras:
///     head_front_camera: {enabled: true, width: 1280, height: 960, rate_hz: 10, hfov_deg: 62.2}
///     torso_back_camera_fisheye1: {enabled: true}    # a '/' in a name becomes '_'
///   effects: {antialiasing_samples: 4, bayer: true}   # what every camera's sensor does
struct CameraRigConfig {
  std::vector<CameraSpec> cameras{ari_camera_specs()};
  DepthEncoding depth_encoding{DepthEncoding::kMetres32F};
  CameraEffects effects;

  template <class V>
  void visit(V& v) {
    v.choice("depth_encoding", depth_encoding,
             "32FC1: float metres, NaN where there is no reading; 16UC1: unsigned millimetres, "
             "0 where there is none",
             kDepthEncodings);
    Cameras each{cameras};
    v.section("cameras", each, "one entry per camera, under its name with / written _");
    v.section("effects", effects,
              "what every camera's lens, sensor and image processor do to the rendered light");
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
  /// Reads overrides of the defaults: every key is optional; unknown cameras or keys and
  /// out-of-range values throw core::ConfigError naming the field.
  static CameraRigConfig from_yaml(const core::YamlMap& map);

 private:
  // The `cameras:` mapping: each camera's settings under its key.
  struct Cameras {
    std::vector<CameraSpec>& specs;

    template <class V>
    void visit(V& v) {
      for (CameraSpec& spec : specs) {
        CameraSettings settings = CameraSettings::of(spec);
        v.section(config_key_of(spec), settings, spec.name.c_str());
        settings.apply_to(spec);
      }
    }
  };
};

}  // namespace ari_social_sim::rendering
