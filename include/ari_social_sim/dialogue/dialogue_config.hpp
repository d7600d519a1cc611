#pragma once

#include <memory>
#include <string>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/domain.hpp"
#include "ari_social_sim/dialogue/error_model.hpp"
#include "ari_social_sim/dialogue/mpgt_corpus.hpp"
#include "ari_social_sim/dialogue/nlg.hpp"
#include "ari_social_sim/dialogue/reward.hpp"
#include "ari_social_sim/dialogue/turn_timing.hpp"
#include "ari_social_sim/dialogue/user_model.hpp"
#include "ari_social_sim/dialogue/user_simulation.hpp"

namespace ari_social_sim::dialogue {

/// The dialogue simulation's settings (config/dialogue/simulation.yaml). File paths are relative
/// to the settings file; an empty corpus_dir means default_mpgt_dir().
struct DialogueConfig {
  std::string domain_file{"hospital_domain.yaml"};
  std::string model_file{"mpgt_user_model.yaml"};
  std::string templates_file{"nlg_templates.yaml"};
  std::string corpus_dir;
  NlgMode nlg{NlgMode::kRetrieval};
  UserSimulationConfig users;
  ErrorModelConfig errors;
  TurnTimingConfig timing;
  RewardConfig reward;

  /// Reads a settings file (every field optional, unknown ones are errors) and resolves paths.
  /// Throws core::ConfigError naming the file and field.
  static DialogueConfig load(const std::string& file_path);
  /// Defaults with the data files of `config_dir` (the source tree's config/dialogue).
  static DialogueConfig defaults(const std::string& config_dir);
};

/// `<source>/config/dialogue` (ARI_DIALOGUE_CONFIG_DIR at build time).
std::string default_dialogue_config_dir();

/// The constant parts every dialogue shares (MuJoCo's model to the episodes' data): domain, user
/// model, corpus, NLG, error layer, timing. Loading validates every file; errors name the file.
struct DialogueSetup {
  DialogueConfig config;
  Domain domain;
  UserModel model;
  MpgtCorpus corpus;
  std::unique_ptr<Nlg> nlg;
  std::unique_ptr<ErrorModel> errors;
  std::unique_ptr<TurnTiming> timing;

  static std::unique_ptr<DialogueSetup> create(const DialogueConfig& config);
};

}  // namespace ari_social_sim::dialogue
