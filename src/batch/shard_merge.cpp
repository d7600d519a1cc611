#include "ari_social_sim/batch/shard_merge.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::batch {

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw core::ConfigError(path + ": not found: expected the output of a finished shard");
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Checks that shard `shard`'s settings, read from `path`, are those of `whole` but for the shard.
void check_shard_settings(const std::string& path, const BatchSettings& whole,
                          const BatchPlan& shard) {
  const BatchSettings there = BatchSettings::parse(read_text(path), path);
  BatchSettings expected = whole;
  expected.plan = shard;
  std::vector<std::string> differences = there.differences(expected);
  if (there.plan.episodes != whole.plan.episodes) {
    differences.push_back("--episodes: " + std::to_string(there.plan.episodes) + " there, " +
                          std::to_string(whole.plan.episodes) + " now");
  }
  if (!differences.empty()) {
    std::string text;
    for (const std::string& line : differences) {
      text += "\n  " + line;
    }
    throw core::ConfigError(path + ": made with other settings than the plan merged:" + text);
  }
}

// The rows of one shard's CSV at `path`, checked to be exactly the shard's episodes.
std::vector<EpisodeCsvRow> shard_rows(const std::string& path, const BatchPlan& shard) {
  const EpisodeCsvContents contents = read_episode_csv(read_text(path), path);
  const std::vector<uint64_t> planned = shard.episode_indices();
  if (contents.partial_row || contents.rows.size() != planned.size()) {
    throw core::ConfigError(path + ": " + std::to_string(contents.rows.size()) +
                            " of the shard's " + std::to_string(planned.size()) +
                            " episodes: expected all (a task that has not finished; resubmit "
                            "the plan to run what is missing)");
  }
  return contents.rows;  // read_episode_csv refuses an episode twice
}

}  // namespace

MergedEpisodeRun merge_episode_shards(const std::string& dir, const BatchSettings& whole,
                                      unsigned shards) {
  std::map<uint64_t, EpisodeCsvRow> by_episode;
  for (unsigned k = 1; k <= shards; ++k) {
    BatchPlan shard = whole.plan;
    shard.shard_index = k;
    shard.shard_count = shards;
    const std::string stem = dir + "/" + whole.scenario + shard.shard_suffix();
    check_shard_settings(stem + ".settings.yaml", whole, shard);
    for (EpisodeCsvRow& row : shard_rows(stem + ".csv", shard)) {
      by_episode.emplace(row.episode, std::move(row));
    }
  }
  MergedEpisodeRun merged;
  merged.settings = whole.to_yaml();
  merged.csv = csv_header() + "\n";
  for (auto& [episode, row] : by_episode) {
    merged.csv += row.text;
    merged.rows.push_back(std::move(row));
  }
  return merged;
}

}  // namespace ari_social_sim::batch
