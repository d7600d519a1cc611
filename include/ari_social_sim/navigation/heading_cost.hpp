#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// Arrival heading: sum_t w k(G_t) (1 - cos(theta_t - theta_goal)), with k(G) = 1 / (1 + (G/r)^2)
/// fading the term in within about r of the goal, so ARI turns to the goal heading as it arrives
/// but drives facing its path elsewhere.
class HeadingCost : public CostTerm {
 public:
  HeadingCost(double weight, double radius_m) : weight_(weight), radius_m_(radius_m) {}
  const char* name() const override { return "heading"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  double weight_, radius_m_;
};

}  // namespace ari_social_sim::navigation
