#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// Progress toward the goal along the geodesic field G (docs/navigation.md):
///   sum_t w_goal rho(G(p_t)) + w_terminal rho(G(p_N)),
/// rho the Huber function of width h (G^2 / 2h below h, G - h/2 above), so the pull is constant far
/// away and fades smoothly at the goal instead of overshooting. p_t is base_footprint.
class GoalCost : public CostTerm {
 public:
  GoalCost(double weight, double terminal_weight, double huber_m)
      : weight_(weight), terminal_weight_(terminal_weight), huber_m_(huber_m) {}
  const char* name() const override { return "goal"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  double weight_, terminal_weight_, huber_m_;
};

}  // namespace ari_social_sim::navigation
