#include "ari_social_sim/world/human.hpp"

#include <box2d/box2d.h>

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/human_navigation.hpp"
#include "ari_social_sim/world/step_motion.hpp"
#include "ari_social_sim/world/walked_distance.hpp"

namespace ari_social_sim::world {

void HumanSpec::validate() const {
  core::check_fields<core::RequestError>(*this, "");
}

Human::Human(const HumanSpec& spec, core::Rng gaze_rng, core::Rng reaction_rng)
    : Object(spec.id, ObjectKind::kHuman),
      spec_(spec),
      gaze_rng_(gaze_rng),
      reaction_rng_(reaction_rng) {
  pose_ = spec.pose;
  posture_.posture = spec.posture;
  navigation_ = &add_component(std::make_unique<HumanNavigation>());
  speech_ = &add_component(std::make_unique<SpeechGenerator>(spec.words_per_minute));
  if (spec.gaze) {
    set_gaze_model(*spec.gaze);
  }
  if (spec.goal) {
    set_goal(*spec.goal);
  }
  set_reaction(spec.reaction);
}

void Human::set_reaction(ReactionProfile profile) {
  spec_.reaction = profile;
  if (reaction_ != nullptr) {
    reaction_->set_profile(profile);
    return;
  }
  // Nothing for kIgnore: a human that never reacts steps exactly as before reactions existed.
  if (profile != ReactionProfile::kIgnore) {
    reaction_ = &add_component(std::make_unique<RobotReaction>(
        profile, spec_.reaction_params.value_or(ReactionParams{}), reaction_rng_));
  }
}

void Human::set_gaze_model(GazeModel model) {
  if (gaze_ != nullptr) {
    gaze_->set_model(std::move(model));
    return;
  }
  gaze_ = &add_component(std::make_unique<GazeGenerator>(std::move(model), gaze_rng_));
  gaze_->set_suspended(conversation_gaze_.has_value());
}

void Human::set_conversation_gaze(const std::optional<GazeEvent>& gaze) {
  conversation_gaze_ = gaze;
  if (gaze_ != nullptr) {
    gaze_->set_suspended(gaze.has_value());
  }
}

const std::optional<core::Pose2>& Human::goal() const {
  return navigation_->goal();
}

void Human::set_velocity(const Eigen::Vector2d& velocity_mps, double angular_velocity_rps) {
  ARI_DCHECK(velocity_mps.allFinite() && std::isfinite(angular_velocity_rps));
  mode_ = MotionMode::kDirect;
  posture_.change_to(Posture::kStanding);
  navigation_->clear_goal();
  direct_velocity_ = velocity_mps;
  direct_angular_velocity_ = angular_velocity_rps;
}

void Human::set_goal(const core::Pose2& goal) {
  ARI_DCHECK(goal.position.allFinite() && std::isfinite(goal.theta));
  mode_ = MotionMode::kNavigation;
  posture_.change_to(Posture::kStanding);
  navigation_->set_goal(goal);
}

void Human::stop() {
  mode_ = MotionMode::kIdle;
  navigation_->clear_goal();
  planned_velocity_.setZero();
  planned_rotation_ = 0.0;
}

void Human::join_group(model::ObjectId group_id) {
  stop();
  mode_ = MotionMode::kGroup;
  group_id_ = group_id;
}

void Human::leave_group() {
  group_id_ = model::kNoObject;
  if (mode_ == MotionMode::kGroup) {
    stop();
  }
}

void Human::plan_motion(const Eigen::Vector2d& velocity_mps, double rotation_rad) {
  // The navigation component and the group script plan every step: a NaN is caught where made.
  ARI_DCHECK(velocity_mps.allFinite() && std::isfinite(rotation_rad));
  planned_velocity_ = velocity_mps;
  planned_rotation_ = rotation_rad;
}

void Human::set_orientation(double theta_rad) {
  pose_.theta = core::wrap_angle(theta_rad);
}

void Human::apply_motion(const StepContext& context) {
  if (!posture_.is_standing()) {
    apply_posture(context.dt_s);
    return;
  }
  if (body()->GetType() != b2_dynamicBody) {
    body()->SetType(b2_dynamicBody);
  }
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  double rotation = 0.0;
  switch (mode_) {
    case MotionMode::kIdle:
      break;
    case MotionMode::kDirect:
      velocity = direct_velocity_;
      rotation = direct_angular_velocity_ * context.dt_s;
      break;
    case MotionMode::kNavigation:
    case MotionMode::kGroup:
      velocity = planned_velocity_;
      rotation = planned_rotation_;
      break;
  }
  if (reaction_ != nullptr && mode_ != MotionMode::kDirect) {
    apply_reaction(reaction_->motion(), context.dt_s, velocity, rotation);
  }
  body()->SetLinearVelocity(
      b2Vec2(static_cast<float>(velocity.x()), static_cast<float>(velocity.y())));
  pose_.theta = core::wrap_angle(pose_.theta + rotation);
  angular_velocity_ = rotation / context.dt_s;
}

void Human::apply_posture(double dt_s) {
  // Kinematic: no contact moves it, so a seated person stays on the seat whoever brushes past;
  // and none is made with furniture, so the seat under them is no obstacle.
  if (body()->GetType() != b2_kinematicBody) {
    body()->SetType(b2_kinematicBody);
  }
  const double speed_mps = posture_.advance(dt_s);
  const Eigen::Vector2d velocity =
      speed_mps * Eigen::Vector2d(std::cos(pose_.theta), std::sin(pose_.theta));
  body()->SetLinearVelocity(
      b2Vec2(static_cast<float>(velocity.x()), static_cast<float>(velocity.y())));
  angular_velocity_ = 0.0;
}

void Human::apply_reaction(const ReactionMotion& reaction, double dt_s, Eigen::Vector2d& velocity,
                           double& rotation) const {
  switch (reaction.kind) {
    case ReactionMotion::Kind::kNone:
      return;
    case ReactionMotion::Kind::kReplace:
      velocity = reaction.velocity_mps;
      rotation = 0.0;
      break;
    case ReactionMotion::Kind::kAdd:
      velocity += reaction.velocity_mps;
      break;
  }
  // Nobody runs, whatever the sum (as step_motion caps a plan).
  const double speed = velocity.norm();
  if (speed > spec_.motion.max_speed_mps) {
    velocity *= spec_.motion.max_speed_mps / speed;
  }
  if (reaction.face_rad) {
    rotation =
        rotation_step(core::angle_difference(*reaction.face_rad, pose_.theta), spec_.motion, dt_s);
  }
}

void Human::sync_from_body(double dt_s) {
  const b2Vec2 position = body()->GetPosition();
  pose_.position = {position.x, position.y};
  const b2Vec2 velocity = body()->GetLinearVelocity();
  velocity_ = {velocity.x, velocity.y};
  walked_m_ = walked_on(walked_m_, velocity_, posture_.seated_fraction(), dt_s);
  ARI_DCHECK(pose_.position.allFinite() && velocity_.allFinite() && std::isfinite(pose_.theta));
}

}  // namespace ari_social_sim::world
