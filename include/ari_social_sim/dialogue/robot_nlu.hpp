#pragma once

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/dialogue/domain.hpp"
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
  size_t exemplar_count() const { return exemplars_.size(); }

 private:
  struct Exemplar {
    std::map<int, double> weights;  ///< word id -> TF-IDF weight, L2-normalised
    std::vector<DialogueAct> acts;
  };
  struct Match {
    double similarity{0.0};
    const Exemplar* exemplar{nullptr};
  };

  void add_exemplar(const std::string& text, const std::vector<DialogueAct>& acts);
  void weigh_exemplars();
  std::map<int, double> weigh(const std::vector<std::string>& words) const;
  Match best_match(const std::string& sentence) const;

  const Domain* domain_;
  double min_similarity_;
  std::map<std::string, int> word_ids_;
  std::vector<double> idf_;
  std::vector<std::vector<std::string>> exemplar_words_;
  std::vector<Exemplar> exemplars_;
};

/// Lower-case words of `text` without punctuation (apostrophes kept: "there's").
std::vector<std::string> normalised_words(const std::string& text);
/// `text` cut into sentences at '.', '?' and '!' (each kept with its words only).
std::vector<std::string> split_sentences(const std::string& text);

}  // namespace ari_social_sim::dialogue
