#include "ari_social_sim/dialogue/model_fitting.hpp"

#include <set>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/dialogue/dialogue_stats.hpp"

namespace ari_social_sim::dialogue {
namespace {

// Intent counts under each context, `*` holding the total over contexts.
using Counts = std::map<std::string, double>;
using TableCounts = std::map<std::string, Counts>;

struct RoleCounts {
  Counts opening;
  TableCounts after_robot;
  TableCounts after_other;
  TableCounts after_self;
  Counts to_other;  // human-to-human utterances per intent
  Counts by_intent;
  double floor_kept{0};
  double floor_chances{0};
};

IntentDistribution to_distribution(const Counts& counts) {
  IntentDistribution d;
  double total = 0.0;
  for (const auto& entry : counts) {
    total += entry.second;
  }
  for (const auto& entry : counts) {
    d.intents.push_back(entry.first);
    d.probabilities.push_back(entry.second / total);
  }
  d.count = static_cast<int>(total);
  return d;
}

void add(TableCounts& table, const std::string& context, const std::string& intent) {
  table[context][intent] += 1.0;
  table[kAnyContext][intent] += 1.0;
}

ConditionalTable to_table(const TableCounts& counts, unsigned min_row_count) {
  ConditionalTable table;
  for (const auto& [context, row] : counts) {
    double total = 0.0;
    for (const auto& entry : row) {
      total += entry.second;
    }
    if (context == kAnyContext || total >= min_row_count) {
      table.rows[context] = to_distribution(row);
    }
  }
  return table;
}

// Everything fit_user_model counts over the corpus before turning counts into probabilities.
struct CorpusCounts {
  std::map<std::string, RoleCounts> roles;
  double robot_opens{0};
  double responder_same{0};
  double responder_chances{0};
  double joint_goals{0};
  double goals_total{0};
  std::map<unsigned, double> goal_counts;  // dialogues per number of distinct goals
};

// Distinct goal targets stated in `u` and whether the first statement of each is joint.
void count_stated_goals(const CorpusUtterance& u, std::set<std::string>& targets,
                        CorpusCounts& counts) {
  for (const GoalLabel& label : u.goals) {
    if (label.kind != GoalLabelKind::kStated) {
      continue;
    }
    if (targets.insert(label.goal.predicate_text()).second) {
      counts.goals_total += 1.0;
      counts.joint_goals += label.goal.is_joint() ? 1.0 : 0.0;
    }
  }
}

// The human utterance `i` of `dialogue`: its intent in the context of the turn before it, whom it
// addresses and whether its speaker keeps the floor. `last_human_speaker` is the human ARI was
// last answering, updated when the next turn is ARI's.
void count_human_utterance(const CorpusDialogue& dialogue, size_t i,
                           std::string& last_human_speaker, CorpusCounts& corpus_counts) {
  const auto& utterances = dialogue.utterances;
  const CorpusUtterance& u = utterances[i];
  RoleCounts& counts = corpus_counts.roles[u.role];
  const std::string intent = u.first_intent();
  counts.by_intent[intent] += 1.0;
  if (i == 0) {
    counts.opening[intent] += 1.0;
  } else {
    const CorpusUtterance& previous = utterances[i - 1];
    if (previous.is_robot()) {
      add(counts.after_robot, previous.first_intent(), intent);
      if (!last_human_speaker.empty()) {
        corpus_counts.responder_chances += 1.0;
        corpus_counts.responder_same += u.speaker == last_human_speaker ? 1.0 : 0.0;
      }
    } else if (previous.speaker != u.speaker) {
      add(counts.after_other, previous.first_intent(), intent);
    } else {
      add(counts.after_self, previous.first_intent(), intent);
    }
  }
  const bool to_other = is_human_to_human(dialogue, i);
  counts.to_other[intent] += to_other ? 1.0 : 0.0;
  if (!to_other && i + 1 < utterances.size()) {
    counts.floor_chances += 1.0;
    counts.floor_kept += utterances[i + 1].speaker == u.speaker ? 1.0 : 0.0;
  }
  if (i + 1 < utterances.size() && utterances[i + 1].is_robot()) {
    last_human_speaker = u.speaker;
  }
}

void count_dialogue(const CorpusDialogue& dialogue, CorpusCounts& counts) {
  const auto& utterances = dialogue.utterances;
  if (utterances.empty()) {
    return;
  }
  counts.robot_opens += utterances.front().is_robot() ? 1.0 : 0.0;
  std::string last_human_speaker;
  std::set<std::string> targets;
  for (size_t i = 0; i < utterances.size(); ++i) {
    count_stated_goals(utterances[i], targets, counts);
    if (!utterances[i].is_robot()) {
      count_human_utterance(dialogue, i, last_human_speaker, counts);
    }
  }
  counts.goal_counts[static_cast<unsigned>(std::max<size_t>(targets.size(), 1))] += 1.0;
}

RoleModel fit_role(const RoleCounts& counts, const FitOptions& options) {
  RoleModel role;
  role.opening = to_distribution(counts.opening.empty() ? counts.by_intent : counts.opening);
  role.after_robot = to_table(counts.after_robot, options.min_row_count);
  role.after_other = to_table(counts.after_other, options.min_row_count);
  role.after_self = to_table(counts.after_self, options.min_row_count);
  role.keep_floor = counts.floor_chances > 0 ? counts.floor_kept / counts.floor_chances : 0.0;
  // P(to other | intent), shrunk towards the role's mean by prior_weight pseudo-counts.
  double to_other_total = 0.0;
  double total = 0.0;
  for (const auto& [intent, n] : counts.by_intent) {
    to_other_total += counts.to_other.at(intent);
    total += n;
  }
  const double mean = total > 0 ? to_other_total / total : 0.0;
  role.to_other[kAnyContext] = mean;
  for (const auto& [intent, n] : counts.by_intent) {
    role.to_other[intent] =
        (counts.to_other.at(intent) + options.prior_weight * mean) / (n + options.prior_weight);
  }
  return role;
}

}  // namespace

void FitOptions::validate() const {
  core::check_fields(*this, "FitOptions");
}

UserModel fit_user_model(const MpgtCorpus& corpus, const FitOptions& options) {
  options.validate();
  CorpusCounts counts;
  for (const CorpusDialogue& dialogue : corpus.dialogues) {
    count_dialogue(dialogue, counts);
  }

  UserModel model;
  const double dialogues = static_cast<double>(corpus.dialogues.size());
  model.robot_opens = dialogues > 0 ? counts.robot_opens / dialogues : 0.5;
  model.same_responder =
      counts.responder_chances > 0 ? counts.responder_same / counts.responder_chances : 0.5;
  model.goals.joint_share = counts.goals_total > 0 ? counts.joint_goals / counts.goals_total : 0.0;
  for (const auto& [count, n] : counts.goal_counts) {
    model.goals.counts.push_back(count);
    model.goals.probabilities.push_back(n / dialogues);
  }
  for (const auto& [name, role_counts] : counts.roles) {
    model.roles[name] = fit_role(role_counts, options);
  }
  model.provenance = "MPGT, " + std::to_string(corpus.dialogues.size()) + " conversations, " +
                     std::to_string(corpus.utterance_count()) + " utterances; min_row_count " +
                     std::to_string(options.min_row_count) + ", prior_weight " +
                     std::to_string(options.prior_weight);
  return model;
}

}  // namespace ari_social_sim::dialogue
