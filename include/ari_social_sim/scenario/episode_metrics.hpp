#pragma once

#include <limits>
#include <optional>

#include "ari_social_sim/scenario/observations.hpp"
#include "ari_social_sim/world/conversation_metrics.hpp"

namespace ari_social_sim::scenario {

/// Navigation figures of one run, from ground truth (docs/scenario.md section 7).
struct EpisodeMetrics {
  bool has_ari{false};            // the run had ARI (else the figures below stay at zero)
  double ari_path_length_m{0.0};  // distance base_footprint travelled
  /// Smallest distance from ARI's footprint (a rectangle) to the edge of a human's body (a 0.2 m
  /// circle): 0 means touching. Infinite when nobody was ever there.
  double min_clearance_m{std::numeric_limits<double>::infinity()};
  int contacts{0};  // times ARI's footprint came within 1 cm of a body (each touch counted once)
  /// Sim time during which a human's centre was within `kPersonalDistanceM` of ARI's footprint.
  double personal_space_time_s{0.0};
  double navigation_time_s{0.0};  // sim time with a navigation goal active
  int navigation_goals{0};        // goals that became active
  int navigation_failures{0};     // goals that ended aborted or rejected
  /// The conversation groups' talk (world::ConversationMetrics, docs/world.md section 12).
  world::ConversationFigures group_talk;
};

/// Accumulates EpisodeMetrics from successive observations (one per world step).
class MetricsRecorder {
 public:
  /// The personal distance (m) of the humans' movement model (docs/world.md, Delta_p): inside it a
  /// simulated person feels crowded.
  static constexpr double kPersonalDistanceM = 0.8;
  static constexpr double kBodyRadiusM = 0.2;  // humans' default body radius
  static constexpr double kContactM = 0.01;

  void observe(const Observations& observations);
  /// The figures so far, the conversation's summarised now.
  EpisodeMetrics metrics() const;

 private:
  EpisodeMetrics metrics_;
  world::ConversationMetrics conversation_;
  model::ObjectId ari_id_{model::kNoObject};
  std::optional<double> previous_time_s_;
  std::optional<Eigen::Vector2d> previous_ari_position_;
  NavigationState previous_navigation_{NavigationState::kIdle};
  bool touching_{false};
};

}  // namespace ari_social_sim::scenario
