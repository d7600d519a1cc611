#include "ari_social_sim/batch/batch_plan.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>

#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/config_writer.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::batch {
namespace {

// 1 to 6 decimal digits: the most a shard's K or N is spelled with.
bool parse_digits(const std::string& text, unsigned& out) {
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
  return true;
}

// `field: `, or nothing for an empty field (a program that names itself).
std::string prefix(const std::string& field) {
  return field.empty() ? "" : field + ": ";
}

// run_episodes' option for each key of BatchPlan::visit.
constexpr std::pair<const char*, const char*> kOptionOfKey[] = {
    {"first_seed", "--seed"}, {"episodes", "--episodes"}, {"shard", "--shard"}};

std::string option_of(const std::string& key) {
  for (const auto& [file_key, option] : kOptionOfKey) {
    if (key == file_key) {
      return option;
    }
  }
  return key;
}

// Hands BatchPlan's fields and rules to `checker` under run_episodes' option names, so that
// validate(field) names what the user typed.
template <class Checker>
class ByOption {
 public:
  explicit ByOption(Checker& checker) : checker_(checker) {}

  template <class T>
  void field(core::Key key, T& value, const char* meaning, const core::Bounds& bounds = {}) {
    key.name = option_of(key.name);
    checker_.field(key, value, meaning, bounds);
  }

  void rule(const std::string& name, bool holds, const std::string& expectation,
            const std::string& got) const {
    checker_.rule(option_of(name), holds, expectation, got);
  }

 private:
  Checker& checker_;
};

// A BatchPlan as check_fields walks it for validate(field).
struct PlanByOption {
  BatchPlan plan;

  template <class V>
  void visit(V& v) {
    ByOption<V> by_option(v);
    plan.visit(by_option);
  }
};

}  // namespace

std::vector<uint64_t> BatchPlan::episode_indices() const {
  std::vector<uint64_t> indices;
  for (uint64_t i = shard_index - 1; i < episodes; i += shard_count) {
    indices.push_back(i);
  }
  return indices;
}

std::string BatchPlan::seed_range() {
  return "[" + std::to_string(static_cast<uint64_t>(kSeedBounds.min)) + ", " +
         std::to_string(static_cast<uint64_t>(kSeedBounds.max)) + "]";
}

std::string BatchPlan::shard_suffix() const {
  return shard_count > 1
             ? "_shard" + std::to_string(shard_index) + "-of-" + std::to_string(shard_count)
             : "";
}

std::string BatchPlan::shard_text() const {
  return std::to_string(shard_index) + "/" + std::to_string(shard_count);
}

bool BatchPlan::set_shard(const std::string& k_of_n) {
  const size_t slash = k_of_n.find('/');
  unsigned k = 0, n = 0;
  if (slash == std::string::npos || !parse_digits(k_of_n.substr(0, slash), k) ||
      !parse_digits(k_of_n.substr(slash + 1), n)) {
    return false;
  }
  shard_index = k;
  shard_count = n;
  return true;
}

void BatchPlan::validate(const std::string& field) const {
  core::check_fields(PlanByOption{*this}, field);
}

namespace {

// The ranges the settings files hold too (BatchPlan::visit).
constexpr core::IntegerOption kEpisodes{"--episodes",
                                        static_cast<int64_t>(BatchPlan::kEpisodeBounds.min),
                                        static_cast<int64_t>(BatchPlan::kEpisodeBounds.max)};
constexpr core::IntegerOption kSeed{"--seed", static_cast<int64_t>(BatchPlan::kSeedBounds.min),
                                    static_cast<int64_t>(BatchPlan::kSeedBounds.max)};

}  // namespace

bool read_plan_option(const std::string& option, const std::string& value, BatchPlan& plan,
                      PlanOptionsGiven& given) {
  if (option == "--episodes") {
    plan.episodes = static_cast<uint64_t>(kEpisodes.parse(value));
    given.episodes = true;
  } else if (option == "--seed") {
    plan.first_seed = static_cast<uint64_t>(kSeed.parse(value));
    given.seed = true;
  } else if (option == "--shard") {
    parse_shard(value, "", plan);
    given.shard = true;
  } else {
    return false;
  }
  return true;
}

unsigned shard_count_option(const std::string& option, const std::string& value) {
  // set_shard's N: one to six digits.
  const core::IntegerOption shards{option.c_str(), 1, 999999};
  return static_cast<unsigned>(shards.parse(value));
}

std::string episodes_option_range() {
  return kEpisodes.range();
}

std::string seed_option_range() {
  return kSeed.range();
}

void parse_shard(const std::string& text, const std::string& field, BatchPlan& plan) {
  BatchPlan shard;  // the defaults' count and seeds hold, so only the shard can be refused
  if (!shard.set_shard(text)) {
    throw core::ConfigError(prefix(field) + "--shard: expected " + BatchPlan::kShardExpectation +
                            ", got '" + text + "'");
  }
  shard.validate(field);
  plan.shard_index = shard.shard_index;
  plan.shard_count = shard.shard_count;
}

void BatchSettings::validate() const {
  core::check_fields(*this, "BatchSettings");
}

std::string BatchSettings::to_yaml() const {
  return "# run_episodes: the settings the rows of the CSV beside this file were made with;\n"
         "# --resume adds rows only with the same ones (docs/scenario.md, section 6).\n" +
         core::write_fields(*this) + "\n";
}

BatchSettings BatchSettings::parse(const std::string& text, const std::string& source) {
  return core::read_fields<BatchSettings>(core::YamlMap::parse(text, source));
}

std::vector<std::string> BatchSettings::differences(const BatchSettings& now) const {
  std::vector<std::string> lines;
  if (scenario != now.scenario) {
    lines.push_back("--scenario: " + scenario + " there, " + now.scenario + " now");
  }
  if (scenario_digest != now.scenario_digest) {
    lines.push_back("--scenario: the scenario or its world file changed since (digest " +
                    scenario_digest + " there, " + now.scenario_digest + " now)");
  }
  if (config_digest != now.config_digest) {
    lines.push_back("config: the configuration files changed since (digest " + config_digest +
                    " there, " + now.config_digest + " now)");
  }
  if (plan.first_seed != now.plan.first_seed) {
    lines.push_back("--seed: first seed " + std::to_string(plan.first_seed) + " there, " +
                    std::to_string(now.plan.first_seed) + " now");
  }
  if (plan.shard_text() != now.plan.shard_text()) {
    lines.push_back("--shard: " + plan.shard_text() + " there, " + now.plan.shard_text() + " now");
  }
  if (bags != now.bags) {
    lines.push_back(std::string("--no-bags: ") + (bags ? "bags" : "no bags") + " there, " +
                    (now.bags ? "bags" : "no bags") + " now");
  }
  if (audio != now.audio) {
    lines.push_back(std::string("--audio: ") + (audio ? "audio" : "no audio") + " there, " +
                    (now.audio ? "audio" : "no audio") + " now");
  }
  return lines;
}

std::vector<std::string> files_under(const std::string& dir, const std::string& extension) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string digest_files(const std::vector<std::string>& paths) {
  // FNV-1a: tiny, stable across builds and platforms (std::hash is neither promised).
  uint64_t hash = 14695981039346656037ull;
  for (const std::string& path : paths) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      throw core::ConfigError(path + ": cannot read the file");
    }
    for (auto it = std::istreambuf_iterator<char>(in); it != std::istreambuf_iterator<char>();
         ++it) {
      hash = (hash ^ static_cast<unsigned char>(*it)) * 1099511628211ull;
    }
    // The boundary between two files counts too.
    hash = (hash ^ 0xffu) * 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace ari_social_sim::batch
