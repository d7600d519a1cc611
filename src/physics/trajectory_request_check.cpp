#include "ari_social_sim/physics/trajectory_request_check.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/world/request_check.hpp"

namespace ari_social_sim::physics {
namespace {

using world::RequestCheck;

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) {
    out += (out.empty() ? "" : ", ") + name;
  }
  return out;
}

// control_msgs/JointTolerance: 0 keeps the default, -1 erases it, anything > 0 replaces it.
void check_tolerance_value(const RequestCheck& check, const std::string& field, double value) {
  if (!std::isfinite(value) || (value < 0.0 && value != -1.0)) {
    check.fail(field, "-1 (none), 0 (the default) or a finite number > 0",
               core::number_text(value));
  }
}

void check_tolerances(const RequestCheck& check, const std::string& field,
                      const std::vector<JointTolerance>& tolerances,
                      const std::vector<std::string>& joints) {
  for (size_t i = 0; i < tolerances.size(); ++i) {
    const JointTolerance& tolerance = tolerances[i];
    const std::string where = field + "[" + std::to_string(i) + "]";
    if (std::find(joints.begin(), joints.end(), tolerance.joint) == joints.end()) {
      check.fail(where + ".name", "one of " + joined(joints), "'" + tolerance.joint + "'");
    }
    check_tolerance_value(check, where + ".position", tolerance.position);
    check_tolerance_value(check, where + ".velocity", tolerance.velocity);
    check_tolerance_value(check, where + ".acceleration", tolerance.acceleration);
  }
}

void check_sizes(const RequestCheck& check, const std::string& where, const TrajectoryPoint& point,
                 size_t joints) {
  const std::string expected = std::to_string(joints) + " values (one per joint name)";
  if (point.positions.size() != joints) {
    check.fail(where + ".positions", expected, std::to_string(point.positions.size()));
  }
  if (!point.velocities.empty() && point.velocities.size() != joints) {
    check.fail(where + ".velocities", "none or " + expected,
               std::to_string(point.velocities.size()));
  }
  if (!point.accelerations.empty() && point.accelerations.size() != joints) {
    check.fail(where + ".accelerations", "none or " + expected,
               std::to_string(point.accelerations.size()));
  }
}

void check_values(const RequestCheck& check, const std::string& where, const TrajectoryPoint& point,
                  const std::vector<std::string>& names, const std::vector<JointBounds>& bounds) {
  for (size_t c = 0; c < names.size(); ++c) {
    const std::string column = "[" + std::to_string(c) + "] (" + names[c] + ")";
    const JointBounds& joint = bounds[c];
    check.in_range(where + ".positions" + column, point.positions[c],
                   core::between(joint.lower_rad, joint.upper_rad), "rad");
    if (!point.velocities.empty()) {
      const std::string field = where + ".velocities" + column;
      const double top = joint.max_velocity_rps;
      if (top > 0.0) {
        check.in_range(field, point.velocities[c], core::between(-top, top), "rad/s");
      } else {
        check.finite(field, point.velocities[c]);  // the URDF gives this joint no velocity limit
      }
    }
    if (!point.accelerations.empty()) {
      check.in_range(where + ".accelerations" + column, point.accelerations[c],
                     core::between(-kMaxJointAccelerationRps2, kMaxJointAccelerationRps2),
                     "rad/s^2");
    }
  }
}

void check_point(const RequestCheck& check, const std::string& where, const TrajectoryPoint& point,
                 double previous_time_s, const std::vector<std::string>& names,
                 const std::vector<JointBounds>& bounds) {
  check_sizes(check, where, point, names.size());
  check_values(check, where, point, names, bounds);
  const std::string time_field = where + ".time_from_start";
  check.in_range(time_field, point.time_from_start_s, core::between(0.0, kMaxTrajectoryTimeS), "s");
  if (point.time_from_start_s <= previous_time_s) {
    check.fail(time_field,
               "more than the previous point's " + core::number_text(previous_time_s) +
                   " s (times increase strictly)",
               core::number_text(point.time_from_start_s) + " s");
  }
}

}  // namespace

void check_trajectory_request(const TrajectoryRequest& request, const ControllerSpec& spec,
                              const std::vector<JointBounds>& bounds_by_column,
                              const std::string& trajectory_field) {
  const RequestCheck check(spec.name);
  try {
    double previous_time_s = -HUGE_VAL;
    for (size_t p = 0; p < request.points.size(); ++p) {
      const std::string where = trajectory_field + "points[" + std::to_string(p) + "]";
      check_point(check, where, request.points[p], previous_time_s, request.joint_names,
                  bounds_by_column);
      previous_time_s = request.points[p].time_from_start_s;
    }
    check_tolerances(check, "path_tolerance", request.path_tolerance, spec.joints);
    check_tolerances(check, "goal_tolerance", request.goal_tolerance, spec.joints);
    check.in_range("goal_time_tolerance", request.goal_time_tolerance_s,
                   core::between(0.0, kMaxTrajectoryTimeS), "s");
  } catch (const core::RequestError& e) {
    throw TrajectoryRejected(TrajectoryErrorCode::kInvalidGoal, e.what());
  }
}

}  // namespace ari_social_sim::physics
