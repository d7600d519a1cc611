#pragma once

#include <cstdint>
#include <string>

#include "ari_social_sim/batch/batch_plan.hpp"

namespace ari_social_sim::batch {

/// Where shard K of N of a dialogue corpus meant for `out` is written: `corpus.jsonl` becomes
/// `corpus_shardK-of-N.jsonl` (the whole corpus, 1/1, keeps `out`).
std::string corpus_shard_path(const std::string& out, const BatchPlan& shard);

/// The corpus one dialogue_corpus process writes for `plan` (its episodes are the dialogues),
/// merged from the `shards` files of corpus_shard_path next to `out`: every line of every
/// dialogue, dialogues in order. Throws core::ConfigError naming the file and the line when a
/// shard is missing, holds a dialogue of another shard or outside the plan, or lacks one of its
/// dialogues (a shard that has not finished).
std::string merge_corpus_shards(const std::string& out, const BatchPlan& plan, unsigned shards);

}  // namespace ari_social_sim::batch
