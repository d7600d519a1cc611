#include "ari_social_sim/dialogue/user_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/dialogue/dialogue_act.hpp"

namespace ari_social_sim::dialogue {
namespace {

constexpr double kSumTolerance = 1e-6;
constexpr double kScale = 1e6;  // probabilities are written with 6 decimals

bool is_intent_or_none(const std::string& intent) {
  return intent == kNoIntent || is_known_intent(intent);
}

void check_intent(const core::YamlMap& map, const std::string& key, const std::string& intent,
                  bool allow_any) {
  if (!is_intent_or_none(intent) && !(allow_any && intent == kAnyContext)) {
    map.fail(key,
             std::string("an MPGT intent (request, inform, thank, ...) or none") +
                 (allow_any ? " or *" : ""),
             "unknown intent '" + intent + "'");
  }
}

// Reads `{count, next, p}` and checks it is a distribution over known intents.
IntentDistribution read_distribution(const core::YamlMap& map) {
  IntentDistribution d;
  d.count = static_cast<int>(map.optional<unsigned>("count", 0));
  d.intents = map.required<std::vector<std::string>>("next");
  d.probabilities = map.required<std::vector<double>>("p", core::between(0.0, 1.0));
  if (d.intents.empty() || d.intents.size() != d.probabilities.size()) {
    map.fail("p", "one probability per intent in next (" + std::to_string(d.intents.size()) + ")",
             std::to_string(d.probabilities.size()) + " values");
  }
  std::set<std::string> seen;
  for (const std::string& intent : d.intents) {
    check_intent(map, "next", intent, false);
    if (!seen.insert(intent).second) {
      map.fail("next", "each intent once", "'" + intent + "' twice");
    }
  }
  double sum = 0.0;
  for (double p : d.probabilities) {
    sum += p;
  }
  if (std::abs(sum - 1.0) > kSumTolerance) {
    char got[64];
    std::snprintf(got, sizeof(got), "a sum of %.6f", sum);
    map.fail("p", "probabilities summing to 1", got);
  }
  map.finish();
  return d;
}

ConditionalTable read_table(const core::YamlMap& map, const std::string& key) {
  ConditionalTable table;
  for (const core::YamlMap& row : map.list(key)) {
    const std::string after = row.required<std::string>("after");
    check_intent(row, "after", after, true);
    if (table.rows.count(after) > 0) {
      row.fail("after", "each context once", "'" + after + "' twice");
    }
    table.rows[after] = read_distribution(row);
  }
  if (table.rows.count(kAnyContext) == 0) {
    map.fail(key, "a row with after: '*' for contexts without a row of their own", "none");
  }
  return table;
}

RoleModel read_role(const core::YamlMap& map) {
  RoleModel role;
  role.keep_floor = map.required<double>("keep_floor", core::between(0.0, 1.0));
  role.opening = read_distribution(map.map("opening"));
  role.after_robot = read_table(map, "after_robot");
  role.after_other = read_table(map, "after_other");
  role.after_self = read_table(map, "after_self");
  const core::YamlMap to_other = map.map("to_other");
  const auto intents = to_other.required<std::vector<std::string>>("intents");
  const auto p = to_other.required<std::vector<double>>("p", core::between(0.0, 1.0));
  if (intents.size() != p.size()) {
    to_other.fail("p", "one probability per intent", std::to_string(p.size()) + " values");
  }
  for (size_t i = 0; i < intents.size(); ++i) {
    check_intent(to_other, "intents", intents[i], true);
    role.to_other[intents[i]] = p[i];
  }
  if (role.to_other.count(kAnyContext) == 0) {
    to_other.fail("intents", "an entry '*' for intents without one", "none");
  }
  to_other.finish();
  map.finish();
  return role;
}

// Probabilities rounded to 6 decimals, the largest absorbing the rounding so the sum is 1.
std::vector<long> rounded(const std::vector<double>& probabilities) {
  std::vector<long> units;
  long sum = 0;
  for (double p : probabilities) {
    units.push_back(std::lround(p * kScale));
    sum += units.back();
  }
  if (!units.empty()) {
    const auto largest = std::max_element(units.begin(), units.end()) - units.begin();
    units[largest] += static_cast<long>(kScale) - sum;
  }
  return units;
}

std::string quoted(const std::string& name) {
  return "\"" + name + "\"";
}

void write_list(std::ostream& out, const std::vector<std::string>& names) {
  out << "[";
  for (size_t i = 0; i < names.size(); ++i) {
    out << (i ? ", " : "") << quoted(names[i]);
  }
  out << "]";
}

void write_units(std::ostream& out, const std::vector<long>& units) {
  out << "[";
  char text[32];
  for (size_t i = 0; i < units.size(); ++i) {
    std::snprintf(text, sizeof(text), "%.6f", units[i] / kScale);
    out << (i ? ", " : "") << text;
  }
  out << "]";
}

void write_distribution(std::ostream& out, const IntentDistribution& d) {
  out << "count: " << d.count << ", next: ";
  write_list(out, d.intents);
  out << ", p: ";
  write_units(out, rounded(d.probabilities));
}

void write_table(std::ostream& out, const std::string& key, const ConditionalTable& table) {
  out << "    " << key << ":\n";
  for (const auto& [after, d] : table.rows) {
    out << "      - {after: " << quoted(after) << ", ";
    write_distribution(out, d);
    out << "}\n";
  }
}

std::string fixed6(double value) {
  return core::format_text("%.6f", value);
}

}  // namespace

const std::string& IntentDistribution::sample(core::Rng& rng) const {
  return intents[rng.categorical(probabilities)];
}

double IntentDistribution::probability_of(const std::string& intent) const {
  for (size_t i = 0; i < intents.size(); ++i) {
    if (intents[i] == intent) {
      return probabilities[i];
    }
  }
  return 0.0;
}

const IntentDistribution& ConditionalTable::row(const std::string& context) const {
  const auto found = rows.find(context);
  return found != rows.end() ? found->second : rows.at(kAnyContext);
}

double RoleModel::to_other_probability(const std::string& intent) const {
  const auto found = to_other.find(intent);
  return found != to_other.end() ? found->second : to_other.at(kAnyContext);
}

const RoleModel& UserModel::role(const std::string& name, const std::string& source) const {
  const auto found = roles.find(name);
  if (found == roles.end()) {
    std::string known;
    for (const auto& entry : roles) {
      known += (known.empty() ? "" : ", ") + entry.first;
    }
    throw core::ConfigError(source + ": roles: missing role '" + name + "' (the file has " +
                            (known.empty() ? std::string("none") : known) + ")");
  }
  return found->second;
}

UserModel UserModel::load(const std::string& file_path) {
  return parse(core::YamlMap::load_file(file_path));
}

UserModel UserModel::parse(const core::YamlMap& map) {
  UserModel model;
  model.provenance = map.optional<std::string>("provenance", "");
  model.robot_opens = map.required<double>("robot_opens", core::between(0.0, 1.0));
  model.same_responder = map.required<double>("same_responder", core::between(0.0, 1.0));
  const core::YamlMap goals = map.map("goals");
  model.goals.counts = goals.required<std::vector<unsigned>>("counts", core::positive());
  model.goals.probabilities = goals.required<std::vector<double>>("p", core::between(0.0, 1.0));
  model.goals.joint_share = goals.required<double>("joint_share", core::between(0.0, 1.0));
  if (model.goals.counts.empty() || model.goals.counts.size() != model.goals.probabilities.size()) {
    goals.fail("p", "one probability per entry of counts", "a different number");
  }
  double sum = 0.0;
  for (double p : model.goals.probabilities) {
    sum += p;
  }
  if (std::abs(sum - 1.0) > kSumTolerance) {
    goals.fail("p", "probabilities summing to 1", "a sum of " + fixed6(sum));
  }
  goals.finish();
  for (const core::YamlMap& entry : map.list("roles")) {
    const std::string name = entry.required<std::string>("role");
    if (model.roles.count(name) > 0) {
      entry.fail("role", "each role once", "'" + name + "' twice");
    }
    model.roles[name] = read_role(entry);
  }
  map.finish();
  return model;
}

void UserModel::write(std::ostream& out) const {
  out << "# P(user act | context) per role, fitted to the MPGT corpus by fit_dialogue_model.\n"
      << "# Regenerate instead of editing: see docs/dialogue.md.\n";
  out << "provenance: " << quoted(provenance) << "\n";
  out << "robot_opens: " << fixed6(robot_opens) << "\n";
  out << "same_responder: " << fixed6(same_responder) << "\n";
  out << "goals:\n  counts: [";
  for (size_t i = 0; i < goals.counts.size(); ++i) {
    out << (i ? ", " : "") << goals.counts[i];
  }
  out << "]\n  p: ";
  write_units(out, rounded(goals.probabilities));
  out << "\n  joint_share: " << fixed6(goals.joint_share) << "\n";
  out << "roles:\n";
  for (const auto& [name, role] : roles) {
    out << "  - role: " << name << "\n";
    out << "    keep_floor: " << fixed6(role.keep_floor) << "\n";
    out << "    opening: {";
    write_distribution(out, role.opening);
    out << "}\n";
    write_table(out, "after_robot", role.after_robot);
    write_table(out, "after_other", role.after_other);
    write_table(out, "after_self", role.after_self);
    std::vector<std::string> intents;
    std::vector<std::string> values;
    out << "    to_other:\n      intents: ";
    for (const auto& [intent, p] : role.to_other) {
      intents.push_back(intent);
      values.push_back(fixed6(p));
    }
    write_list(out, intents);
    out << "\n      p: [";
    for (size_t i = 0; i < values.size(); ++i) {
      out << (i ? ", " : "") << values[i];
    }
    out << "]\n";
  }
}

}  // namespace ari_social_sim::dialogue
