#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/learning/nav_task_config.hpp"
#include "ari_social_sim/navigation/episode_scorer.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::learning {

struct NavMetrics;

/// The part of a learning step judged on the truth the same way in every task: nav_benchmark's
/// EpisodeScorer on the true scene, the reward's time, collision, personal-space and o-space
/// terms, and the episode's social metrics.
class SocialScore {
 public:
  SocialScore(const navigation::FootprintModel& footprint,
              const navigation::PersonalSpaceParams& spaces, std::vector<std::string> exempt_people,
              std::string exempt_group, double stride_m);

  /// What one world step added.
  struct Step {
    double reward{0.0};  // time, collision, personal_space and ospace terms
    int collisions{0};   // contacts begun in the step
  };
  /// Scores the world as it is after a step of `dt_s`.
  Step add(const world::Simulation& sim, double dt_s, const RewardWeights& weights);
  /// Writes the episode's social metrics and time into `metrics`.
  void fill(NavMetrics& metrics, double time_s) const;

 private:
  navigation::EpisodeScorer scorer_;
  double stride_m_;
  navigation::EpisodeScore last_;
};

}  // namespace ari_social_sim::learning
