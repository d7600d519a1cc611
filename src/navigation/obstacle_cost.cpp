#include "ari_social_sim/navigation/obstacle_cost.hpp"

namespace ari_social_sim::navigation {

double ObstacleCost::evaluate(const MpcProblem& problem, const Rollout& rollout,
                              const Eigen::VectorXd&, RolloutGradient* gradient) const {
  double total = 0.0;
  for (int t = 1; t <= rollout.steps(); ++t) {
    for (int i = 0; i < rollout.circle_count; ++i) {
      Eigen::Vector2d g;
      const double clearance = problem.sdf->sample(rollout.circle(t, i), &g);
      double slope;
      total += weight_ * hinge_squared(reach_m_ - clearance, &slope);
      if (gradient != nullptr && slope > 0.0) {
        gradient->add_body_point(rollout, t, offsets_[i], -weight_ * slope * g);
      }
    }
  }
  return total;
}

}  // namespace ari_social_sim::navigation
