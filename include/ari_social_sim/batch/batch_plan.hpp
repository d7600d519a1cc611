#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::batch {

/// Which episodes one batch process runs: episode i of `episodes` runs with seed `first_seed + i`
/// (so episode i can be replayed live with `seed:=first_seed+i`), and shard K of N (1 <= K <= N)
/// takes the episodes with i % N == K - 1, so N machines with K = 1..N cover every episode once.
struct BatchPlan {
  /// --episodes' documented range (README, docs/scenario.md): a million episodes take a day or
  /// more at the fastest scenario's 600 per minute, and a terabyte of bags.
  static constexpr core::Bounds kEpisodeBounds{1.0, 1000000.0};
  /// Seeds are scene seeds, integers below 2^31: the first and the last, first_seed + episodes - 1.
  static constexpr core::Bounds kSeedBounds{0.0, 2147483647.0};
  /// What a shard must be, in messages about --shard and the settings files' `shard`.
  static constexpr const char* kShardExpectation = "K/N with 1 <= K <= N";

  uint64_t episodes{1};
  uint64_t first_seed{1};
  unsigned shard_index{1};  // K
  unsigned shard_count{1};  // N

  /// The fields under the keys of the settings files (BatchSettings); validate(field) names them
  /// by run_episodes' options instead.
  template <class V>
  void visit(V& v) {
    v.field(core::required("first_seed"), first_seed,
            "seed of episode 0 (--seed); episode i runs with first_seed + i", kSeedBounds);
    v.field(core::required("episodes"), episodes,
            "episodes of the whole batch, every shard's together (--episodes)", kEpisodeBounds);
    // One text, as --shard takes it: files written before visit existed spell it so.
    std::string shard = shard_text();
    v.field(core::required("shard"), shard,
            "K/N (--shard): this process runs the episodes with i % N == K - 1");
    const bool spelled_k_of_n = set_shard(shard);
    v.rule("shard", spelled_k_of_n && shard_index >= 1 && shard_index <= shard_count,
           kShardExpectation, "'" + shard + "'");
    const uint64_t last_seed = first_seed + episodes - 1;
    v.rule("first_seed", static_cast<double>(last_seed) <= kSeedBounds.max,
           "the episodes' seeds in " + seed_range() + " (scene seeds)",
           "seeds " + std::to_string(first_seed) + ".." + std::to_string(last_seed));
  }

  /// The episode indices of this shard, in increasing order.
  std::vector<uint64_t> episode_indices() const;
  uint64_t seed_of(uint64_t episode) const { return first_seed + episode; }
  /// kSeedBounds in whole numbers, `[0, 2147483647]` (core::Bounds::describe shows six
  /// significant digits).
  static std::string seed_range();
  /// `K/N`, as --shard and the settings files spell the shard.
  std::string shard_text() const;
  /// What a shard's output files add to their name, `_shardK-of-N`; empty for a whole run (1/1).
  std::string shard_suffix() const;
  /// Sets K and N from `K/N`, each of 1 to 6 digits; false, leaving them as they were, when the
  /// text is not of that form. Whether 1 <= K <= N is visit's rule.
  bool set_shard(const std::string& k_of_n);
  /// Throws core::ConfigError unless the plan is what visit allows, naming `field` (when not
  /// empty) and the option that sets the value, e.g. `--seed: expected the episodes' seeds in
  /// [0, 2147483647] (scene seeds), got seeds 2147483640..2147483649`.
  void validate(const std::string& field) const;
};

/// Reads `K/N`, e.g. `3/8`, into `plan`, checked as visit checks a shard. Throws core::ConfigError
/// naming `field` (when not empty) and --shard with the expectation.
void parse_shard(const std::string& text, const std::string& field, BatchPlan& plan);

/// Which of a plan's values the command line gave, so that a tool can default the others.
struct PlanOptionsGiven {
  bool episodes{false};
  bool seed{false};
  bool shard{false};
};

/// Reads one of the command-line options the batch tools share (`--episodes N`, `--seed S`,
/// `--shard K/N`) into `plan`; false when `option` is none of them. Throws core::ConfigError
/// naming the option and its range for a bad value.
bool read_plan_option(const std::string& option, const std::string& value, BatchPlan& plan,
                      PlanOptionsGiven& given);

/// A count of shards given to `option` (`--merge-shards 4`): N of --shard's K/N, 1 to 999999.
/// Throws core::ConfigError naming the option and the range.
unsigned shard_count_option(const std::string& option, const std::string& value);

/// The ranges of --episodes and --seed, as the tools' usage lines print them.
std::string episodes_option_range();
std::string seed_option_range();

/// What a batch's rows were made with, kept beside its CSV (`NAME.settings.yaml`), so that a
/// resumed run (`run_episodes --resume`) adds only rows made the same way: the same scenario and
/// configuration files (by digest), seeds, shard, bags and audio. The episode count is the one
/// asked for last: a resumed run may extend it.
struct BatchSettings {
  std::string scenario;
  std::string scenario_file;
  std::string scenario_digest;
  std::string config_digest;
  BatchPlan plan;
  bool bags{true};
  bool audio{false};

  template <class V>
  void visit(V& v) {
    v.field(core::required("scenario"), scenario,
            "the scenario's name, as in the CSV's `scenario` column");
    v.field(core::required("scenario_file"), scenario_file,
            "the path the scenario was read from (informative, not compared)");
    v.field(core::required("scenario_digest"), scenario_digest,
            "digest_files of the scenario file and its world file");
    v.field(core::required("config_digest"), config_digest,
            "digest_files of the configuration files the episodes read");
    plan.visit(v);  // beside the other keys, not a section of its own
    v.field(core::required("bags"), bags, "a rosbag per episode (false: --no-bags)");
    v.field("audio", audio, "the microphone array's audio and its labels per episode (--audio)");
  }

  /// Throws core::ConfigError naming the field outside what visit allows (an empty string too),
  /// e.g. `BatchSettings: shard: expected K/N with 1 <= K <= N, got '5/4'`.
  void validate() const;
  /// The settings as YAML, with a comment saying what they are for.
  std::string to_yaml() const;
  /// Reads to_yaml's text, that of earlier versions too. Throws core::ConfigError naming `source`
  /// and the field.
  static BatchSettings parse(const std::string& text, const std::string& source);
  /// One line per setting in which `now` differs from these (all but the episode count and the
  /// scenario file's path), naming the option, e.g. `--seed: first seed 1 there, 5 now`.
  std::vector<std::string> differences(const BatchSettings& now) const;
};

/// Every regular file under `dir` (recursively) whose name ends with `extension` (".yaml"),
/// sorted: e.g. the configuration files an episode may read, for digest_files.
std::vector<std::string> files_under(const std::string& dir, const std::string& extension);

/// FNV-1a (64 bits) of the files' contents in order, as 16 hex digits: equal digests mean, in
/// practice, unchanged files. Throws core::ConfigError naming a file that cannot be read.
std::string digest_files(const std::vector<std::string>& paths);

}  // namespace ari_social_sim::batch
