#include "ari_social_sim/world/gaze_generator.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/world/request_check.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {

void GazeModel::validate() const {
  const RequestCheck check;
  if (targets.empty() == !directions.has_value()) {
    check.fail("gaze", "either targets with probabilities or directions (exactly one of them)",
               targets.empty() ? "neither" : "both");
  }
  if (targets.size() > kMaxGazeTargets) {
    check.fail("gaze.targets", "at most " + std::to_string(kMaxGazeTargets) + " targets",
               std::to_string(targets.size()));
  }
  double total = 0.0;
  for (size_t i = 0; i < targets.size(); ++i) {
    if (targets[i].id == model::kNoObject) {
      check.fail("gaze.targets[" + std::to_string(i) + "]", "a positive object id", "0");
    }
    check.in_range("gaze.probabilities[" + std::to_string(i) + "]", targets[i].probability,
                   core::between(0.0, 1.0));
    total += targets[i].probability;
  }
  if (!targets.empty() && std::abs(total - 1.0) > 1e-6) {
    check.fail("gaze.probabilities", "numbers in [0, 1] that sum to 1 (within 1e-6)",
               "a sum of " + core::number_text(total));
  }
  if (directions) {
    const bool uniform = directions->distribution == GazeDirections::Distribution::kUniform;
    if (uniform) {
      check.heading("gaze.directions.low", directions->low_rad);
      check.heading("gaze.directions.high", directions->high_rad);
      if (!(directions->low_rad <= directions->high_rad)) {
        check.fail("gaze.directions", "low <= high",
                   "low " + core::number_text(directions->low_rad) + ", high " +
                       core::number_text(directions->high_rad));
      }
    } else {
      check.heading("gaze.directions.mean", directions->mean_rad);
      check.in_range("gaze.directions.stddev", directions->stddev_rad,
                     core::between(0.0, kMaxHeadingRad), "rad");
    }
  }
  check.in_range("gaze.mean_duration", mean_duration_s, {0.0, kMaxGazeMeanDurationS, true}, "s");
}

GazeGenerator::GazeGenerator(GazeModel model, core::Rng rng)
    : model_(std::move(model)), rng_(rng) {}

void GazeGenerator::set_model(GazeModel model) {
  model_ = std::move(model);
  next_change_s_.reset();
}

void GazeGenerator::draw(Object& owner, const StepContext& context, double now_s) {
  since_s_ = now_s;
  if (model_.directions) {
    const GazeDirections& d = *model_.directions;
    target_ = model::kNoObject;
    relative_direction_rad_ = d.distribution == GazeDirections::Distribution::kUniform
                                  ? rng_.uniform(d.low_rad, d.high_rad)
                                  : rng_.normal(d.mean_rad, d.stddev_rad);
    return;
  }
  // Targets that left the world get no weight; with none left the human looks ahead.
  std::vector<double> weights;
  weights.reserve(model_.targets.size());
  double total = 0.0;
  for (const GazeTarget& target : model_.targets) {
    const bool present = context.simulation.find_object(target.id) != nullptr;
    weights.push_back(present ? target.probability : 0.0);
    total += weights.back();
  }
  if (total <= 0.0) {
    target_ = model::kNoObject;
    relative_direction_rad_ = 0.0;
    return;
  }
  target_ = model_.targets[rng_.categorical(weights)].id;
}

void GazeGenerator::step(Object& owner, const StepContext& context) {
  const double now_s = context.time_s + context.dt_s;
  if (!next_change_s_) {
    next_change_s_ = now_s;
  }
  const bool target_lost =
      target_ != model::kNoObject && context.simulation.find_object(target_) == nullptr;
  if (now_s + 1e-9 >= *next_change_s_ || target_lost) {
    draw(owner, context, now_s);
    // Next change counts from the sampled time, not the step it was noticed at, so step
    // quantisation does not lengthen the mean dwell.
    *next_change_s_ =
        (target_lost ? now_s : *next_change_s_) + rng_.exponential(model_.mean_duration_s);
  }
  const Object* target =
      target_ == model::kNoObject ? nullptr : context.simulation.find_object(target_);
  if (target != nullptr) {
    const Eigen::Vector2d to_target = target->centre() - owner.centre();
    direction_rad_ = std::atan2(to_target.y(), to_target.x());
  } else {
    direction_rad_ = core::wrap_angle(owner.pose().theta + relative_direction_rad_);
  }
  ARI_DCHECK(std::isfinite(direction_rad_));
}

}  // namespace ari_social_sim::world
