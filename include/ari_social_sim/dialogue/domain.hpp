#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/dialogue/goal.hpp"

namespace ari_social_sim::dialogue {

/// Something a goal can be about: a place (`toilet`), an entity's attribute (`cafe(opening_times)`)
/// or nothing (`eat()`), with what ARI and the other human know about it.
struct DomainObject {
  std::vector<std::string> path;
  double weight{1.0};       ///< relative sampling weight within its predicate
  bool ari_knows{true};     ///< ARI can answer; otherwise the right answer is cant-help()
  bool humans_know{false};  ///< the other human may answer it (e.g. the appointment time)
};

/// A goal predicate, how users state it and how ARI answers it. Patterns use `*` for the object
/// path: `request(location(*))` with object [toilet] is `request(location(toilet))`; with an
/// empty object `request(food(*))` is `request(food)`.
struct PredicateSpec {
  std::string name;
  double weight{1.0};  ///< relative sampling weight among predicates
  std::vector<DialogueAct> ask;
  DialogueAct answer;
  std::vector<DomainObject> objects;
};

/// The setting's goal space (config/dialogue/hospital_domain.yaml): places, entities with their
/// attributes, what ARI can answer, and the weights goals are sampled with. Constant once loaded.
class Domain {
 public:
  /// Reads a domain file. Throws core::ConfigError naming the file and entry on any malformed,
  /// unknown or missing field (unknown intent in a pattern, a pattern without `*`, weight <= 0,
  /// duplicate predicate or object).
  static Domain load(const std::string& file_path);
  static Domain parse(const core::YamlMap& map);

  const std::vector<PredicateSpec>& predicates() const { return predicates_; }

  /// Draws a predicate by weight, then an object by weight.
  Goal sample_goal(std::vector<std::string> owners, core::Rng& rng) const;

  /// The predicate and object a goal refers to; null when the domain has no such goal.
  const PredicateSpec* find_predicate(const std::string& name) const;
  const DomainObject* find_object(const Goal& goal) const;

  /// The acts that state `goal` (one per ask pattern) and ARI's correct answer to it.
  std::vector<DialogueAct> ask_acts(const Goal& goal) const;
  DialogueAct answer_act(const Goal& goal) const;

  /// The goal a user act states (the first predicate whose ask pattern and object match), owners
  /// left empty; nullopt when no goal of the domain matches.
  std::optional<Goal> goal_of_request(const DialogueAct& act) const;
  /// The goal an ARI act answers (its answer pattern matches), owners left empty.
  std::optional<Goal> goal_of_answer(const DialogueAct& act) const;

  /// Names used by the error model for confusions: every slot and every object name.
  const std::vector<std::string>& slot_names() const { return slot_names_; }
  const std::vector<std::string>& object_names() const { return object_names_; }

 private:
  std::vector<PredicateSpec> predicates_;
  std::vector<double> predicate_weights_;
  std::vector<std::string> slot_names_;
  std::vector<std::string> object_names_;
};

/// `pattern` with its `*` replaced by `object` (any number of names, including none).
DialogueAct instantiate_pattern(const DialogueAct& pattern, const std::vector<std::string>& object);
/// The object an act fills a pattern's `*` with; nullopt when the act does not fit the pattern.
std::optional<std::vector<std::string>> match_pattern(const DialogueAct& pattern,
                                                      const DialogueAct& act);

}  // namespace ari_social_sim::dialogue
