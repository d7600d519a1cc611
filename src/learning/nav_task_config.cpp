#include "ari_social_sim/learning/nav_task_config.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::learning {

void NavTaskConfig::validate() const {
  core::check_fields(*this, "NavTaskConfig");
}

NavTaskConfig NavTaskConfig::load_file(const std::string& path) {
  return core::read_fields<NavTaskConfig>(core::YamlMap::load_file(path));
}

}  // namespace ari_social_sim::learning
