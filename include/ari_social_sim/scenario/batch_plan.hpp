#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ari_social_sim::scenario {

/// Which episodes one batch process runs: episode i of `episodes` runs with seed `first_seed + i`
/// (so episode i can be replayed live with `seed:=first_seed+i`), and shard K of N (1 <= K <= N)
/// takes the episodes with i % N == K - 1, so N machines with K = 1..N cover every episode once.
struct BatchPlan {
  uint64_t episodes{1};
  uint64_t first_seed{1};
  unsigned shard_index{1};  // K
  unsigned shard_count{1};  // N

  /// The episode indices of this shard, in increasing order.
  std::vector<uint64_t> episode_indices() const;
  uint64_t seed_of(uint64_t episode) const { return first_seed + episode; }
  /// Throws core::ConfigError naming `field` (when not empty) and the option unless
  /// 1 <= K <= N, the count is at least 1, and every seed fits the scene format (< 2^31).
  void validate(const std::string& field) const;
};

/// Reads `K/N`, e.g. `3/8`. Throws core::ConfigError naming `field` (when not empty) and --shard
/// with the expectation.
void parse_shard(const std::string& text, const std::string& field, BatchPlan& plan);

/// What a batch's rows were made with, kept beside its CSV (`NAME.settings.yaml`), so that a
/// resumed run (`run_episodes --resume`) adds only rows made the same way: the same scenario and
/// configuration files (by digest), seeds, shard and bags. The episode count is the one asked for
/// last: a resumed run may extend it.
struct BatchSettings {
  std::string scenario;         // the scenario's name, as in the CSV's `scenario` column
  std::string scenario_file;    // the path it was read from (informative, not compared)
  std::string scenario_digest;  // digest_files of the scenario file and its world file
  std::string config_digest;    // digest_files of the configuration files the episodes read
  BatchPlan plan;
  bool bags{true};

  /// The settings as YAML, with a comment saying what they are for.
  std::string to_yaml() const;
  /// Reads to_yaml's text. Throws core::ConfigError naming `source` and the field.
  static BatchSettings parse(const std::string& text, const std::string& source);
  /// One line per setting in which `now` differs from these (all but the episode count and the
  /// scenario file's path), naming the option, e.g. `--seed: first seed 1 there, 5 now`.
  std::vector<std::string> differences(const BatchSettings& now) const;
};

/// FNV-1a (64 bits) of the files' contents in order, as 16 hex digits: equal digests mean, in
/// practice, unchanged files. Throws core::ConfigError naming a file that cannot be read.
std::string digest_files(const std::vector<std::string>& paths);

}  // namespace ari_social_sim::scenario
