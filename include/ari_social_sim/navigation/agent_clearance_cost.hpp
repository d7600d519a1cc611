#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// Physical clearance from people, social or not: for every footprint circle and every person
/// predicted at constant velocity, w max(0, r + r_person + margin - |c - p_j(t)|)^2. The
/// non-social baseline keeps this term and drops the personal and group spaces.
class AgentClearanceCost : public CostTerm {
 public:
  AgentClearanceCost(double weight, const FootprintModel& footprint, double person_radius_m,
                     double margin_m, double step_s)
      : weight_(weight),
        offsets_(footprint.circle_offsets_x_m),
        reach_m_(footprint.circle_radius_m + person_radius_m + margin_m),
        step_s_(step_s) {}
  const char* name() const override { return "agent_clearance"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  double weight_;
  std::vector<double> offsets_;
  double reach_m_;
  double step_s_;
};

}  // namespace ari_social_sim::navigation
