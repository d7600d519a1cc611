#include "ari_social_sim/perception/detection_model.hpp"

#include <algorithm>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::perception {

double miss_probability(const DetectionErrors& errors, const DetectionGeometry& geometry) {
  const double distance =
      errors.miss_rate_at_max_range * std::clamp(geometry.distance_m / geometry.range_m, 0.0, 1.0);
  double border = 0.0;
  const double band_rad = core::deg_to_rad(errors.fov_border_deg);
  if (band_rad > 0.0) {
    border = errors.miss_rate_at_fov_border *
             std::clamp(1.0 - geometry.angle_inside_rad / band_rad, 0.0, 1.0);
  }
  double occlusion = 0.0;
  if (geometry.min_visible_fraction < 1.0) {
    occlusion = errors.miss_rate_occluded * std::clamp((1.0 - geometry.visible_fraction) /
                                                           (1.0 - geometry.min_visible_fraction),
                                                       0.0, 1.0);
  }
  return 1.0 - (1.0 - errors.miss_rate) * (1.0 - distance) * (1.0 - border) * (1.0 - occlusion);
}

Sighting decide_sighting(const DetectionErrors& errors, const FieldOfView& sensor,
                         const Eigen::Vector2d& person_map, double visible_fraction,
                         double min_visible_fraction, core::Rng& rng) {
  const double distance = sensor.distance_to(person_map);
  const double inside = sensor.angle_inside(sensor.bearing_of(person_map));
  if (distance > sensor.range_m || inside < 0.0) {
    return Sighting::kOutOfView;
  }
  if (visible_fraction < min_visible_fraction || visible_fraction <= 0.0) {
    return Sighting::kOccluded;
  }
  const double miss = miss_probability(
      errors, {distance, sensor.range_m, inside, visible_fraction, min_visible_fraction});
  return miss > 0.0 && rng.bernoulli(miss) ? Sighting::kMissed : Sighting::kDetected;
}

}  // namespace ari_social_sim::perception
