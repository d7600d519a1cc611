#pragma once

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/dialogue/dialogue_act.hpp"

namespace ari_social_sim::dialogue {

/// Nearest-neighbour understanding of text: exemplar sentences with the acts they say, matched by
/// the TF-IDF weighted cosine of their word sets. What RobotNlu understands ARI's words by and
/// HumanNlu the humans' words by. Add every exemplar, then finish() once; deterministic.
class ExemplarIndex {
 public:
  /// An exemplar; a text without words is skipped. Only before finish().
  void add(const std::string& text, std::vector<DialogueAct> acts);
  /// Weighs the exemplars (inverse document frequency over all of them).
  void finish();

  /// The acts of `text`, sentence by sentence in the order said, without repeats: each sentence
  /// takes the acts of its most similar exemplar, none when below `min_similarity`.
  std::vector<DialogueAct> understand(const std::string& text, double min_similarity) const;

  size_t size() const { return exemplars_.size(); }

 private:
  struct Exemplar {
    std::map<int, double> weights;  ///< word id -> TF-IDF weight, L2-normalised
    std::vector<DialogueAct> acts;
  };
  struct Match {
    double similarity{0.0};
    const Exemplar* exemplar{nullptr};
  };

  std::map<int, double> weigh(const std::vector<std::string>& words) const;
  Match best_match(const std::string& sentence) const;

  std::map<std::string, int> word_ids_;
  std::vector<double> idf_;
  std::vector<std::vector<std::string>> exemplar_words_;  ///< until finish()
  std::vector<Exemplar> exemplars_;
};

/// Lower-case words of `text` without punctuation (apostrophes kept: "there's").
std::vector<std::string> normalised_words(const std::string& text);
/// `text` cut into sentences at '.', '?' and '!' (each kept with its words only).
std::vector<std::string> split_sentences(const std::string& text);

}  // namespace ari_social_sim::dialogue
