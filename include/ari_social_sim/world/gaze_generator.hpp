#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

/// One potential gaze target and the probability of choosing it at a gaze change.
struct GazeTarget {
  model::ObjectId id{model::kNoObject};
  double probability{0.0};
};

/// A distribution of gaze directions relative to the body heading (rad), used instead of targets.
struct GazeDirections {
  enum class Distribution { kUniform, kNormal };
  Distribution distribution{Distribution::kUniform};
  double low_rad{-0.5};    // uniform: lower bound
  double high_rad{0.5};    // uniform: upper bound
  double mean_rad{0.0};    // normal: mean
  double stddev_rad{0.3};  // normal: standard deviation
};

/// Most targets one gaze model may list (each is drawn from at every gaze change).
constexpr size_t kMaxGazeTargets = 50;
/// Longest mean dwell (s) of a gaze model: a day, far beyond any run.
constexpr double kMaxGazeMeanDurationS = 86400.0;

/// D6.4 §3.3.2: either targets with probabilities summing to 1, or a distribution of directions.
/// Gaze changes follow a Poisson process: dwell times are exponential with mean `mean_duration_s`.
/// (D6.4 calls the parameter a rate lambda yet says the mean is lambda seconds; the mean is
/// what is configured here, in seconds.)
struct GazeModel {
  std::vector<GazeTarget> targets;
  std::optional<GazeDirections> directions;
  double mean_duration_s{3.0};

  /// Throws core::RequestError naming the field unless exactly one of targets / directions is
  /// given, there are at most kMaxGazeTargets targets, every probability is a finite number in
  /// [0, 1] and they sum to 1 (within 1e-6), directions are finite (low <= high, stddev >= 0) and
  /// the mean duration is a finite number in (0, kMaxGazeMeanDurationS] s.
  void validate() const;
};

/// D6.4 §3.3.2 GazeGenerator: samples a new target (or direction) at each change of an exponential
/// clock and keeps the gaze direction on the target as both move. A change may pick the same
/// target again (each change is one gaze event), so each target's share of time equals its
/// probability and every event's dwell has the configured mean. A target that leaves the world is
/// replaced at once by a draw among the remaining ones.
class GazeGenerator : public Component {
 public:
  GazeGenerator(GazeModel model, core::Rng rng);

  ComponentPhase phase() const override { return ComponentPhase::kGenerator; }
  void step(Object& owner, const StepContext& context) override;

  /// Replaces the model; the next step draws a new gaze.
  void set_model(GazeModel model);
  const GazeModel& model() const { return model_; }

  model::ObjectId target() const { return target_; }
  /// Gaze direction in the map frame (rad).
  double direction_rad() const { return direction_rad_; }
  /// Sim time (s) the current gaze started.
  double since_s() const { return since_s_; }

 private:
  void draw(Object& owner, const StepContext& context, double now_s);

  GazeModel model_;
  core::Rng rng_;
  model::ObjectId target_{model::kNoObject};
  double relative_direction_rad_{0.0};
  double direction_rad_{0.0};
  double since_s_{0.0};
  std::optional<double> next_change_s_;
};

}  // namespace ari_social_sim::world
