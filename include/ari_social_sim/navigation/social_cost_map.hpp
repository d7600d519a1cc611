#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/navigation/mpc_problem.hpp"
#include "ari_social_sim/navigation/social_spaces.hpp"

namespace ari_social_sim::navigation {

/// The social cost density of one point, as the MPC weighs it (per unit weight, before ARI's
/// footprint): sum of the people's personal-space Gaussians times their space scale, plus the
/// o-space Gaussians of the groups ARI is not joining.
double social_cost_density(const MpcProblem& problem, const PersonalSpaceParams& spaces,
                           const Eigen::Vector2d& point);

struct CostSample {
  Eigen::Vector2d position;
  double value;
};

/// social_cost_density on a square grid of `spacing_m` within `half_extent_m` of `centre`, keeping
/// the samples above `min_value` (what rviz shows as the social cost markers).
std::vector<CostSample> sample_social_cost(const MpcProblem& problem,
                                           const PersonalSpaceParams& spaces,
                                           const Eigen::Vector2d& centre, double half_extent_m,
                                           double spacing_m, double min_value);

}  // namespace ari_social_sim::navigation
