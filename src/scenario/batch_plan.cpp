#include "ari_social_sim/scenario/batch_plan.hpp"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

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

// `field: `, or nothing for an empty field (a program that names itself).
std::string prefix(const std::string& field) {
  return field.empty() ? "" : field + ": ";
}

// A YAML single-quoted scalar: any text, a quote written twice.
std::string yaml_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    out += c == '\'' ? std::string("''") : std::string(1, c);
  }
  return out + "'";
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
    throw core::ConfigError(prefix(field) + "--episodes: expected at least 1, got 0");
  }
  if (shard_index == 0 || shard_index > shard_count) {
    throw core::ConfigError(prefix(field) + "--shard: expected K/N with 1 <= K <= N, got " +
                            std::to_string(shard_index) + "/" + std::to_string(shard_count));
  }
  if (first_seed + episodes > kSeedLimit) {
    throw core::ConfigError(prefix(field) + "--seed: expected seeds " + std::to_string(first_seed) +
                            ".." + std::to_string(first_seed + episodes - 1) +
                            " below 2^31 (scene seeds), got a last seed beyond it");
  }
}

void parse_shard(const std::string& text, const std::string& field, BatchPlan& plan) {
  const size_t slash = text.find('/');
  unsigned k = 0, n = 0;
  if (slash == std::string::npos || !parse_positive(text.substr(0, slash), k) ||
      !parse_positive(text.substr(slash + 1), n) || k > n) {
    throw core::ConfigError(prefix(field) + "--shard: expected K/N with 1 <= K <= N, got '" + text +
                            "'");
  }
  plan.shard_index = k;
  plan.shard_count = n;
}

std::string BatchSettings::to_yaml() const {
  return "# run_episodes: the settings the rows of the CSV beside this file were made with;\n"
         "# --resume adds rows only with the same ones (docs/scenario.md, section 6).\n"
         "scenario: " +
         yaml_quoted(scenario) + "\nscenario_file: " + yaml_quoted(scenario_file) +
         "\nscenario_digest: " + yaml_quoted(scenario_digest) +
         "\nconfig_digest: " + yaml_quoted(config_digest) +
         "\nfirst_seed: " + std::to_string(plan.first_seed) +
         "\nepisodes: " + std::to_string(plan.episodes) + "\nshard: '" +
         std::to_string(plan.shard_index) + "/" + std::to_string(plan.shard_count) +
         "'\nbags: " + (bags ? "true" : "false") + "\n";
}

BatchSettings BatchSettings::parse(const std::string& text, const std::string& source) {
  const core::YamlMap map = core::YamlMap::parse(text, source);
  BatchSettings settings;
  settings.scenario = map.required<std::string>("scenario");
  settings.scenario_file = map.required<std::string>("scenario_file");
  settings.scenario_digest = map.required<std::string>("scenario_digest");
  settings.config_digest = map.required<std::string>("config_digest");
  settings.plan.first_seed = static_cast<uint64_t>(
      map.required<int>("first_seed", core::between(0.0, static_cast<double>(kSeedLimit - 1))));
  settings.plan.episodes =
      static_cast<uint64_t>(map.required<int>("episodes", core::Bounds{1.0, 2147483647.0}));
  parse_shard(map.required<std::string>("shard"), source + ": shard", settings.plan);
  settings.bags = map.required<bool>("bags");
  map.finish();
  return settings;
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
  if (plan.shard_index != now.plan.shard_index || plan.shard_count != now.plan.shard_count) {
    lines.push_back("--shard: " + std::to_string(plan.shard_index) + "/" +
                    std::to_string(plan.shard_count) + " there, " +
                    std::to_string(now.plan.shard_index) + "/" +
                    std::to_string(now.plan.shard_count) + " now");
  }
  if (bags != now.bags) {
    lines.push_back(std::string("--no-bags: ") + (bags ? "bags" : "no bags") + " there, " +
                    (now.bags ? "bags" : "no bags") + " now");
  }
  return lines;
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

}  // namespace ari_social_sim::scenario
