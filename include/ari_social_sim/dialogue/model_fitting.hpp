#pragma once

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/dialogue/mpgt_corpus.hpp"
#include "ari_social_sim/dialogue/user_model.hpp"

namespace ari_social_sim::dialogue {

/// How fit_user_model pools sparse data, so that the tables carry the general behaviour of the
/// 29 conversations rather than their quirks (the project's own choice).
struct FitOptions {
  unsigned min_row_count{10};
  double prior_weight{5.0};

  template <class V>
  void visit(V& v) {
    v.field("min_row_count", min_row_count,
            "contexts seen fewer times use the `*` row (the role's marginal)", core::positive());
    v.field("prior_weight", prior_weight,
            "pseudo-counts pulling P(to other | intent) to the role's mean", core::non_negative());
  }

  /// Throws core::ConfigError when min_row_count is 0 or prior_weight is negative.
  void validate() const;
};

/// Fits the user model to MPGT: for every human utterance its first intent (or `none`) is counted
/// under its context, the previous utterance: ARI's first intent (after_robot), the other human's
/// (after_other), its own (after_self), or the dialogue start (opening). Addressees come from
/// is_human_to_human (the corpus does not label them). Roles are those of the speakers (patient,
/// companion). Goal counts are distinct G-label targets per dialogue.
UserModel fit_user_model(const MpgtCorpus& corpus, const FitOptions& options);

}  // namespace ari_social_sim::dialogue
