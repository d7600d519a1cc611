#include "ari_social_sim/scenario/scenario_run_config.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

namespace ari_social_sim::scenario {

void ScenarioRunConfig::validate() const {
  core::check_fields(*this, "ScenarioRunConfig");
}

ScenarioRunConfig ScenarioRunConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<ScenarioRunConfig>(map);
}

double ScenarioRunConfig::script_time_limit_for(double file_time_limit_s) const {
  return time_limit_s.value_or(file_time_limit_s);
}

double ScenarioRunConfig::wall_time_limit_for(double script_time_limit_s) const {
  return wall_time_limit_s ? *wall_time_limit_s : 3.0 * script_time_limit_s + server_timeout_s;
}

}  // namespace ari_social_sim::scenario
