#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/batch/batch_plan.hpp"
#include "ari_social_sim/batch/episode_csv.hpp"

namespace ari_social_sim::batch {

/// A job array's shards of one run_episodes plan, merged into what one process running the whole
/// plan writes (docs/cluster.md): the CSV with every row in episode order, and the settings file.
struct MergedEpisodeRun {
  std::string csv;                  // NAME.csv: the header, then the rows
  std::string settings;             // NAME.settings.yaml
  std::vector<EpisodeCsvRow> rows;  // in episode order
};

/// Reads the CSV and settings of shards 1..`shards` of the plan `whole` (its shard 1/1) from `dir`
/// (`NAME_shardK-of-N.csv`, `.settings.yaml`) and merges them. Throws core::ConfigError naming the
/// file and what is wrong when a shard is missing, was made with other settings, or lacks
/// episodes (a task that has not finished: resubmit it).
MergedEpisodeRun merge_episode_shards(const std::string& dir, const BatchSettings& whole,
                                      unsigned shards);

}  // namespace ari_social_sim::batch
