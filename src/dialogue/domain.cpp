#include "ari_social_sim/dialogue/domain.hpp"

#include <algorithm>
#include <set>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::dialogue {
namespace {

constexpr const char* kWildcard = "*";

DialogueAct read_pattern(const core::YamlMap& map, const std::string& key, const std::string& text,
                         const std::string& field) {
  if (text.find(kWildcard) == std::string::npos) {
    map.fail(key, "an act pattern with * for the object, such as request(location(*))",
             "'" + text + "'");
  }
  DialogueAct act = parse_pattern(text, field);
  std::vector<std::string> path = act.path();
  if (path.empty() || path.back() != kWildcard ||
      std::count(path.begin(), path.end(), kWildcard) != 1) {
    map.fail(key, "exactly one * as the innermost name of the pattern", "'" + text + "'");
  }
  act.slots = std::move(path);
  act.value.clear();
  return act;
}

void add_unique(std::vector<std::string>& names, const std::string& name) {
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    names.push_back(name);
  }
}

}  // namespace

DialogueAct instantiate_pattern(const DialogueAct& pattern,
                                const std::vector<std::string>& object) {
  // Patterns keep the whole path (ending in `*`) in `slots`.
  std::vector<std::string> path(pattern.slots.begin(), pattern.slots.end() - 1);
  path.insert(path.end(), object.begin(), object.end());
  return DialogueAct::from_path(pattern.intent, std::move(path));
}

std::optional<std::vector<std::string>> match_pattern(const DialogueAct& pattern,
                                                      const DialogueAct& act) {
  if (act.intent != pattern.intent) {
    return std::nullopt;
  }
  const std::vector<std::string> path = act.path();
  const size_t prefix = pattern.slots.size() - 1;
  if (path.size() < prefix ||
      !std::equal(pattern.slots.begin(), pattern.slots.end() - 1, path.begin())) {
    return std::nullopt;
  }
  return std::vector<std::string>(path.begin() + static_cast<std::ptrdiff_t>(prefix), path.end());
}

Domain Domain::load(const std::string& file_path) {
  return parse(core::YamlMap::load_file(file_path));
}

Domain Domain::parse(const core::YamlMap& map) {
  Domain domain;
  std::set<std::string> predicate_names;
  for (const core::YamlMap& entry : map.list("predicates")) {
    PredicateSpec spec;
    spec.name = entry.required<std::string>("name");
    if (!predicate_names.insert(spec.name).second) {
      entry.fail("name", "a predicate name used once", "'" + spec.name + "' again");
    }
    spec.weight = entry.required<double>("weight", core::positive());
    const auto ask = entry.required<std::vector<std::string>>("ask");
    if (ask.empty()) {
      entry.fail("ask", "at least one act pattern", "[]");
    }
    for (size_t i = 0; i < ask.size(); ++i) {
      spec.ask.push_back(
          read_pattern(entry, "ask", ask[i], entry.field_name("ask[" + std::to_string(i) + "]")));
    }
    spec.answer = read_pattern(entry, "answer", entry.required<std::string>("answer"),
                               entry.field_name("answer"));
    std::set<std::vector<std::string>> object_paths;
    for (const core::YamlMap& item : entry.list("objects")) {
      DomainObject object;
      object.path = parse_path(item.required<std::string>("path"), item.field_name("path"));
      if (!object_paths.insert(object.path).second) {
        item.fail("path", "an object listed once per predicate", "a repeat");
      }
      object.weight = item.required<double>("weight", core::positive());
      object.ari_knows = item.required<bool>("ari_knows");
      object.humans_know = item.optional<bool>("humans_know", false);
      item.finish();
      for (const std::string& name : object.path) {
        add_unique(domain.object_names_, name);
      }
      spec.objects.push_back(std::move(object));
    }
    if (spec.objects.empty()) {
      entry.fail("objects", "at least one object", "[]");
    }
    for (const DialogueAct& pattern : spec.ask) {
      for (size_t i = 0; i + 1 < pattern.slots.size(); ++i) {
        add_unique(domain.slot_names_, pattern.slots[i]);
      }
    }
    entry.finish();
    domain.predicate_weights_.push_back(spec.weight);
    domain.predicates_.push_back(std::move(spec));
  }
  if (domain.predicates_.empty()) {
    map.fail("predicates", "at least one predicate", "[]");
  }
  map.finish();
  return domain;
}

Goal Domain::sample_goal(std::vector<std::string> owners, core::Rng& rng) const {
  const PredicateSpec& spec = predicates_[rng.categorical(predicate_weights_)];
  std::vector<double> weights;
  weights.reserve(spec.objects.size());
  for (const DomainObject& object : spec.objects) {
    weights.push_back(object.weight);
  }
  return Goal{std::move(owners), spec.name, spec.objects[rng.categorical(weights)].path};
}

const PredicateSpec* Domain::find_predicate(const std::string& name) const {
  for (const PredicateSpec& spec : predicates_) {
    if (spec.name == name) {
      return &spec;
    }
  }
  return nullptr;
}

const DomainObject* Domain::find_object(const Goal& goal) const {
  const PredicateSpec* spec = find_predicate(goal.predicate);
  if (spec == nullptr) {
    return nullptr;
  }
  for (const DomainObject& object : spec->objects) {
    if (object.path == goal.object) {
      return &object;
    }
  }
  return nullptr;
}

std::vector<DialogueAct> Domain::ask_acts(const Goal& goal) const {
  std::vector<DialogueAct> acts;
  if (const PredicateSpec* spec = find_predicate(goal.predicate)) {
    for (const DialogueAct& pattern : spec->ask) {
      acts.push_back(instantiate_pattern(pattern, goal.object));
    }
  }
  return acts;
}

DialogueAct Domain::answer_act(const Goal& goal) const {
  const PredicateSpec* spec = find_predicate(goal.predicate);
  return spec == nullptr ? DialogueAct{"cant-help", {}, ""}
                         : instantiate_pattern(spec->answer, goal.object);
}

std::optional<Goal> Domain::goal_of_request(const DialogueAct& act) const {
  for (const PredicateSpec& spec : predicates_) {
    for (const DialogueAct& pattern : spec.ask) {
      if (auto object = match_pattern(pattern, act)) {
        Goal goal{{}, spec.name, std::move(*object)};
        if (find_object(goal) != nullptr) {
          return goal;
        }
      }
    }
  }
  return std::nullopt;
}

std::optional<Goal> Domain::goal_of_answer(const DialogueAct& act) const {
  for (const PredicateSpec& spec : predicates_) {
    if (auto object = match_pattern(spec.answer, act)) {
      Goal goal{{}, spec.name, std::move(*object)};
      if (find_object(goal) != nullptr) {
        return goal;
      }
    }
  }
  return std::nullopt;
}

}  // namespace ari_social_sim::dialogue
