#pragma once

#include <cstdint>
#include <string>

#include "ari_social_sim/scenario/episode_metrics.hpp"
#include "ari_social_sim/scenario/script_runner.hpp"

namespace ari_social_sim::scenario {

/// One batch episode as a CSV row (docs/scenario.md, "Metrics"): identity, outcome, durations,
/// navigation figures, what was said, and the wall time it took.
struct EpisodeSummary {
  std::string scenario;
  uint64_t episode{0};
  uint64_t seed{0};
  bool finished{false};
  Outcome outcome;
  std::string states;  // `name=seconds` per visit in order, `;`-separated: time spent in each
  EpisodeMetrics metrics;
  int utterances{0};
  int ari_utterances{0};
  double wall_time_s{0.0};

  static EpisodeSummary of(const std::string& scenario, uint64_t episode, uint64_t seed,
                           const ScriptRunner& runner, const EpisodeMetrics& metrics,
                           double wall_time_s);
};

/// The header line (no newline).
std::string csv_header();
/// One row (no newline); text fields are quoted when they hold a comma or a quote.
std::string csv_row(const EpisodeSummary& summary);

}  // namespace ari_social_sim::scenario
