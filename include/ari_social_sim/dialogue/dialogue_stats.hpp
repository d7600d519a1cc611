#pragma once

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/dialogue/mpgt_corpus.hpp"

namespace ari_social_sim::dialogue {

/// The addressee heuristic for MPGT, which does not label addressees: a human utterance is
/// addressed to the other human when the next utterance is by another human (neither ARI nor the
/// same speaker) and its text does not name ARI. On MPGT it labels 174 of 768 utterances (22.7 %;
/// docs/dialogue.md).
bool is_human_to_human(const CorpusDialogue& dialogue, size_t index);

/// Normalised counts; keys in name order.
using Distribution = std::map<std::string, double>;

/// How many utterances at the end of a dialogue count as its closing.
inline constexpr size_t kClosingUtterances = 3;

/// Figures compared between generated dialogues and the corpus (docs/dialogue.md).
struct DialogueStats {
  size_t dialogues{0};
  size_t utterances{0};
  size_t human_utterances{0};
  Distribution first_intents;      ///< first intent (or none) of human utterances
  Distribution all_intents;        ///< every act of human utterances
  double human_to_human_share{0};  ///< by is_human_to_human, over all utterances
  std::vector<size_t> lengths;     ///< utterances per dialogue, sorted
  /// Distinct goal targets per dialogue among its goal labels of any kind (G, AG, CG), mean.
  double mean_goal_targets{0};
  /// Closings: share of dialogues with a bye() act, or with a thank() act, by anyone in their
  /// last kClosingUtterances utterances.
  double bye_closing_share{0};
  double thank_closing_share{0};

  double mean_length() const;
  /// Length at quantile q in [0, 1] (nearest rank).
  size_t length_quantile(double q) const;
};

DialogueStats compute_stats(const std::vector<CorpusDialogue>& dialogues);

/// How varied the words are for one act: the distinct texts among the utterances of one side
/// (ARI or the humans) that start with that act.
struct ActVariety {
  bool robot{false};
  std::string first_act;  ///< in full (`request(location(toilet))`), `none` when unannotated
  size_t utterances{0};
  size_t distinct_texts{0};

  /// distinct_texts / utterances: 1 when no text repeats, 1 / utterances when one text is said.
  double ratio() const;
};

/// The variety of every (side, first act) of `dialogues`, humans first, then by utterances
/// (most first) and act name. Texts count as said (Utterance::text, before any error layer);
/// an utterance's text includes the words of its later acts.
std::vector<ActVariety> act_variety(const std::vector<CorpusDialogue>& dialogues);

/// Jensen-Shannon divergence with base-2 logarithms, in [0, 1]; keys missing on one side count 0.
double js_divergence(const Distribution& p, const Distribution& q);

}  // namespace ari_social_sim::dialogue
