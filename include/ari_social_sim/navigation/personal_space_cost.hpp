#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// Personal spaces (specs/algorithms.md 2.5): for every person j, footprint circle and step,
/// w s_j f_j(q), f_j the asymmetric Gaussian of PersonalSpaceParams around the person predicted at
/// constant velocity, q the point of the circle nearest to the person (ARI's body edge, not its
/// axis), s_j the person's space scale (reduced for the person approached or the group joined).
class PersonalSpaceCost : public CostTerm {
 public:
  PersonalSpaceCost(double weight, const FootprintModel& footprint,
                    const PersonalSpaceParams& params, double step_s)
      : weight_(weight),
        offsets_(footprint.circle_offsets_x_m),
        circle_radius_m_(footprint.circle_radius_m),
        params_(params),
        step_s_(step_s) {}
  const char* name() const override { return "personal_space"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  double weight_;
  std::vector<double> offsets_;
  double circle_radius_m_;
  PersonalSpaceParams params_;
  double step_s_;
};

}  // namespace ari_social_sim::navigation
