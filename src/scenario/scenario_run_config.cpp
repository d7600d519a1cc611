#include "ari_social_sim/scenario/scenario_run_config.hpp"

namespace ari_social_sim::scenario {

ScenarioRunConfig ScenarioRunConfig::from_yaml(const core::YamlMap& map) {
  ScenarioRunConfig config;
  config.scenario = map.required<std::string>("scenario");
  config.seed = map.optional<int>("seed", -1, core::Bounds{-1.0, 2147483647.0, false});
  config.server_timeout_s =
      map.optional<double>("server_timeout", config.server_timeout_s, core::positive());
  config.group_timeout_s =
      map.optional<double>("group_timeout", config.group_timeout_s, core::positive());
  config.dialogue_config = map.optional<std::string>("dialogue_config", config.dialogue_config);
  config.start_world = map.optional<bool>("start_world", config.start_world);
  if (map.has("wall_time_limit")) {
    config.wall_time_limit_s = map.required<double>("wall_time_limit", core::non_negative());
  }
  config.world_timeout_s =
      map.optional<double>("world_timeout", config.world_timeout_s, core::positive());
  map.finish();
  return config;
}

double ScenarioRunConfig::wall_time_limit_for(double script_time_limit_s) const {
  return wall_time_limit_s ? *wall_time_limit_s : 3.0 * script_time_limit_s + server_timeout_s;
}

}  // namespace ari_social_sim::scenario
