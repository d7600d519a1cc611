#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/dialogue/domain.hpp"
#include "ari_social_sim/dialogue/utterance.hpp"

namespace ari_social_sim::dialogue {

/// Rates of the error layer shared by every mode (docs/dialogue.md). Defaults: a mild setting
/// between PyDial's 0 % and 15 % semantic error rates.
struct ErrorModelConfig {
  double semantic_error_rate{0.05};
  double intent_share{0.2};  // PyDial 0.2
  double slot_share{0.3};    // PyDial 0.3
  double word_error_rate{0.10};
  double drop_rate{0.02};
  double misattribution_rate{0.03};
  double wrong_addressee_rate{0.05};
  double confidence_noise{0.05};

  template <class V>
  void visit(V& v) {
    const core::Bounds probability = core::between(0.0, 1.0);
    v.field("semantic_error_rate", semantic_error_rate, "P(one act of an utterance is confused)",
            probability);
    v.field("intent_share", intent_share, "of confusions: the intent is replaced", probability);
    v.field("slot_share", slot_share, "of confusions: a slot is replaced; the rest: the value",
            probability);
    v.rule("slot_share", intent_share + slot_share <= 1.0, "intent_share + slot_share <= 1",
           core::number_text(intent_share + slot_share));
    v.field("word_error_rate", word_error_rate, "target WER: (S + D + I) / words", probability);
    v.field("drop_rate", drop_rate, "P(an utterance is not perceived at all)", probability);
    v.field("misattribution_rate", misattribution_rate, "P(attributed to another human)",
            probability);
    v.field("wrong_addressee_rate", wrong_addressee_rate,
            "P(addressee perceived wrongly: ARI <-> the others)", probability);
    v.field("confidence_noise", confidence_noise,
            "standard deviation of the confidence around 1 - observed WER", probability);
  }

  /// Throws core::ConfigError naming the field when a rate is outside [0, 1] or
  /// intent_share + slot_share > 1.
  void validate() const;
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
