#include "ari_social_sim/navigation/agent_clearance_cost.hpp"

namespace ari_social_sim::navigation {

double AgentClearanceCost::evaluate(const MpcProblem& problem, const Rollout& rollout,
                                    const Eigen::VectorXd&, RolloutGradient* gradient) const {
  double total = 0.0;
  for (const ProblemPerson& person : problem.people) {
    for (int t = 1; t <= rollout.steps(); ++t) {
      const Eigen::Vector2d position = person.estimate.position_at(t * step_s_);
      for (int i = 0; i < rollout.circle_count; ++i) {
        const Eigen::Vector2d offset = rollout.circle(t, i) - position;
        const double distance = offset.norm();
        double slope;
        total += weight_ * hinge_squared(reach_m_ - distance, &slope);
        if (gradient != nullptr && slope > 0.0 && distance > 1e-9) {
          gradient->add_body_point(rollout, t, offsets_[i], -weight_ * slope * offset / distance);
        }
      }
    }
  }
  return total;
}

}  // namespace ari_social_sim::navigation
