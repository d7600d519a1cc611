#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/scenario/group_mix.hpp"
#include "ari_social_sim/scenario/scenario.hpp"

namespace ari_social_sim::scenario {

/// What random group scenes are drawn from (export_group_streams; docs/perception_gcff.md, "GCFF
/// on perceived streams"): conversational groups in Kendon's arrangements, a few people alone,
/// and ARI driving from group to group, in an empty room.
struct RandomGroupSceneSpec {
  /// An empty room (worlds/room_12x12.yaml); nothing but its walls is avoided.
  model::WorldDescription world;
  std::string world_path;  // for messages
  /// The box (m, map frame) that holds the o-space centres, the lone people and ARI's start; ARI's
  /// waypoints may lie up to 1 m outside it (validate() wants that margin inside the floor).
  Eigen::Vector2d area_min{2.0, 2.0};
  Eigen::Vector2d area_max{10.0, 10.0};
  unsigned min_groups{3};
  unsigned max_groups{5};
  /// Each group's arrangement and size are drawn from this mix, by weight. A circle has 3 or more
  /// people: the world keeps a circle of two as a vis-a-vis (GroupNavigation::arrangement).
  std::vector<GroupKind> mix{recorded_group_mix()};
  double min_centre_distance_m{3.0};  // between two groups' o-space centres
  unsigned max_lone_people{2};        // 0 to this many, each standing or walking
  /// Members spawn within this distance (m) of their place, turned by up to heading_jitter_rad:
  /// as people who gathered a moment ago stand. Below half the shoulder spacing less a body's
  /// diameter (0.65 - 0.4), so that neighbours never spawn overlapping.
  double position_jitter_m{0.1};
  double heading_jitter_rad{0.2};
  /// ARI's waypoints lie this far (m) from a group's o-space centre, facing it: more than
  /// world::kRobotJoinReachM beyond the o-space, so that ARI looks at a group without joining it.
  double waypoint_distance_m{2.8};
  double goal_timeout_s{20.0};  // ARI moves on to the next waypoint after this
  double duration_s{60.0};      // sim time; the script's time limit

  /// Throws core::ConfigError naming the first field that cannot give a scene (no arrangement,
  /// min_groups above max_groups, the area outside the world's floor, a duration not > 0, ...).
  void validate() const;
};

/// One random group scene as a scenario named `random_group_scene`, drawn from `seed` (the same
/// seed gives the same scenario; the scene's seed is `seed`): min_groups to max_groups groups
/// (ids 1, 2, ...) with o-space centres in the area at least min_centre_distance_m apart, each
/// of an arrangement and size drawn as above with a uniform heading, members (ids from 10, group
/// by group) spawned at the formation's places (world::formation_slots) with jitter, facing the
/// o-space; 0 to max_lone_people people alone (after the members), each standing or walking to a
/// point of the area away from the groups; ARI at a free place of the area, and a script that
/// sends ARI to a waypoint by each group in turn (social navigation, one goal at a time, moving
/// on when the goal is reached, fails or takes longer than goal_timeout_s, the route repeating)
/// until duration_s. Throws core::ConfigError for an invalid spec or when no free place is found
/// in many draws.
Scenario make_random_group_scene(const RandomGroupSceneSpec& spec, uint64_t seed);

}  // namespace ari_social_sim::scenario
