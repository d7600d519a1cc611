#include "ari_social_sim/world/member_manner.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/rng_streams.hpp"

namespace ari_social_sim::world {
namespace {

// A stream of its own per (group, member).
uint64_t member_index(model::ObjectId group, model::ObjectId member) {
  return (static_cast<uint64_t>(group) << 24) + member;
}

}  // namespace

double bounded_normal(core::Rng& rng, double stddev) {
  const double limit = kMannerDrawLimitSd * stddev;
  return std::clamp(rng.normal(0.0, stddev), -limit, limit);
}

double group_spacing_scale(uint64_t seed, model::ObjectId group, double spacing_spread) {
  core::Rng rng =
      core::rng_for(seed, core::rng_streams::kGroupStance, member_index(group, model::kNoObject));
  return std::exp(bounded_normal(rng, spacing_spread));
}

MemberManner::MemberManner(uint64_t seed, model::ObjectId group, model::ObjectId member,
                           const MannerParams& params)
    : shift_rng_(core::rng_for(seed, core::rng_streams::kGroupShift, member_index(group, member))) {
  // The stance is the stream's first draw, as it was before members had a spacing of their own,
  // so that a seed keeps its stances.
  core::Rng rng = core::rng_for(seed, core::rng_streams::kGroupStance, member_index(group, member));
  stance_rad_ = rng.normal(0.0, params.facing_spread_rad);
  // Log-normal: a member stands as much closer as farther in proportion, never at or past the
  // centre.
  spacing_scale_ = std::exp(bounded_normal(rng, params.spacing_spread));
}

void MemberManner::update(double time_s, model::ObjectId self,
                          const std::vector<model::ObjectId>& participants,
                          const MannerParams& params) {
  if (started_ && time_s < next_shift_s_) {
    return;
  }
  started_ = true;
  next_shift_s_ = time_s + shift_rng_.exponential(params.shift_interval_s);
  shift_ = {bounded_normal(shift_rng_, params.shift_m), bounded_normal(shift_rng_, params.shift_m)};
  shift_turn_rad_ = bounded_normal(shift_rng_, params.shift_turn_rad);
  others_.clear();
  std::copy_if(participants.begin(), participants.end(), std::back_inserter(others_),
               [self](model::ObjectId id) { return id != self; });
  // In a pair the partner is where the formation faces anyway. Draws are made all the same, so
  // that the shifts' draws do not depend on the group's size. Most shifts keep whom the member
  // attends to (kAttentionRedrawShare): a conversation's turns outlast a shift of weight.
  const bool attend_anew =
      shift_rng_.bernoulli(kAttentionRedrawShare) || attended_ == model::kNoObject;
  const uint64_t pick = shift_rng_.uniform_index(std::max<size_t>(others_.size(), 1));
  if (others_.size() < 2) {
    attended_ = model::kNoObject;
  } else if (attend_anew || std::find(others_.begin(), others_.end(), attended_) == others_.end()) {
    attended_ = others_[pick];
  }
}

}  // namespace ari_social_sim::world
