#include "ari_social_sim/world/object.hpp"

#include <box2d/box2d.h>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::world {

void Object::step_components(ComponentPhase phase, const StepContext& context) {
  for (const std::unique_ptr<Component>& component : components_) {
    if (component->phase() == phase) {
      component->step(*this, context);
    }
  }
}

void Object::sync_from_body(double dt_s) {
  const b2Vec2 position = body_->GetPosition();
  pose_.position = {position.x, position.y};
  pose_.theta = core::wrap_angle(body_->GetAngle());
  const b2Vec2 velocity = body_->GetLinearVelocity();
  velocity_ = {velocity.x, velocity.y};
  angular_velocity_ = body_->GetAngularVelocity();
}

}  // namespace ari_social_sim::world
