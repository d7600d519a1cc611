#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

namespace ari_social_sim::physics {

/// Longest head move a PointHead goal may ask for (min_duration, or a move at max_velocity): a
/// minute, far longer than ARI's head takes across its whole range at a crawl (2.6 rad at
/// 0.05 rad/s); a goal for 1e9 s would never end.
constexpr double kMaxPointHeadDurationS = 60.0;
/// Shortest head move, as PAL's head_action (control_msgs/PointHead's server) times it.
constexpr double kMinPointHeadDurationS = 0.01;

/// control_msgs/PointHead's goal without ROS.
struct PointHeadGoal {
  std::string target_frame;  // target.header.frame_id; empty = base_footprint
  Eigen::Vector3d target_point{Eigen::Vector3d::Zero()};
  Eigen::Vector3d pointing_axis{Eigen::Vector3d::UnitZ()};
  std::string pointing_frame;  // empty = the head camera's optical frame
  double min_duration_s{0.0};
  double max_velocity_rps{0.0};  // 0 = the joints' own limits
};

/// Checks the goal's numbers before anything moves; throws core::RequestError naming the field,
/// what it expects and what it got, e.g. `target.point.x: expected a finite number, got nan`,
/// `max_velocity: expected 0 (the joints' limits) or a finite number (0, 3] rad/s, got -1`.
/// `head_max_velocity_rps`: the slower head joint's URDF velocity limit.
void check_point_head_goal(const PointHeadGoal& goal, double head_max_velocity_rps);

/// How long the head's move takes, as PAL's head_action times it: at least min_duration (and
/// kMinPointHeadDurationS); with a max_velocity, at least the larger joint rotation over it. Here
/// also never faster than each joint's URDF velocity limit (`*_max_velocity_rps`), which the
/// controller would enforce anyway. Throws core::RequestError naming max_velocity when the move
/// would take more than kMaxPointHeadDurationS (e.g. max_velocity 1e-300).
double point_head_duration(const PointHeadGoal& goal, double pan_move_rad, double tilt_move_rad,
                           double pan_max_velocity_rps, double tilt_max_velocity_rps);

/// Whether a tf frame a goal depends on is there, judged from non-blocking look-ups (never
/// waiting on a clock, so the thread that makes sim time can ask). A frame never seen fails
/// `timeout_s` of wall time after start(); a frame seen fails once its newest transform is
/// `timeout_s` old on both clocks: wall (it stopped coming) and sim (so a paused or slow world,
/// whose publishers stamp in sim time, does not make a live frame look gone).
class FrameWatch {
 public:
  enum class Status { kWaiting, kFresh, kNeverSeen, kStale };

  explicit FrameWatch(double timeout_s) : timeout_s_(timeout_s) {}

  /// Starts watching a frame at wall time `wall_s` (seconds).
  void start(double wall_s);
  /// One look-up's outcome: the newest stamp tf holds for the frame (sim seconds; 0 for a frame
  /// whose transforms are all static) or nothing when tf cannot transform it.
  Status look(std::optional<double> newest_stamp_s, double wall_s, double sim_s);
  /// The newest stamp seen (sim seconds), when there was one.
  std::optional<double> newest_stamp_s() const { return newest_stamp_s_; }
  double timeout_s() const { return timeout_s_; }

 private:
  double timeout_s_;
  double started_wall_s_{0.0};
  std::optional<double> newest_stamp_s_;
  double newest_seen_wall_s_{0.0};  // when newest_stamp_s_ arrived
};

}  // namespace ari_social_sim::physics
