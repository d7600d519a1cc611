#include "ari_social_sim/navigation/control_cost.hpp"

#include <cmath>

namespace ari_social_sim::navigation {
namespace {

// w max(0, |delta| - limit)^2 and its derivative with respect to delta.
double excess_change(double delta, double limit, double weight, double* derivative) {
  double slope;
  const double cost = weight * hinge_squared(std::abs(delta) - limit, &slope);
  *derivative = weight * slope * (delta < 0.0 ? -1.0 : 1.0);
  return cost;
}

}  // namespace

double ControlCost::evaluate(const MpcProblem& problem, const Rollout&,
                             const Eigen::VectorXd& controls, RolloutGradient* gradient) const {
  const CostWeights& w = weights_;
  const double effort[3] = {w.effort_linear, w.effort_angular, w.effort_pan};
  const double smooth[3] = {w.smooth_linear, w.smooth_angular, w.smooth_pan};
  double previous[3] = {problem.start_linear_mps, problem.start_angular_rps, problem.start_pan_rps};
  double total = 0.0;
  const int steps = static_cast<int>(controls.size()) / kControlsPerStep;
  for (int t = 0; t < steps; ++t) {
    const int base = kControlsPerStep * t;
    for (int k = 0; k < kControlsPerStep; ++k) {
      const double u = controls[base + k];
      const double delta = u - previous[k];
      total += effort[k] * u * u + smooth[k] * delta * delta;
      double d_delta = 2.0 * smooth[k] * delta;
      if (k < 2) {
        double d_excess;
        total += excess_change(delta, k == 0 ? max_linear_change_ : max_angular_change_,
                               w.acceleration, &d_excess);
        d_delta += d_excess;
      }
      double d_u = 2.0 * effort[k] * u + d_delta;
      if (k == 0 && u < 0.0) {
        total += w.reverse * u * u;
        d_u += 2.0 * w.reverse * u;
      }
      if (gradient != nullptr) {
        gradient->controls[base + k] += d_u;
        if (t > 0) {
          gradient->controls[base + k - kControlsPerStep] -= d_delta;
        }
      }
      previous[k] = u;
    }
  }
  return total;
}

}  // namespace ari_social_sim::navigation
