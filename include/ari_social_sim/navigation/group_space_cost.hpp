#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// O-spaces of the groups ARI is not joining (docs/navigation.md): for every such group,
/// footprint circle and step, a soft isotropic Gaussian w_g exp(-|q - c|^2 / (2 R^2)) (q the circle
/// point nearest the centre c, R the members' radius) plus a stiff edge
/// w_e max(0, r_o + margin - (|c_i - c| - r))^2 that keeps the footprint out of the o-space disc of
/// radius r_o. Members' personal spaces are PersonalSpaceCost's.
class GroupSpaceCost : public CostTerm {
 public:
  GroupSpaceCost(double weight, double edge_weight, const FootprintModel& footprint,
                 const PersonalSpaceParams& params, double margin_m)
      : weight_(weight),
        edge_weight_(edge_weight),
        offsets_(footprint.circle_offsets_x_m),
        circle_radius_m_(footprint.circle_radius_m),
        params_(params),
        margin_m_(margin_m) {}
  const char* name() const override { return "group_space"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  double weight_, edge_weight_;
  std::vector<double> offsets_;
  double circle_radius_m_;
  PersonalSpaceParams params_;
  double margin_m_;
};

}  // namespace ari_social_sim::navigation
