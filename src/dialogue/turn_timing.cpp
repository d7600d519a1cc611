#include "ari_social_sim/dialogue/turn_timing.hpp"

#include <algorithm>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::dialogue {

void TurnTimingConfig::validate() const {
  if (!(gap_mean_s >= 0.0) || !(gap_sd_s >= 0.0) || !(min_duration_s >= 0.0)) {
    throw core::ConfigError(
        "TurnTimingConfig: gap_mean_s, gap_sd_s, min_duration_s: expected numbers >= 0");
  }
  if (!(seconds_per_word > 0.0)) {
    throw core::ConfigError("TurnTimingConfig: seconds_per_word: expected a number > 0, got " +
                            std::to_string(seconds_per_word));
  }
}

TurnTimingConfig TurnTimingConfig::from_yaml(const core::YamlMap& map) {
  TurnTimingConfig config;
  config.gap_mean_s = map.optional<double>("gap_mean_s", config.gap_mean_s, core::non_negative());
  config.gap_sd_s = map.optional<double>("gap_sd_s", config.gap_sd_s, core::non_negative());
  config.seconds_per_word =
      map.optional<double>("seconds_per_word", config.seconds_per_word, core::positive());
  config.min_duration_s =
      map.optional<double>("min_duration_s", config.min_duration_s, core::non_negative());
  map.finish();
  return config;
}

TurnTiming::TurnTiming(TurnTimingConfig config) : config_(config) { config_.validate(); }

double TurnTiming::next_start(double previous_end_s, core::Rng& rng) const {
  return previous_end_s + std::max(0.0, rng.normal(config_.gap_mean_s, config_.gap_sd_s));
}

double TurnTiming::duration(const std::string& text) const {
  size_t words = 0;
  bool in_word = false;
  for (char c : text) {
    const bool letter = c != ' ';
    words += letter && !in_word ? 1 : 0;
    in_word = letter;
  }
  return std::max(config_.min_duration_s, config_.seconds_per_word * static_cast<double>(words));
}

}  // namespace ari_social_sim::dialogue
