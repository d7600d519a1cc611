#include "ari_social_sim/scenario/random_group_scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/rng_streams.hpp"
#include "ari_social_sim/scenario/script_time_limit.hpp"
#include "ari_social_sim/world/formation_layout.hpp"
#include "ari_social_sim/world/group_navigation.hpp"

namespace ari_social_sim::scenario {
namespace {

using core::kPi;

constexpr int kMaxDraws = 1000;
constexpr model::ObjectId kFirstHuman = 10;
// A lone person or ARI stays this far (m) from every o-space centre: clear of the members (at
// most 0.8 m out, plus jitter and a body) and of the group's p-space.
constexpr double kGroupClearanceM = 2.0;
// Between lone people and ARI (m): two bodies and a step.
constexpr double kPersonClearanceM = 1.0;
// ARI's waypoints may lie this far (m) outside the area, so that the groups at its border can be
// looked at from outside too; the shipped room leaves 2 m between the area and its walls.
constexpr double kRouteMarginM = 1.0;
// Bearings tried around a group for ARI's waypoint.
constexpr int kWaypointBearings = 16;

bool inside(const Eigen::Vector2d& p, const Eigen::Vector2d& low, const Eigen::Vector2d& high) {
  return (p.array() >= low.array()).all() && (p.array() <= high.array()).all();
}

// Smallest distance from `p` to any of `points` (infinity when there are none).
double nearest(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& points) {
  double d = INFINITY;
  for (const Eigen::Vector2d& q : points) {
    d = std::min(d, (p - q).norm());
  }
  return d;
}

// An adult of either gender, as RandomGroup draws them: the age in whole years, as scene files
// give ages.
void draw_looks(world::HumanSpec& human, core::Rng& rng) {
  human.age_years = std::floor(rng.uniform(18.0, 81.0));
  human.gender = rng.bernoulli(0.5) ? model::Gender::kFemale : model::Gender::kMale;
}

[[noreturn]] void no_place(const RandomGroupSceneSpec& spec, const std::string& what) {
  throw core::ConfigError("random group scene in " + spec.world_path + ": no free place for " +
                          what + " in " + std::to_string(kMaxDraws) + " draws");
}

// A group's members at their places in the formation (world::formation_slots, with the radius
// GroupNavigation gives the arrangement), each moved and turned by a little jitter.
void add_group(Scenario& scenario, const RandomGroupSceneSpec& spec, core::Rng& rng,
               model::ObjectId id, const Eigen::Vector2d& centre, model::ObjectId& next_human) {
  world::GroupSpec group;
  group.id = id;
  group.centre = centre;
  std::vector<double> weights;
  for (const GroupKind& kind : spec.mix) {
    weights.push_back(kind.weight);
  }
  const GroupKind& kind = spec.mix[rng.categorical(weights)];
  group.arrangement = kind.arrangement;
  const unsigned size = kind.size;
  group.heading_rad = rng.uniform(-kPi, kPi);

  const world::FormationShape shape = world::GroupNavigation::settled_shape(group, size);
  for (const world::FormationSlot& slot : world::formation_slots(shape, size)) {
    world::HumanSpec human;
    human.id = next_human++;
    const double jitter_bearing = rng.uniform(-kPi, kPi);
    const double jitter_m = spec.position_jitter_m * std::sqrt(rng.uniform());  // uniform in a disc
    human.pose =
        core::Pose2{slot.position + jitter_m * Eigen::Vector2d(std::cos(jitter_bearing),
                                                               std::sin(jitter_bearing)),
                    core::wrap_angle(slot.facing_rad + rng.uniform(-spec.heading_jitter_rad,
                                                                   spec.heading_jitter_rad))};
    draw_looks(human, rng);
    group.members.push_back(human.id);
    scenario.scene.humans.push_back(human);
  }
  scenario.scene.groups.push_back(group);
}

// A free place of the area: clear of every group and of `others` (lone people, ARI).
Eigen::Vector2d free_place(const RandomGroupSceneSpec& spec, core::Rng& rng,
                           const std::vector<Eigen::Vector2d>& centres,
                           const std::vector<Eigen::Vector2d>& others, const std::string& what) {
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    Eigen::Vector2d p = rng.uniform_point(spec.area_min, spec.area_max);
    if (nearest(p, centres) >= kGroupClearanceM && nearest(p, others) >= kPersonClearanceM) {
      return p;
    }
  }
  no_place(spec, what);
}

// Where ARI looks at the group around `centre` from: waypoint_distance_m away on the first of
// evenly spread bearings (from a random one) that stays in the route's box and as far from every
// other group, facing the centre. None when every bearing fails.
std::optional<core::Pose2> waypoint_by(const RandomGroupSceneSpec& spec, core::Rng& rng,
                                       const Eigen::Vector2d& centre,
                                       const std::vector<Eigen::Vector2d>& centres) {
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(kRouteMarginM);
  const double first = rng.uniform(-kPi, kPi);
  for (int k = 0; k < kWaypointBearings; ++k) {
    const double bearing = first + 2.0 * kPi * k / kWaypointBearings;
    const Eigen::Vector2d p =
        centre + spec.waypoint_distance_m * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
    if (inside(p, spec.area_min - margin, spec.area_max + margin) &&
        nearest(p, centres) >= spec.waypoint_distance_m - 1e-9) {
      return core::Pose2{p, core::wrap_angle(bearing + kPi)};
    }
  }
  return std::nullopt;
}

// ARI's route: state k sends ARI to waypoint k and moves on to the next (the last to the first)
// once the goal is reached, fails, or takes too long.
Script route_script(const RandomGroupSceneSpec& spec, const std::vector<core::Pose2>& waypoints) {
  Script script;
  script.time_limit_s = spec.duration_s;
  const auto name = [](size_t k) { return "waypoint_" + std::to_string(k); };
  script.start = name(0);
  for (size_t k = 0; k < waypoints.size(); ++k) {
    State state;
    state.name = name(k);
    state.on_enter.emplace_back(SetGoalAction{AgentRef::ari(), waypoints[k]});
    const std::string next = name((k + 1) % waypoints.size());
    for (const Condition& condition :
         {Condition{GoalReachedCondition{AgentRef::ari()}}, Condition{NavigationFailedCondition{}},
          Condition{TimeElapsedCondition{spec.goal_timeout_s}}}) {
      Transition transition;
      transition.when.push_back(condition);
      transition.next = next;
      transition.field = "random group scene: " + state.name;
      state.transitions.push_back(transition);
    }
    script.states.push_back(state);
  }
  return script;
}

// Groups: centres drawn in turn, each far enough from those before. Returns the centres.
std::vector<Eigen::Vector2d> add_groups(Scenario& scenario, const RandomGroupSceneSpec& spec,
                                        core::Rng& rng, model::ObjectId& next_human) {
  const unsigned group_count =
      spec.min_groups +
      static_cast<unsigned>(rng.uniform_index(spec.max_groups - spec.min_groups + 1));
  std::vector<Eigen::Vector2d> centres;
  for (unsigned g = 0; g < group_count; ++g) {
    Eigen::Vector2d centre;
    int draw = 0;
    do {
      if (++draw > kMaxDraws) {
        no_place(spec, "group " + std::to_string(g + 1));
      }
      centre = rng.uniform_point(spec.area_min, spec.area_max);
    } while (nearest(centre, centres) < spec.min_centre_distance_m);
    centres.push_back(centre);
    add_group(scenario, spec, rng, g + 1, centre, next_human);
  }
  return centres;
}

// People alone, standing or walking somewhere away from the groups. Returns where they stand.
std::vector<Eigen::Vector2d> add_lone_people(Scenario& scenario, const RandomGroupSceneSpec& spec,
                                             core::Rng& rng,
                                             const std::vector<Eigen::Vector2d>& centres,
                                             model::ObjectId& next_human) {
  std::vector<Eigen::Vector2d> others;
  const unsigned lone_count = static_cast<unsigned>(rng.uniform_index(spec.max_lone_people + 1));
  for (unsigned k = 0; k < lone_count; ++k) {
    world::HumanSpec human;
    human.id = next_human++;
    const std::string what = "person " + std::to_string(human.id);
    // The heading is drawn before the place, as the seeded scenes of docs/perception_gcff.md were.
    const double heading = rng.uniform(-kPi, kPi);
    human.pose = core::Pose2{free_place(spec, rng, centres, others, what), heading};
    draw_looks(human, rng);
    if (rng.bernoulli(0.5)) {
      const Eigen::Vector2d to = free_place(spec, rng, centres, {}, what + "'s goal");
      const Eigen::Vector2d way = to - human.pose.position;
      human.goal = core::Pose2{to, std::atan2(way.y(), way.x())};
    }
    others.push_back(human.pose.position);
    scenario.scene.humans.push_back(human);
  }
  return others;
}

// ARI, and its route past the groups in a random order.
void add_ari_and_route(Scenario& scenario, const RandomGroupSceneSpec& spec, core::Rng& rng,
                       const std::vector<Eigen::Vector2d>& centres,
                       const std::vector<Eigen::Vector2d>& others) {
  world::AriSpec ari;
  const double ari_heading = rng.uniform(-kPi, kPi);
  ari.pose = core::Pose2{free_place(spec, rng, centres, others, "ARI"), ari_heading};
  scenario.scene.ari = ari;
  std::vector<size_t> order(centres.size());
  for (size_t i = 0; i < order.size(); ++i) {
    order[i] = i;
  }
  for (size_t i = order.size(); i > 1; --i) {  // Fisher-Yates
    std::swap(order[i - 1], order[rng.uniform_index(i)]);
  }
  std::vector<core::Pose2> waypoints;
  for (size_t i : order) {
    if (const std::optional<core::Pose2> waypoint = waypoint_by(spec, rng, centres[i], centres)) {
      waypoints.push_back(*waypoint);
    }
  }
  if (waypoints.empty()) {
    no_place(spec, "ARI's waypoints");
  }
  scenario.script = route_script(spec, waypoints);
}

// Where each entry came from, for build_simulation's messages.
void name_entries(world::Scene& scene) {
  for (size_t i = 0; i < scene.humans.size(); ++i) {
    scene.human_fields.push_back(scene.path + ": humans[" + std::to_string(i) + "]");
  }
  for (size_t i = 0; i < scene.groups.size(); ++i) {
    scene.group_fields.push_back(scene.path + ": groups[" + std::to_string(i) + "]");
  }
}

}  // namespace

void RandomGroupSceneSpec::validate() const {
  const auto fail = [](const std::string& field, const std::string& expected,
                       const std::string& got) {
    throw core::ConfigError("RandomGroupSceneSpec: " + field + ": expected " + expected + ", got " +
                            got);
  };
  if (const std::optional<MixProblem> problem = mix_problem(mix)) {
    fail("mix", problem->expected, problem->got);
  }
  if (min_groups < 1 || min_groups > max_groups) {
    fail("min_groups", "1 <= min_groups <= max_groups (" + std::to_string(max_groups) + ")",
         std::to_string(min_groups));
  }
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(kRouteMarginM);
  const Eigen::Vector2d floor_max = world.origin + world.size;
  if (!((area_min.array() < area_max.array()).all() &&
        inside(area_min - margin, world.origin, floor_max) &&
        inside(area_max + margin, world.origin, floor_max))) {
    fail("area_min",
         "a box at least " + core::number_text(kRouteMarginM) + " m inside the floor of " +
             world_path,
         "(" + core::number_text(area_min.x()) + ", " + core::number_text(area_min.y()) + ") to (" +
             core::number_text(area_max.x()) + ", " + core::number_text(area_max.y()) + ")");
  }
  for (const auto& [field, value] : {std::pair{"min_centre_distance", min_centre_distance_m},
                                     std::pair{"waypoint_distance", waypoint_distance_m},
                                     std::pair{"goal_timeout", goal_timeout_s}}) {
    if (!(value > 0.0 && std::isfinite(value))) {
      fail(field, "a finite number > 0", core::number_text(value));
    }
  }
  if (!script_time_limit_bounds().contains(duration_s)) {
    fail("duration",
         "a number " + script_time_limit_bounds().describe() + " (the script's time limit)",
         core::number_text(duration_s));
  }
  for (const auto& [field, value] : {std::pair{"position_jitter", position_jitter_m},
                                     std::pair{"heading_jitter", heading_jitter_rad}}) {
    if (!(value >= 0.0 && std::isfinite(value))) {
      fail(field, "a finite number >= 0", core::number_text(value));
    }
  }
}

Scenario make_random_group_scene(const RandomGroupSceneSpec& spec, uint64_t seed) {
  spec.validate();
  core::Rng rng = core::rng_for(seed, core::rng_streams::kRandomGroupScene);
  Scenario scenario;
  scenario.name = "random_group_scene";
  scenario.scene.path = "random group scene " + std::to_string(seed);
  scenario.scene.world_path = spec.world_path;
  scenario.scene.world = spec.world;
  scenario.scene.seed = seed;

  model::ObjectId next_human = kFirstHuman;
  const std::vector<Eigen::Vector2d> centres = add_groups(scenario, spec, rng, next_human);
  const std::vector<Eigen::Vector2d> others =
      add_lone_people(scenario, spec, rng, centres, next_human);
  add_ari_and_route(scenario, spec, rng, centres, others);
  name_entries(scenario.scene);
  return scenario;
}

}  // namespace ari_social_sim::scenario
