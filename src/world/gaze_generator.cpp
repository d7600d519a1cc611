#include "ari_social_sim/world/gaze_generator.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {

double GazeModel::probability_sum() const {
  double total = 0.0;
  for (const GazeTarget& target : targets) {
    total += target.probability;
  }
  return total;
}

void GazeModel::validate() const {
  core::check_fields<core::RequestError>(*this, "");
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
  if (suspended_) {
    return;
  }
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
