#include "ari_social_sim/physics/trajectory_controller.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/physics/trajectory_request_check.hpp"

namespace ari_social_sim::physics {
namespace {

std::string number(double value) {
  return core::format_text("%.4g", value);
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

std::vector<JointBounds> TrajectoryController::bounds_by_column(
    const std::vector<int>& permutation) const {
  std::vector<JointBounds> bounds(permutation.size());
  for (size_t joint = 0; joint < permutation.size(); ++joint) {
    bounds[static_cast<size_t>(permutation[joint])] = bounds_[joint];
  }
  return bounds;
}

void TrajectoryController::check_timing(const TrajectoryRequest& request, double start_s,
                                        double now_s, const std::string& trajectory_field) const {
  // A start far ahead would hold the goal open for good, as a long time_from_start would.
  if (start_s > now_s + kMaxTrajectoryTimeS) {
    throw TrajectoryRejected(TrajectoryErrorCode::kInvalidGoal,
                             spec_.name + ": " + trajectory_field +
                                 "header.stamp: expected 0 (now) or at most " +
                                 number(kMaxTrajectoryTimeS) + " s after now (" + number(now_s) +
                                 " s), got " + number(start_s) + " s");
  }
  const double end_s = start_s + request.points.back().time_from_start_s;
  if (request.start_time_s > 0.0 && end_s < now_s) {
    throw TrajectoryRejected(TrajectoryErrorCode::kOldHeaderTimestamp,
                             spec_.name + ": the trajectory ended at " + number(end_s) +
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
  // Joint names first (INVALID_JOINTS), then every value in the request's own order, so errors
  // name the request's columns; then reorder into the controller's joint order.
  const std::vector<int> permutation = joint_permutation(request.joint_names);
  const std::string trajectory_field = monitored ? "trajectory." : "";
  check_trajectory_request(request, spec_, bounds_by_column(permutation), trajectory_field);
  check_timing(request, start_s, now_s, trajectory_field);
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
