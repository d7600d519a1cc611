#include "ari_social_sim/navigation/heading_cost.hpp"

#include <cmath>

namespace ari_social_sim::navigation {

double HeadingCost::evaluate(const MpcProblem& problem, const Rollout& rollout,
                             const Eigen::VectorXd&, RolloutGradient* gradient) const {
  const int last = rollout.steps();
  if (problem.at_goal_position) {
    // Standing at the goal: every step off the goal heading counts, so ARI turns now rather than
    // at the end of the horizon.
    double total = 0.0;
    for (int t = 1; t <= last; ++t) {
      const double error = rollout.states[t].theta - problem.goal.theta;
      total += weight_ * (1.0 - std::cos(error));
      if (gradient != nullptr) {
        gradient->states[t][2] += weight_ * std::sin(error);
      }
    }
    return total;
  }
  const RobotState& s = rollout.states[last];
  Eigen::Vector2d g;
  double cross;
  const double distance = problem.geodesic->cost(s.position, &g, &cross);
  const double d2 = distance * distance;
  const double q = 1.0 + d2 * d2 / std::pow(radius_m_, 4);
  const double fade = 1.0 / q;
  const double d_fade = -4.0 * d2 * distance / std::pow(radius_m_, 4) / (q * q);  // d(fade)/dG

  double total = 0.0;
  // On the way: the direction of the path, fading out at the goal where it has none.
  const double g2 = g.squaredNorm();
  if (path_weight_ <= 0.0 || g2 < 1e-12) {
    return total;
  }
  const double path = std::atan2(-g.y(), -g.x());
  const double path_error = s.theta - path;
  const double path_misalignment = 1.0 - std::cos(path_error);
  total += path_weight_ * (1.0 - fade) * path_misalignment;
  if (gradient != nullptr) {
    // psi = atan2(-g_y, -g_x): d(psi)/d(g) = (-g_y, g_x) / |g|^2, and d(g)/d(p) = [[0, c],
    // [c, 0]] for the bilinear field (c its mixed derivative).
    const Eigen::Vector2d d_path(g.x() * cross / g2, -g.y() * cross / g2);
    const double d_error = path_weight_ * (1.0 - fade) * std::sin(path_error);
    gradient->states[last].head<2>() +=
        -path_weight_ * path_misalignment * d_fade * g - d_error * d_path;
    gradient->states[last][2] += d_error;
  }
  return total;
}

}  // namespace ari_social_sim::navigation
