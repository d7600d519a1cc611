#pragma once

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/perception/field_of_view.hpp"
#include "ari_social_sim/perception/perception_config.hpp"

namespace ari_social_sim::perception {

/// What a tracker made of one person in one frame. Ordered by how badly the track was broken:
/// a re-found track looks at the worst cause of its gap.
enum class Sighting { kDetected = 0, kMissed = 1, kOccluded = 2, kOutOfView = 3 };

/// Where a person stood for a sensor in one frame.
struct DetectionGeometry {
  double distance_m{0.0};
  double range_m{1.0};
  double angle_inside_rad{0.0};  ///< From the person's bearing to the nearer edge of the view.
  double visible_fraction{1.0};
  double min_visible_fraction{0.0};  ///< The sensor's occlusion threshold.
};

/// Probability of missing a person the sensor could see: independent causes combined as
/// 1 - (1 - base)(1 - distance)(1 - border)(1 - occlusion), where
///  - distance  = miss_rate_at_max_range * distance / range,
///  - border    = miss_rate_at_fov_border * (1 - angle_inside / band), within the band only,
///  - occlusion = miss_rate_occluded * (1 - visible) / (1 - min_visible).
double miss_probability(const DetectionErrors& errors, const DetectionGeometry& geometry);

/// Decides one frame's sighting of a person: out of view when beyond range or outside the wedge,
/// occluded when less than the minimum fraction is visible, otherwise detected unless a miss is
/// drawn with miss_probability. Draws from `rng` only in the last case.
Sighting decide_sighting(const DetectionErrors& errors, const FieldOfView& sensor,
                         const Eigen::Vector2d& person_map, double visible_fraction,
                         double min_visible_fraction, core::Rng& rng);

}  // namespace ari_social_sim::perception
