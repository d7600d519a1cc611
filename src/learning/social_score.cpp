#include "ari_social_sim/learning/social_score.hpp"

#include "ari_social_sim/learning/ground_truth.hpp"
#include "ari_social_sim/learning/nav_env.hpp"

namespace ari_social_sim::learning {

SocialScore::SocialScore(const navigation::FootprintModel& footprint,
                         const navigation::PersonalSpaceParams& spaces,
                         std::vector<std::string> exempt_people, std::string exempt_group,
                         double stride_m)
    : scorer_(footprint, spaces, std::move(exempt_people), std::move(exempt_group)),
      stride_m_(stride_m) {}

SocialScore::Step SocialScore::add(const world::Simulation& sim, double dt_s,
                                   const RewardWeights& weights) {
  Step step;
  step.reward = weights.time * dt_s;
  if (sim.ari() == nullptr) {
    return step;
  }
  navigation::PerceivedScene truth = true_scene(sim, stride_m_);
  navigation::ScoredTick tick;
  tick.time_s = sim.time_s();
  tick.ari = sim.ari()->pose();
  tick.linear_mps = sim.ari()->linear_mps();
  tick.people = std::move(truth.people);
  tick.groups = std::move(truth.groups);
  tick.static_penetration_m = sim.static_penetration_m(*sim.ari());
  scorer_.add(tick);
  const navigation::EpisodeScore score = scorer_.score();
  step.collisions = score.person_collisions + score.static_collisions - last_.person_collisions -
                    last_.static_collisions;
  step.reward += weights.collision * step.collisions +
                 weights.personal_space * (scorer_.last_tick_in_space() ? dt_s : 0.0) +
                 weights.ospace * (score.ospace_intrusions - last_.ospace_intrusions);
  last_ = score;
  return step;
}

void SocialScore::fill(NavMetrics& metrics, double time_s) const {
  metrics.person_collisions = last_.person_collisions;
  metrics.static_collisions = last_.static_collisions;
  metrics.personal_space_time_s = last_.personal_space_share * last_.duration_s;
  metrics.path_length_m = last_.path_length_m;
  metrics.ospace_intrusions = last_.ospace_intrusions;
  metrics.min_person_distance_m = last_.min_person_distance_m;
  metrics.time_s = time_s;
}

}  // namespace ari_social_sim::learning
