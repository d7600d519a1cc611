#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/navigation/goal_finder.hpp"
#include "ari_social_sim/navigation/navigator.hpp"
#include "ari_social_sim/navigation/perceived_scene.hpp"

namespace ari_social_sim::navigation {

/// What a learned navigation policy is shown: how many people, how much of the map.
struct PolicyObservationConfig {
  int nearest_people{6};
  int patch_cells{16};
  double patch_resolution_m{0.25};
  double people_range_m{8.0};

  template <class V>
  void visit(V& v) {
    v.field("nearest_people", nearest_people, "people shown, nearest first (K)",
            core::between(0, 64));
    v.field("patch_cells", patch_cells, "cells along each side of the egocentric occupancy patch",
            core::between(1, 128));
    v.field("patch_resolution", patch_resolution_m, "m per cell of the occupancy patch",
            core::between(0.02, 2.0));
    v.field("people_range", people_range_m, "m: people farther from ARI are not shown",
            core::positive());
  }
  void validate() const;
};

/// One named part of the observation vector, with the bounds of its values.
struct ObservationField {
  std::string name;
  int offset{0};
  int size{0};
  float low{0.0f};
  float high{0.0f};
};

/// Turns what navigation knows at a control cycle (ARI as measured, the perceived scene, the goal
/// the goal finder placed) into the flat vector a learned policy reads. Written once for the
/// learning environments and for the policy driving ARI live, so that a policy trained in batch
/// sees the same numbers on the robot. Everything is in ARI's base_footprint frame (x forward,
/// y left), metres, seconds and radians:
/// - robot (3): linear and angular velocity, head pan;
/// - goal (6): perceived (1/0: placed on what perception reports, or given otherwise), x, y, cos
/// and sin of the goal heading relative to ARI's, distance;
/// - group (4): joining (1/0), x, y of the joined group's o-space centre, its radius;
/// - people (9 per person, K of them, nearest first; absent ones all 0): present, x, y, vx, vy,
///   cos and sin of their facing relative to ARI's, target (the person approached or a member of
///   the group joined), grouped (in any group);
/// - occupancy (P x P): 1 where the static map is occupied, unknown or outside, else 0; cell
///   (i, j), index i * P + j, centred at x = (i - (P - 1) / 2) * r, y = (j - (P - 1) / 2) * r.
class PolicyObservation {
 public:
  explicit PolicyObservation(const PolicyObservationConfig& config);

  int size() const { return size_; }
  const std::vector<ObservationField>& fields() const { return fields_; }
  const PolicyObservationConfig& config() const { return config_; }

  /// Writes size() values into `out`. `goal` is empty while the target has no place (all goal
  /// values 0); `goal_perceived` tells whether it was placed on `scene`.
  void build(const RobotObservation& robot, const PerceivedScene& scene,
             const std::optional<Goal>& goal, bool goal_perceived, const model::OccupancyGrid& map,
             float* out) const;

 private:
  void write_people(const core::Pose2& pose, const PerceivedScene& scene,
                    const std::optional<Goal>& goal, float* at) const;
  void write_occupancy(const core::Pose2& pose, const model::OccupancyGrid& map, float* at) const;

  PolicyObservationConfig config_;
  std::vector<ObservationField> fields_;
  int size_{0};
};

}  // namespace ari_social_sim::navigation
