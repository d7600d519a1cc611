#include "ari_social_sim/world/ari.hpp"

#include <box2d/box2d.h>

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::world {

void AriSpec::validate() const {
  if (id == kNoObject) {
    throw core::RequestError("ari.id must be a positive integer");
  }
  if (std::abs(head_pan_rad) > limits.head_pan_limit_rad) {
    throw core::RequestError("ari.head_pan must be within +-" +
                             std::to_string(limits.head_pan_limit_rad) + " rad, got " +
                             std::to_string(head_pan_rad));
  }
  if (!(words_per_minute > 0.0)) {
    throw core::RequestError("ari.words_per_minute must be > 0");
  }
}

Ari::Ari(const AriSpec& spec, double map_resolution_m)
    : Object(spec.id, ObjectKind::kAri), spec_(spec) {
  pose_ = spec.pose;
  drive_ = &add_component(std::make_unique<DifferentialDrive>(spec.limits));
  head_ = &add_component(std::make_unique<HeadPanController>(spec.limits, spec.head_pan_rad));
  speech_ = &add_component(std::make_unique<SpeechGenerator>(spec.words_per_minute));
  map_sensor_ = &add_component(std::make_unique<MapSensor>(map_resolution_m));
}

void Ari::follow(const core::Pose2& pose, double linear_mps, double angular_rps) {
  followed_ = pose;
  followed_linear_mps_ = linear_mps;
  followed_angular_rps_ = angular_rps;
}

void Ari::apply_motion(const StepContext& context) {
  if (followed_) {
    // The velocity that lands the body on the followed pose at the end of this step; contacts
    // with people may still stop it short, as they would stop the 3D robot.
    const Eigen::Vector2d velocity = (followed_->position - pose_.position) / context.dt_s;
    body()->SetLinearVelocity(
        b2Vec2(static_cast<float>(velocity.x()), static_cast<float>(velocity.y())));
    body()->SetAngularVelocity(
        static_cast<float>(core::angle_difference(followed_->theta, pose_.theta) / context.dt_s));
    return;
  }
  // The body's centre of mass is placed at base_footprint, so Box2D rotates it about the wheel
  // axle as a differential drive turns.
  const double v = drive_->linear_mps();
  body()->SetLinearVelocity(b2Vec2(static_cast<float>(v * std::cos(pose_.theta)),
                                   static_cast<float>(v * std::sin(pose_.theta))));
  body()->SetAngularVelocity(static_cast<float>(drive_->angular_rps()));
}

}  // namespace ari_social_sim::world
