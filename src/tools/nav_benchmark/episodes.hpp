#pragma once

// Randomised, seeded navigation episodes for nav_benchmark: a world with people and groups, ARI's
// start, the navigation target, and what the metrics exempt.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/navigation/goal_finder.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::tools {

// The numbering seeds the episodes: a new type goes last, so that the others keep their worlds.
enum class EpisodeType { kPose, kCorridor, kCrossing, kApproach, kJoin2, kJoin3, kJoin4, kDoorway };

const std::vector<EpisodeType>& all_episode_types();
const char* type_name(EpisodeType type);
/// Parses a type name as type_name() prints it; false when unknown.
bool parse_type(const std::string& name, EpisodeType& type);

/// A human starts walking to `goal` at sim time `start_s` (crossing episodes).
struct ScheduledWalk {
  double start_s{0.0};
  model::ObjectId human{model::kNoObject};
  core::Pose2 goal;
};

struct Episode {
  EpisodeType type{EpisodeType::kPose};
  int index{0};
  uint64_t seed{0};
  std::unique_ptr<world::Simulation> simulation;
  navigation::NavigationTarget target;
  std::vector<std::string> exempt_people;  // person ids (human<N>) approached or joined
  std::string exempt_group;                // group id (group<N>) joined
  std::vector<ScheduledWalk> walks;
  double time_limit_s{60.0};
};

/// Builds episode `index` of `type` from `base_seed` (the same arguments give the same episode).
/// `worlds_dir` holds the shipped worlds (two_room_flat.yaml for the pose and doorway episodes).
Episode make_episode(EpisodeType type, int index, uint64_t base_seed,
                     const std::string& worlds_dir);

/// The ROS4HRI-style ids the tool gives simulated people and groups, as perception would.
std::string person_id(model::ObjectId human);
std::string group_id(model::ObjectId group);

}  // namespace ari_social_sim::tools
