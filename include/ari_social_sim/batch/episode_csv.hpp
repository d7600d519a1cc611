#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/scenario/episode_metrics.hpp"
#include "ari_social_sim/scenario/script_runner.hpp"

namespace ari_social_sim::batch {

/// One batch episode as a CSV row (docs/scenario.md, "Metrics"): identity, outcome, durations,
/// navigation figures and what was said. Nothing that depends on the machine (no wall time), so
/// that the same plan gives the same bytes, on one process or merged from a job array's shards.
struct EpisodeSummary {
  std::string scenario;
  uint64_t episode{0};
  uint64_t seed{0};
  bool finished{false};
  scenario::Outcome outcome;
  std::string states;  // `name=seconds` per visit in order, `;`-separated: time spent in each
  scenario::EpisodeMetrics metrics;
  int utterances{0};
  int ari_utterances{0};

  static EpisodeSummary of(const std::string& scenario, uint64_t episode, uint64_t seed,
                           const scenario::ScriptRunner& runner,
                           const scenario::EpisodeMetrics& metrics);
};

/// The header line (no newline).
std::string csv_header();
/// One row (no newline); text fields are quoted when they hold a comma or a quote.
std::string csv_row(const EpisodeSummary& summary);

/// Which run a row of a batch CSV is, and how it ended.
struct EpisodeCsvRow {
  std::string scenario;
  uint64_t episode{0};
  uint64_t seed{0};
  bool success{false};
  std::string reason;
  std::string final_state;
  std::string text;  // the row's bytes as read_episode_csv found them, newline included

  /// The row csv_row(summary) writes, as read_episode_csv reads it back.
  static EpisodeCsvRow of(const EpisodeSummary& summary);
};

/// A batch CSV as found on disk, read to resume it.
struct EpisodeCsvContents {
  std::vector<EpisodeCsvRow> rows;  // the complete rows, in file order
  /// Bytes of the header and the complete rows: what a resumed run keeps. 0 when not even the
  /// header is complete (the resumed run writes it).
  size_t complete_bytes{0};
  /// The text ends in a row without its newline (a run killed while writing it); not in `rows`.
  bool partial_row{false};
};

/// Reads a CSV written with csv_header() and csv_row(). Throws core::ConfigError naming `source`
/// and the line for another header (another version's columns), a row with another number of
/// columns, an episode or seed that is not a number, a success other than 0 or 1, or an episode
/// found twice.
EpisodeCsvContents read_episode_csv(const std::string& text, const std::string& source);

}  // namespace ari_social_sim::batch
