#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/object_id.hpp"

// How one member of a conversational group stands in its formation, apart from the shared
// shape (issue 31, "formations that live"): real members neither keep one spacing nor face the
// o-space squarely, and they keep shifting and turning while they talk (docs/world.md section
// 4.5, measured against the recordings of [Cristani 2011]).

namespace ari_social_sim::world {

/// What a group gives its members' manners (GroupSpec's fields, in radians).
struct MannerParams {
  /// Standard deviation of a member's stance: its body's lasting turn off the formation's facing.
  double facing_spread_rad{0.0};
  /// Standard deviation of the natural log of a member's spacing scale.
  double spacing_spread{0.0};
  /// Standard deviation (m) of each coordinate of a member's shift off its place.
  double shift_m{0.0};
  /// Standard deviation of a member's passing turn off its facing.
  double shift_turn_rad{0.0};
  /// Mean time (s) between a member's shifts.
  double shift_interval_s{4.0};
};

/// Draws are cut at this many standard deviations, so that every offset stays bounded.
constexpr double kMannerDrawLimitSd = 2.0;

/// Share of a member's shifts at which it draws anew whom it attends to.
constexpr double kAttentionRedrawShare = 0.3;

/// A normal draw of the given standard deviation cut at kMannerDrawLimitSd of it.
double bounded_normal(core::Rng& rng, double stddev);

/// The factor on a group's o-space radius: log-normal of log sd `spacing_spread`, drawn from the
/// group_stance stream of index (group id << 24), which no member uses (member ids start at 1).
double group_spacing_scale(uint64_t seed, model::ObjectId group, double spacing_spread);

/// One member's seeded manner: drawn once, its stance and its spacing scale (from the
/// group_stance stream); then, at seeded moments, a new shift of its place and facing and whom it
/// attends to (from the group_shift stream). Same seed, group and member: same draws.
class MemberManner {
 public:
  MemberManner(uint64_t seed, model::ObjectId group, model::ObjectId member,
               const MannerParams& params);

  /// rad: how far the member's body stays turned off the formation's facing.
  double stance_rad() const { return stance_rad_; }
  /// Factor on the member's distance to the o-space centre (1: the formation's own).
  double spacing_scale() const { return spacing_scale_; }
  /// m, map frame: where the member stands off its place for now.
  const Eigen::Vector2d& shift() const { return shift_; }
  /// rad: the member's passing turn off its facing for now.
  double shift_turn_rad() const { return shift_turn_rad_; }
  /// The participant the member turns toward for now, or kNoObject.
  model::ObjectId attended() const { return attended_; }

  /// At the first call and whenever the next shift is due (seeded exponential intervals), draws a
  /// new shift and turn and whom to attend to among `participants` (the member itself excepted;
  /// nobody in a pair, whose partner is the formation's facing anyway).
  void update(double time_s, model::ObjectId self, const std::vector<model::ObjectId>& participants,
              const MannerParams& params);

 private:
  double stance_rad_{0.0};
  double spacing_scale_{1.0};
  Eigen::Vector2d shift_{Eigen::Vector2d::Zero()};
  double shift_turn_rad_{0.0};
  model::ObjectId attended_{model::kNoObject};
  bool started_{false};
  double next_shift_s_{0.0};
  core::Rng shift_rng_;
  std::vector<model::ObjectId> others_;  // scratch
};

}  // namespace ari_social_sim::world
