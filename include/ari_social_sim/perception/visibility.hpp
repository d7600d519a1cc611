#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/perception/field_of_view.hpp"

namespace ari_social_sim::perception {

/// What blocks sight in one instant: the static map and the people, as circles of one radius.
struct SightObstacles {
  const model::OccupancyGrid* grid{nullptr};  ///< Not owned; null = no static obstacles.
  int occupied_threshold{50};
  const std::vector<Eigen::Vector2d>* people{nullptr};  ///< Circle centres (map); not owned.
  double person_radius_m{0.2};
  /// Per person (indices of `people`): true while sitting or standing up or sitting down. Not
  /// owned; null = everyone stands.
  const std::vector<bool>* seated{nullptr};
};

/// D6.4 §3.5.2 raycasting: the share of `ray_count` rays from the sensor, spread evenly over the
/// angular width of person `target` (index into obstacles.people), that reach that person's circle
/// without entering a blocking grid cell or another person's circle first, and that lie inside
/// the sensor's wedge. 1 when the sensor stands inside the circle. Range is not checked here.
/// For a seated target the map is not checked within person_radius_m of its circle: what the
/// map holds there is the chair under them (the map has no heights).
double visible_fraction(const FieldOfView& sensor, const SightObstacles& obstacles, size_t target,
                        int ray_count);

}  // namespace ari_social_sim::perception
