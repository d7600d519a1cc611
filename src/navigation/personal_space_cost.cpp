#include "ari_social_sim/navigation/personal_space_cost.hpp"

namespace ari_social_sim::navigation {

double PersonalSpaceCost::evaluate(const MpcProblem& problem, const Rollout& rollout,
                                   const Eigen::VectorXd&, RolloutGradient* gradient) const {
  double total = 0.0;
  for (const ProblemPerson& person : problem.people) {
    const double w = weight_ * person.space_scale;
    if (w <= 0.0) {
      continue;
    }
    for (int t = 1; t <= rollout.steps(); ++t) {
      const double time_s = t * step_s_;
      const Eigen::Vector2d position = person.estimate.position_at(time_s);
      for (int i = 0; i < rollout.circle_count; ++i) {
        Eigen::Matrix2d jacobian;
        const Eigen::Vector2d edge = nearest_point_of_disc(
            rollout.circle(t, i), circle_radius_m_, position, gradient ? &jacobian : nullptr);
        Eigen::Vector2d g;
        total += w * personal_space_value(person.estimate, params_, edge, time_s,
                                          gradient ? &g : nullptr);
        if (gradient != nullptr) {
          gradient->add_body_point(rollout, t, offsets_[i], w * jacobian.transpose() * g);
        }
      }
    }
  }
  return total;
}

}  // namespace ari_social_sim::navigation
