#include "ari_social_sim/dialogue/goal.hpp"

#include <algorithm>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::dialogue {
namespace {

std::string kind_text(GoalLabelKind kind) {
  switch (kind) {
    case GoalLabelKind::kStated:
      return "G";
    case GoalLabelKind::kAnswered:
      return "AG";
    case GoalLabelKind::kClosed:
      return "CG";
  }
  return "G";
}

// Reads `LP+RC` into roles in first-seen order, without repeats; false if a code is unknown.
bool read_owners(const std::string& text, std::vector<std::string>& owners) {
  std::string code;
  const std::string padded = text + "+";
  for (char c : padded) {
    if (c == '+' || c == '_') {
      const std::string role = mpgt_role(trim(code));
      if (role.empty() || role == "ARI") {
        return false;
      }
      if (std::find(owners.begin(), owners.end(), role) == owners.end()) {
        owners.push_back(role);
      }
      code.clear();
      continue;
    }
    code += c;
  }
  return !owners.empty();
}

bool read_label(const std::string& text, GoalLabel& label) {
  const size_t open = text.find('(');
  const size_t comma = text.find(',');
  if (open == std::string::npos || comma == std::string::npos || comma < open) {
    return false;
  }
  const std::string kind = trim(text.substr(0, open));
  if (kind == "G") {
    label.kind = GoalLabelKind::kStated;
  } else if (kind == "AG") {
    label.kind = GoalLabelKind::kAnswered;
  } else if (kind == "CG") {
    label.kind = GoalLabelKind::kClosed;
  } else {
    return false;
  }
  if (!read_owners(text.substr(open + 1, comma - open - 1), label.goal.owners)) {
    return false;
  }
  std::string predicate = trim(text.substr(comma + 1));
  if (!predicate.empty() && predicate.back() == ')') {
    predicate.pop_back();  // the label's own closing bracket
  }
  try {
    const std::vector<DialogueAct> parsed = parse_acts(predicate, "goal", true);
    if (parsed.size() != 1) {
      return false;
    }
    label.goal.predicate = parsed[0].intent;
    // `go_to` occurs once for `go-to`.
    std::replace(label.goal.predicate.begin(), label.goal.predicate.end(), '_', '-');
    label.goal.object = parsed[0].path();
  } catch (const core::ConfigError&) {
    return false;
  }
  return true;
}

}  // namespace

std::string Goal::owner_text() const {
  std::string text;
  for (const std::string& owner : owners) {
    text += (text.empty() ? "" : "+") + owner;
  }
  return text;
}

std::string Goal::predicate_text() const {
  return DialogueAct{predicate, object, ""}.to_string();
}

bool Goal::same_target(const Goal& other) const {
  return predicate == other.predicate && object == other.object;
}

std::string GoalLabel::to_string() const {
  return kind_text(kind) + "(" + goal.owner_text() + ", " + goal.predicate_text() + ")";
}

std::vector<GoalLabel> parse_mpgt_goal_labels(const std::string& text, int* skipped) {
  std::vector<GoalLabel> labels;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(';', start), text.size());
    const std::string part = trim(text.substr(start, end - start));
    start = end + 1;
    if (part.empty()) {
      continue;
    }
    GoalLabel label;
    if (read_label(part, label)) {
      labels.push_back(std::move(label));
    } else if (skipped != nullptr) {
      ++*skipped;
    }
  }
  return labels;
}

std::string mpgt_role(const std::string& code) {
  if (code == "LP" || code == "RP") {
    return "patient";
  }
  if (code == "LC" || code == "RC") {
    return "companion";
  }
  if (code == "ARI") {
    return "ARI";
  }
  return "";
}

}  // namespace ari_social_sim::dialogue
