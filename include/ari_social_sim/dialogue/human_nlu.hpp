#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/dialogue/domain.hpp"
#include "ari_social_sim/dialogue/exemplar_index.hpp"
#include "ari_social_sim/dialogue/mpgt_corpus.hpp"
#include "ari_social_sim/dialogue/nlg.hpp"

namespace ari_social_sim::dialogue {

/// ARI's understanding of what the people say, for a dialogue that hears them through speech
/// recognition instead of the simulated perceptions' acts. Nearest neighbour over exemplars
/// (ExemplarIndex): every human template realised for every act a person says in the domain
/// (greetings, thanks, repeats, closings) and for each goal's requests, plus MPGT's human
/// utterances with their annotated acts. Each sentence is matched on its own; one below
/// `min_similarity` adds no act. Deterministic; holds no reference to its inputs.
class HumanNlu {
 public:
  /// `corpus` may be null (templates only).
  HumanNlu(const Nlg& nlg, const Domain& domain, const MpgtCorpus* corpus,
           double min_similarity = 0.3);

  /// The acts of `text`, in the order said, without repeats; empty when nothing is understood.
  std::vector<DialogueAct> understand(const std::string& text) const {
    return index_.understand(text, min_similarity_);
  }

  size_t exemplar_count() const { return index_.size(); }

 private:
  double min_similarity_;
  ExemplarIndex index_;
};

}  // namespace ari_social_sim::dialogue
