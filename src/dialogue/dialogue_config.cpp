#include "ari_social_sim/dialogue/dialogue_config.hpp"

#include <filesystem>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/data_sets.hpp"
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

// `config` with its relative file paths taken relative to `base_dir`.
DialogueConfig with_paths_in(const std::string& base_dir, DialogueConfig config) {
  for (std::string* path :
       {&config.domain_file, &config.model_file, &config.templates_file, &config.corpus_dir}) {
    *path = resolve(base_dir, *path);
  }
  return config;
}

// How messages name a field of `config`: `file: field`, or `DialogueConfig: field` for settings
// made in code (as core::check_fields does).
std::string field_name(const DialogueConfig& config, const std::string& field) {
  return (config.settings_file.empty() ? std::string("DialogueConfig") : config.settings_file) +
         ": " + field;
}

[[noreturn]] void refuse_retrieval_without_corpus(const DialogueConfig& config) {
  throw core::ConfigError(
      field_name(config, "nlg") +
      ": retrieval needs the MPGT corpus, which is not part of the repository, and none is "
      "pointed at: set corpus_dir (relative to the settings file) or the environment variable "
      "ARI_MPGT_DIR to the folder of its convo*.txt files (scripts/fetch_data.sh fetches it into " +
      core::data_set_dir(kMpgtDataSet) + "), or use nlg: template");
}

// The corpus the settings point at: corpus_dir, else $ARI_MPGT_DIR; none when neither is set. A
// folder that is named but missing is an error rather than a quiet run without the corpus.
std::optional<MpgtCorpus> load_pointed_corpus(const DialogueConfig& config) {
  std::string dir = config.corpus_dir;
  std::string named_by = field_name(config, "corpus_dir");
  if (dir.empty()) {
    dir = mpgt_dir_from_environment();
    named_by = "ARI_MPGT_DIR (" + named_by + " is empty)";
  }
  if (dir.empty()) {
    if (config.nlg == NlgMode::kRetrieval) {
      refuse_retrieval_without_corpus(config);
    }
    return std::nullopt;
  }
  std::error_code error;
  if (!std::filesystem::is_directory(dir, error)) {
    throw core::ConfigError(
        named_by + ": " + dir +
        ": expected the folder of the MPGT corpus's convo*.txt files, got " +
        (std::filesystem::exists(dir, error) ? "a file" : "nothing (no such path)"));
  }
  return load_mpgt_corpus(dir);
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
  DialogueConfig config =
      with_paths_in(std::filesystem::path(file_path).parent_path().string(),
                    core::read_fields<DialogueConfig>(core::YamlMap::load_file(file_path)));
  config.settings_file = file_path;
  return config;
}

std::unique_ptr<DialogueSetup> DialogueSetup::create(const DialogueConfig& config) {
  auto setup = std::make_unique<DialogueSetup>();
  setup->config = core::validated(config);
  setup->domain = Domain::load(config.domain_file);
  setup->model = UserModel::load(config.model_file);
  for (const std::string& role : config.users.roles) {
    setup->model.role(role, config.model_file);
  }
  setup->corpus = load_pointed_corpus(config);
  setup->nlg = std::make_unique<Nlg>(NlgTemplates::load(config.templates_file),
                                     setup->corpus_or_null(), config.nlg);
  setup->errors =
      std::make_unique<ErrorModel>(config.errors, setup->domain, setup->nlg->vocabulary());
  setup->timing = std::make_unique<TurnTiming>(config.timing);
  return setup;
}

}  // namespace ari_social_sim::dialogue
