#include "ari_social_sim/navigation/goal_request.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::navigation {
namespace {

void check_finite(double value, const std::string& name) {
  if (!std::isfinite(value)) {
    throw core::RequestError(name + ": expected a finite number, got " + core::number_text(value));
  }
}

}  // namespace

core::Pose2 planar_goal(const PoseGoalRequest& request, const std::string& field) {
  if (request.frame_id.empty()) {
    throw core::RequestError(field + "header.frame_id: expected a tf frame such as map, got ''");
  }
  const std::string position = field + "pose.position.";
  check_finite(request.x, position + "x");
  check_finite(request.y, position + "y");
  check_finite(request.z, position + "z");
  const std::string orientation = field + "pose.orientation.";
  check_finite(request.qx, orientation + "x");
  check_finite(request.qy, orientation + "y");
  check_finite(request.qz, orientation + "z");
  check_finite(request.qw, orientation + "w");
  const double norm = std::sqrt(request.qx * request.qx + request.qy * request.qy +
                                request.qz * request.qz + request.qw * request.qw);
  if (std::abs(norm - 1.0) > kQuaternionNormTolerance) {
    throw core::RequestError(field + "pose.orientation: expected a unit quaternion (norm within " +
                             core::number_text(kQuaternionNormTolerance) + " of 1), got (" +
                             core::number_text(request.qx) + ", " + core::number_text(request.qy) +
                             ", " + core::number_text(request.qz) + ", " +
                             core::number_text(request.qw) + ") of norm " +
                             core::number_text(norm));
  }
  core::Pose2 pose;
  pose.position = {request.x, request.y};
  // The yaw of the rotation (its z-y-x Euler angle), as tf2::getYaw.
  const double qx = request.qx / norm, qy = request.qy / norm, qz = request.qz / norm,
               qw = request.qw / norm;
  pose.theta = std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
  return pose;
}

bool names_map_frame(const std::string& frame_id) {
  return frame_id == "map" || frame_id == "/map";
}

MapBounds MapBounds::of(const GridField& map) {
  MapBounds bounds;
  bounds.min = map.origin();
  bounds.max = map.origin() + map.resolution_m() * Eigen::Vector2d(map.width(), map.height());
  return bounds;
}

std::string MapBounds::describe() const {
  return "x [" + core::coordinate_text(min.x()) + ", " + core::coordinate_text(max.x()) +
         "] and y [" + core::coordinate_text(min.y()) + ", " + core::coordinate_text(max.y()) + "]";
}

bool MapBounds::contains(const Eigen::Vector2d& point) const {
  return point.x() >= min.x() && point.x() <= max.x() && point.y() >= min.y() &&
         point.y() <= max.y();
}

void check_inside_map(const core::Pose2& X_map_goal, const MapBounds& bounds,
                      const std::string& field) {
  if (bounds.contains(X_map_goal.position)) {
    return;
  }
  throw core::RequestError(field + ": " + core::point_text(X_map_goal.position) +
                           " in map is outside the map, which spans " + bounds.describe());
}

void check_target_id(const std::string& id, const std::string& field) {
  const bool has_space = std::any_of(id.begin(), id.end(), [](char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
  });
  if (id.empty() || has_space) {
    throw core::RequestError(
        field + ": expected a person or group id (not empty, no whitespace), got '" + id + "'");
  }
}

void check_target(const NavigationTarget& target) {
  if (const auto* pose = std::get_if<PoseTarget>(&target)) {
    const core::Pose2& p = pose->pose;
    if (!std::isfinite(p.position.x()) || !std::isfinite(p.position.y()) ||
        !std::isfinite(p.theta)) {
      throw core::RequestError("pose target: expected finite x, y and theta, got (" +
                               core::coordinate_text(p.position.x()) + ", " +
                               core::coordinate_text(p.position.y()) + ", " +
                               core::coordinate_text(p.theta) + ")");
    }
  } else if (const auto* person = std::get_if<PersonTarget>(&target)) {
    check_target_id(person->person_id, "person target");
  } else if (const auto* group = std::get_if<GroupTarget>(&target)) {
    check_target_id(group->group_id, "group target");
  } else {
    check_target_id(std::get<GroupOfPersonTarget>(target).person_id, "group-of-person target");
  }
}

}  // namespace ari_social_sim::navigation
