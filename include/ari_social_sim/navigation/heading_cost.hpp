#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// Heading, in two phases. On the way, a cost-to-go on the last state of the horizon:
///   w_path (1 - k(G_N)) (1 - cos(theta_N - psi(p_N))),   k(G) = 1 / (1 + (G/r)^4),
/// psi the direction of -grad G: a horizon ending facing away from the way still owes the turn, so
/// crawling backwards toward a goal behind ARI never beats turning round (k switches it off
/// within about r of the goal, where the path has no direction). Once ARI stands at the goal
/// position (MpcProblem::at_goal_position), the arrival heading on every step:
///   sum_t w (1 - cos(theta_t - theta_goal)),
/// so ARI turns on the spot now rather than at the end of the horizon. The goal heading plays no
/// part before: a unicycle that turns to it before arriving must reverse or manoeuvre sideways to
/// close the last decimetres, which within a 3 s horizon looks dearer than stopping short.
class HeadingCost : public CostTerm {
 public:
  HeadingCost(double weight, double path_weight, double radius_m)
      : weight_(weight), path_weight_(path_weight), radius_m_(radius_m) {}
  const char* name() const override { return "heading"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  double weight_, path_weight_, radius_m_;
};

}  // namespace ari_social_sim::navigation
