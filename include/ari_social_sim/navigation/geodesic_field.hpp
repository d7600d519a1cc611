#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/navigation/grid_field.hpp"

namespace ari_social_sim::navigation {

/// How the travel-distance field weighs the map ("G" of docs/navigation.md).
struct GeodesicParams {
  double inscribed_radius_m{0.28};  // ARI's half width
  double preferred_clearance_m{0.7};
  double clearance_penalty{1.5};
  double blocked_cost{25.0};
  double snap_radius_m{0.35};
  double person_clearance_m{0.3};
  double person_cost{6.0};
  double group_cost{6.0};

  template <class V>
  void visit(V& v) {
    v.field("inscribed_radius", inscribed_radius_m,
            "m: base_footprint closer than this to a wall or furniture cannot pass",
            core::Bounds{0.0, 2.0, true});
    v.field("preferred_clearance", preferred_clearance_m,
            "m: below this clearance a cell costs more, so paths keep to the middle of doors and "
            "corridors",
            core::Bounds{0.0, 5.0, true});
    v.rule("preferred_clearance", preferred_clearance_m >= inscribed_radius_m,
           "a value >= inscribed_radius (" + core::number_text(inscribed_radius_m) + ")",
           core::number_text(preferred_clearance_m));
    v.field("clearance_penalty", clearance_penalty,
            "extra cost per metre at zero spare clearance (1 = twice the free-space cost)",
            core::non_negative());
    // Finite, so that the field's gradient still leads back into free space.
    v.field("blocked_cost", blocked_cost,
            "cost per metre of cells ARI cannot pass (closer than the inscribed radius, or "
            "occupied)",
            core::between(1.0, 1e6));
    // ARI's base_footprint sits at the front of the body and may stand nearer to a wall than the
    // inscribed radius.
    v.field("snap_radius", snap_radius_m,
            "m: a start or goal this close to a passable cell counts as on it",
            core::between(0.0, 2.0));
    v.field("person_clearance", person_clearance_m,
            "m: people standing (slower than 0.3 m/s) raise the cost within their body radius + "
            "the inscribed radius + this, so the way leads around them",
            core::between(0.0, 2.0));
    v.field("person_cost", person_cost,
            "extra cost per metre near a standing person (0 = ignore people)",
            core::non_negative());
    v.field("group_cost", group_cost,
            "extra cost per metre inside the o-space of groups ARI is not joining (0 = ignore "
            "groups)",
            core::non_negative());
  }
};

/// A disc of the map where travel costs `extra_cost` more per metre (people, groups): it bends the
/// way around them without making anything unreachable.
struct CostDisc {
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
  double radius_m{0.0};
  double extra_cost{0.0};
};

/// Travel cost (m of free-space travel) from every cell to a goal point on the static map, solved
/// with the fast marching method (first-order upwind Eikonal updates from a binary heap), so the
/// MPC's progress term has no local minima behind walls, nor behind a group standing in the way
/// (cost discs). Cells ARI cannot pass carry a high but finite cost; `reachable()` tells apart the
/// cells joined to the goal through passable space of the static map.
class GeodesicField {
 public:
  GeodesicField() = default;
  /// `sdf` is the signed distance field of the map; `goal` is in the map frame.
  GeodesicField(const GridField& sdf, const Eigen::Vector2d& goal, const GeodesicParams& params,
                const std::vector<CostDisc>& discs = {});

  const GridField& field() const { return field_; }
  const Eigen::Vector2d& goal() const { return goal_; }
  /// Interpolated travel cost (m) at `point`, its gradient and mixed second derivative.
  double cost(const Eigen::Vector2d& point, Eigen::Vector2d* gradient = nullptr,
              double* cross = nullptr) const {
    return field_.sample(point, gradient, cross);
  }
  /// True when `point` lies within the snap radius of a passable cell joined to the goal through
  /// passable cells. False also when the goal itself has no passable cell near it.
  bool reachable(const Eigen::Vector2d& point) const;

 private:
  void march(const std::vector<float>& cost_per_m);
  void flood_passable();
  /// Passable cells within the snap radius of `point`.
  template <class Visit>
  void for_each_near(const Eigen::Vector2d& point, Visit visit) const;

  GridField field_;
  Eigen::Vector2d goal_{Eigen::Vector2d::Zero()};
  GeodesicParams params_;
  std::vector<uint8_t> passable_;
  std::vector<uint8_t> joined_;  // passable and connected to the goal through passable cells
};

}  // namespace ari_social_sim::navigation
