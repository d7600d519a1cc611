#include "ari_social_sim/batch/corpus_shard_merge.hpp"

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::batch {

namespace {

// Every JSON line of the corpus starts so (dialogue::utterance_json).
constexpr const char* kLineStart = "{\"dialogue\":";

// The dialogue index a corpus line starts with; throws naming `where` for another line.
uint64_t dialogue_of(const std::string& line, const std::string& where) {
  const std::string start = kLineStart;
  if (line.rfind(start, 0) != 0) {
    throw core::ConfigError(where + ": expected a line of dialogue_corpus, starting " + start +
                            ", got '" + line.substr(0, 40) + "'");
  }
  size_t used = 0;
  const std::string digits = line.substr(start.size());
  uint64_t index = 0;
  try {
    index = std::stoull(digits, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || digits[used] != ',') {
    throw core::ConfigError(where + ": expected the dialogue's index after " + start);
  }
  return index;
}

}  // namespace

std::string corpus_shard_path(const std::string& out, const BatchPlan& shard) {
  const std::string suffix = shard.shard_suffix();
  const size_t slash = out.find_last_of('/');
  const size_t dot = out.find_last_of('.');
  const bool has_extension =
      dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return has_extension ? out.substr(0, dot) + suffix + out.substr(dot) : out + suffix;
}

std::string merge_corpus_shards(const std::string& out, const BatchPlan& plan, unsigned shards) {
  std::map<uint64_t, std::string> dialogues;  // index -> its lines
  for (unsigned k = 1; k <= shards; ++k) {
    BatchPlan shard = plan;
    shard.shard_index = k;
    shard.shard_count = shards;
    const std::string path = corpus_shard_path(out, shard);
    std::ifstream in(path);
    if (!in) {
      throw core::ConfigError(path + ": not found: expected the corpus of a finished shard");
    }
    const std::vector<uint64_t> planned = shard.episode_indices();
    const std::set<uint64_t> mine(planned.begin(), planned.end());
    std::set<uint64_t> seen;
    size_t number = 0;
    for (std::string line; std::getline(in, line);) {
      const std::string where = path + ":" + std::to_string(++number);
      const uint64_t index = dialogue_of(line, where);
      if (mine.count(index) == 0) {
        throw core::ConfigError(where + ": dialogue " + std::to_string(index) +
                                " is not one of this shard's (" + shard.shard_text() + " of " +
                                std::to_string(plan.episodes) + " dialogues)");
      }
      seen.insert(index);
      dialogues[index] += line + "\n";
    }
    if (seen.size() != planned.size()) {
      throw core::ConfigError(path + ": " + std::to_string(seen.size()) + " of the shard's " +
                              std::to_string(planned.size()) +
                              " dialogues: expected all (a shard that has not finished)");
    }
  }
  std::string merged;
  for (const auto& [index, lines] : dialogues) {
    merged += lines;
  }
  return merged;
}

}  // namespace ari_social_sim::batch
