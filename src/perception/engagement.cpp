#include "ari_social_sim/perception/engagement.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::perception {
namespace {

// How close `target` is to the x axis of `viewer`, within the field of attention.
double gaze_towards(const core::Pose2& viewer, const Eigen::Vector2d& target, double tan_fov) {
  const Eigen::Vector2d offset = target - viewer.position;
  const double c = std::cos(viewer.theta), s = std::sin(viewer.theta);
  const double forward = c * offset.x() + s * offset.y();
  const double lateral = -s * offset.x() + c * offset.y();
  if (forward <= 0.0) {
    return 0.0;
  }
  return std::max(0.0, 1.0 - std::abs(lateral) / (tan_fov * forward));
}

}  // namespace

double engagement_score(const EngagementConfig& config, const core::Pose2& X_map_robot,
                        const core::Pose2& X_map_gaze) {
  const double distance = (X_map_gaze.position - X_map_robot.position).norm();
  if (distance > config.max_distance_m) {
    return 0.0;
  }
  const double tan_fov = std::tan(core::deg_to_rad(config.field_of_attention_deg));
  const double mutual = gaze_towards(X_map_gaze, X_map_robot.position, tan_fov) *
                        gaze_towards(X_map_robot, X_map_gaze.position, tan_fov);
  const double proximity =
      std::log(config.max_distance_m + 1.0 - distance) / std::log(config.max_distance_m + 1.0);
  return std::min(1.0, mutual * proximity);
}

void EngagementTracker::reset() {
  history_.clear();
  level_ = EngagementLevel::kUnknown;
}

EngagementLevel EngagementTracker::update(double time_s, double score) {
  history_.emplace_back(time_s, score > config_.threshold ? 1 : -1);
  while (history_.front().first < time_s - config_.window_s) {
    history_.pop_front();
  }
  if (time_s - history_.front().first < 0.5 * config_.window_s) {
    return level_;
  }
  double sum = 0.0;
  for (const auto& [t, vote] : history_) {
    sum += vote;
  }
  const double mean = sum / static_cast<double>(history_.size());
  switch (level_) {
    case EngagementLevel::kUnknown:
      level_ = EngagementLevel::kDisengaged;
      break;
    case EngagementLevel::kDisengaged:
      if (mean > -0.4) {
        level_ = EngagementLevel::kEngaging;
      }
      break;
    case EngagementLevel::kEngaging:
      if (mean < -0.6) {
        level_ = EngagementLevel::kDisengaged;
      } else if (mean > 0.5) {
        level_ = EngagementLevel::kEngaged;
      }
      break;
    case EngagementLevel::kEngaged:
      if (mean < 0.4) {
        level_ = EngagementLevel::kDisengaging;
      }
      break;
    case EngagementLevel::kDisengaging:
      if (mean > 0.6) {
        level_ = EngagementLevel::kEngaged;
      } else if (mean < -0.5) {
        level_ = EngagementLevel::kDisengaged;
      }
      break;
  }
  return level_;
}

}  // namespace ari_social_sim::perception
