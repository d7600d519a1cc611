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
  /// Throws core::ConfigError naming `field` unless 1 <= K <= N, the count is at least 1, and
  /// every seed fits the scene format (< 2^31).
  void validate(const std::string& field) const;
};

/// Reads `K/N`, e.g. `3/8`. Throws core::ConfigError naming `field` with the expectation.
void parse_shard(const std::string& text, const std::string& field, BatchPlan& plan);

}  // namespace ari_social_sim::scenario
