#include "ari_social_sim/navigation/social_cost_map.hpp"

#include <cmath>

namespace ari_social_sim::navigation {

double social_cost_density(const MpcProblem& problem, const PersonalSpaceParams& spaces,
                           const Eigen::Vector2d& point) {
  double value = 0.0;
  for (const ProblemPerson& person : problem.people) {
    value += person.space_scale * personal_space_value(person.estimate, spaces, point, 0.0);
  }
  for (const ProblemGroup& group : problem.groups) {
    if (!group.is_target) {
      const double spread = std::max(group.estimate.radius_m, 0.3);
      value += std::exp(-(point - group.estimate.centre).squaredNorm() / (2.0 * spread * spread));
    }
  }
  return value;
}

std::vector<CostSample> sample_social_cost(const MpcProblem& problem,
                                           const PersonalSpaceParams& spaces,
                                           const Eigen::Vector2d& centre, double half_extent_m,
                                           double spacing_m, double min_value) {
  std::vector<CostSample> samples;
  const int steps = static_cast<int>(std::floor(half_extent_m / spacing_m));
  for (int iy = -steps; iy <= steps; ++iy) {
    for (int ix = -steps; ix <= steps; ++ix) {
      const Eigen::Vector2d point = centre + spacing_m * Eigen::Vector2d(ix, iy);
      const double value = social_cost_density(problem, spaces, point);
      if (value >= min_value) {
        samples.push_back({point, value});
      }
    }
  }
  return samples;
}

}  // namespace ari_social_sim::navigation
