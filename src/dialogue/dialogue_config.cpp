#include "ari_social_sim/dialogue/dialogue_config.hpp"

#include <filesystem>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

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

// `config` with its relative file paths taken relative to `base_dir`.
DialogueConfig with_paths_in(const std::string& base_dir, DialogueConfig config) {
  for (std::string* path :
       {&config.domain_file, &config.model_file, &config.templates_file, &config.corpus_dir}) {
    *path = resolve(base_dir, *path);
  }
  return config;
}

}  // namespace

std::string default_dialogue_config_dir() {
  return ARI_DIALOGUE_CONFIG_DIR;
}

DialogueConfig DialogueConfig::defaults(const std::string& config_dir) {
  return with_paths_in(config_dir, DialogueConfig{});
}

void DialogueConfig::validate() const {
  core::check_fields(*this, "DialogueConfig");
}

DialogueConfig DialogueConfig::load(const std::string& file_path) {
  return with_paths_in(std::filesystem::path(file_path).parent_path().string(),
                       core::read_fields<DialogueConfig>(core::YamlMap::load_file(file_path)));
}

std::unique_ptr<DialogueSetup> DialogueSetup::create(const DialogueConfig& config) {
  auto setup = std::make_unique<DialogueSetup>();
  setup->config = core::validated(config);
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
