#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ari_social_sim::navigation {

/// A person as perception reports them, in the map frame.
struct PersonEstimate {
  std::string id;                                     // ROS4HRI person id, e.g. "human12"
  Eigen::Vector2d position{Eigen::Vector2d::Zero()};  // m, body centre
  double heading{0.0};                                // rad, facing direction of the body
  Eigen::Vector2d velocity{Eigen::Vector2d::Zero()};  // m/s

  /// Predicted position after `t_s` seconds at constant velocity.
  Eigen::Vector2d position_at(double t_s) const { return position + velocity * t_s; }
};

/// A conversational group (F-formation) with its o-space, from its members' poses.
struct GroupEstimate {
  std::string id;                                   // ROS4HRI group id
  std::vector<std::string> members;                 // person ids of the members perception knows
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};  // m, o-space centre
  double radius_m{0.0};  // mean distance of the members from the centre (where they stand)
};

/// O-space of a group (docs/navigation.md): centre = mean of the members' candidate centres
/// p_i + stride (cos theta_i, sin theta_i), as GCFF fits it; radius = mean distance of the members
/// from that centre. Needs at least one member.
GroupEstimate estimate_group(const std::string& id, const std::vector<PersonEstimate>& members,
                             double stride_m);

/// Everyone and every group perception reports at one time.
struct PerceivedScene {
  std::vector<PersonEstimate> people;
  std::vector<GroupEstimate> groups;

  const PersonEstimate* find_person(const std::string& id) const;
  const GroupEstimate* find_group(const std::string& id) const;
  /// The group that lists `person_id`, or null.
  const GroupEstimate* group_of(const std::string& person_id) const;
};

}  // namespace ari_social_sim::navigation
