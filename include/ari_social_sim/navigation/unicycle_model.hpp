#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/navigation/footprint_model.hpp"

namespace ari_social_sim::navigation {

/// ARI's state as the MPC predicts it (docs/navigation.md): base_footprint pose in the map
/// frame and the head pan (head_1_joint, rad, positive to the left).
struct RobotState {
  Eigen::Vector2d position{Eigen::Vector2d::Zero()};
  double theta{0.0};
  double pan{0.0};
};

/// Controls of one step: base linear velocity (m/s), base angular velocity (rad/s), head pan
/// velocity (rad/s). A sequence of N steps is stored flat as [v_0, w_0, pan_rate_0, v_1, ...].
constexpr int kControlsPerStep = 3;

/// A predicted trajectory: states 0..N (0 = now) and, per state, the points the costs read (the
/// footprint circle centres and the head pan axis), so each term does not recompute them.
struct Rollout {
  std::vector<RobotState> states;
  std::vector<Eigen::Vector2d> circle_centres;  // (N + 1) x circle count, row per state
  std::vector<Eigen::Vector2d> heads;           // head pan axis per state
  int circle_count{0};

  int steps() const { return static_cast<int>(states.size()) - 1; }
  const Eigen::Vector2d& circle(int step, int i) const {
    return circle_centres[static_cast<size_t>(step) * circle_count + i];
  }
};

/// d(cost)/d(state) per state, as (x, y, theta, pan), and d(cost)/d(controls) (flat, 3 N).
struct RolloutGradient {
  std::vector<Eigen::Vector4d> states;
  Eigen::VectorXd controls;

  void reset(int steps);
  /// Adds the gradient `g` of a cost with respect to a point rigidly attached to the base at
  /// `offset_x_m` on the body axis, at state `step` (theta enters through the point's lever arm).
  void add_body_point(const Rollout& rollout, int step, double offset_x_m,
                      const Eigen::Vector2d& g);
};

/// Unicycle base plus head pan, integrated with the heading at mid-step:
///   m = theta + w dt / 2, x+ = x + v dt cos m, y+ = y + v dt sin m, theta+ = theta + w dt,
///   pan+ = pan + pan_rate dt.
/// Joint and acceleration limits are left to the costs and the solvers' bounds, so the map from
/// controls to states stays smooth for gradient-based solvers.
class UnicycleModel {
 public:
  UnicycleModel(double step_s, FootprintModel footprint)
      : step_s_(step_s), footprint_(std::move(footprint)) {}

  double step_s() const { return step_s_; }
  const FootprintModel& footprint() const { return footprint_; }

  /// Fills `rollout` from `start` under `controls` (3 N values).
  void rollout(const RobotState& start, const Eigen::VectorXd& controls, Rollout& rollout) const;
  /// Turns per-state gradients into gradients with respect to the controls (reverse mode through
  /// the dynamics), adding to gradient.controls. `gradient.states` is used as scratch.
  void backpropagate(const Rollout& rollout, const Eigen::VectorXd& controls,
                     RolloutGradient& gradient) const;

 private:
  double step_s_;
  FootprintModel footprint_;
};

}  // namespace ari_social_sim::navigation
