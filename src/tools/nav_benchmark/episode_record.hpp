#pragma once

// One nav_benchmark episode's record and its two written forms: a row of the CSV (rounded, for
// users) and a line of the progress and shard files (every number exact, so that a resumed or
// merged run's CSV and table come from the same values as one uninterrupted process's).

#include <string>
#include <vector>

#include "ari_social_sim/navigation/episode_scorer.hpp"

namespace ari_social_sim::tools::nav {

struct EpisodeRecord {
  std::string type, controller, profile, outcome, reason;
  int index{0};
  uint64_t seed{0};
  bool success{false};
  double time_to_goal_s{0.0};
  double shortest_path_m{0.0};
  navigation::EpisodeScore score;
  double final_position_error_m{-1.0};
  double final_heading_error_rad{-1.0};
  int gcff_includes_ari{-1};               // -1 = not a joining episode
  std::vector<double> solve_times_s;       // CPU time of each solve on its thread
  std::vector<double> solve_wall_times_s;  // wall time of each solve (grows with machine load)
};

/// The q-quantile (0 <= q <= 1) of `values`, one of them; 0 when there are none.
double percentile(std::vector<double> values, double q);

/// Writes the CSV, one row per record, whole or not at all. Throws core::Error naming the path
/// when writing fails; the file then keeps what it held.
void write_csv(const std::string& path, const std::vector<EpisodeRecord>& records);

/// A record as one line of tab-separated fields, without the newline.
std::string record_line(const EpisodeRecord& record);
/// Reads record_line's text back. Throws core::ConfigError naming `source` and the field.
EpisodeRecord parse_record(const std::string& line, const std::string& source);

}  // namespace ari_social_sim::tools::nav
