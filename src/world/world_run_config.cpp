#include "ari_social_sim/world/world_run_config.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

namespace ari_social_sim::world {

void WorldRunConfig::validate() const {
  core::check_fields(*this, "WorldRunConfig");
}

WorldRunConfig WorldRunConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<WorldRunConfig>(map);
}

}  // namespace ari_social_sim::world
