#include "ari_social_sim/dialogue/dialogue_config.hpp"

#include <filesystem>

#include "ari_social_sim/core/error.hpp"

#ifndef ARI_DIALOGUE_CONFIG_DIR
#define ARI_DIALOGUE_CONFIG_DIR "config/dialogue"
#endif

namespace ari_social_sim::dialogue {
namespace {

std::string resolve(const std::string& base_dir, const std::string& path) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) {
    return path;
  }
  return (std::filesystem::path(base_dir) / path).string();
}

}  // namespace

std::string default_dialogue_config_dir() {
  return ARI_DIALOGUE_CONFIG_DIR;
}

DialogueConfig DialogueConfig::defaults(const std::string& config_dir) {
  DialogueConfig config;
  config.domain_file = resolve(config_dir, config.domain_file);
  config.model_file = resolve(config_dir, config.model_file);
  config.templates_file = resolve(config_dir, config.templates_file);
  return config;
}

DialogueConfig DialogueConfig::load(const std::string& file_path) {
  const core::YamlMap map = core::YamlMap::load_file(file_path);
  const std::string dir = std::filesystem::path(file_path).parent_path().string();
  DialogueConfig config;
  config.domain_file = resolve(dir, map.optional<std::string>("domain_file", config.domain_file));
  config.model_file = resolve(dir, map.optional<std::string>("model_file", config.model_file));
  config.templates_file =
      resolve(dir, map.optional<std::string>("templates_file", config.templates_file));
  config.corpus_dir = resolve(dir, map.optional<std::string>("corpus_dir", ""));
  config.nlg = parse_nlg_mode(map.optional<std::string>("nlg", "retrieval"), map.field_name("nlg"));
  if (map.has("users")) {
    config.users = UserSimulationConfig::from_yaml(map.map("users"));
  }
  if (map.has("errors")) {
    config.errors = ErrorModelConfig::from_yaml(map.map("errors"));
  }
  if (map.has("timing")) {
    config.timing = TurnTimingConfig::from_yaml(map.map("timing"));
  }
  if (map.has("reward")) {
    config.reward = RewardConfig::from_yaml(map.map("reward"));
  }
  map.finish();
  return config;
}

std::unique_ptr<DialogueSetup> DialogueSetup::create(const DialogueConfig& config) {
  auto setup = std::make_unique<DialogueSetup>();
  setup->config = config;
  setup->config.users.validate();
  setup->config.errors.validate();
  setup->config.timing.validate();
  setup->config.reward.validate();
  setup->domain = Domain::load(config.domain_file);
  setup->model = UserModel::load(config.model_file);
  for (const std::string& role : config.users.roles) {
    setup->model.role(role, config.model_file);
  }
  setup->corpus =
      load_mpgt_corpus(config.corpus_dir.empty() ? default_mpgt_dir() : config.corpus_dir);
  setup->nlg =
      std::make_unique<Nlg>(NlgTemplates::load(config.templates_file), &setup->corpus, config.nlg);
  setup->errors =
      std::make_unique<ErrorModel>(config.errors, setup->domain, setup->nlg->vocabulary());
  setup->timing = std::make_unique<TurnTiming>(config.timing);
  return setup;
}

}  // namespace ari_social_sim::dialogue
