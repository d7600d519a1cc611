#pragma once

#include <Eigen/Core>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::model {

/// ARI's footprint in base_footprint (ari_robot's URDF, see docs/references.md): the mobile base
/// spans x -0.60..+0.16 m, y +-0.27 m; base_footprint sits on the wheel axle at the front.
struct AriFootprint {
  double rear_x_m{-0.60};
  double front_x_m{0.16};
  double half_width_m{0.27};

  Eigen::Vector2d centre_local() const { return {0.5 * (rear_x_m + front_x_m), 0.0}; }

  /// The footprint's bounds (config_fields.hpp); the world checks them in AriSpec::validate.
  template <class V>
  void visit(V& v) {
    v.field("rear_x", rear_x_m, "m, the base's rear edge in base_footprint");
    v.field("front_x", front_x_m, "m, the base's front edge in base_footprint");
    v.rule("front_x", rear_x_m < front_x_m,
           "a number above rear_x (" + core::number_text(rear_x_m) + ")",
           core::number_text(front_x_m));
    v.field("half_width", half_width_m, "m, half the base's width", core::positive());
  }
};

}  // namespace ari_social_sim::model
