#pragma once

#include <Eigen/Geometry>
#include <cstdint>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/person_attributes.hpp"

namespace ari_social_sim::physics {

/// Proportions of the person-shaped bodies standing in for the 2D world's humans (m). The body is
/// a vertical cylinder from the floor to the shoulders, the head a sphere above it.
struct PersonShapeConfig {
  double body_radius_m{0.2};  // the 2D world's body_radius
  double shoulder_height_m{1.45};
  double head_radius_m{0.11};
  double head_centre_height_m{1.62};  // eyes at about 1.6 m, an adult's

  template <class V>
  void visit(V& v) {
    v.field("body_radius", body_radius_m, "m, the cylinder's radius", core::positive());
    v.field("shoulder_height", shoulder_height_m, "m, the cylinder's top", core::positive());
    v.field("head_radius", head_radius_m, "m, the head sphere's radius", core::positive());
    v.field("head_centre_height", head_centre_height_m, "m, the head sphere's centre",
            core::positive());
    v.rule("head_centre_height", head_centre_height_m > shoulder_height_m,
           "a height above shoulder_height (" + core::number_text(shoulder_height_m) + ")",
           core::number_text(head_centre_height_m));
  }
};

/// A human as the 2D world reports it (/sim/world_state): map frame.
struct PersonState {
  uint32_t id{0};
  core::Pose2 pose;                                       // body centre and heading
  Eigen::Vector2d velocity_mps{Eigen::Vector2d::Zero()};  // map frame
  double angular_velocity_rps{0.0};
  double face_yaw_rad{0.0};    // where the face points (the gaze direction), map frame
  double head_pitch_rad{0.0};  // positive: down (a nod)
  // How the cameras draw them (physics::HumanFigure).
  double age_years{35.0};
  model::Gender gender{model::Gender::kNonIdentified};
  bool mask{false};
  model::Emotion emotion{model::Emotion::kNeutral};
  bool speaking{false};
  double seated_fraction{0.0};  // 0 standing, 1 seated (world::PostureState::seated_fraction)
  double walked_m{0.0};         // world::HumanSnapshot::walked_m, walked on to now
};

/// A person's 3D shape at one instant, for collisions and rendering.
struct PersonShape {
  uint32_t id{0};
  /// Feet centre on the floor; x along the body's heading, z up.
  Eigen::Isometry3d X_map_body{Eigen::Isometry3d::Identity()};
  Eigen::Vector3d head_centre_map{Eigen::Vector3d::Zero()};
  double face_yaw_rad{0.0};
  PersonShapeConfig proportions;

  static PersonShape of(const PersonState& state, const PersonShapeConfig& proportions);
};

}  // namespace ari_social_sim::physics
