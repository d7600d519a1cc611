#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ari_social_sim/model/object_id.hpp"

namespace ari_social_sim::world {

class Simulation;
class GroupNavigation;

/// How well one member stands in its F-formation.
struct MemberPlacement {
  model::ObjectId id{model::kNoObject};
  Eigen::Vector2d position{Eigen::Vector2d::Zero()};
  double orientation_rad{0.0};
  double distance_to_circle_m{0.0};  // | |p - o| - s |
  double facing_error_rad{0.0};      // |angle between the heading and the direction to o|
};

struct MemberDistance {
  model::ObjectId a{model::kNoObject};
  model::ObjectId b{model::kNoObject};
  double distance_m{0.0};
};

/// A group's formation measured against its o-space circle: what the formation tests assert and
/// what world_node prints at the end of a run.
struct GroupReport {
  model::ObjectId id{model::kNoObject};
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
  double ospace_radius_m{0.0};
  std::vector<MemberPlacement> members;
  std::vector<MemberDistance> distances;  // every pair once

  double max_distance_to_circle_m() const;
  double max_facing_error_rad() const;
  double min_member_distance_m() const;

  static GroupReport of(const Simulation& simulation, const GroupNavigation& group);
  /// A few lines for a terminal: members' positions, headings and pairwise distances.
  std::string to_text() const;
};

}  // namespace ari_social_sim::world
