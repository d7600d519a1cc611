#include "ari_social_sim/navigation/navigation_config.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

namespace ari_social_sim::navigation {

const char* solver_name(SolverKind kind) {
  return core::choice_name(kind, kSolverNames);
}

void NavigationConfig::validate() const {
  core::check_fields(*this, "NavigationConfig");
}

NavigationConfig NavigationConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<NavigationConfig>(map);
}

NavigationConfig NavigationConfig::load_file(const std::string& path) {
  return from_yaml(core::YamlMap::load_file(path));
}

}  // namespace ari_social_sim::navigation
