#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/navigation/perceived_scene.hpp"

namespace ari_social_sim::navigation {

/// Asymmetric Gaussian personal space (Kirby 2010), in the person's frame
/// (x along their heading): f = exp(-(x^2 / (2 s_x^2) + y^2 / (2 s_side^2))), s_x = front sigma
/// ahead of the person and rear sigma behind. The front sigma grows with walking speed, as people
/// claim more room ahead when they walk. The space's edge is the contour at `boundary_sigmas`.
struct PersonalSpaceParams {
  double sigma_front_m{0.6};  // standing person: edge 1.2 m ahead at 2 sigma
  double sigma_side_m{0.4};
  double sigma_rear_m{0.3};
  double front_per_speed_s{0.3};
  double boundary_sigmas{2.0};
  double person_radius_m{0.2};

  /// Value at which the edge lies: exp(-boundary_sigmas^2 / 2).
  double boundary_value() const;

  template <class V>
  void visit(V& v) {
    v.field("sigma_front", sigma_front_m, "m ahead of a standing person", core::positive());
    v.field("sigma_side", sigma_side_m, "m to the side", core::positive());
    v.field("sigma_rear", sigma_rear_m, "m behind", core::positive());
    v.field("front_per_speed", front_per_speed_s, "m of front sigma per m/s of walking speed",
            core::non_negative());
    v.field("boundary_sigmas", boundary_sigmas, "where the personal space's edge lies",
            core::Bounds{0.0, 5.0, true});
    v.field("person_radius", person_radius_m, "m, body radius, for clearance and the o-space edge",
            core::Bounds{0.0, 1.0, true});
  }
};

/// f at `point` (map frame) for a person standing or walking as estimated; with `gradient`, also
/// df/dpoint. The person's position is taken at `t_s` seconds ahead (constant velocity).
double personal_space_value(const PersonEstimate& person, const PersonalSpaceParams& params,
                            const Eigen::Vector2d& point, double t_s,
                            Eigen::Vector2d* gradient = nullptr);

/// True when a point of `outline` (ARI's footprint outline in base_footprint) placed at `ari`
/// lies on or within the edge contour of `person`'s personal space.
bool outline_inside_personal_space(const std::vector<Eigen::Vector2d>& outline,
                                   const core::Pose2& ari, const PersonEstimate& person,
                                   const PersonalSpaceParams& params);

/// Point of a disc (centre `centre`, radius `radius_m`) nearest to `target`, and its Jacobian with
/// respect to the disc centre (symmetric, written to `jacobian` when given). The target itself when
/// it lies inside the disc. Lets social costs judge ARI's body edge rather than its centre line.
Eigen::Vector2d nearest_point_of_disc(const Eigen::Vector2d& centre, double radius_m,
                                      const Eigen::Vector2d& target,
                                      Eigen::Matrix2d* jacobian = nullptr);

/// Radius (m) of a group's o-space, the free disc inside its members' bodies (never below 0.3 m).
double ospace_radius(const GroupEstimate& group, const PersonalSpaceParams& params);

}  // namespace ari_social_sim::navigation
