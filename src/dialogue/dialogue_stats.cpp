#include "ari_social_sim/dialogue/dialogue_stats.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

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

// Whether any of the last kClosingUtterances utterances of `dialogue` has an act of `intent`.
bool closes_with(const CorpusDialogue& dialogue, const std::string& intent) {
  const auto& utterances = dialogue.utterances;
  const size_t first =
      utterances.size() > kClosingUtterances ? utterances.size() - kClosingUtterances : 0;
  for (size_t i = first; i < utterances.size(); ++i) {
    for (const DialogueAct& act : utterances[i].acts) {
      if (act.intent == intent) {
        return true;
      }
    }
  }
  return false;
}

size_t goal_targets(const CorpusDialogue& dialogue) {
  std::set<std::string> targets;
  for (const CorpusUtterance& u : dialogue.utterances) {
    for (const GoalLabel& label : u.goals) {
      targets.insert(label.goal.predicate_text());
    }
  }
  return targets.size();
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
    stats.mean_goal_targets += static_cast<double>(goal_targets(dialogue));
    stats.bye_closing_share += closes_with(dialogue, "bye") ? 1.0 : 0.0;
    stats.thank_closing_share += closes_with(dialogue, "thank") ? 1.0 : 0.0;
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
  if (stats.dialogues > 0) {
    const double n = static_cast<double>(stats.dialogues);
    stats.mean_goal_targets /= n;
    stats.bye_closing_share /= n;
    stats.thank_closing_share /= n;
  }
  return stats;
}

double ActVariety::ratio() const {
  return utterances == 0 ? 0.0
                         : static_cast<double>(distinct_texts) / static_cast<double>(utterances);
}

std::vector<ActVariety> act_variety(const std::vector<CorpusDialogue>& dialogues) {
  struct Texts {
    size_t utterances{0};
    std::set<std::string> distinct;
  };
  std::map<std::pair<bool, std::string>, Texts> by_act;
  for (const CorpusDialogue& dialogue : dialogues) {
    for (const CorpusUtterance& u : dialogue.utterances) {
      const std::string first_act = u.acts.empty() ? "none" : u.acts.front().to_string();
      Texts& texts = by_act[{u.is_robot(), first_act}];
      ++texts.utterances;
      texts.distinct.insert(u.text);
    }
  }
  std::vector<ActVariety> variety;
  variety.reserve(by_act.size());
  for (const auto& [key, texts] : by_act) {
    variety.push_back({key.first, key.second, texts.utterances, texts.distinct.size()});
  }
  std::sort(variety.begin(), variety.end(), [](const ActVariety& a, const ActVariety& b) {
    return std::make_tuple(a.robot, b.utterances, a.first_act) <
           std::make_tuple(b.robot, a.utterances, b.first_act);
  });
  return variety;
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
