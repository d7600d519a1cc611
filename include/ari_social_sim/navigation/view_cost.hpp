#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// Keeps the target in the head camera's view (the project's own term, docs/navigation.md:
/// w_p (pan + theta - bearing)^2 in the bounded form w (1 - cos e)), e the angle between the
/// camera axis (theta + pan) and the bearing from the head pan axis to the target. Without a target
/// the head looks ahead (e = pan). Pan beyond head_1_joint's +-75 deg costs w_limit per rad^2.
class ViewCost : public CostTerm {
 public:
  ViewCost(double weight, double limit_weight, const FootprintModel& footprint, double pan_limit)
      : weight_(weight),
        limit_weight_(limit_weight),
        head_offset_x_m_(footprint.head_offset_x_m),
        pan_limit_(pan_limit) {}
  const char* name() const override { return "view"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  double weight_, limit_weight_;
  double head_offset_x_m_;
  double pan_limit_;
};

}  // namespace ari_social_sim::navigation
