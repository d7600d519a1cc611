#include "ari_social_sim/physics/point_head_goal.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/world/request_check.hpp"

namespace ari_social_sim::physics {

void check_point_head_goal(const PointHeadGoal& goal, double head_max_velocity_rps) {
  const world::RequestCheck check;
  check.finite("target.point.x", goal.target_point.x());
  check.finite("target.point.y", goal.target_point.y());
  check.finite("target.point.z", goal.target_point.z());
  check.finite("pointing_axis.x", goal.pointing_axis.x());
  check.finite("pointing_axis.y", goal.pointing_axis.y());
  check.finite("pointing_axis.z", goal.pointing_axis.z());
  check.in_range("min_duration", goal.min_duration_s, core::between(0.0, kMaxPointHeadDurationS),
                 "s");
  if (!std::isfinite(goal.max_velocity_rps) || goal.max_velocity_rps < 0.0 ||
      goal.max_velocity_rps > head_max_velocity_rps) {
    check.fail("max_velocity",
               "0 (the joints' limits) or a finite number (0, " +
                   core::number_text(head_max_velocity_rps) + "] rad/s",
               core::number_text(goal.max_velocity_rps));
  }
}

double point_head_duration(const PointHeadGoal& goal, double pan_move_rad, double tilt_move_rad,
                           double pan_max_velocity_rps, double tilt_max_velocity_rps) {
  double duration_s =
      std::max({kMinPointHeadDurationS, goal.min_duration_s, pan_move_rad / pan_max_velocity_rps,
                tilt_move_rad / tilt_max_velocity_rps});
  if (goal.max_velocity_rps > 0.0) {
    const double move_s = std::max(pan_move_rad, tilt_move_rad) / goal.max_velocity_rps;
    if (!(move_s <= kMaxPointHeadDurationS)) {
      world::RequestCheck().fail("max_velocity",
                                 "a speed that moves the head " +
                                     core::number_text(std::max(pan_move_rad, tilt_move_rad)) +
                                     " rad within " + core::number_text(kMaxPointHeadDurationS) +
                                     " s",
                                 core::number_text(goal.max_velocity_rps) + " rad/s (" +
                                     core::number_text(move_s) + " s)");
    }
    duration_s = std::max(duration_s, move_s);
  }
  return duration_s;
}

void FrameWatch::start(double wall_s) {
  started_wall_s_ = wall_s;
  newest_stamp_s_.reset();
  newest_seen_wall_s_ = wall_s;
}

FrameWatch::Status FrameWatch::look(std::optional<double> newest_stamp_s, double wall_s,
                                    double sim_s) {
  if (newest_stamp_s && (!newest_stamp_s_ || *newest_stamp_s > *newest_stamp_s_)) {
    newest_stamp_s_ = newest_stamp_s;
    newest_seen_wall_s_ = wall_s;
  }
  if (!newest_stamp_s_) {
    return wall_s - started_wall_s_ >= timeout_s_ ? Status::kNeverSeen : Status::kWaiting;
  }
  if (*newest_stamp_s_ == 0.0) {
    return Status::kFresh;  // static transforms never age
  }
  const bool stale_on_wall = wall_s - newest_seen_wall_s_ >= timeout_s_;
  const bool stale_on_sim = sim_s - *newest_stamp_s_ >= timeout_s_;
  return stale_on_wall && stale_on_sim ? Status::kStale : Status::kFresh;
}

}  // namespace ari_social_sim::physics
