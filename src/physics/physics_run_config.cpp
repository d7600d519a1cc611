#include "ari_social_sim/physics/physics_run_config.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

namespace ari_social_sim::physics {

std::optional<core::Pose2> PhysicsRunConfig::start_pose() const {
  if (!initial_pose || initial_pose->size() != 3) {
    return std::nullopt;
  }
  return core::Pose2{{(*initial_pose)[0], (*initial_pose)[1]}, (*initial_pose)[2]};
}

void PhysicsRunConfig::validate() const {
  core::check_fields(*this, "PhysicsRunConfig");
}

PhysicsRunConfig PhysicsRunConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<PhysicsRunConfig>(map);
}

}  // namespace ari_social_sim::physics
