#pragma once

#include <deque>
#include <utility>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::perception {

/// Visual social engagement between ARI and a person (Webb & Lemaignan, RO-MAN 2022, as
/// hri_engagement computes it), in the plane: with d their distance,
///   gaze(A -> B) = max(0, 1 - |lateral offset of B| / (tan(fov) * forward offset of B)) in A's
///                  gaze frame (0 when B is behind A),
///   distance factor = log(max_distance + 1 - d) / log(max_distance + 1),
///   score = min(1, gaze(person -> ARI) * gaze(ARI -> person) * distance factor),
/// and 0 beyond max_distance. `X_map_robot` is ARI's head (its x axis the head's direction),
/// `X_map_gaze` the person's face with theta the gaze direction.
double engagement_score(const EngagementConfig& config, const core::Pose2& X_map_robot,
                        const core::Pose2& X_map_gaze);

/// The engagement level of one person over time, with hri_engagement's rules: each frame adds
/// +1 (score above the threshold) or -1 to a history of the last `window` seconds; once the
/// history spans half the window, its mean m moves the level:
/// UNKNOWN -> DISENGAGED; DISENGAGED -> ENGAGING if m > -0.4; ENGAGING -> DISENGAGED if m < -0.6,
/// -> ENGAGED if m > 0.5; ENGAGED -> DISENGAGING if m < 0.4; DISENGAGING -> ENGAGED if m > 0.6,
/// -> DISENGAGED if m < -0.5.
class EngagementTracker {
 public:
  explicit EngagementTracker(const EngagementConfig& config) : config_(config) {}

  /// Adds the frame at `time_s` (non-decreasing) with its score; returns the level.
  EngagementLevel update(double time_s, double score);
  /// Back to UNKNOWN with no history (the person is no longer tracked).
  void reset();
  EngagementLevel level() const { return level_; }
  /// Frames in the history (at most the window's worth).
  size_t history_size() const { return history_.size(); }

 private:
  EngagementConfig config_;
  std::deque<std::pair<double, int>> history_;  ///< (time, +1 or -1)
  EngagementLevel level_{EngagementLevel::kUnknown};
};

}  // namespace ari_social_sim::perception
