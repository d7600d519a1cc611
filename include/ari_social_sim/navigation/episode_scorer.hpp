#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/navigation/footprint_model.hpp"
#include "ari_social_sim/navigation/perceived_scene.hpp"
#include "ari_social_sim/navigation/social_spaces.hpp"

namespace ari_social_sim::navigation {

/// Ground truth at one tick of an episode.
struct ScoredTick {
  double time_s{0.0};
  core::Pose2 ari;                     // base_footprint
  double linear_mps{0.0};              // ARI's base speed
  std::vector<PersonEstimate> people;  // true poses and velocities
  std::vector<GroupEstimate> groups;   // true groups (o-space from the members)
  double static_penetration_m{0.0};    // how deep ARI's body reaches into walls or furniture
};

/// Social-navigation metrics of one episode (the project's own set, docs/navigation.md).
struct EpisodeScore {
  double duration_s{0.0};
  double path_length_m{0.0};          // base_footprint path
  int person_collisions{0};           // contacts begun: footprint reaching a person's body
  int static_collisions{0};           // contacts begun with walls or furniture (> 1 cm deep)
  double min_person_distance_m{1e9};  // footprint to the nearest body surface
  double personal_space_share{0.0};   // share of ticks inside a personal space (exempt excepted)
  int ospace_intrusions{0};           // entries of the footprint into other groups' o-space disc
  double mean_abs_jerk{0.0};          // m/s^3, of the base's linear velocity
};

/// Accumulates EpisodeScore tick by tick. People in `exempt_people` (the person approached, the
/// members of the group joined) do not count for personal spaces, nor group `exempt_group` for
/// o-spaces; everyone counts for collisions and distances.
class EpisodeScorer {
 public:
  EpisodeScorer(const FootprintModel& footprint, const PersonalSpaceParams& spaces,
                std::vector<std::string> exempt_people, std::string exempt_group);

  void add(const ScoredTick& tick);
  /// The score of the ticks so far.
  EpisodeScore score() const;

  /// True when ARI's footprint outline at `ari` lies inside the personal space (edge contour of
  /// the asymmetric Gaussian) of `person`.
  bool inside_personal_space(const core::Pose2& ari, const PersonEstimate& person) const;
  /// True when ARI was inside a personal space (exempt excepted) at the last tick added.
  bool last_tick_in_space() const { return last_tick_in_space_; }

 private:
  void add_jerk_sample(double time_s, double speed_mps);

  FootprintModel footprint_;
  PersonalSpaceParams spaces_;
  std::vector<Eigen::Vector2d> outline_;
  std::vector<std::string> exempt_people_;
  std::string exempt_group_;
  EpisodeScore score_;
  int ticks_{0};
  int ticks_in_space_{0};
  bool last_tick_in_space_{false};
  bool touching_person_{false};
  bool touching_static_{false};
  std::vector<std::string> groups_intruded_;
  double first_time_s_{0.0};
  double speeds_[2]{};  // the two ticks before the current one, oldest first
  double times_[2]{};
  double jerk_sum_{0.0};
  int jerk_count_{0};
  core::Pose2 last_pose_;
};

}  // namespace ari_social_sim::navigation
