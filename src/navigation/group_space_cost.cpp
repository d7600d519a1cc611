#include "ari_social_sim/navigation/group_space_cost.hpp"

#include <cmath>

namespace ari_social_sim::navigation {

double GroupSpaceCost::evaluate(const MpcProblem& problem, const Rollout& rollout,
                                const Eigen::VectorXd&, RolloutGradient* gradient) const {
  double total = 0.0;
  for (const ProblemGroup& group : problem.groups) {
    if (group.is_target) {
      continue;
    }
    const Eigen::Vector2d& centre = group.estimate.centre;
    const double spread = std::max(group.estimate.radius_m, 0.3);
    const double inv_2s2 = 0.5 / (spread * spread);
    const double edge_reach = ospace_radius(group.estimate, params_) + margin_m_ + circle_radius_m_;
    for (int t = 1; t <= rollout.steps(); ++t) {
      for (int i = 0; i < rollout.circle_count; ++i) {
        const Eigen::Vector2d& circle = rollout.circle(t, i);
        Eigen::Matrix2d jacobian;
        const Eigen::Vector2d edge =
            nearest_point_of_disc(circle, circle_radius_m_, centre, gradient ? &jacobian : nullptr);
        const Eigen::Vector2d d = edge - centre;
        const double soft = std::exp(-d.squaredNorm() * inv_2s2);
        const Eigen::Vector2d offset = circle - centre;
        const double distance = offset.norm();
        double slope;
        const double stiff = hinge_squared(edge_reach - distance, &slope);
        total += weight_ * soft + edge_weight_ * stiff;
        if (gradient != nullptr) {
          Eigen::Vector2d g = weight_ * jacobian.transpose() * (-2.0 * inv_2s2 * soft * d);
          if (slope > 0.0 && distance > 1e-9) {
            g -= edge_weight_ * slope * offset / distance;
          }
          gradient->add_body_point(rollout, t, offsets_[i], g);
        }
      }
    }
  }
  return total;
}

}  // namespace ari_social_sim::navigation
