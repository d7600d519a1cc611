#include "ari_social_sim/perception/group_detection_run_config.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

namespace ari_social_sim::perception {

bool GroupDetectionRunConfig::is_frame_name(const std::string& frame) {
  return !frame.empty() && frame.front() != '/' &&
         frame.find_first_of(" \t\n") == std::string::npos;
}

void GroupDetectionRunConfig::validate() const {
  core::check_fields(*this, "GroupDetectionRunConfig");
}

GroupDetectionRunConfig GroupDetectionRunConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<GroupDetectionRunConfig>(map);
}

}  // namespace ari_social_sim::perception
