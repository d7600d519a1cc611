#pragma once

#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::audio {

/// How speech_recognition_node runs: its private parameters, listed once in visit
/// (config_fields.hpp; docs/parameters.md is generated from it).
struct SpeechRecognitionRunConfig {
  /// What the recogniser listens for: the sentences of the dialogue domain (and of the scenario)
  /// as a trigram model, or pocketsphinx's general English model.
  enum class LanguageModel { kDomain, kGeneral };
  static constexpr core::Choice<LanguageModel> kLanguageModels[] = {
      {LanguageModel::kDomain, "domain"}, {LanguageModel::kGeneral, "general"}};

  LanguageModel language_model{LanguageModel::kDomain};
  std::string domain;
  std::string templates;
  std::string scenario;
  int scenario_line_weight{100};
  double voice_separation_deg{20.0};
  double voice_range_m{1.0};

  template <class V>
  void visit(V& v) {
    v.choice("language_model", language_model,
             "domain: a trigram model of what the dialogue's people (and the scenario's) say; "
             "general: pocketsphinx's general US English model",
             kLanguageModels);
    v.field("domain", domain,
            "the dialogue domain whose objects fill the templates; empty: the package's "
            "config/dialogue/hospital_domain.yaml");
    v.field("templates", templates,
            "the NLG templates whose human sentences the model learns; empty: the package's "
            "config/dialogue/nlg_templates.yaml");
    v.field("scenario", scenario,
            "a scenario file whose humans' scripted lines join the model's sentences; empty: none");
    v.field("scenario_line_weight", scenario_line_weight,
            "how many of the domain's sentences each scenario line counts as in the model: the "
            "lines a scene's people say are what its recogniser should expect most",
            core::Bounds{1.0, 10000.0});
    v.field("voice_separation", voice_separation_deg,
            "degrees: an utterance from farther than this from every known voice is a new voice",
            core::Bounds{1.0, 180.0});
    v.field("voice_range", voice_range_m,
            "m from the array at which a voice's frame is placed (a direction has no distance)",
            core::Bounds{0.1, 10.0});
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
  /// Reads every field from a mapping (parameter server or file); unknown keys and out-of-range
  /// values throw core::ConfigError naming the parameter.
  static SpeechRecognitionRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::audio
