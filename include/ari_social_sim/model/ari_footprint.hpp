#pragma once

#include <Eigen/Core>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/model/shape_geometry.hpp"

namespace ari_social_sim::model {

/// ARI's footprint in base_footprint (ari_robot's URDF, see docs/references.md): the mobile base
/// spans x -0.60..+0.16 m, y +-0.27 m; base_footprint sits on the wheel axle at the front.
struct AriFootprint {
  /// Farthest a footprint edge may lie from base_footprint (m): a robot base, not a building.
  static constexpr double kMaxFootprintReachM = 5.0;

  double rear_x_m{-0.60};
  double front_x_m{0.16};
  double half_width_m{0.27};

  Eigen::Vector2d centre_local() const { return {0.5 * (rear_x_m + front_x_m), 0.0}; }

  /// The footprint's bounds (config_fields.hpp); the world checks them in AriSpec::validate. The
  /// base is a Box2D box with mass: each side at least Box2D's slop (shape_geometry.hpp), or its
  /// mass computation aborts the process.
  template <class V>
  void visit(V& v) {
    const core::Bounds reach = core::between(-kMaxFootprintReachM, kMaxFootprintReachM);
    v.field("rear_x", rear_x_m, "m, the base's rear edge in base_footprint", reach);
    v.field("front_x", front_x_m, "m, the base's front edge in base_footprint", reach);
    v.rule("front_x", front_x_m - rear_x_m >= kMinShapeFeatureM,
           "a number at least " + core::number_text(kMinShapeFeatureM) + " m above rear_x (" +
               core::number_text(rear_x_m) + ")",
           core::number_text(front_x_m));
    v.field("half_width", half_width_m, "m, half the base's width",
            core::between(kMinShapeFeatureM, kMaxFootprintReachM));
  }
};

}  // namespace ari_social_sim::model
