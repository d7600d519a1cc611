#include "ari_social_sim/learning/navigation_episodes.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/rng_streams.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/navigation/footprint_model.hpp"
#include "ari_social_sim/navigation/signed_distance_field.hpp"
#include "ari_social_sim/world/map_sensor.hpp"

namespace ari_social_sim::learning {
namespace {

using core::kPi;
using model::ObjectId;

constexpr int kMaxDraws = 2000;
// Walkers added to an episode take ids from here up, clear of the episode's own people.
constexpr ObjectId kFirstWalker = 100;

model::StaticObject wall(ObjectId id, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  model::StaticObject object;
  object.id = id;
  object.type = model::ShapeType::kWall;
  object.pose.position = 0.5 * (from + to);
  object.pose.theta = std::atan2(to.y() - from.y(), to.x() - from.x());
  object.size = {(to - from).norm(), 0.1};
  return object;
}

// A walled rectangle of `size` with its inner floor from (0, 0).
model::WorldDescription walled_room(const std::string& name, const Eigen::Vector2d& size) {
  model::WorldDescription world;
  world.name = name;
  world.origin = {-0.2, -0.2};
  world.size = size + Eigen::Vector2d(0.4, 0.4);
  const double w = size.x(), h = size.y();
  world.objects.push_back(wall(1000, {-0.05, 0.0}, {w + 0.05, 0.0}));
  world.objects.push_back(wall(1001, {-0.05, h}, {w + 0.05, h}));
  world.objects.push_back(wall(1002, {0.0, 0.05}, {0.0, h - 0.05}));
  world.objects.push_back(wall(1003, {w, 0.05}, {w, h - 0.05}));
  return world;
}

core::Pose2 pose(const Eigen::Vector2d& position, double theta) {
  core::Pose2 p;
  p.position = position;
  p.theta = theta;
  return p;
}

// Places ARI at random within the box until the simulation accepts it (no overlap) and
// `accept` agrees.
template <class Accept>
void place_ari(world::Simulation& sim, core::Rng& rng, const Eigen::Vector2d& low,
               const Eigen::Vector2d& high, Accept accept) {
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    world::AriSpec spec;
    spec.id = 1;
    spec.pose = pose(rng.uniform_point(low, high), rng.uniform(-kPi, kPi));
    if (!accept(spec.pose)) {
      continue;
    }
    try {
      sim.add_ari(spec);
      return;
    } catch (const core::RequestError&) {
    }
  }
  throw core::RequestError("navigation episode: no free start pose for ARI");
}

// A standing person at a random free place in the box.
template <class Accept>
ObjectId place_person(world::Simulation& sim, core::Rng& rng, ObjectId id,
                      const Eigen::Vector2d& low, const Eigen::Vector2d& high, Accept accept) {
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    world::HumanSpec spec;
    spec.id = id;
    spec.pose = pose(rng.uniform_point(low, high), rng.uniform(-kPi, kPi));
    if (!accept(spec.pose)) {
      continue;
    }
    try {
      sim.add_human(spec);
      return id;
    } catch (const core::RequestError&) {
    }
  }
  throw core::RequestError("navigation episode: no free place for person " + std::to_string(id));
}

// A group of `size` people standing in formation around `centre` (GroupNavigation keeps it).
std::vector<ObjectId> place_group(world::Simulation& sim, core::Rng& rng, ObjectId group,
                                  ObjectId first_member, int size, const Eigen::Vector2d& centre) {
  world::GroupSpec spec;
  spec.id = group;
  spec.centre = centre;
  const double radius = world::GroupNavigation::ospace_radius_for(
      static_cast<size_t>(size),
      world::GroupNavigation::member_spacing_for(spec, static_cast<size_t>(size)),
      spec.min_ospace_radius_m);
  const double phase = rng.uniform(-kPi, kPi);
  for (int i = 0; i < size; ++i) {
    // Evenly spread with some jitter, as people who gathered a moment ago stand.
    const double angle = phase + 2.0 * kPi * i / size + rng.uniform(-0.15, 0.15);
    world::HumanSpec member;
    member.id = first_member + i;
    member.pose =
        pose(centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)), angle + kPi);
    sim.add_human(member);
    spec.members.push_back(member.id);
  }
  sim.add_group(spec);
  return spec.members;
}

std::unique_ptr<world::Simulation> simulation_of(model::WorldDescription world, uint64_t seed) {
  world::SimulationConfig config;
  config.seed = seed;
  return std::make_unique<world::Simulation>(std::move(world), config);
}

// Small round tables at random, away from `keep_clear` points by `clearance`.
void add_tables(model::WorldDescription& world, core::Rng& rng, int count,
                const Eigen::Vector2d& low, const Eigen::Vector2d& high,
                const std::vector<Eigen::Vector2d>& keep_clear, double clearance) {
  ObjectId id = 2000;
  for (int draw = 0; draw < kMaxDraws && count > 0; ++draw) {
    const Eigen::Vector2d at = rng.uniform_point(low, high);
    bool clear = true;
    for (const Eigen::Vector2d& point : keep_clear) {
      clear = clear && (point - at).norm() > clearance;
    }
    if (!clear) {
      continue;
    }
    model::StaticObject table;
    table.id = id++;
    table.name = "table";
    table.type = model::ShapeType::kCircle;
    table.pose.position = at;
    table.radius_m = rng.uniform(0.3, 0.5);
    world.objects.push_back(table);
    --count;
  }
}

// True when ARI's footprint circles at `base` keep `margin_m` from walls and furniture.
bool footprint_clear(const navigation::GridField& sdf, const core::Pose2& base, double margin_m) {
  static const navigation::FootprintModel footprint =
      navigation::FootprintModel::covering(model::AriFootprint{}, 3);
  for (double offset : footprint.circle_offsets_x_m) {
    if (sdf.sample(base.position + offset * base.heading()) <
        footprint.circle_radius_m + margin_m) {
      return false;
    }
  }
  return true;
}

// two_room_flat.yaml's door: the 1 m gap in the middle wall (x = 5) between y = 1 and 2.
const Eigen::Vector2d kFlatDoor(5.0, 1.5);
// A standing person this near the door's centre closes it: their personal space's front edge
// (1.2 m) plus half of ARI's width reaches across.
constexpr double kDoorClosingDistance = 1.5;

// The flat with ARI placed anywhere ARI fits, its static map as a distance field.
navigation::GridField flat_with_ari(NavigationEpisode& e, core::Rng& rng,
                                    const EpisodeWorlds& worlds, const Eigen::Vector2d& low,
                                    const Eigen::Vector2d& high) {
  e.simulation = simulation_of(worlds.two_room_flat, e.seed);
  navigation::GridField sdf =
      navigation::signed_distance_field(world::rasterize_static_map(e.simulation->world(), 0.05));
  place_ari(*e.simulation, rng, low, high,
            [&](const core::Pose2& p) { return footprint_clear(sdf, p, 0.1); });
  return sdf;
}

// A goal pose in the box, its footprint clear of furniture, 1.5 m from everyone and `accept`ed
// (the goal finder checks the footprint against people when the run starts).
template <class Accept>
core::Pose2 flat_goal(const world::Simulation& sim, const navigation::GridField& sdf,
                      core::Rng& rng, const Eigen::Vector2d& low, const Eigen::Vector2d& high,
                      Accept accept) {
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    core::Pose2 goal = pose(rng.uniform_point(low, high), rng.uniform(-kPi, kPi));
    bool far_from_people = true;
    for (const auto& human : sim.humans()) {
      far_from_people = far_from_people && (human->pose().position - goal.position).norm() > 1.5;
    }
    if (far_from_people && footprint_clear(sdf, goal, 0.1) && accept(goal)) {
      return goal;
    }
  }
  throw core::RequestError("navigation episode: no free goal pose");
}

NavigationEpisode pose_episode(NavigationEpisode e, core::Rng& rng, const EpisodeWorlds& worlds) {
  // The furnished two-room flat (10 x 6 m): ARI crosses it, often through the 1 m door.
  const Eigen::Vector2d low(0.6, 0.6), high(9.4, 5.4);
  const navigation::GridField sdf = flat_with_ari(e, rng, worlds, low, high);
  world::Simulation& sim = *e.simulation;
  const Eigen::Vector2d start = sim.ari()->pose().position;
  // Two people standing about, never in a narrow passage (0.7 m from any wall) nor closing the
  // door (the doorway type has someone there).
  for (ObjectId id : {10, 11}) {
    place_person(sim, rng, id, low, high, [&](const core::Pose2& p) {
      return (p.position - start).norm() > 1.5 && sdf.sample(p.position) > 0.7 &&
             (p.position - kFlatDoor).norm() > kDoorClosingDistance;
    });
  }
  // A goal at least 4 m away.
  const core::Pose2 goal = flat_goal(sim, sdf, rng, low, high, [&](const core::Pose2& g) {
    return (g.position - start).norm() > 4.0;
  });
  e.floor_low = low;
  e.floor_high = high;
  e.target = navigation::PoseTarget{goal};
  e.time_limit_s = 90.0;
  return e;
}

NavigationEpisode doorway_episode(NavigationEpisode e, core::Rng& rng,
                                  const EpisodeWorlds& worlds) {
  // The flat again, ARI going from one room to the other while someone stands near the door:
  // every way passes through their personal space, so ARI must wait, then claim the way.
  const bool from_living_room = rng.uniform(0.0, 1.0) < 0.5;
  const Eigen::Vector2d living_low(0.6, 0.6), living_high(4.4, 5.4);
  const Eigen::Vector2d kitchen_low(5.6, 0.6), kitchen_high(9.4, 5.4);
  const navigation::GridField sdf =
      flat_with_ari(e, rng, worlds, from_living_room ? living_low : kitchen_low,
                    from_living_room ? living_high : kitchen_high);
  world::Simulation& sim = *e.simulation;
  const Eigen::Vector2d start = sim.ari()->pose().position;
  place_person(sim, rng, 10, kFlatDoor - Eigen::Vector2d(1.3, 1.3),
               kFlatDoor + Eigen::Vector2d(1.3, 1.3), [&](const core::Pose2& p) {
                 const double to_door = (p.position - kFlatDoor).norm();
                 return to_door > 0.8 && to_door < 1.3 && sdf.sample(p.position) > 0.6 &&
                        (p.position - start).norm() > 1.5;
               });
  const core::Pose2 goal =
      flat_goal(sim, sdf, rng, from_living_room ? kitchen_low : living_low,
                from_living_room ? kitchen_high : living_high,
                [&](const core::Pose2& g) { return (g.position - kFlatDoor).norm() > 2.0; });
  e.floor_low = Eigen::Vector2d(0.6, 0.6);
  e.floor_high = Eigen::Vector2d(9.4, 5.4);
  e.target = navigation::PoseTarget{goal};
  e.time_limit_s = 90.0;
  return e;
}

NavigationEpisode corridor_episode(NavigationEpisode e, core::Rng& rng) {
  // A 16 m corridor 3.4-4 m wide; a group of 2 or 3 stands by one wall; ARI walks its length.
  const double width = rng.uniform(3.4, 4.0);
  e.simulation = simulation_of(walled_room("corridor", {16.0, width}), e.seed);
  world::Simulation& sim = *e.simulation;
  const int size = 2 + static_cast<int>(rng.uniform_index(2));
  const double radius = world::GroupNavigation::ospace_radius_for(size, 1.1, 0.6);
  const bool north = rng.bernoulli(0.5);
  const double offset = 0.35 + radius;  // centre from the wall it stands by
  const Eigen::Vector2d centre(rng.uniform(6.0, 10.0), north ? width - offset : offset);
  place_group(sim, rng, 1, 10, size, centre);
  world::AriSpec ari;
  ari.pose = pose({1.5, 0.5 * width + rng.uniform(-0.3, 0.3)}, rng.uniform(-0.3, 0.3));
  sim.add_ari(ari);
  e.floor_low = Eigen::Vector2d(0.5, 0.5);
  e.floor_high = Eigen::Vector2d(15.5, width - 0.5);
  e.target = navigation::PoseTarget{pose({14.5, 0.5 * width}, 0.0)};
  e.time_limit_s = 60.0;
  return e;
}

NavigationEpisode crossing_episode(NavigationEpisode e, core::Rng& rng) {
  // A 12 x 8 m hall; ARI crosses it west to east while two people cross its path north-south at
  // staggered times and one walks the other way along it.
  e.simulation = simulation_of(walled_room("hall", {12.0, 8.0}), e.seed);
  world::Simulation& sim = *e.simulation;
  world::AriSpec ari;
  ari.pose = pose({1.2, 4.0 + rng.uniform(-0.5, 0.5)}, rng.uniform(-0.3, 0.3));
  sim.add_ari(ari);
  for (int i = 0; i < 2; ++i) {
    const bool from_south = rng.bernoulli(0.5);
    const double x = rng.uniform(3.5 + 3.0 * i, 5.5 + 3.0 * i);
    world::HumanSpec walker;
    walker.id = 10 + i;
    walker.pose = pose({x, from_south ? 0.6 : 7.4}, from_south ? kPi / 2 : -kPi / 2);
    sim.add_human(walker);
    const double start = rng.uniform(0.0, 2.0 + 3.0 * i);
    e.walks.push_back({start, walker.id,
                       pose({x + rng.uniform(-1.5, 1.5), from_south ? 7.4 : 0.6},
                            from_south ? kPi / 2 : -kPi / 2)});
  }
  world::HumanSpec oncoming;
  oncoming.id = 12;
  oncoming.pose = pose({11.2, 4.0 + rng.uniform(-0.8, 0.8)}, kPi);
  sim.add_human(oncoming);
  e.walks.push_back(
      {rng.uniform(0.0, 3.0), oncoming.id, pose({0.8, 4.0 + rng.uniform(-0.8, 0.8)}, kPi)});
  e.floor_low = Eigen::Vector2d(0.6, 0.6);
  e.floor_high = Eigen::Vector2d(11.4, 7.4);
  e.target = navigation::PoseTarget{pose({10.8, 4.0}, 0.0)};
  e.time_limit_s = 60.0;
  return e;
}

NavigationEpisode approach_episode(NavigationEpisode e, core::Rng& rng) {
  // An 8 x 8 m room with a few tables; ARI approaches one of three standing people.
  model::WorldDescription world = walled_room("room", {8.0, 8.0});
  const Eigen::Vector2d target_at = rng.uniform_point({2.0, 2.0}, {6.0, 6.0});
  add_tables(world, rng, 3, {1.0, 1.0}, {7.0, 7.0}, {target_at}, 2.2);
  e.simulation = simulation_of(std::move(world), e.seed);
  world::Simulation& sim = *e.simulation;
  world::HumanSpec target;
  target.id = 10;
  // Facing roughly into the room, so there is floor in front of them.
  const Eigen::Vector2d inward = Eigen::Vector2d(4.0, 4.0) - target_at;
  target.pose = pose(target_at, std::atan2(inward.y(), inward.x()) + rng.uniform(-1.2, 1.2));
  sim.add_human(target);
  for (ObjectId id : {11, 12}) {
    place_person(sim, rng, id, {0.8, 0.8}, {7.2, 7.2},
                 [&](const core::Pose2& p) { return (p.position - target_at).norm() > 2.0; });
  }
  place_ari(sim, rng, {0.8, 0.8}, {7.2, 7.2}, [&](const core::Pose2& p) {
    bool clear = (p.position - target_at).norm() > 3.0;
    for (const auto& human : sim.humans()) {
      clear = clear && (human->pose().position - p.position).norm() > 1.2;
    }
    return clear;
  });
  e.floor_low = Eigen::Vector2d(0.8, 0.8);
  e.floor_high = Eigen::Vector2d(7.2, 7.2);
  e.target = navigation::PersonTarget{person_id(target.id)};
  e.exempt_people = {person_id(target.id)};
  e.time_limit_s = 60.0;
  return e;
}

NavigationEpisode join_episode(NavigationEpisode e, core::Rng& rng, int size) {
  // A 10 x 10 m room with a few tables, the group to join and another group of 2 or 3.
  model::WorldDescription world = walled_room("room", {10.0, 10.0});
  const Eigen::Vector2d target_centre = rng.uniform_point({2.5, 2.5}, {7.5, 7.5});
  Eigen::Vector2d other_centre;
  for (int draw = 0;; ++draw) {
    other_centre = rng.uniform_point({1.8, 1.8}, {8.2, 8.2});
    if ((other_centre - target_centre).norm() > 3.5 || draw > kMaxDraws) {
      break;
    }
  }
  add_tables(world, rng, 3, {1.0, 1.0}, {9.0, 9.0}, {target_centre, other_centre}, 2.4);
  e.simulation = simulation_of(std::move(world), e.seed);
  world::Simulation& sim = *e.simulation;
  const std::vector<ObjectId> members = place_group(sim, rng, 1, 10, size, target_centre);
  place_group(sim, rng, 2, 20, 2 + static_cast<int>(rng.uniform_index(2)), other_centre);
  place_ari(sim, rng, {0.8, 0.8}, {9.2, 9.2}, [&](const core::Pose2& p) {
    return (p.position - target_centre).norm() > 3.0 && (p.position - other_centre).norm() > 2.0;
  });
  e.floor_low = Eigen::Vector2d(0.8, 0.8);
  e.floor_high = Eigen::Vector2d(9.2, 9.2);
  e.target = navigation::GroupTarget{group_id(1)};
  for (ObjectId member : members) {
    e.exempt_people.push_back(person_id(member));
  }
  e.exempt_group = group_id(1);
  e.time_limit_s = 60.0;
  return e;
}

}  // namespace

const std::vector<EpisodeType>& all_episode_types() {
  static const std::vector<EpisodeType> types = {
      EpisodeType::kPose,     EpisodeType::kDoorway, EpisodeType::kCorridor, EpisodeType::kCrossing,
      EpisodeType::kApproach, EpisodeType::kJoin2,   EpisodeType::kJoin3,    EpisodeType::kJoin4};
  return types;
}

const char* type_name(EpisodeType type) {
  switch (type) {
    case EpisodeType::kPose:
      return "pose";
    case EpisodeType::kDoorway:
      return "doorway";
    case EpisodeType::kCorridor:
      return "corridor";
    case EpisodeType::kCrossing:
      return "crossing";
    case EpisodeType::kApproach:
      return "approach";
    case EpisodeType::kJoin2:
      return "join2";
    case EpisodeType::kJoin3:
      return "join3";
    case EpisodeType::kJoin4:
      return "join4";
  }
  return "";
}

bool parse_type(const std::string& name, EpisodeType& type) {
  for (EpisodeType t : all_episode_types()) {
    if (name == type_name(t)) {
      type = t;
      return true;
    }
  }
  return false;
}

EpisodeWorlds EpisodeWorlds::load(const std::string& worlds_dir) {
  EpisodeWorlds worlds;
  worlds.two_room_flat = model::load_world_file(worlds_dir + "/two_room_flat.yaml");
  return worlds;
}

void add_walkers(NavigationEpisode& episode, int count, core::Rng& rng) {
  world::Simulation& sim = *episode.simulation;
  const Eigen::Vector2d ari = sim.ari()->pose().position;
  for (int i = 0; i < count; ++i) {
    // Not on top of ARI, whom they would push at the first step.
    place_person(sim, rng, kFirstWalker + i, episode.floor_low, episode.floor_high,
                 [&](const core::Pose2& p) { return (p.position - ari).norm() > 1.5; });
  }
  keep_walking(episode, rng);
}

void keep_walking(NavigationEpisode& episode, core::Rng& rng) {
  world::Simulation& sim = *episode.simulation;
  for (const auto& human : sim.humans()) {
    if (human->id() < kFirstWalker || human->goal()) {
      continue;
    }
    const Eigen::Vector2d to = rng.uniform_point(episode.floor_low, episode.floor_high);
    const Eigen::Vector2d way = to - human->pose().position;
    sim.set_human_goal(human->id(), pose(to, std::atan2(way.y(), way.x())));
  }
}

std::string person_id(model::ObjectId human) {
  return "human" + std::to_string(human);
}

std::string group_id(model::ObjectId group) {
  return "group" + std::to_string(group);
}

NavigationEpisode make_episode(EpisodeType type, int index, uint64_t base_seed,
                               const EpisodeWorlds& worlds) {
  NavigationEpisode e;
  e.type = type;
  e.index = index;
  // The types' streams are 2^20 apart (nav_benchmark runs at most 10 000 episodes of a type).
  ARI_CHECK(index >= 0 && index < (1 << 20));
  const uint64_t stream = (static_cast<uint64_t>(type) << 20) + static_cast<uint64_t>(index);
  e.seed = core::rng_for(base_seed, core::rng_streams::kNavigationEpisodes, stream).next_u64() %
           2147483647u;
  core::Rng rng(e.seed);
  switch (type) {
    case EpisodeType::kPose:
      return pose_episode(std::move(e), rng, worlds);
    case EpisodeType::kDoorway:
      return doorway_episode(std::move(e), rng, worlds);
    case EpisodeType::kCorridor:
      return corridor_episode(std::move(e), rng);
    case EpisodeType::kCrossing:
      return crossing_episode(std::move(e), rng);
    case EpisodeType::kApproach:
      return approach_episode(std::move(e), rng);
    case EpisodeType::kJoin2:
      return join_episode(std::move(e), rng, 2);
    case EpisodeType::kJoin3:
      return join_episode(std::move(e), rng, 3);
    case EpisodeType::kJoin4:
      return join_episode(std::move(e), rng, 4);
  }
  return e;
}

}  // namespace ari_social_sim::learning
