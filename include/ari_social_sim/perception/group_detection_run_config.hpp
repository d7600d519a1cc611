#pragma once

#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::perception {

/// How group_detection_node runs: its private parameters (~config, ~reference_frame, ~rate),
/// listed once in visit (core/config_fields.hpp; docs/parameters.md is generated from it).
struct GroupDetectionRunConfig {
  /// Detections per second of sim time a node may be asked for (the engine's too).
  static constexpr core::Bounds kRateBounds{0.0, 1000.0, true};

  std::string config;
  std::string reference_frame{"map"};
  double rate_hz{20.0};

  template <class V>
  void visit(V& v) {
    v.field("config", config,
            "perception config whose `groups:` section configures GCFF (stride, mdl, "
            "membership_window_frames, id_memory_frames); the whole file is checked. Empty: the "
            "package's config/perception.yaml");
    v.field("reference_frame", reference_frame,
            "the fixed tf frame people are placed in and groups are reported in");
    // tf2 refuses frame ids with a leading slash, and an empty one names no frame: either would
    // make every lookup fail and the node publish nothing, without saying why.
    v.rule("reference_frame", is_frame_name(reference_frame),
           "a tf frame name without a leading slash or spaces, e.g. map",
           "'" + reference_frame + "'");
    v.field("rate", rate_hz,
            "detections per second of sim time on the latest tracked persons; 20 is the "
            "perception's frame rate at the world's default step, which "
            "membership_window_frames counts in",
            kRateBounds);
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
  /// Reads every field from a mapping (parameter server or file); unknown keys and out-of-range
  /// values throw core::ConfigError naming the parameter.
  static GroupDetectionRunConfig from_yaml(const core::YamlMap& map);

 private:
  static bool is_frame_name(const std::string& frame);
};

}  // namespace ari_social_sim::perception
