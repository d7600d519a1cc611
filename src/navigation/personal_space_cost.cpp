#include "ari_social_sim/navigation/personal_space_cost.hpp"

#include <cmath>

namespace ari_social_sim::navigation {

PersonalSpaceCost::PersonalSpaceCost(double weight, double edge_weight,
                                     const FootprintModel& footprint,
                                     const PersonalSpaceParams& params, double margin_sigmas,
                                     double step_s)
    : weight_(weight),
      edge_weight_(edge_weight),
      log_edge_value_(-0.5 * std::pow(params.boundary_sigmas + margin_sigmas, 2)),
      offsets_(footprint.circle_offsets_x_m),
      circle_radius_m_(footprint.circle_radius_m),
      params_(params),
      step_s_(step_s) {}

double PersonalSpaceCost::evaluate(const MpcProblem& problem, const Rollout& rollout,
                                   const Eigen::VectorXd&, RolloutGradient* gradient) const {
  double total = 0.0;
  for (const ProblemPerson& person : problem.people) {
    const double w = weight_ * person.space_scale;
    const double w_edge = edge_weight_ * person.space_scale;
    if (w <= 0.0 && w_edge <= 0.0) {
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
        const double f =
            personal_space_value(person.estimate, params_, edge, time_s, gradient ? &g : nullptr);
        const double depth = std::max(0.0, std::log(f) - log_edge_value_);
        total += w * f + w_edge * depth * depth;
        if (gradient != nullptr) {
          // d ln f / dq = g / f.
          const double slope = w + (depth > 0.0 ? 2.0 * w_edge * depth / f : 0.0);
          gradient->add_body_point(rollout, t, offsets_[i], slope * jacobian.transpose() * g);
        }
      }
    }
  }
  return total;
}

}  // namespace ari_social_sim::navigation
