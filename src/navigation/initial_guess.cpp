#include "ari_social_sim/navigation/initial_guess.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::navigation {

Eigen::VectorXd follow_geodesic(const MpcProblem& problem, const MpcConfig& config,
                                const ControlBounds& bounds, double turn_bias_rps) {
  constexpr double kTurnGain = 2.0;      // 1/s, heading error to angular velocity
  constexpr double kPanGain = 4.0;       // 1/s, pan error to pan velocity
  constexpr double kSlowRadius = 0.8;    // m, full speed beyond this travel distance
  constexpr double kDirectRadius = 0.5;  // m, head straight for the goal point within this
  const double dt = config.step_s;
  const double max_dv = config.limits.max_linear_accel_mps2 * dt;
  const double max_dw = config.limits.max_angular_accel_rps2 * dt;
  Eigen::VectorXd controls(config.control_count());
  RobotState s = problem.start;
  double v_prev = problem.start_linear_mps, w_prev = problem.start_angular_rps;
  for (int t = 0; t < config.horizon_steps; ++t) {
    Eigen::Vector2d g;
    const double distance = problem.geodesic->cost(s.position, &g);
    // Standing at the goal: turn on the spot to its heading. On the way: steer down the field, or
    // straight at the goal point over the last half metre, where the field is coarse.
    double desired = problem.goal.theta;
    double v = 0.0;
    double error = core::angle_difference(desired, s.theta);
    if (!problem.at_goal_position) {
      const Eigen::Vector2d to_goal = problem.goal.position - s.position;
      const Eigen::Vector2d direction =
          distance < kDirectRadius || g.norm() < 1e-6 ? to_goal : Eigen::Vector2d(-g);
      desired = std::atan2(direction.y(), direction.x());
      error = core::angle_difference(desired, s.theta);
      v = config.max_linear_mps * std::max(0.0, std::cos(error)) *
          std::min(1.0, to_goal.norm() / kSlowRadius);
    }
    const double bias = t < config.horizon_steps / 2 ? turn_bias_rps : 0.0;
    // Ramp toward the wanted velocities within ARI's acceleration limits.
    v = std::clamp(v, v_prev - max_dv, v_prev + max_dv);
    const double w = std::clamp(kTurnGain * error + bias, w_prev - max_dw, w_prev + max_dw);
    double pan_target = 0.0;
    if (problem.look_at) {
      const Eigen::Vector2d to = *problem.look_at - s.position;
      pan_target = core::angle_difference(std::atan2(to.y(), to.x()), s.theta);
    }
    const double pan_rate = kPanGain * (pan_target - s.pan);
    controls.segment<3>(3 * t) << v, w, pan_rate;
    controls.segment<3>(3 * t) = controls.segment<3>(3 * t)
                                     .cwiseMax(bounds.lower.segment<3>(3 * t))
                                     .cwiseMin(bounds.upper.segment<3>(3 * t));
    const double applied_v = controls[3 * t], applied_w = controls[3 * t + 1];
    v_prev = applied_v;
    w_prev = applied_w;
    const double mid = s.theta + 0.5 * applied_w * dt;
    s.position += applied_v * dt * Eigen::Vector2d(std::cos(mid), std::sin(mid));
    s.theta += applied_w * dt;
    s.pan += controls[3 * t + 2] * dt;
  }
  return controls;
}

Eigen::VectorXd shift_by_one_step(const Eigen::VectorXd& previous) {
  const Eigen::Index n = previous.size();
  Eigen::VectorXd shifted(n);
  shifted.head(n - kControlsPerStep) = previous.tail(n - kControlsPerStep);
  shifted.tail(kControlsPerStep) = previous.tail(kControlsPerStep);
  return shifted;
}

}  // namespace ari_social_sim::navigation
