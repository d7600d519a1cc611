#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ari_social_sim/model/fformation_arrangement.hpp"
#include "ari_social_sim/perception/gcff.hpp"

// The shape of one conversational group, for comparing the world's groups with recorded ones
// (docs/perception_gcff.md, "Geometry of recorded groups").

namespace ari_social_sim::perception {

using model::Arrangement;

/// One group's geometry: the o-space centre as GCFF places it (each member's point `stride` ahead
/// of them, averaged), each member's distance to it and how far their facing turns away from it,
/// and the distance of every pair of members. Lengths in the members' unit.
struct FormationGeometry {
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
  std::vector<double> centre_distances;
  std::vector<double> facing_offsets_rad;  // in [0, pi]
  std::vector<double> pair_distances;
  Arrangement arrangement{Arrangement::kCircle};
};

/// Precondition: at least two members, stride > 0.
FormationGeometry formation_geometry(const std::vector<GcffPerson>& members, double stride);

/// Side-by-side when every two members' facings are within 45 degrees; otherwise two people are
/// vis-a-vis when their facings are at least 135 degrees apart and an L-shape between, and three
/// or more form a circle.
Arrangement classify_arrangement(const std::vector<GcffPerson>& members);

}  // namespace ari_social_sim::perception
