#pragma once

#include <memory>
#include <optional>
#include <string>

#include "ari_social_sim/core/config_fields.hpp"
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
/// to the settings file. The MPGT corpus is optional: corpus_dir, else $ARI_MPGT_DIR, else none.
struct DialogueConfig {
  std::string domain_file{"hospital_domain.yaml"};
  std::string model_file{"mpgt_user_model.yaml"};
  std::string templates_file{"nlg_templates.yaml"};
  std::string corpus_dir;
  NlgMode nlg{NlgMode::kTemplate};
  UserSimulationConfig users;
  ErrorModelConfig errors;
  TurnTimingConfig timing;
  RewardConfig reward;
  /// The settings file load() read, or "" for settings made in code; messages name it. Not a
  /// field of the file.
  std::string settings_file;

  template <class V>
  void visit(V& v) {
    v.field("domain_file", domain_file,
            "the domain: what the humans ask about, what ARI can tell them");
    v.field("model_file", model_file, "the user model fitted to MPGT (fit_dialogue_model)");
    v.field("templates_file", templates_file, "the NLG templates and slot words");
    v.field("corpus_dir", corpus_dir,
            "the MPGT corpus's folder, optional; empty: $ARI_MPGT_DIR when set, else no corpus");
    v.choice("nlg", nlg,
             "template: templates per act; retrieval: a real MPGT utterance with the same acts, "
             "templates when the corpus has none (needs the corpus)",
             kNlgModes);
    v.section("users", users, "the simulated humans' behaviour beyond the corpus");
    v.section("errors", errors, "the error layer between the humans and ARI");
    v.section("timing", timing, "turn-taking times");
    v.section("reward", reward, "episode reward and turn cap, in robot turns");
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
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
  /// Loaded only when pointed at (corpus_dir, else $ARI_MPGT_DIR); the templates do without it.
  std::optional<MpgtCorpus> corpus;
  std::unique_ptr<Nlg> nlg;
  std::unique_ptr<ErrorModel> errors;
  std::unique_ptr<TurnTiming> timing;

  /// Throws core::ConfigError naming the settings file and field on a bad file, a corpus folder
  /// that is missing, or `nlg: retrieval` with no corpus pointed at.
  static std::unique_ptr<DialogueSetup> create(const DialogueConfig& config);

  /// The corpus for Nlg and RobotNlu: null when none was pointed at.
  const MpgtCorpus* corpus_or_null() const { return corpus ? &*corpus : nullptr; }
};

}  // namespace ari_social_sim::dialogue
