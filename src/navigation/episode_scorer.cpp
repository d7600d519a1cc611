#include "ari_social_sim/navigation/episode_scorer.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::navigation {
namespace {

// Box2D lets bodies overlap by up to its 5 mm slop; deeper is a collision.
constexpr double kContactTolerance = 0.01;

}  // namespace

EpisodeScorer::EpisodeScorer(const FootprintModel& footprint, const PersonalSpaceParams& spaces,
                             std::vector<std::string> exempt_people, std::string exempt_group)
    : footprint_(footprint),
      spaces_(spaces),
      outline_(footprint.outline(0.1)),
      exempt_people_(std::move(exempt_people)),
      exempt_group_(std::move(exempt_group)) {}

bool EpisodeScorer::inside_personal_space(const core::Pose2& ari,
                                          const PersonEstimate& person) const {
  return outline_inside_personal_space(outline_, ari, person, spaces_);
}

void EpisodeScorer::add(const ScoredTick& tick) {
  if (ticks_ > 0) {
    score_.path_length_m += (tick.ari.position - last_pose_.position).norm();
  }
  last_pose_ = tick.ari;
  ++ticks_;
  if (ticks_ == 1) {
    first_time_s_ = tick.time_s;
  }
  score_.duration_s = tick.time_s - first_time_s_;
  add_jerk_sample(tick.time_s, tick.linear_mps);

  bool touching = false;
  bool in_space = false;
  for (const PersonEstimate& person : tick.people) {
    const double gap = footprint_.distance_to(tick.ari, person.position) - spaces_.person_radius_m;
    score_.min_person_distance_m = std::min(score_.min_person_distance_m, gap);
    touching = touching || gap < -kContactTolerance;
    const bool exempt =
        std::find(exempt_people_.begin(), exempt_people_.end(), person.id) != exempt_people_.end();
    in_space = in_space || (!exempt && inside_personal_space(tick.ari, person));
  }
  score_.person_collisions += touching && !touching_person_ ? 1 : 0;
  touching_person_ = touching;
  const bool static_touch = tick.static_penetration_m > kContactTolerance;
  score_.static_collisions += static_touch && !touching_static_ ? 1 : 0;
  touching_static_ = static_touch;
  ticks_in_space_ += in_space ? 1 : 0;
  last_tick_in_space_ = in_space;
  score_.personal_space_share = static_cast<double>(ticks_in_space_) / ticks_;

  std::vector<std::string> intruded;
  for (const GroupEstimate& group : tick.groups) {
    if (group.id != exempt_group_ &&
        footprint_.distance_to(tick.ari, group.centre) < ospace_radius(group, spaces_)) {
      intruded.push_back(group.id);
      if (std::find(groups_intruded_.begin(), groups_intruded_.end(), group.id) ==
          groups_intruded_.end()) {
        ++score_.ospace_intrusions;
      }
    }
  }
  groups_intruded_ = std::move(intruded);
}

// Jerk by second differences of the speed over consecutive ticks, summed as they come.
void EpisodeScorer::add_jerk_sample(double time_s, double speed_mps) {
  if (ticks_ >= 3) {
    const double dt1 = time_s - times_[1], dt0 = times_[1] - times_[0];
    if (dt1 > 0.0 && dt0 > 0.0) {
      const double a1 = (speed_mps - speeds_[1]) / dt1;
      const double a0 = (speeds_[1] - speeds_[0]) / dt0;
      jerk_sum_ += std::abs(a1 - a0) / (0.5 * (dt1 + dt0));
      ++jerk_count_;
    }
  }
  speeds_[0] = speeds_[1];
  times_[0] = times_[1];
  speeds_[1] = speed_mps;
  times_[1] = time_s;
}

EpisodeScore EpisodeScorer::score() const {
  EpisodeScore score = score_;
  score.mean_abs_jerk = jerk_count_ > 0 ? jerk_sum_ / jerk_count_ : 0.0;
  return score;
}

}  // namespace ari_social_sim::navigation
