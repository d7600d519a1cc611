#include "ari_social_sim/dialogue/turn_timing.hpp"

#include <algorithm>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::dialogue {

void TurnTimingConfig::validate() const {
  core::check_fields(*this, "TurnTimingConfig");
}

TurnTiming::TurnTiming(TurnTimingConfig config) : config_(config) {
  config_.validate();
}

double TurnTiming::next_start(double previous_end_s, core::Rng& rng) const {
  return previous_end_s + std::max(0.0, rng.normal(config_.gap_mean_s, config_.gap_sd_s));
}

double TurnTiming::duration(const std::string& text) const {
  const double words = static_cast<double>(split_words(text).size());
  return std::max(config_.min_duration_s, config_.seconds_per_word * words);
}

}  // namespace ari_social_sim::dialogue
