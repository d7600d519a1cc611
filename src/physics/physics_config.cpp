#include "ari_social_sim/physics/physics_config.hpp"

#include "ari_social_sim/core/config_check.hpp"

namespace ari_social_sim::physics {

void PhysicsConfig::validate() const {
  core::check_fields(*this, "PhysicsConfig");
}

}  // namespace ari_social_sim::physics
