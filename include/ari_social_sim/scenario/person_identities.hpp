#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::scenario {

/// One person perception tracks in a frame (ROS4HRI `/humans/persons/tracked`) and where it is.
struct PersonSighting {
  std::string person_id;
  /// In the map frame: the person's body (mid-hips), or without a body its person frame (the
  /// head's last known place, from a face or a voice).
  Eigen::Vector2d position{Eigen::Vector2d::Zero()};
  /// False when only the person frame places the person: a weaker cue than a body (a voice's
  /// direction, a stale face), so a body sighting always wins over it.
  bool from_body{true};
};

/// What the in-process engine's perception tracks, as scenario_node reads it from ROS: each
/// tracked person at its body's X_map_body, or without a body at `location` (its person frame).
std::vector<PersonSighting> sightings_of(const perception::PerceptionFrame& frame);

/// Who is who between the script's simulated humans (ground truth, by world id) and the persons
/// perception reports (by whatever ids its person manager gives: `human<N>`, anonymous ids of
/// hri_person_manager, ...): the person whose body stands where the human is. Scenarios address
/// people through perception only by these matches, never by the form of an id.
///
/// Each update assigns sightings to humans one to one, nearest pairs first and at most
/// kMaxDistance_m apart, body sightings before person-frame ones. An assigned pair replaces what
/// either side was matched with before; a human or person not assigned keeps its match, as person
/// ids are permanent and someone hidden for a while is still the same person. A match made
/// through a body is never replaced by one made through a person frame only. A human no longer in
/// the world loses its match (an added human may reuse the id). Deterministic: ties go to the
/// lower human id, then the lower person id.
class PersonIdentities {
 public:
  /// Farthest a sighting may be from a human to be that human (m). Above perception's body
  /// position noise (config/perception.yaml body_errors: 0.03 m + 0.02 m per metre, per axis):
  /// at 5 m (0.13 m) a sighting lands farther than 0.6 m about twice in 10^5 (Rayleigh,
  /// e^(-0.6^2 / (2 * 0.13^2))), at the fisheye's 10 m range (0.23 m) 3 % of the time, and the
  /// person then keeps its earlier match. Two bodies (0.2 m radius) can stand 0.4 m apart, so a
  /// sighting may be within reach of both; nearest-first assignment settles it.
  static constexpr double kMaxDistance_m = 0.6;

  /// Matches this frame's sightings with the humans of `world`.
  void update(const world::WorldSnapshot& world, const std::vector<PersonSighting>& sightings);

  /// The person id the human is perceived as; nothing until a sighting has matched it.
  std::optional<std::string> person_of(model::ObjectId human) const;
  /// The human a person id stands for; nothing for persons matched with no one.
  std::optional<model::ObjectId> human_of(const std::string& person_id) const;
  /// Every match, by human.
  std::map<model::ObjectId, std::string> person_ids() const;

 private:
  struct Match {
    std::string person_id;
    bool through_body{false};  // made or confirmed by a body sighting
  };

  void forget_person(const std::string& person_id);

  std::map<model::ObjectId, Match> matches_;
};

}  // namespace ari_social_sim::scenario
