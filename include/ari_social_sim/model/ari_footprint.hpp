#pragma once

#include <Eigen/Core>

namespace ari_social_sim::model {

/// ARI's footprint in base_footprint (ari_robot's URDF, see docs/references.md): the mobile base
/// spans x -0.60..+0.16 m, y +-0.27 m; base_footprint sits on the wheel axle at the front.
struct AriFootprint {
  double rear_x_m{-0.60};
  double front_x_m{0.16};
  double half_width_m{0.27};

  Eigen::Vector2d centre_local() const { return {0.5 * (rear_x_m + front_x_m), 0.0}; }
};

}  // namespace ari_social_sim::model
