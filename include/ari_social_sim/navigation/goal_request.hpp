#pragma once

#include <Eigen/Core>
#include <string>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/navigation/goal_finder.hpp"
#include "ari_social_sim/navigation/grid_field.hpp"

namespace ari_social_sim::navigation {

/// A goal pose as a client sends it (geometry_msgs/PoseStamped's fields, without ROS types):
/// move_base's `target_pose`, /move_base_simple/goal.
struct PoseGoalRequest {
  std::string frame_id;
  double x{0.0}, y{0.0}, z{0.0};              ///< m, in frame_id
  double qx{0.0}, qy{0.0}, qz{0.0}, qw{0.0};  ///< orientation quaternion
};

/// How far a goal's quaternion norm may be from 1: clients normalise in single or double precision
/// (1e-7 or better); anything farther is a quaternion nobody meant, such as (0, 0, 0, 0) or yaw
/// angles written into z and w.
constexpr double kQuaternionNormTolerance = 1e-3;

/// The planar pose a request names in its own frame: (x, y) and the yaw of the quaternion (z is
/// ignored, as ARI drives on the floor). `field` prefixes the names in messages ("target_pose."
/// for move_base, "" for /move_base_simple/goal). Throws core::RequestError naming the field:
///   `target_pose.pose.position.x: expected a finite number, got nan`,
///   `target_pose.pose.orientation: expected a unit quaternion (norm within 0.001 of 1), got
///    (0, 0, 0, 0) of norm 0`,
///   `target_pose.header.frame_id: expected a tf frame such as map, got ''`.
core::Pose2 planar_goal(const PoseGoalRequest& request, const std::string& field);

/// True when `frame_id` is the map frame, "map" or "/map" (tf2 drops a leading slash).
bool names_map_frame(const std::string& frame_id);

/// The rectangle a map covers (m, map frame): from its origin to its far corner.
struct MapBounds {
  Eigen::Vector2d min{Eigen::Vector2d::Zero()};
  Eigen::Vector2d max{Eigen::Vector2d::Zero()};

  static MapBounds of(const GridField& map);
  bool contains(const Eigen::Vector2d& point) const;
  /// "x [-0.20, 12.20] and y [-0.20, 8.20]".
  std::string describe() const;
};

/// Throws core::RequestError when `X_map_goal` lies outside the map, naming `field` and giving
/// both: `target_pose.pose.position: (25.00, 3.00) in map is outside the map, which spans x
/// [-0.20, 12.20] and y [-0.20, 8.20]`.
void check_inside_map(const core::Pose2& X_map_goal, const MapBounds& bounds,
                      const std::string& field);

/// A ROS4HRI person or group id as an approach goal names it: not empty and without whitespace
/// (ids are parts of topic and frame names). Throws core::RequestError naming `field`:
/// `target_id: expected a person or group id (not empty, no whitespace), got 'human 3'`.
void check_target_id(const std::string& id, const std::string& field);

/// What Navigator::start checks of any target, from a node or in process: a pose's x, y and theta
/// finite, a person's or group's id as check_target_id. Throws core::RequestError, e.g.
/// `pose target: expected finite x, y and theta, got (nan, 1.00, 0.00)`.
void check_target(const NavigationTarget& target);

}  // namespace ari_social_sim::navigation
