#include "ari_social_sim/physics/trajectory_controller.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/format_text.hpp"

namespace ari_social_sim::physics {
namespace {

std::string number(double value) {
  return core::format_text("%.4g", value);
}

bool all_finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

TrajectoryController::TrajectoryController(ControllerSpec spec, std::vector<JointBounds> bounds,
                                           const std::vector<double>& initial_positions)
    : spec_(std::move(spec)), bounds_(std::move(bounds)) {
  ARI_CHECK(bounds_.size() == spec_.joints.size());
  ARI_CHECK(initial_positions.size() == spec_.joints.size());
  desired_ = JointSetpoint::at_rest(initial_positions);
  trajectory_ = JointTrajectory::hold(desired_, 0.0);
  command_ = initial_positions;
}

std::vector<int> TrajectoryController::joint_permutation(
    const std::vector<std::string>& names) const {
  // permutation[i] = the request's column holding controller joint i
  std::vector<int> permutation(spec_.joints.size(), -1);
  for (size_t column = 0; column < names.size(); ++column) {
    const auto it = std::find(spec_.joints.begin(), spec_.joints.end(), names[column]);
    if (it == spec_.joints.end()) {
      throw TrajectoryRejected(TrajectoryErrorCode::kInvalidJoints,
                               spec_.name + ": joint '" + names[column] + "' is not one of mine");
    }
    const size_t joint = static_cast<size_t>(it - spec_.joints.begin());
    if (permutation[joint] >= 0) {
      throw TrajectoryRejected(TrajectoryErrorCode::kInvalidJoints,
                               spec_.name + ": joint '" + names[column] + "' is named twice");
    }
    permutation[joint] = static_cast<int>(column);
  }
  for (size_t joint = 0; joint < spec_.joints.size(); ++joint) {
    if (permutation[joint] < 0) {
      throw TrajectoryRejected(TrajectoryErrorCode::kInvalidJoints,
                               spec_.name + ": the trajectory has no '" + spec_.joints[joint] +
                                   "' (every joint of the controller is required)");
    }
  }
  return permutation;
}

void TrajectoryController::validate(const TrajectoryRequest& request, double start_s,
                                    double now_s) const {
  const size_t joints = spec_.joints.size();
  double previous_time = -1.0;
  for (size_t p = 0; p < request.points.size(); ++p) {
    const TrajectoryPoint& point = request.points[p];
    const std::string where = spec_.name + ": points[" + std::to_string(p) + "]";
    if (point.positions.size() != joints) {
      throw TrajectoryRejected(TrajectoryErrorCode::kInvalidGoal,
                               where + ": expected " + std::to_string(joints) + " positions, got " +
                                   std::to_string(point.positions.size()));
    }
    if ((!point.velocities.empty() && point.velocities.size() != joints) ||
        (!point.accelerations.empty() && point.accelerations.size() != joints)) {
      throw TrajectoryRejected(TrajectoryErrorCode::kInvalidGoal,
                               where + ": velocities and accelerations must be empty or give " +
                                   std::to_string(joints) + " values");
    }
    if (!all_finite(point.positions) || !all_finite(point.velocities) ||
        !all_finite(point.accelerations) || !std::isfinite(point.time_from_start_s)) {
      throw TrajectoryRejected(TrajectoryErrorCode::kInvalidGoal,
                               where + ": values must be finite");
    }
    if (point.time_from_start_s < 0.0 || point.time_from_start_s <= previous_time) {
      throw TrajectoryRejected(TrajectoryErrorCode::kInvalidGoal,
                               where +
                                   ": time_from_start must be >= 0 and increase strictly, got " +
                                   number(point.time_from_start_s) + " s");
    }
    previous_time = point.time_from_start_s;
  }
  // Limits are checked on the controller's own order (positions were permuted by the caller).
  for (size_t p = 0; p < request.points.size(); ++p) {
    for (size_t j = 0; j < joints; ++j) {
      const double q = request.points[p].positions[j];
      const JointBounds& b = bounds_[j];
      if (q < b.lower_rad || q > b.upper_rad) {
        throw TrajectoryRejected(TrajectoryErrorCode::kInvalidGoal,
                                 spec_.name + ": points[" + std::to_string(p) +
                                     "]: " + spec_.joints[j] + " = " + number(q) +
                                     " rad is beyond its limits [" + number(b.lower_rad) + ", " +
                                     number(b.upper_rad) + "]");
      }
    }
  }
  if (request.start_time_s > 0.0 && !request.points.empty() &&
      start_s + request.points.back().time_from_start_s < now_s) {
    throw TrajectoryRejected(TrajectoryErrorCode::kOldHeaderTimestamp,
                             spec_.name + ": the trajectory ended at " +
                                 number(start_s + request.points.back().time_from_start_s) +
                                 " s, before now (" + number(now_s) + " s)");
  }
}

double TrajectoryController::tolerance_for(const std::vector<JointTolerance>& tolerances,
                                           size_t joint, double fallback) const {
  for (const JointTolerance& tolerance : tolerances) {
    if (tolerance.joint == spec_.joints[joint] && tolerance.position != 0.0) {
      return tolerance.position;  // > 0: this tolerance; -1: none
    }
  }
  return fallback;
}

uint64_t TrajectoryController::follow(const TrajectoryRequest& request, double now_s,
                                      bool monitored) {
  const double start_s = request.start_time_s > 0.0 ? request.start_time_s : now_s;
  if (request.points.empty()) {
    if (monitored) {
      throw TrajectoryRejected(TrajectoryErrorCode::kInvalidGoal,
                               spec_.name + ": the trajectory has no points");
    }
    // An empty command stops the controller where it is, as ros_controllers does.
    cancel(goal_.goal_id, now_s);
    return 0;
  }
  // Reorder every point into the controller's joint order before checking values.
  const std::vector<int> permutation = joint_permutation(request.joint_names);
  TrajectoryRequest ordered = request;
  for (TrajectoryPoint& point : ordered.points) {
    const TrajectoryPoint original = point;
    for (size_t j = 0; j < permutation.size(); ++j) {
      const size_t column = static_cast<size_t>(permutation[j]);
      if (column < original.positions.size()) {
        point.positions[j] = original.positions[column];
      }
      if (column < original.velocities.size()) {
        point.velocities[j] = original.velocities[column];
      }
      if (column < original.accelerations.size()) {
        point.accelerations[j] = original.accelerations[column];
      }
    }
  }
  validate(ordered, start_s, now_s);

  // Splice onto where the joint servos are heading now, so the motion continues smoothly.
  JointSetpoint from = trajectory_.sample(now_s);
  from.positions = command_;
  trajectory_ = JointTrajectory(from, now_s, start_s, ordered.points);

  if (goal_.state == GoalState::kActive) {
    goal_.state = GoalState::kPreempted;
    goal_.message = "preempted by a newer trajectory";
  }
  if (!monitored) {
    return 0;
  }
  goal_ = GoalOutcome{next_goal_id_++, GoalState::kActive, TrajectoryErrorCode::kSuccessful, ""};
  goal_tolerance_rad_.assign(spec_.joints.size(), spec_.goal_tolerance_rad);
  path_tolerance_rad_.assign(spec_.joints.size(), 0.0);
  for (size_t j = 0; j < spec_.joints.size(); ++j) {
    goal_tolerance_rad_[j] = tolerance_for(ordered.goal_tolerance, j, spec_.goal_tolerance_rad);
    path_tolerance_rad_[j] = tolerance_for(ordered.path_tolerance, j, 0.0);
  }
  const double goal_time =
      request.goal_time_tolerance_s > 0.0 ? request.goal_time_tolerance_s : spec_.goal_time_s;
  goal_deadline_s_ = trajectory_.end_time_s() + goal_time;
  return goal_.goal_id;
}

void TrajectoryController::cancel(uint64_t goal_id, double now_s) {
  trajectory_ = JointTrajectory::hold(JointSetpoint::at_rest(command_), now_s);
  if (goal_.state == GoalState::kActive && goal_.goal_id == goal_id) {
    goal_.state = GoalState::kPreempted;
    goal_.message = "canceled";
  }
}

void TrajectoryController::update(double now_s, double dt_s,
                                  const std::vector<double>& actual_positions,
                                  const std::vector<double>& actual_velocities) {
  ARI_DCHECK(actual_positions.size() == spec_.joints.size());
  desired_ = trajectory_.sample(now_s);
  // joint_limits_interface's position saturation: at most max_velocity * dt per tick, and
  // never beyond the position limits.
  for (size_t j = 0; j < command_.size(); ++j) {
    const JointBounds& b = bounds_[j];
    const double step = b.max_velocity_rps * dt_s;
    double next = std::clamp(desired_.positions[j], command_[j] - step, command_[j] + step);
    command_[j] = std::clamp(next, b.lower_rad, b.upper_rad);
  }
  if (goal_.state != GoalState::kActive) {
    return;
  }
  for (size_t j = 0; j < command_.size(); ++j) {
    const double error = std::abs(desired_.positions[j] - actual_positions[j]);
    if (path_tolerance_rad_[j] > 0.0 && error > path_tolerance_rad_[j]) {
      goal_.state = GoalState::kAborted;
      goal_.code = TrajectoryErrorCode::kPathToleranceViolated;
      goal_.message = spec_.name + ": " + spec_.joints[j] + " is " + number(error) +
                      " rad off its path (tolerance " + number(path_tolerance_rad_[j]) + ")";
      trajectory_ = JointTrajectory::hold(JointSetpoint::at_rest(actual_positions), now_s);
      return;
    }
  }
  if (now_s < trajectory_.end_time_s()) {
    return;
  }
  const std::vector<double>& target = trajectory_.final_positions();
  size_t worst = 0;
  double worst_excess = -1.0;
  bool reached = true;
  for (size_t j = 0; j < command_.size(); ++j) {
    const double error = std::abs(target[j] - actual_positions[j]);
    const bool position_ok = goal_tolerance_rad_[j] < 0.0 || error <= goal_tolerance_rad_[j];
    const bool stopped = std::abs(actual_velocities[j]) <= spec_.stopped_velocity_tolerance_rps;
    if (!position_ok || !stopped) {
      reached = false;
      if (error - goal_tolerance_rad_[j] > worst_excess) {
        worst_excess = error - goal_tolerance_rad_[j];
        worst = j;
      }
    }
  }
  if (reached) {
    goal_.state = GoalState::kSucceeded;
    goal_.code = TrajectoryErrorCode::kSuccessful;
    goal_.message.clear();
  } else if (now_s > goal_deadline_s_) {
    goal_.state = GoalState::kAborted;
    goal_.code = TrajectoryErrorCode::kGoalToleranceViolated;
    goal_.message = spec_.name + ": " + spec_.joints[worst] + " ended " +
                    number(std::abs(target[worst] - actual_positions[worst])) +
                    " rad from its goal (tolerance " + number(goal_tolerance_rad_[worst]) + ")";
    trajectory_ = JointTrajectory::hold(JointSetpoint::at_rest(actual_positions), now_s);
  }
}

}  // namespace ari_social_sim::physics
