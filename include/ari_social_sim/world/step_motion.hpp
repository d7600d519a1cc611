#pragma once

#include <Eigen/Core>
#include <cmath>

#include "ari_social_sim/world/human.hpp"

namespace ari_social_sim::world {

/// The velocity that moves a human by eta * f over one step (eq. 3.3, 3.11), with
/// eta = walking_speed * step and the speed capped at max_speed.
struct StepMotion {
  Eigen::Vector2d velocity_mps{Eigen::Vector2d::Zero()};

  bool is_moving() const { return velocity_mps.squaredNorm() > 1e-12; }
  double direction_rad() const { return std::atan2(velocity_mps.y(), velocity_mps.x()); }
};

inline StepMotion step_motion(const Eigen::Vector2d& force, const HumanMotionParams& params) {
  // eta * f / dt = walking_speed * f: the step length is folded into a velocity for Box2D.
  Eigen::Vector2d velocity = params.walking_speed_mps * force;
  const double speed = velocity.norm();
  if (speed > params.max_speed_mps) {
    velocity *= params.max_speed_mps / speed;
  }
  return {velocity};
}

/// The rotation over one step toward a remaining turn `turn_rad` (eq. 3.4, 3.12).
inline double rotation_step(double turn_rad, const HumanMotionParams& params, double dt_s) {
  return std::min(1.0, params.turn_gain_per_s * dt_s) * turn_rad;
}

}  // namespace ari_social_sim::world
