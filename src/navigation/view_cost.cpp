#include "ari_social_sim/navigation/view_cost.hpp"

#include <cmath>

namespace ari_social_sim::navigation {

double ViewCost::evaluate(const MpcProblem& problem, const Rollout& rollout, const Eigen::VectorXd&,
                          RolloutGradient* gradient) const {
  // Closer than this to the head pan axis the bearing turns too fast to be worth following.
  constexpr double kMinBearingDistance = 0.3;
  double total = 0.0;
  for (int t = 1; t <= rollout.steps(); ++t) {
    const RobotState& s = rollout.states[t];
    double error = s.pan;
    Eigen::Vector2d to_target = Eigen::Vector2d::Zero();
    if (problem.look_at) {
      to_target = *problem.look_at - rollout.heads[t];
      if (to_target.norm() >= kMinBearingDistance) {
        error = s.theta + s.pan - std::atan2(to_target.y(), to_target.x());
      } else {
        to_target.setZero();
      }
    }
    total += weight_ * (1.0 - std::cos(error));
    double slope;
    const double excess = std::abs(s.pan) - pan_limit_;
    total += limit_weight_ * hinge_squared(excess, &slope);
    if (gradient != nullptr) {
      const double d_error = weight_ * std::sin(error);
      gradient->states[t][3] += d_error + limit_weight_ * slope * (s.pan < 0.0 ? -1.0 : 1.0);
      if (!to_target.isZero()) {
        gradient->states[t][2] += d_error;
        // bearing = atan2(d), d = target - head: d(bearing)/d(head) = (d_y, -d_x) / |d|^2.
        const Eigen::Vector2d d_bearing =
            Eigen::Vector2d(to_target.y(), -to_target.x()) / to_target.squaredNorm();
        gradient->add_body_point(rollout, t, head_offset_x_m_, -d_error * d_bearing);
      }
    }
  }
  return total;
}

}  // namespace ari_social_sim::navigation
