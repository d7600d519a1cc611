#include "ari_social_sim/navigation/heading_cost.hpp"

#include <cmath>

namespace ari_social_sim::navigation {

double HeadingCost::evaluate(const MpcProblem& problem, const Rollout& rollout,
                             const Eigen::VectorXd&, RolloutGradient* gradient) const {
  double total = 0.0;
  const double inv_r2 = 1.0 / (radius_m_ * radius_m_);
  for (int t = 1; t <= rollout.steps(); ++t) {
    const RobotState& s = rollout.states[t];
    Eigen::Vector2d g;
    const double distance = problem.geodesic->cost(s.position, &g);
    const double q = 1.0 + distance * distance * inv_r2;
    const double fade = 1.0 / q;
    const double error = s.theta - problem.goal.theta;
    const double misalignment = 1.0 - std::cos(error);
    total += weight_ * fade * misalignment;
    if (gradient != nullptr) {
      const double d_fade = -2.0 * distance * inv_r2 / (q * q);
      gradient->states[t].head<2>() += weight_ * misalignment * d_fade * g;
      gradient->states[t][2] += weight_ * fade * std::sin(error);
    }
  }
  return total;
}

}  // namespace ari_social_sim::navigation
