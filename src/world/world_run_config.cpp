#include "ari_social_sim/world/world_run_config.hpp"

namespace ari_social_sim::world {

WorldRunConfig WorldRunConfig::from_yaml(const core::YamlMap& map) {
  WorldRunConfig config;
  config.scene = map.optional<std::string>("scene", config.scene);
  config.step_s = map.optional<double>("step", config.step_s, {0.0, 1.0, true});
  config.real_time_factor =
      map.optional<double>("real_time_factor", config.real_time_factor, core::non_negative());
  config.seed = map.optional<int>("seed", -1, core::Bounds{-1.0, 2147483647.0, false});
  config.duration_s = map.optional<double>("duration", config.duration_s, core::non_negative());
  config.marker_rate_hz =
      map.optional<double>("marker_rate", config.marker_rate_hz, {0.0, 30.0, true});
  config.map_resolution_m =
      map.optional<double>("map_resolution", config.map_resolution_m, core::between(0.01, 1.0));
  config.start_paused = map.optional<bool>("start_paused", config.start_paused);
  const std::string ari_source = map.optional<std::string>("ari_source", "internal");
  if (ari_source == "internal") {
    config.ari_source = AriSource::kInternal;
  } else if (ari_source == "physics") {
    config.ari_source = AriSource::kPhysics;
  } else {
    map.fail("ari_source", "internal or physics", "'" + ari_source + "'");
  }
  map.finish();
  return config;
}

}  // namespace ari_social_sim::world
