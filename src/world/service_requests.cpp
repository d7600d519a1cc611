#include "ari_social_sim/world/service_requests.hpp"

#include <optional>

#include "ari_social_sim/world/request_check.hpp"

namespace ari_social_sim::world {

namespace {

// An optional text field: empty keeps `value`, anything else must name one of `choices`.
template <class Value, class Choices>
void read_choice(const RequestCheck& check, const std::string& field, const std::string& text,
                 const Choices& choices, Value& value) {
  if (text.empty()) {
    return;
  }
  for (const auto& choice : choices) {
    if (text == choice.name) {
      value = choice.value;
      return;
    }
  }
  check.fail(field, core::choice_names(choices), "'" + text + "'");
}

}  // namespace

HumanSpec SpawnHumanRequest::spec() const {
  const RequestCheck check("spawn_human");
  HumanSpec spec;
  spec.id = id;
  spec.name = name;
  spec.role = role;
  spec.pose = pose;
  if (age_years != 0.0) {
    spec.age_years = age_years;
  }
  read_choice(check, "gender", gender, model::kGenders, spec.gender);
  spec.mask = mask;
  read_choice(check, "emotion", emotion, model::kEmotions, spec.emotion);
  return spec;
}

GazeModel GazeTargetsRequest::model() const {
  if (probabilities.size() != targets.size()) {
    RequestCheck("set_gaze_targets")
        .fail("probabilities", "one per target (" + std::to_string(targets.size()) + ")",
              std::to_string(probabilities.size()));
  }
  GazeModel model;
  for (size_t i = 0; i < targets.size(); ++i) {
    model.targets.push_back({targets[i], probabilities[i]});
  }
  model.mean_duration_s = mean_duration_s;
  return model;
}

WalkingGroupSpec WalkingGroupRequest::spec() const {
  const RequestCheck check("create_walking_group");
  WalkingGroupSpec spec;
  spec.id = id;
  spec.members = members;
  read_choice(check, "formation", formation, kWalkingFormations, spec.formation);
  spec.goal = goal;
  if (speed_mps != 0.0) {
    spec.speed_mps = speed_mps;
  }
  if (spacing_m != 0.0) {
    spec.spacing_m = spacing_m;
  }
  read_choice(check, "on_arrival", on_arrival, kArrivalActions, spec.on_arrival);
  read_choice(check, "arrangement", arrangement, model::kArrangements, spec.arrangement);
  return spec;
}

model::Arrangement requested_arrangement(const std::string& request, const std::string& text,
                                         model::Arrangement unnamed) {
  model::Arrangement arrangement = unnamed;
  read_choice(RequestCheck(request), "arrangement", text, model::kArrangements, arrangement);
  return arrangement;
}

Posture requested_posture(const std::string& text) {
  const RequestCheck check("set_posture");
  std::optional<Posture> posture;
  read_choice(check, "posture", text, kPostures, posture);
  if (!posture) {
    check.fail("posture", core::choice_names(kPostures), "''");
  }
  return *posture;
}

}  // namespace ari_social_sim::world
