#include "ari_social_sim/navigation/unicycle_model.hpp"

#include <cmath>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::navigation {

void RolloutGradient::reset(int steps) {
  states.assign(static_cast<size_t>(steps) + 1, Eigen::Vector4d::Zero());
  controls.setZero(static_cast<Eigen::Index>(steps) * kControlsPerStep);
}

void RolloutGradient::add_body_point(const Rollout& rollout, int step, double offset_x_m,
                                     const Eigen::Vector2d& g) {
  const double theta = rollout.states[step].theta;
  // d(point)/d(theta) = offset_x (-sin theta, cos theta).
  const double d_theta = offset_x_m * (-std::sin(theta) * g.x() + std::cos(theta) * g.y());
  states[step] += Eigen::Vector4d(g.x(), g.y(), d_theta, 0.0);
}

void UnicycleModel::rollout(const RobotState& start, const Eigen::VectorXd& controls,
                            Rollout& out) const {
  const int steps = static_cast<int>(controls.size()) / kControlsPerStep;
  ARI_DCHECK(controls.size() == steps * kControlsPerStep);
  const int circles = static_cast<int>(footprint_.circle_offsets_x_m.size());
  out.circle_count = circles;
  out.states.resize(static_cast<size_t>(steps) + 1);
  out.circle_centres.resize(static_cast<size_t>(steps + 1) * circles);
  out.heads.resize(static_cast<size_t>(steps) + 1);
  out.states[0] = start;
  for (int t = 0; t <= steps; ++t) {
    RobotState& s = out.states[t];
    if (t > 0) {
      const RobotState& prev = out.states[t - 1];
      const double v = controls[kControlsPerStep * (t - 1)];
      const double w = controls[kControlsPerStep * (t - 1) + 1];
      const double pan_rate = controls[kControlsPerStep * (t - 1) + 2];
      const double mid = prev.theta + 0.5 * w * step_s_;
      s.position = prev.position + v * step_s_ * Eigen::Vector2d(std::cos(mid), std::sin(mid));
      s.theta = prev.theta + w * step_s_;
      s.pan = prev.pan + pan_rate * step_s_;
    }
    const Eigen::Vector2d axis(std::cos(s.theta), std::sin(s.theta));
    for (int i = 0; i < circles; ++i) {
      out.circle_centres[static_cast<size_t>(t) * circles + i] =
          s.position + footprint_.circle_offsets_x_m[i] * axis;
    }
    out.heads[t] = s.position + footprint_.head_offset_x_m * axis;
  }
}

void UnicycleModel::backpropagate(const Rollout& rollout, const Eigen::VectorXd& controls,
                                  RolloutGradient& gradient) const {
  const int steps = rollout.steps();
  // lambda accumulates d(total cost)/d(state t) from step N down to 1.
  Eigen::Vector4d lambda = gradient.states[steps];
  for (int t = steps; t >= 1; --t) {
    const RobotState& prev = rollout.states[t - 1];
    const double v = controls[kControlsPerStep * (t - 1)];
    const double w = controls[kControlsPerStep * (t - 1) + 1];
    const double mid = prev.theta + 0.5 * w * step_s_;
    const double c = std::cos(mid), s = std::sin(mid);
    // d(x+, y+)/d(mid) = v dt (-sin m, cos m).
    const double d_mid = v * step_s_ * (-s * lambda[0] + c * lambda[1]);
    gradient.controls[kControlsPerStep * (t - 1)] += step_s_ * (c * lambda[0] + s * lambda[1]);
    gradient.controls[kControlsPerStep * (t - 1) + 1] +=
        0.5 * step_s_ * d_mid + step_s_ * lambda[2];
    gradient.controls[kControlsPerStep * (t - 1) + 2] += step_s_ * lambda[3];
    lambda[2] += d_mid;
    lambda += gradient.states[t - 1];
  }
}

}  // namespace ari_social_sim::navigation
