#include "ari_social_sim/dialogue/dialogue_stats.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::dialogue {
namespace {

void normalise(Distribution& counts) {
  double total = 0.0;
  for (const auto& entry : counts) {
    total += entry.second;
  }
  if (total > 0.0) {
    for (auto& entry : counts) {
      entry.second /= total;
    }
  }
}

}  // namespace

bool is_human_to_human(const CorpusDialogue& dialogue, size_t index) {
  const auto& utterances = dialogue.utterances;
  const CorpusUtterance& u = utterances[index];
  if (u.is_robot() || index + 1 >= utterances.size()) {
    return false;
  }
  const CorpusUtterance& next = utterances[index + 1];
  return !next.is_robot() && next.speaker != u.speaker && u.text.find("ARI") == std::string::npos;
}

double DialogueStats::mean_length() const {
  if (lengths.empty()) {
    return 0.0;
  }
  double sum = 0.0;
  for (size_t length : lengths) {
    sum += static_cast<double>(length);
  }
  return sum / static_cast<double>(lengths.size());
}

size_t DialogueStats::length_quantile(double q) const {
  if (lengths.empty()) {
    return 0;
  }
  const double rank = std::ceil(q * static_cast<double>(lengths.size()));
  const size_t index = rank < 1.0 ? 0 : static_cast<size_t>(rank) - 1;
  return lengths[std::min(index, lengths.size() - 1)];
}

DialogueStats compute_stats(const std::vector<CorpusDialogue>& dialogues) {
  DialogueStats stats;
  size_t human_to_human = 0;
  for (const CorpusDialogue& dialogue : dialogues) {
    ++stats.dialogues;
    stats.lengths.push_back(dialogue.utterances.size());
    for (size_t i = 0; i < dialogue.utterances.size(); ++i) {
      const CorpusUtterance& u = dialogue.utterances[i];
      ++stats.utterances;
      if (u.is_robot()) {
        continue;
      }
      ++stats.human_utterances;
      stats.first_intents[u.first_intent()] += 1.0;
      for (const DialogueAct& act : u.acts) {
        stats.all_intents[act.intent] += 1.0;
      }
      human_to_human += is_human_to_human(dialogue, i) ? 1 : 0;
    }
  }
  normalise(stats.first_intents);
  normalise(stats.all_intents);
  stats.human_to_human_share = stats.utterances == 0 ? 0.0
                                                     : static_cast<double>(human_to_human) /
                                                           static_cast<double>(stats.utterances);
  std::sort(stats.lengths.begin(), stats.lengths.end());
  return stats;
}

double js_divergence(const Distribution& p, const Distribution& q) {
  // JS(P, Q) = (KL(P || M) + KL(Q || M)) / 2 with M = (P + Q) / 2.
  Distribution keys = p;
  for (const auto& entry : q) {
    keys[entry.first] += 0.0;
  }
  double divergence = 0.0;
  for (const auto& entry : keys) {
    const auto pi = p.find(entry.first);
    const auto qi = q.find(entry.first);
    const double a = pi == p.end() ? 0.0 : pi->second;
    const double b = qi == q.end() ? 0.0 : qi->second;
    const double m = 0.5 * (a + b);
    if (a > 0.0) {
      divergence += 0.5 * a * std::log2(a / m);
    }
    if (b > 0.0) {
      divergence += 0.5 * b * std::log2(b / m);
    }
  }
  return divergence;
}

}  // namespace ari_social_sim::dialogue
