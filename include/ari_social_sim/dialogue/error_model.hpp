#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/domain.hpp"
#include "ari_social_sim/dialogue/utterance.hpp"

namespace ari_social_sim::dialogue {

/// Rates of the error layer shared by every mode (docs/dialogue.md). Defaults: a mild setting
/// between PyDial's 0 % and 15 % semantic error rates.
struct ErrorModelConfig {
  double semantic_error_rate{0.05};   ///< P(one act of an utterance is confused)
  double intent_share{0.2};           ///< of confusions: the intent is replaced (PyDial 0.2)
  double slot_share{0.3};             ///< ... a slot is replaced (PyDial 0.3); rest: the value
  double word_error_rate{0.10};       ///< target WER: (S + D + I) / words
  double drop_rate{0.02};             ///< P(utterance not perceived at all)
  double misattribution_rate{0.03};   ///< P(attributed to another human)
  double wrong_addressee_rate{0.05};  ///< P(addressee perceived wrongly: ARI <-> the others)
  double confidence_noise{0.05};      ///< sd of the confidence around 1 - observed WER

  template <class V>
  void visit(V& v) {
    v("semantic_error_rate", semantic_error_rate, core::between(0.0, 1.0));
    v("intent_share", intent_share, core::between(0.0, 1.0));
    v("slot_share", slot_share, core::between(0.0, 1.0));
    v("word_error_rate", word_error_rate, core::between(0.0, 1.0));
    v("drop_rate", drop_rate, core::between(0.0, 1.0));
    v("misattribution_rate", misattribution_rate, core::between(0.0, 1.0));
    v("wrong_addressee_rate", wrong_addressee_rate, core::between(0.0, 1.0));
    v("confidence_noise", confidence_noise, core::between(0.0, 1.0));
  }
  /// Throws core::ConfigError naming the field when a rate is outside [0, 1] or
  /// intent_share + slot_share > 1.
  void validate() const;
  /// Reads the fields present in `map` (all optional), then validates.
  static ErrorModelConfig from_yaml(const core::YamlMap& map);
};

/// Turns a true human utterance into what ARI perceives. Seeded by the caller's generator; never
/// throws once constructed.
class ErrorModel {
 public:
  /// `humans`: every human role of the dialogue (for misattribution and addressee errors).
  ErrorModel(ErrorModelConfig config, const Domain& domain, std::vector<std::string> vocabulary);

  Perception apply(const Utterance& utterance, const std::vector<std::string>& humans,
                   core::Rng& rng) const;

  /// Word-level noise at the target WER; returns the number of errors made.
  int corrupt_words(std::string& text, core::Rng& rng) const;
  /// One semantic confusion of one act (intent, slot or value).
  void confuse(std::vector<DialogueAct>& acts, core::Rng& rng) const;

  const ErrorModelConfig& config() const { return config_; }

 private:
  ErrorModelConfig config_;
  std::vector<std::string> slots_;
  std::vector<std::string> values_;
  std::vector<std::string> vocabulary_;
};

}  // namespace ari_social_sim::dialogue
