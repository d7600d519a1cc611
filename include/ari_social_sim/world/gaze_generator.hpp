#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

/// One potential gaze target and the probability of choosing it at a gaze change.
struct GazeTarget {
  model::ObjectId id{model::kNoObject};
  double probability{0.0};

  template <class V>
  void visit(V& v) {
    v.field(core::required("id"), id, "the object looked at: a human or ARI", core::positive());
    v.field(core::required("probability"), probability, "chance of choosing it at a gaze change",
            core::between(0.0, 1.0));
  }
};

/// A distribution of gaze directions relative to the body heading (rad), used instead of targets.
struct GazeDirections {
  enum class Distribution { kUniform, kNormal };
  static constexpr core::Choice<Distribution> kDistributions[] = {
      {Distribution::kUniform, "uniform"}, {Distribution::kNormal, "normal"}};

  Distribution distribution{Distribution::kUniform};
  double low_rad{-0.5};    // uniform: lower bound
  double high_rad{0.5};    // uniform: upper bound
  double mean_rad{0.0};    // normal: mean
  double stddev_rad{0.3};  // normal: standard deviation

  template <class V>
  void visit(V& v) {
    const core::Bounds heading = core::between(-core::kMaxHeadingRad, core::kMaxHeadingRad);
    v.choice(core::required("distribution"), distribution, "how directions are drawn",
             kDistributions);
    v.field("low", low_rad, "rad, uniform's lower bound", heading);
    v.field("high", high_rad, "rad, uniform's upper bound", heading);
    v.field("mean", mean_rad, "rad, normal's mean", heading);
    v.field("stddev", stddev_rad, "rad, normal's standard deviation",
            core::between(0.0, core::kMaxHeadingRad));
    v.rule("high", low_rad <= high_rad, "a number >= low (" + core::number_text(low_rad) + ")",
           core::number_text(high_rad));
  }
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

  template <class V>
  void visit(V& v) {
    v.field(core::required("mean_duration"), mean_duration_s, "s, mean dwell of one gaze",
            {0.0, kMaxGazeMeanDurationS, true});
    v.list("targets", targets, "objects looked at, with probabilities summing to 1",
           kMaxGazeTargets);
    v.section("directions", directions, "directions relative to the body, instead of targets");
    v.rule("targets", targets.empty() == directions.has_value(),
           "either a list of targets or directions (exactly one of them)",
           targets.empty() ? "neither" : "both");
    const double total = probability_sum();
    v.rule("targets", targets.empty() || std::abs(total - 1.0) <= 1e-6,
           "probabilities that sum to 1 (within 1e-6)", "a sum of " + core::number_text(total));
  }

  double probability_sum() const;

  /// Throws core::RequestError naming the first field outside what visit allows (exactly one of
  /// targets and directions, at most kMaxGazeTargets targets, probabilities in [0, 1] summing to
  /// 1, low <= high, a mean duration in (0, kMaxGazeMeanDurationS] s).
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
  /// While suspended (another gaze overrides this one, as a conversation's does), steps draw and
  /// aim nothing; on resuming, a gaze whose time is up is drawn at the next step.
  void set_suspended(bool suspended) { suspended_ = suspended; }
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
  bool suspended_{false};
};

}  // namespace ari_social_sim::world
