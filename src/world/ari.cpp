#include "ari_social_sim/world/ari.hpp"

#include <box2d/box2d.h>

#include <cmath>
#include <limits>
#include <utility>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::world {

void AriSpec::validate() const {
  core::check_fields<core::RequestError>(*this, "");
  core::check_fields<core::RequestError>(limits, "limits");
  core::check_fields<core::RequestError>(footprint, "footprint");
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
  ARI_DCHECK(pose.position.allFinite() && std::isfinite(pose.theta) && std::isfinite(linear_mps) &&
             std::isfinite(angular_rps));
  followed_ = pose;
  followed_linear_mps_ = linear_mps;
  followed_angular_rps_ = angular_rps;
}

void Ari::apply_motion(const StepContext& context) {
  if (followed_) {
    // The velocity that lands the body on the followed pose at the end of this step; contacts
    // with people may still stop it short, as they would stop the 3D robot.
    const Eigen::Vector2d velocity = (followed_->position - pose_.position) / context.dt_s;
    ARI_DCHECK(velocity.allFinite());
    body()->SetLinearVelocity(
        b2Vec2(static_cast<float>(velocity.x()), static_cast<float>(velocity.y())));
    body()->SetAngularVelocity(
        static_cast<float>(core::angle_difference(followed_->theta, pose_.theta) / context.dt_s));
    return;
  }
  // The body's centre of mass is placed at base_footprint, so Box2D rotates it about the wheel
  // axle as a differential drive turns.
  const double v = drive_->linear_mps();
  ARI_DCHECK(std::isfinite(v) && std::isfinite(drive_->angular_rps()) &&
             std::isfinite(pose_.theta));
  body()->SetLinearVelocity(b2Vec2(static_cast<float>(v * std::cos(pose_.theta)),
                                   static_cast<float>(v * std::sin(pose_.theta))));
  body()->SetAngularVelocity(static_cast<float>(drive_->angular_rps()));
}

}  // namespace ari_social_sim::world
