#include "ari_social_sim/perception/perception_run_config.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

namespace ari_social_sim::perception {

void PerceptionRunConfig::validate() const {
  core::check_fields(*this, "PerceptionRunConfig");
}

PerceptionRunConfig PerceptionRunConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<PerceptionRunConfig>(map);
}

}  // namespace ari_social_sim::perception
