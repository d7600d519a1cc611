#pragma once

// Randomised, seeded navigation episodes: a world with people and groups, ARI's start, the
// navigation target, and what the metrics exempt. nav_benchmark measures SocialMPC on them and
// the learning environments train policies on them, so that both are scored on the same worlds.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/navigation/goal_finder.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::learning {

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

struct NavigationEpisode {
  EpisodeType type{EpisodeType::kPose};
  int index{0};
  uint64_t seed{0};
  std::unique_ptr<world::Simulation> simulation;
  navigation::NavigationTarget target;
  std::vector<std::string> exempt_people;  // person ids (human<N>) approached or joined
  std::string exempt_group;                // group id (group<N>) joined
  std::vector<ScheduledWalk> walks;
  double time_limit_s{60.0};
  Eigen::Vector2d floor_low{Eigen::Vector2d::Zero()};  // the box people and ARI were placed in
  Eigen::Vector2d floor_high{Eigen::Vector2d::Zero()};
};

/// The shipped worlds some episode types are built in, loaded once.
struct EpisodeWorlds {
  model::WorldDescription two_room_flat;  // the pose and doorway episodes

  /// Reads them from `worlds_dir` (the package's worlds/). Throws core::ConfigError naming the
  /// file when one cannot be read.
  static EpisodeWorlds load(const std::string& worlds_dir);
};

/// Builds episode `index` of `type` from `base_seed` (the same arguments give the same episode).
NavigationEpisode make_episode(EpisodeType type, int index, uint64_t base_seed,
                               const EpisodeWorlds& worlds);

/// Adds `count` people who walk between random free places of the episode's floor, ids from 100
/// up, drawn from `rng`; keep_walking() gives them their next goal. Throws core::RequestError
/// when the floor has no room for them.
void add_walkers(NavigationEpisode& episode, int count, core::Rng& rng);
/// A new random goal on the floor for every walker (id >= 100) who has arrived.
void keep_walking(NavigationEpisode& episode, core::Rng& rng);

/// The ROS4HRI-style ids perception gives simulated people and groups.
std::string person_id(model::ObjectId human);
std::string group_id(model::ObjectId group);

}  // namespace ari_social_sim::learning
