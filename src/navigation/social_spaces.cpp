#include "ari_social_sim/navigation/social_spaces.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::navigation {

double PersonalSpaceParams::boundary_value() const {
  return std::exp(-0.5 * boundary_sigmas * boundary_sigmas);
}

double personal_space_value(const PersonEstimate& person, const PersonalSpaceParams& params,
                            const Eigen::Vector2d& point, double t_s, Eigen::Vector2d* gradient) {
  const Eigen::Vector2d d = point - person.position_at(t_s);
  const double c = std::cos(person.heading), s = std::sin(person.heading);
  const double along = c * d.x() + s * d.y();
  const double across = -s * d.x() + c * d.y();
  const double sigma_along =
      along > 0.0 ? params.sigma_front_m + params.front_per_speed_s * person.velocity.norm()
                  : params.sigma_rear_m;
  const double inv_along = 1.0 / (sigma_along * sigma_along);
  const double inv_across = 1.0 / (params.sigma_side_m * params.sigma_side_m);
  const double value = std::exp(-0.5 * (along * along * inv_along + across * across * inv_across));
  if (gradient != nullptr) {
    // The two halves meet with equal value and zero slope along x, so f is C1 everywhere.
    const double d_along = -value * along * inv_along;
    const double d_across = -value * across * inv_across;
    *gradient = {c * d_along - s * d_across, s * d_along + c * d_across};
  }
  return value;
}

bool outline_inside_personal_space(const std::vector<Eigen::Vector2d>& outline,
                                   const core::Pose2& ari, const PersonEstimate& person,
                                   const PersonalSpaceParams& params) {
  const double edge = params.boundary_value();
  return std::any_of(outline.begin(), outline.end(), [&](const Eigen::Vector2d& point) {
    return personal_space_value(person, params, ari.transform(point), 0.0) >= edge;
  });
}

Eigen::Vector2d nearest_point_of_disc(const Eigen::Vector2d& centre, double radius_m,
                                      const Eigen::Vector2d& target, Eigen::Matrix2d* jacobian) {
  const Eigen::Vector2d offset = target - centre;
  const double distance = offset.norm();
  if (distance <= radius_m) {
    if (jacobian != nullptr) {
      jacobian->setZero();
    }
    return target;
  }
  const Eigen::Vector2d unit = offset / distance;
  if (jacobian != nullptr) {
    // q = centre + r u with u = (target - centre) / |target - centre|: dq/dcentre = I - r (I - u
    // u^T) / distance.
    const Eigen::Matrix2d projector = Eigen::Matrix2d::Identity() - unit * unit.transpose();
    *jacobian = Eigen::Matrix2d::Identity() - (radius_m / distance) * projector;
  }
  return centre + radius_m * unit;
}

double ospace_radius(const GroupEstimate& group, const PersonalSpaceParams& params) {
  return std::max(group.radius_m - params.person_radius_m, 0.3);
}

}  // namespace ari_social_sim::navigation
