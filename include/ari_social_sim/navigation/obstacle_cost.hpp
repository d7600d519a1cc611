#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// Clearance from walls and furniture (docs/navigation.md): for every footprint circle
/// (radius r) at every step, w max(0, r + margin - d(c))^2 with d the signed distance field, so the
/// whole footprint, not only base_footprint, keeps off obstacles.
class ObstacleCost : public CostTerm {
 public:
  ObstacleCost(double weight, const FootprintModel& footprint, double margin_m)
      : weight_(weight),
        offsets_(footprint.circle_offsets_x_m),
        reach_m_(footprint.circle_radius_m + margin_m) {}
  const char* name() const override { return "obstacle"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  double weight_;
  std::vector<double> offsets_;
  double reach_m_;
};

}  // namespace ari_social_sim::navigation
