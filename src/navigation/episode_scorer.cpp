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
  score_.duration_s = times_.empty() ? 0.0 : tick.time_s - times_.front();
  speeds_.push_back(tick.linear_mps);
  times_.push_back(tick.time_s);

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

EpisodeScore EpisodeScorer::score() const {
  EpisodeScore score = score_;
  // Jerk by second differences of the speed over consecutive ticks.
  double sum = 0.0;
  int count = 0;
  for (size_t i = 2; i < speeds_.size(); ++i) {
    const double dt1 = times_[i] - times_[i - 1], dt0 = times_[i - 1] - times_[i - 2];
    if (dt1 <= 0.0 || dt0 <= 0.0) {
      continue;
    }
    const double a1 = (speeds_[i] - speeds_[i - 1]) / dt1;
    const double a0 = (speeds_[i - 1] - speeds_[i - 2]) / dt0;
    sum += std::abs(a1 - a0) / (0.5 * (dt1 + dt0));
    ++count;
  }
  score.mean_abs_jerk = count > 0 ? sum / count : 0.0;
  return score;
}

}  // namespace ari_social_sim::navigation
