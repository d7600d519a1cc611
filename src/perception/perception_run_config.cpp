#include "ari_social_sim/perception/perception_run_config.hpp"

namespace ari_social_sim::perception {

PerceptionRunConfig PerceptionRunConfig::from_yaml(const core::YamlMap& map) {
  PerceptionRunConfig config;
  const std::string mode = map.optional<std::string>("mode", "sim");
  if (mode == "detectors") {
    config.mode = Mode::kDetectors;
  } else if (mode != "sim") {
    map.fail("mode", "sim or detectors", "'" + mode + "'");
  }
  config.config = map.optional<std::string>("config", config.config);
  config.seed = map.optional<int>("seed", -1, core::Bounds{-1.0, 2147483647.0, false});
  if (map.has("errors_enabled")) {
    config.errors_enabled = map.required<bool>("errors_enabled");
  }
  if (map.has("person_ids")) {
    config.person_ids = map.required<std::string>("person_ids");
    if (*config.person_ids != "human" && *config.person_ids != "random") {
      map.fail("person_ids", "human or random", "'" + *config.person_ids + "'");
    }
  }
  config.world = map.optional<std::string>("world", config.world);
  config.max_rate_hz = map.optional<double>("max_rate", config.max_rate_hz, {0.0, 1000.0, true});
  config.id_linger_s = map.optional<double>("id_linger", config.id_linger_s, core::between(0, 60));
  config.marker_rate_hz =
      map.optional<double>("marker_rate", config.marker_rate_hz, {0.0, 30.0, true});
  map.finish();
  return config;
}

}  // namespace ari_social_sim::perception
