#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace ari_social_sim::physics {

/// One waypoint of a joint trajectory (trajectory_msgs/JointTrajectoryPoint without ROS): one
/// value per joint; velocities and accelerations are empty or complete.
struct TrajectoryPoint {
  std::vector<double> positions;      // rad
  std::vector<double> velocities;     // rad/s
  std::vector<double> accelerations;  // rad/s^2
  double time_from_start_s{0.0};
};

/// Position, velocity and acceleration of a set of joints at one instant.
struct JointSetpoint {
  std::vector<double> positions;
  std::vector<double> velocities;
  std::vector<double> accelerations;

  static JointSetpoint at_rest(const std::vector<double>& positions);
};

/// A joint trajectory as time-stamped spline segments, interpolated the way ros_controllers'
/// JointTrajectoryController does: between two waypoints a segment is linear when the waypoints
/// give positions only, cubic (position and velocity continuous) when they give velocities, and
/// quintic (acceleration continuous too) when they give accelerations. The first segment starts
/// from the given state; a waypoint at or before the start time is a step to it.
class JointTrajectory {
 public:
  JointTrajectory() = default;
  /// From `start` at `start_time_s` through `points` timed from `points_origin_s`. Preconditions
  /// (checked by TrajectoryController before it builds one): sizes match the joint count and
  /// the points' times increase strictly.
  JointTrajectory(const JointSetpoint& start, double start_time_s, double points_origin_s,
                  const std::vector<TrajectoryPoint>& points);

  /// Holding still at `state` forever.
  static JointTrajectory hold(const JointSetpoint& state, double time_s);

  /// The state at time t (s): the start state before the first segment, the last waypoint
  /// (with zero velocity and acceleration) after the end.
  JointSetpoint sample(double time_s) const;
  double end_time_s() const { return end_time_s_; }
  /// The last waypoint's positions.
  const std::vector<double>& final_positions() const { return final_.positions; }

 private:
  struct Segment {
    double start_s{0.0};
    double duration_s{0.0};
    // One set of polynomial coefficients per joint, c0 + c1 tau + ... + c5 tau^5, tau in seconds.
    std::vector<std::array<double, 6>> coefficients;
  };

  JointSetpoint start_;
  double start_time_s_{0.0};
  std::vector<Segment> segments_;
  JointSetpoint final_;
  double end_time_s_{0.0};
};

}  // namespace ari_social_sim::physics
