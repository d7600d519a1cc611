#include "ari_social_sim/navigation/goal_cost.hpp"

namespace ari_social_sim::navigation {

double GoalCost::evaluate(const MpcProblem& problem, const Rollout& rollout, const Eigen::VectorXd&,
                          RolloutGradient* gradient) const {
  double total = 0.0;
  const int steps = rollout.steps();
  for (int t = 1; t <= steps; ++t) {
    const double w = weight_ + (t == steps ? terminal_weight_ : 0.0);
    Eigen::Vector2d g;
    const double distance = problem.geodesic->cost(rollout.states[t].position, &g);
    const bool quadratic = distance < huber_m_;
    total += w * (quadratic ? 0.5 * distance * distance / huber_m_ : distance - 0.5 * huber_m_);
    if (gradient != nullptr) {
      const double slope = w * (quadratic ? distance / huber_m_ : 1.0);
      gradient->states[t].head<2>() += slope * g;
    }
  }
  return total;
}

}  // namespace ari_social_sim::navigation
