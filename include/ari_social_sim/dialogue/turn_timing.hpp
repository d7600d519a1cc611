#pragma once

#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/rng.hpp"

namespace ari_social_sim::dialogue {

/// Turn-taking times: the next speaker starts after a gap ~ N(200 ms, 200 ms) clipped at 0
/// (Stivers 2009), and speaks at 150 wpm, 0.4 s a word.
struct TurnTimingConfig {
  double gap_mean_s{0.2};
  double gap_sd_s{0.2};
  double seconds_per_word{0.4};
  double min_duration_s{0.4};

  template <class V>
  void visit(V& v) {
    v.field("gap_mean_s", gap_mean_s, "mean gap (s) before the next speaker starts",
            core::non_negative());
    v.field("gap_sd_s", gap_sd_s, "its standard deviation (s); gaps are clipped at 0",
            core::non_negative());
    v.field("seconds_per_word", seconds_per_word, "speech rate (0.4 s: 150 words a minute)",
            core::positive());
    v.field("min_duration_s", min_duration_s, "shortest utterance (s): even \"Ok.\" takes a moment",
            core::non_negative());
  }

  /// Throws core::ConfigError naming the field when a value is negative or seconds_per_word is 0.
  void validate() const;
};

/// Places utterances on the dialogue's clock.
class TurnTiming {
 public:
  explicit TurnTiming(TurnTimingConfig config);

  /// Start (s) of an utterance that follows one ending at `previous_end_s`.
  double next_start(double previous_end_s, core::Rng& rng) const;
  /// Duration (s) of `text` at the configured speech rate.
  double duration(const std::string& text) const;

 private:
  TurnTimingConfig config_;
};

}  // namespace ari_social_sim::dialogue
