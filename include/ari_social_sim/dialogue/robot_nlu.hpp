#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/dialogue/domain.hpp"
#include "ari_social_sim/dialogue/exemplar_index.hpp"
#include "ari_social_sim/dialogue/mpgt_corpus.hpp"
#include "ari_social_sim/dialogue/nlg.hpp"

namespace ari_social_sim::dialogue {

/// Understanding of what ARI says, so that the simulated humans can react to a real robot's words
/// (the /tts text of modes 1 and 3) and not only to acts. Nearest neighbour over exemplars: every
/// robot template realised for every act ARI can say in the domain (greetings, closings, the
/// answer to each goal), plus MPGT's ARI utterances with their annotated acts. Each sentence of
/// the text is matched on its own (TF-IDF weighted cosine of word sets), so "Hello. The toilets
/// are on the left." gives greet(); inform(directions(toilet)). A sentence below
/// `min_similarity` is not understood and adds no act. Answers are put in the domain's form
/// (the corpus's inform(location(cafe)) becomes the domain's inform(directions(cafe))) so that
/// they resolve the humans' goals. Deterministic; holds no reference to its inputs.
class RobotNlu {
 public:
  /// `corpus` may be null (templates only).
  RobotNlu(const Nlg& nlg, const Domain& domain, const MpgtCorpus* corpus,
           double min_similarity = 0.3);

  /// The acts of `text`, in the order said, without repeats; empty when nothing is understood.
  std::vector<DialogueAct> understand(const std::string& text) const;

  /// An inform whose path ends with a domain object's path, as the domain's answer to that
  /// object's goal (inform(location(cafe)) -> inform(directions(cafe))); other acts unchanged.
  DialogueAct in_domain_form(const DialogueAct& act) const;

  /// Number of exemplars (for tests and logs).
  size_t exemplar_count() const { return index_.size(); }

 private:
  void add_exemplar(const std::string& text, const std::vector<DialogueAct>& acts);

  const Domain* domain_;
  double min_similarity_;
  ExemplarIndex index_;
};

}  // namespace ari_social_sim::dialogue
