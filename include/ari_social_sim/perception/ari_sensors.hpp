#pragma once

#include <Eigen/Core>

#include "ari_social_sim/perception/field_of_view.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::perception {

/// Where ARI's perceiving sensors are at one instant, in the map frame: the torso fisheye (fixed
/// to the base), the head camera (turning with the head pan) and the microphone array.
struct AriSensors {
  FieldOfView body_camera;
  FieldOfView face_camera;
  Eigen::Vector2d microphone{Eigen::Vector2d::Zero()};
  double listening_range_m{0.0};

  static AriSensors of(const world::AriSnapshot& ari, const PerceptionConfig& config);
};

}  // namespace ari_social_sim::perception
