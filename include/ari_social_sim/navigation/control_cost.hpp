#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// Control effort and smoothness (docs/navigation.md, w_u |u|^2 + w_d |u_t - u_{t-1}|^2), plus
/// ARI's acceleration limits (1 m/s^2, 2.094 rad/s^2) as a stiff penalty on each step's change
/// beyond a_max dt, and a penalty on driving backwards (ARI has no rear sensors). The first step's
/// change is taken from the measured velocities.
class ControlCost : public CostTerm {
 public:
  ControlCost(const CostWeights& weights, const model::AriLimits& limits, double step_s)
      : weights_(weights),
        max_linear_change_(limits.max_linear_accel_mps2 * step_s),
        max_angular_change_(limits.max_angular_accel_rps2 * step_s) {}
  const char* name() const override { return "control"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  CostWeights weights_;
  double max_linear_change_;
  double max_angular_change_;
};

}  // namespace ari_social_sim::navigation
