#include "ari_social_sim/perception/fformation_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::perception {
namespace {

Eigen::Vector2d position(const GcffPerson& person) {
  return {person.x, person.y};
}

Eigen::Vector2d facing(const GcffPerson& person) {
  return {std::cos(person.theta), std::sin(person.theta)};
}

}  // namespace

Arrangement classify_arrangement(const std::vector<GcffPerson>& members) {
  // Shoulder to shoulder: every two facings within 45 degrees.
  double widest = 0.0;
  for (size_t i = 0; i < members.size(); ++i) {
    for (size_t j = i + 1; j < members.size(); ++j) {
      widest =
          std::max(widest, std::abs(core::angle_difference(members[i].theta, members[j].theta)));
    }
  }
  if (widest <= 0.25 * M_PI) {
    return Arrangement::kSideBySide;
  }
  if (members.size() != 2) {
    return Arrangement::kCircle;
  }
  return widest >= 0.75 * M_PI ? Arrangement::kVisAVis : Arrangement::kLShape;
}

FormationGeometry formation_geometry(const std::vector<GcffPerson>& members, double stride) {
  FormationGeometry geometry;
  for (const GcffPerson& member : members) {
    geometry.centre += position(member) + stride * facing(member);
  }
  geometry.centre /= static_cast<double>(members.size());
  for (size_t i = 0; i < members.size(); ++i) {
    const Eigen::Vector2d to_centre = geometry.centre - position(members[i]);
    geometry.centre_distances.push_back(to_centre.norm());
    geometry.facing_offsets_rad.push_back(std::abs(
        core::angle_difference(std::atan2(to_centre.y(), to_centre.x()), members[i].theta)));
    for (size_t j = i + 1; j < members.size(); ++j) {
      geometry.pair_distances.push_back((position(members[j]) - position(members[i])).norm());
    }
  }
  geometry.arrangement = classify_arrangement(members);
  return geometry;
}

}  // namespace ari_social_sim::perception
