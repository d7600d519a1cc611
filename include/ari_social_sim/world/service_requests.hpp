#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/fformation_arrangement.hpp"
#include "ari_social_sim/world/gaze_generator.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/posture.hpp"
#include "ari_social_sim/world/walking_group.hpp"

namespace ari_social_sim::world {

/// /sim/spawn_human's fields as the service carries them (srv/SpawnHuman.srv): zero and empty
/// values stand for "automatic" or "the default", gender and emotion are text. A client of the
/// world copies its request into this and hands spec() to Simulation::add_human.
struct SpawnHumanRequest {
  model::ObjectId id{model::kNoObject};  // kNoObject: the next free id (Simulation::add_human)
  std::string name;
  std::string role;
  core::Pose2 pose;
  double age_years{0.0};  // 0: HumanSpec's default age
  std::string gender;     // a name of model::kGenders; empty: HumanSpec's default
  bool mask{false};
  std::string emotion;  // a name of model::kEmotions; empty: HumanSpec's default

  /// The human asked for. Throws core::RequestError for a gender or emotion text it does not
  /// know, e.g. `spawn_human: gender: expected female, male or non-identified, got 'robot'`.
  HumanSpec spec() const;
};

/// /sim/set_gaze_targets's fields as the service carries them (srv/SetGazeTargets.srv): the
/// targets and their probabilities as two parallel lists.
struct GazeTargetsRequest {
  std::vector<model::ObjectId> targets;
  std::vector<double> probabilities;
  double mean_duration_s{0.0};

  /// The gaze model asked for, for Simulation::set_human_gaze. Throws core::RequestError unless
  /// there is one probability per target, e.g.
  /// `set_gaze_targets: probabilities: expected one per target (2), got 1`.
  GazeModel model() const;
};

/// /sim/create_walking_group's fields as the service carries them (srv/CreateWalkingGroup.srv):
/// zero and empty values stand for the defaults, choices are text.
struct WalkingGroupRequest {
  model::ObjectId id{model::kNoObject};  // kNoObject: the next free group id
  std::vector<model::ObjectId> members;
  std::string formation;  // a name of kWalkingFormations; empty: side-by-side
  core::Pose2 goal;
  double speed_mps{0.0};    // 0: WalkingGroupSpec's default
  double spacing_m{0.0};    // 0: WalkingGroupSpec's default
  std::string on_arrival;   // a name of kArrivalActions; empty: stop
  std::string arrangement;  // a name of model::kArrangements; empty: circle

  /// The walking group asked for, for Simulation::add_walking_group. Throws core::RequestError
  /// for a text it does not know, e.g.
  /// `create_walking_group: formation: expected side-by-side or line, got 'abreast'`.
  WalkingGroupSpec spec() const;
};

/// The arrangement a service names in its `arrangement` field (/sim/create_group,
/// /sim/set_group_arrangement): empty gives `unnamed`. Throws core::RequestError for another
/// name, e.g. `create_group: arrangement: expected circle, vis-a-vis, l-shape or side-by-side, got
/// 'line'`.
model::Arrangement requested_arrangement(const std::string& request, const std::string& text,
                                         model::Arrangement unnamed);

/// The posture /sim/set_posture names: `standing` or `sitting`. Throws core::RequestError for
/// another text, e.g. `set_posture: posture: expected standing or sitting, got 'lying'`.
Posture requested_posture(const std::string& text);

}  // namespace ari_social_sim::world
