#pragma once

#include "ari_social_sim/navigation/cost_term.hpp"

namespace ari_social_sim::navigation {

/// Personal spaces (Kirby 2010; docs/navigation.md): for every person j, footprint circle and step,
///   s_j (w f_j(q) + w_e max(0, ln(f_j(q) / f_e))^2),
/// f_j the asymmetric Gaussian of PersonalSpaceParams around the person predicted at constant
/// velocity, q the point of the circle nearest to the person (ARI's body edge, not its axis), s_j
/// the person's space scale (reduced for the person approached or the group joined). The soft
/// Gaussian alone either lets ARI cut through a space when the way round is longer or, weighted
/// up, pushes ARI off goals that lie just outside one; the stiff edge term is zero outside the
/// contour f_e (the space's edge `margin_sigmas` beyond boundary_sigmas) and grows with the
/// squared Mahalanobis depth inside it (ln f = -m^2 / 2), so it keeps ARI out without reaching
/// farther than the space itself.
class PersonalSpaceCost : public CostTerm {
 public:
  PersonalSpaceCost(double weight, double edge_weight, const FootprintModel& footprint,
                    const PersonalSpaceParams& params, double margin_sigmas, double step_s);
  const char* name() const override { return "personal_space"; }
  double evaluate(const MpcProblem& problem, const Rollout& rollout,
                  const Eigen::VectorXd& controls, RolloutGradient* gradient) const override;

 private:
  double weight_, edge_weight_;
  double log_edge_value_;  // ln f_e
  std::vector<double> offsets_;
  double circle_radius_m_;
  PersonalSpaceParams params_;
  double step_s_;
};

}  // namespace ari_social_sim::navigation
