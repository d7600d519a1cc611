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
  map.finish();
  return config;
}

}  // namespace ari_social_sim::scenario
