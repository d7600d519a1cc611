#include "ari_social_sim/scenario/episode_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/world/ari.hpp"

namespace ari_social_sim::scenario {
namespace {

// Distance (m) from a point to ARI's footprint rectangle (0 inside it).
double distance_to_footprint(const core::Pose2& X_map_base, const Eigen::Vector2d& p_map) {
  const model::AriFootprint footprint;
  const Eigen::Vector2d d = p_map - X_map_base.position;
  const double c = std::cos(X_map_base.theta), s = std::sin(X_map_base.theta);
  const Eigen::Vector2d p_base(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  const double dx =
      std::max({footprint.rear_x_m - p_base.x(), 0.0, p_base.x() - footprint.front_x_m});
  const double dy = std::max(std::abs(p_base.y()) - footprint.half_width_m, 0.0);
  return std::hypot(dx, dy);
}

}  // namespace

EpisodeMetrics MetricsRecorder::metrics() const {
  EpisodeMetrics metrics = metrics_;
  metrics.group_talk = world::ConversationFigures::of(conversation_.summary(), ari_id_);
  return metrics;
}

void MetricsRecorder::observe(const Observations& observations) {
  const world::WorldSnapshot& world = observations.world;
  conversation_.observe(world);
  const double dt_s = previous_time_s_ ? world.time_s - *previous_time_s_ : 0.0;
  previous_time_s_ = world.time_s;
  const NavigationState navigation = observations.navigation.state;
  if (navigation == NavigationState::kActive) {
    metrics_.navigation_time_s += dt_s;
    if (previous_navigation_ != NavigationState::kActive) {
      ++metrics_.navigation_goals;
    }
  }
  if (navigation == NavigationState::kFailed && previous_navigation_ != NavigationState::kFailed) {
    ++metrics_.navigation_failures;
  }
  previous_navigation_ = navigation;

  if (world.ari) {
    metrics_.has_ari = true;
    ari_id_ = world.ari->id;
    if (previous_ari_position_) {
      metrics_.ari_path_length_m += (world.ari->pose.position - *previous_ari_position_).norm();
    }
    previous_ari_position_ = world.ari->pose.position;
    bool touching = false;
    bool crowding = false;
    for (const world::HumanSnapshot& human : world.humans) {
      const double to_centre = distance_to_footprint(world.ari->pose, human.pose.position);
      const double clearance = std::max(to_centre - kBodyRadiusM, 0.0);
      metrics_.min_clearance_m = std::min(metrics_.min_clearance_m, clearance);
      touching = touching || clearance < kContactM;
      crowding = crowding || to_centre < kPersonalDistanceM;
    }
    if (touching && !touching_) {
      ++metrics_.contacts;
    }
    touching_ = touching;
    if (crowding) {
      metrics_.personal_space_time_s += dt_s;
    }
  }
}

}  // namespace ari_social_sim::scenario
