#include "ari_social_sim/scenario/batch_plan.hpp"

#include <cctype>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::scenario {
namespace {

constexpr uint64_t kSeedLimit = 2147483648ull;  // scene seeds are integers below 2^31

bool parse_positive(const std::string& text, unsigned& out) {
  if (text.empty() || text.size() > 6) {
    return false;
  }
  unsigned value = 0;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) {
      return false;
    }
    value = value * 10 + static_cast<unsigned>(c - '0');
  }
  out = value;
  return value > 0;
}

}  // namespace

std::vector<uint64_t> BatchPlan::episode_indices() const {
  std::vector<uint64_t> indices;
  for (uint64_t i = shard_index - 1; i < episodes; i += shard_count) {
    indices.push_back(i);
  }
  return indices;
}

void BatchPlan::validate(const std::string& field) const {
  if (episodes == 0) {
    throw core::ConfigError(field + ": --episodes: expected at least 1, got 0");
  }
  if (shard_index == 0 || shard_index > shard_count) {
    throw core::ConfigError(field + ": --shard: expected K/N with 1 <= K <= N, got " +
                            std::to_string(shard_index) + "/" + std::to_string(shard_count));
  }
  if (first_seed + episodes > kSeedLimit) {
    throw core::ConfigError(field + ": --seed: expected seeds " + std::to_string(first_seed) +
                            ".." + std::to_string(first_seed + episodes - 1) +
                            " below 2^31 (scene seeds), got a last seed beyond it");
  }
}

void parse_shard(const std::string& text, const std::string& field, BatchPlan& plan) {
  const size_t slash = text.find('/');
  unsigned k = 0, n = 0;
  if (slash == std::string::npos || !parse_positive(text.substr(0, slash), k) ||
      !parse_positive(text.substr(slash + 1), n) || k > n) {
    throw core::ConfigError(field + ": --shard: expected K/N with 1 <= K <= N, got '" + text + "'");
  }
  plan.shard_index = k;
  plan.shard_count = n;
}

}  // namespace ari_social_sim::scenario
