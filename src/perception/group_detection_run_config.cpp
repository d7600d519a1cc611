#include "ari_social_sim/perception/group_detection_run_config.hpp"

namespace ari_social_sim::perception {

GroupDetectionRunConfig GroupDetectionRunConfig::from_yaml(const core::YamlMap& map) {
  GroupDetectionRunConfig config;
  config.config = map.optional<std::string>("config", config.config);
  config.reference_frame = map.optional<std::string>("reference_frame", config.reference_frame);
  // tf2 refuses frame ids with a leading slash, and an empty one names no frame: either would
  // make every lookup fail and the node publish nothing, without saying why.
  if (config.reference_frame.empty() || config.reference_frame.front() == '/' ||
      config.reference_frame.find_first_of(" \t\n") != std::string::npos) {
    map.fail("reference_frame", "a tf frame name without a leading slash or spaces, e.g. map",
             "'" + config.reference_frame + "'");
  }
  config.rate_hz = map.optional<double>("rate", config.rate_hz, {0.0, 1000.0, true});
  map.finish();
  return config;
}

}  // namespace ari_social_sim::perception
