#include "ari_social_sim/rendering/weight_shifts.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/rng_streams.hpp"
#include "ari_social_sim/core/smoothstep.hpp"

namespace ari_social_sim::rendering {
namespace {

// Duarte and Zatsiorsky (1999), the medio-lateral direction over 30 minutes of free standing.
constexpr double kShiftMeanS = 199.0;
constexpr double kShiftSpreadS = 148.0;
constexpr double kFidgetMeanS = 49.0;
constexpr double kFidgetSpreadS = 16.0;
// How long the weight takes to move over, and how long a fidget rests on the other leg: our
// choices (about a step's time), not measured.
constexpr double kMoveS = 0.8;
constexpr double kFidgetRestS = 2.0;

// A log-normal draw with the given mean and standard deviation: positive and skewed like the
// measured intervals (their spread is three quarters of the mean for shifts).
double log_normal(core::Rng& rng, double mean, double spread) {
  const double sigma_squared = std::log1p(spread * spread / (mean * mean));
  return std::exp(rng.normal(std::log(mean) - 0.5 * sigma_squared, std::sqrt(sigma_squared)));
}

}  // namespace

WeightShifts::WeightShifts(uint64_t seed, uint32_t person_id) : seed_(seed), person_id_(person_id) {
  restart();
}

void WeightShifts::restart() {
  rng_ = core::rng_for(seed_, core::rng_streams::kHumanWeightShifts, person_id_);
  side_ = rng_.bernoulli(0.5) ? 1.0 : -1.0;
  side_before_ = side_;
  // People have stood a while at time 0: the first waits are a share of a whole one, so that
  // nobody moves in step with the others.
  next_shift_s_ = rng_.uniform() * log_normal(rng_, kShiftMeanS, kShiftSpreadS);
  next_fidget_s_ = rng_.uniform() * log_normal(rng_, kFidgetMeanS, kFidgetSpreadS);
  still_from_s_ = 0.0;
  changes_.clear();
  forgotten_until_s_ = 0.0;
}

void WeightShifts::add_change(double time_s, double side) {
  changes_.push_back({time_s, side});
  still_from_s_ = time_s + kMoveS;
}

void WeightShifts::plan_until(double time_s) {
  while (std::min(next_shift_s_, next_fidget_s_) <= time_s) {
    // A move due while the weight is still moving waits for it to settle.
    if (next_shift_s_ <= next_fidget_s_) {
      side_ = -side_;
      add_change(std::max(next_shift_s_, still_from_s_), side_);
      next_shift_s_ += log_normal(rng_, kShiftMeanS, kShiftSpreadS);
    } else {
      add_change(std::max(next_fidget_s_, still_from_s_), -side_);
      add_change(still_from_s_ + kFidgetRestS, side_);
      next_fidget_s_ += log_normal(rng_, kFidgetMeanS, kFidgetSpreadS);
    }
  }
}

void WeightShifts::forget_before(double time_s) {
  // A change is needed while it or the one after it may still be under way.
  while (changes_.size() >= 2 && changes_[1].time_s + kMoveS <= time_s) {
    side_before_ = changes_.front().side;
    forgotten_until_s_ = changes_[1].time_s;
    changes_.pop_front();
  }
}

double WeightShifts::load_side(double time_s) {
  if (time_s < forgotten_until_s_) {
    restart();
  }
  plan_until(time_s);
  double from = side_before_;
  double load = side_before_;
  for (const Change& change : changes_) {
    if (change.time_s > time_s) {
      break;
    }
    load = from + (change.side - from) * core::smoothstep((time_s - change.time_s) / kMoveS);
    from = change.side;
  }
  forget_before(time_s);
  return load;
}

}  // namespace ari_social_sim::rendering
