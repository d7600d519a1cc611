#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/config_writer.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/world/robot_reaction.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"
#include "expect_config_error.hpp"
#include "refusal_text.hpp"
#include "scene_builders.hpp"
#include "snapshot_hash.hpp"

namespace ari_social_sim::world {
namespace {

constexpr double kStepS = 0.05;
constexpr model::ObjectId kAri = 1;
constexpr model::ObjectId kPerson = 10;
// ARI's half width (0.27 m) plus a body radius (0.2 m) plus 0.3 m: a person this far from ARI's
// path line leaves ARI's side 0.3 m of air.
constexpr double kClearOfPathM = 0.27 + 0.2 + 0.3;

std::unique_ptr<Simulation> room(double side_m = 12.0, uint64_t seed = 5) {
  return std::make_unique<Simulation>(test::square_room(side_m),
                                      SimulationConfig{kStepS, seed, 0.05});
}

void add_ari(Simulation& sim, double x, double y, double theta) {
  AriSpec ari;
  ari.id = kAri;
  ari.pose = {{x, y}, theta};
  sim.add_ari(ari);
}

HumanSpec person(double x, double y, double theta, ReactionProfile profile) {
  HumanSpec spec;
  spec.id = kPerson;
  spec.pose = {{x, y}, theta};
  spec.reaction = profile;
  return spec;
}

RobotView robot_of(const Simulation& sim) {
  const Ari& ari = *sim.ari();
  return {ari.id(), ari.pose(), ari.spec().footprint, ari.linear_mps()};
}

// Steps `seconds` with ARI commanded (v, w) at every step (its command times out after 0.25 s),
// calling `each` after every step.
template <class Each>
void drive(Simulation& sim, double linear_mps, double angular_rps, double seconds, Each each) {
  const int steps = static_cast<int>(std::lround(seconds / kStepS));
  for (int i = 0; i < steps; ++i) {
    sim.command_ari_twist(linear_mps, angular_rps);
    sim.step();
    each();
  }
}

void drive(Simulation& sim, double linear_mps, double angular_rps, double seconds) {
  drive(sim, linear_mps, angular_rps, seconds, [] {});
}

// The share of steps, among those where ARI is within `range_m` of the person, in which the
// person's reported gaze is at ARI.
struct GazeShare {
  int at_robot{0};
  int steps{0};
  void add(const Simulation& sim, double range_m = 4.0) {
    const WorldSnapshot snapshot = WorldSnapshot::of(sim);
    const HumanSnapshot& h = snapshot.humans.front();
    if (robot_of(sim).distance_to(h.pose.position) < range_m) {
      ++steps;
      at_robot += h.gaze.target == kAri ? 1 : 0;
    }
  }
  double share() const { return steps == 0 ? 0.0 : static_cast<double>(at_robot) / steps; }
};

TEST(RobotView, DistancesAndPathOffsetsAreFromTheFootprintsEdges) {
  // ARI at the origin facing +x: front edge x = 0.16, rear -0.60, sides y = +-0.27.
  RobotView robot{kAri, {{0.0, 0.0}, 0.0}, model::AriFootprint{}, 0.5};
  EXPECT_NEAR(robot.distance_to({1.16, 0.0}), 1.0, 1e-12);   // 1 m ahead of the front
  EXPECT_NEAR(robot.distance_to({-0.3, 1.27}), 1.0, 1e-12);  // 1 m beside the side
  EXPECT_NEAR(robot.distance_to({0.16 + 0.6, 0.27 + 0.8}), 1.0,
              1e-12);                              // 0.6-0.8-1 from the corner
  EXPECT_EQ(robot.distance_to({-0.2, 0.1}), 0.0);  // inside
  const PathOffset ahead = path_offset(robot, {2.0, 0.5});
  EXPECT_NEAR(ahead.ahead_m, 1.84, 1e-12);  // 2 - 0.16
  EXPECT_NEAR(ahead.lateral_m, 0.5, 1e-12);
  // Reversing at 0.2 m/s: the rear leads, and ARI's left is now -y.
  robot.linear_mps = -0.2;
  const PathOffset behind = path_offset(robot, {-2.0, 0.5});
  EXPECT_NEAR(behind.ahead_m, 1.4, 1e-12);  // -0.6 - (-2)
  EXPECT_NEAR(behind.lateral_m, -0.5, 1e-12);
}

TEST(RobotView, TheCorridorIsAheadOfAMovingRobotAndAsWideAsItPlusAPersonalDistance) {
  const ReactionParams params;
  RobotView robot{kAri, {{0.0, 0.0}, 0.0}, model::AriFootprint{}, 0.5};
  // 0.5 m/s: 1.5 s x 0.5 + 2 = 2.75 m ahead of the front edge (x = 2.91); 0.27 + 0.8 = 1.07 m to
  // each side.
  EXPECT_TRUE(in_robot_corridor(robot, {2.9, 1.0}, params));
  EXPECT_FALSE(in_robot_corridor(robot, {2.95, 0.0}, params));
  EXPECT_FALSE(in_robot_corridor(robot, {1.0, 1.1}, params));
  EXPECT_TRUE(in_robot_corridor(robot, {-0.5, 0.9}, params));   // beside ARI's body
  EXPECT_FALSE(in_robot_corridor(robot, {-1.0, 0.0}, params));  // behind it
  robot.linear_mps = 0.04;  // standing (below 0.05 m/s): it needs no way
  EXPECT_FALSE(in_robot_corridor(robot, {1.0, 0.0}, params));
}

TEST(RobotReaction, AYieldingPersonStepsOffThePathWaitsWhileAriPassesThenReturns) {
  auto sim = room();
  add_ari(*sim, 2.0, 6.0, 0.0);
  sim->add_human(person(6.0, 6.0, core::kPi, ReactionProfile::kYield));
  const Human& h = *sim->find_human(kPerson);
  double stepping_since = -1.0, clear_at = -1.0;
  double closest = std::numeric_limits<double>::infinity();
  double fastest_while_passing = 0.0;
  drive(*sim, 0.5, 0.0, 18.0, [&] {
    const auto phase = h.reaction()->phase_state();
    if (phase == RobotReaction::Phase::kSteppingAside && stepping_since < 0.0) {
      stepping_since = sim->time_s();
    }
    const double off_path = std::abs(h.pose().position.y() - 6.0);
    if (stepping_since >= 0.0 && clear_at < 0.0 && off_path >= kClearOfPathM) {
      clear_at = sim->time_s();
    }
    const RobotView robot = robot_of(*sim);
    closest = std::min(closest, robot.distance_to(h.pose().position));
    // While ARI's body is level with the person (front past them, rear not yet), they stand.
    const double x = h.pose().position.x();
    if (robot.pose.position.x() + 0.16 > x && robot.pose.position.x() - 0.6 < x) {
      fastest_while_passing = std::max(fastest_while_passing, h.velocity().norm());
    }
  });
  ASSERT_GT(stepping_since, 0.0);
  ASSERT_GT(clear_at, 0.0);
  // The corridor reaches 2.75 m ahead at 0.5 m/s: ARI's front (2.16) gets there after about
  // 1.1 m, 2.5 s with the ramp. The sidestep is 1.17 m at 1 m/s, slowing over its last 0.3 m.
  EXPECT_LT(clear_at - stepping_since, 2.0);
  EXPECT_GT(stepping_since, 1.5);
  // ARI passed at full speed, never closer than half a metre to the person.
  EXPECT_GT(sim->ari()->pose().position.x(), 10.0);
  EXPECT_GT(closest, kClearOfPathM - 0.27);
  EXPECT_LT(fastest_while_passing, 0.05);
  // ARI's rear left 1 m behind, and its corridor off the person's place: back to it.
  drive(*sim, 0.0, 0.0, 6.0);
  EXPECT_LT((h.pose().position - Eigen::Vector2d(6.0, 6.0)).norm(), 0.1);
  EXPECT_LT(std::abs(core::angle_difference(h.pose().theta, core::kPi)), 0.1);
  EXPECT_EQ(h.reaction()->phase_state(), RobotReaction::Phase::kIdle);
}

TEST(RobotReaction, AYieldingPersonByAWallStepsToTheFreeSide) {
  // ARI drives along the south wall (its face at y = 0.05) on y = 1.0; the person stands at
  // y = 0.6, leaning south of the path, where a sidestep to 1.0 - 1.17 = -0.17 m is wall.
  auto sim = room();
  add_ari(*sim, 2.0, 1.0, 0.0);
  sim->add_human(person(6.0, 0.6, core::kPi, ReactionProfile::kYield));
  const Human& h = *sim->find_human(kPerson);
  double deepest = -1.0, min_y = 10.0;
  drive(*sim, 0.5, 0.0, 12.0, [&] {
    deepest = std::max(deepest, sim->static_penetration_m(h));
    if (std::abs(sim->ari()->pose().position.x() - 6.0) < 0.4) {
      min_y = std::min(min_y, h.pose().position.y());
    }
  });
  EXPECT_LT(deepest, 0.005);              // never into the wall
  EXPECT_GE(min_y, 1.0 + kClearOfPathM);  // north of the path while ARI passed
  EXPECT_GT(sim->ari()->pose().position.x(), 7.5);
}

TEST(RobotReaction, AYieldingPersonByTheFlatsDoorLetsAriThrough) {
  // two_room_flat.yaml's 1 m door: x = 5, y from 1 to 2. The person stands 1 m inside the living
  // room on the door's axis; ARI comes from the kitchen along the axis.
  auto sim = std::make_unique<Simulation>(
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/two_room_flat.yaml"),
      SimulationConfig{kStepS, 3, 0.05});
  add_ari(*sim, 7.2, 1.5, core::kPi);
  sim->add_human(person(4.0, 1.4, 0.0, ReactionProfile::kYield));
  const Human& h = *sim->find_human(kPerson);
  double deepest = -1.0, closest = 10.0;
  drive(*sim, 0.4, 0.0, 14.0, [&] {
    deepest = std::max(deepest, sim->static_penetration_m(h));
    closest = std::min(closest, robot_of(*sim).distance_to(h.pose().position));
  });
  EXPECT_LT(sim->ari()->pose().position.x(), 2.5);  // through the door and on into the room
  EXPECT_LT(deepest, 0.005);
  EXPECT_GT(closest, 0.45);
}

TEST(RobotReaction, ACuriousPersonStopsFacesAriWalksUpToItAndLooksAtIt) {
  auto sim = room();
  add_ari(*sim, 2.0, 6.0, 0.0);
  HumanSpec spec = person(6.5, 6.0, 0.0, ReactionProfile::kCurious);  // back to ARI
  spec.reaction_params = ReactionParams{};
  spec.reaction_params->curious_approach_probability = 1.0;
  sim->add_human(spec);
  const Human& h = *sim->find_human(kPerson);
  GazeShare gaze;
  double closest = 10.0;
  // ARI drives 1 m toward the person (its front then 3.3 m away), then stands.
  drive(*sim, 0.5, 0.0, 2.5, [&] { gaze.add(*sim); });
  drive(*sim, 0.0, 0.0, 20.0, [&] {
    gaze.add(*sim);
    closest = std::min(closest, robot_of(*sim).distance_to(h.pose().position));
  });
  const RobotView robot = robot_of(*sim);
  const double distance = robot.distance_to(h.pose().position);
  EXPECT_GE(distance, 1.0);
  EXPECT_LE(distance, 1.6);
  EXPECT_GE(closest, 0.98);
  const Eigen::Vector2d to_robot = robot.centre() - h.pose().position;
  EXPECT_LT(
      std::abs(core::angle_difference(std::atan2(to_robot.y(), to_robot.x()), h.pose().theta)),
      core::deg_to_rad(10.0));
  EXPECT_LT(h.velocity().norm(), 0.02);
  EXPECT_GE(gaze.share(), 0.6);  // 0.85 of the gaze events at ARI, exponential 1 s dwells
}

TEST(RobotReaction, ACuriousWalkerStopsWhileAriIsNearAndWalksOnOnceItIsGone) {
  auto sim = room();
  add_ari(*sim, 2.0, 2.0, 0.0);
  HumanSpec spec = person(3.0, 6.0, 0.0, ReactionProfile::kCurious);
  spec.reaction_params = ReactionParams{};
  spec.reaction_params->curious_approach_probability = 0.0;
  spec.goal = core::Pose2{{11.0, 6.0}, 0.0};
  sim->add_human(spec);
  const Human& h = *sim->find_human(kPerson);
  // ARI's outline is 3.7 m away: noticed at once.
  drive(*sim, 0.0, 0.0, 2.0);
  EXPECT_LT(h.velocity().norm(), 0.02);
  EXPECT_LT(h.pose().position.x(), 3.1);
  // ARI placed 9 m away: the walker walks on to its goal.
  sim->set_pose(kAri, {{1.0, 11.0}, 0.0});
  drive(*sim, 0.0, 0.0, 12.0);
  EXPECT_LT((h.pose().position - Eigen::Vector2d(11.0, 6.0)).norm(), 0.1);
}

TEST(RobotReaction, AnAvoidingPersonKeepsAwayAndRarelyLooks) {
  auto sim = room();
  add_ari(*sim, 2.0, 6.0, 0.0);
  sim->add_human(person(6.0, 6.2, core::kPi, ReactionProfile::kAvoid));
  const Human& h = *sim->find_human(kPerson);
  GazeShare gaze;
  double closest = 10.0, deepest = -1.0;
  // ARI drives 6 m straight at where the person stood, at 0.6 m/s.
  drive(*sim, 0.6, 0.0, 11.0, [&] {
    gaze.add(*sim);
    closest = std::min(closest, robot_of(*sim).distance_to(h.pose().position));
    deepest = std::max(deepest, sim->static_penetration_m(h));
  });
  EXPECT_GT(sim->ari()->pose().position.x(), 7.5);
  EXPECT_GE(closest, 2.0);  // avoid_distance 2.5 m, full speed 0.2 m inside it
  EXPECT_LE(gaze.share(), 0.2);
  EXPECT_GT(gaze.steps, 100);
  EXPECT_LT(deepest, 0.005);
  // Turned away: ARI's centre more than 90 degrees off the person's heading.
  const Eigen::Vector2d to_robot = robot_of(*sim).centre() - h.pose().position;
  EXPECT_GT(
      std::abs(core::angle_difference(std::atan2(to_robot.y(), to_robot.x()), h.pose().theta)),
      core::kPi / 2);
}

TEST(RobotReaction, ABlockingPersonStaysInFrontOfAri) {
  auto sim = room();
  add_ari(*sim, 2.0, 4.0, 0.0);
  sim->add_human(person(4.5, 6.0, 0.0, ReactionProfile::kBlock));
  const Human& h = *sim->find_human(kPerson);
  drive(*sim, 0.3, 0.05, 3.0);  // time to get in front
  int in_front = 0, steps = 0;
  drive(*sim, 0.3, 0.05, 12.0, [&] {
    // In ARI's frame: ahead of its front edge by 0.6 to 1.3 m, within 0.5 m of its heading line.
    const Eigen::Vector2d local =
        core::Pose2{h.pose().position, 0.0}.relative_to(sim->ari()->pose()).position;
    const double ahead = local.x() - 0.16;
    ++steps;
    in_front += ahead > 0.6 && ahead < 1.3 && std::abs(local.y()) < 0.5 ? 1 : 0;
  });
  EXPECT_GE(static_cast<double>(in_front) / steps, 0.9);
}

// A pair standing as group 1 around (6, 6), members 10 (south) and 11 (north); ARI drives from
// (2, 6) for 5 s at 0.5 m/s, to 1.8 m from the group's centre, and stands there for 15 s. Returns
// how far each member moved at most from where it stood before ARI came (m), and the share of
// member 10's gaze at ARI.
struct PairRun {
  double moved[2]{0.0, 0.0};
  double gaze_share{0.0};
  model::ObjectId group[2]{0, 0};
};

// ARI drives east along y = `ari_y` toward (or, off y = 6, past) a pair standing north and south
// of (6, 6). Straight at the pair, ARI ends within reach of its o-space, facing it: the pair then
// opens a place for it (docs/world.md section 4.6).
PairRun pair_meets_ari(ReactionProfile south, ReactionProfile north, double ari_y = 6.0) {
  auto sim = room();
  add_ari(*sim, 2.0, ari_y, 0.0);
  HumanSpec a = person(6.0, 5.4, core::kPi / 2, south);
  HumanSpec b = person(6.0, 6.6, -core::kPi / 2, north);
  b.id = 11;
  sim->add_human(a);
  sim->add_human(b);
  GroupSpec group;
  group.id = 1;
  group.members = {10, 11};
  group.centre = {6.0, 6.0};
  test::without_manners(group);  // no shifts of their own: what moves them is their reaction
  sim->add_group(group);
  drive(*sim, 0.0, 0.0, 10.0);  // the pair settles on its o-space circle
  const Eigen::Vector2d start[2] = {sim->find_human(10)->pose().position,
                                    sim->find_human(11)->pose().position};
  PairRun run;
  GazeShare gaze;
  auto measure = [&] {
    gaze.add(*sim);
    for (int i = 0; i < 2; ++i) {
      const Human& h = *sim->find_human(10 + i);
      run.moved[i] = std::max(run.moved[i], (h.pose().position - start[i]).norm());
    }
  };
  drive(*sim, 0.5, 0.0, 5.0, measure);
  drive(*sim, 0.0, 0.0, 15.0, measure);
  run.gaze_share = gaze.share();
  run.group[0] = sim->find_human(10)->group_id();
  run.group[1] = sim->find_human(11)->group_id();
  return run;
}

TEST(RobotReaction, CuriousGroupMembersLookAtAriWithoutLeavingTheirPlace) {
  // ARI passes 2 m south of the pair's centre, in their sight, without joining them.
  const PairRun run = pair_meets_ari(ReactionProfile::kCurious, ReactionProfile::kCurious, 4.0);
  EXPECT_EQ(run.group[0], 1u);
  EXPECT_EQ(run.group[1], 1u);
  EXPECT_GE(run.gaze_share, 0.6);
  EXPECT_LT(run.moved[0], 0.02);
  EXPECT_LT(run.moved[1], 0.02);
}

TEST(RobotReaction, AnAvoidingGroupMemberShiftsAwayABitAndStaysAMember) {
  const PairRun run = pair_meets_ari(ReactionProfile::kIgnore, ReactionProfile::kAvoid);
  EXPECT_EQ(run.group[1], 1u);
  EXPECT_GT(run.moved[1], 0.1);    // steps away from ARI ...
  EXPECT_LT(run.moved[1], 0.45);   // ... no further than group_offset (0.3 m) and the group's pull
  EXPECT_LT(run.gaze_share, 0.6);  // member 10 ignores ARI: no gaze override
}

TEST(RobotReaction, AYieldingGroupMemberInAriSWaySidestepsABitAndStaysAMember) {
  // Member 10 stands 0.6 m south of ARI's path line: in its corridor while ARI drives. ARI stops
  // short of joining (docs/world.md section 4.6), so the step is the reaction's alone, held back
  // by the group's cohesion.
  const PairRun run = pair_meets_ari(ReactionProfile::kYield, ReactionProfile::kIgnore);
  EXPECT_EQ(run.group[0], 1u);
  EXPECT_GT(run.moved[0], 0.05);
  EXPECT_LT(run.moved[0], 0.45);
}

std::unique_ptr<Simulation> reacting_crowd(uint64_t seed, bool set_back_to_ignore = false) {
  auto sim = room(12.0, seed);
  add_ari(*sim, 2.0, 6.0, 0.0);
  const ReactionProfile profiles[] = {ReactionProfile::kYield, ReactionProfile::kCurious,
                                      ReactionProfile::kAvoid, ReactionProfile::kBlock};
  for (int i = 0; i < 4; ++i) {
    HumanSpec spec = person(5.0 + 1.5 * i, 3.0 + 2.0 * i, 0.0, profiles[i]);
    spec.id = static_cast<model::ObjectId>(10 + i);
    if (set_back_to_ignore) {
      spec.reaction = ReactionProfile::kIgnore;
    }
    sim->add_human(spec);
    if (set_back_to_ignore) {
      sim->set_human_reaction(spec.id, profiles[i]);
      sim->set_human_reaction(spec.id, ReactionProfile::kIgnore);
    }
  }
  return sim;
}

TEST(RobotReaction, SameSeedSameRunOtherSeedOtherRun) {
  auto a = reacting_crowd(7), b = reacting_crowd(7), c = reacting_crowd(8);
  bool differs = false;
  for (int i = 0; i < 300; ++i) {
    for (Simulation* sim : {a.get(), b.get(), c.get()}) {
      sim->command_ari_twist(0.4, 0.1);
      sim->step();
    }
    const uint64_t ha = test::hash_of(WorldSnapshot::of(*a));
    ASSERT_EQ(ha, test::hash_of(WorldSnapshot::of(*b))) << "step " << i;
    differs = differs || ha != test::hash_of(WorldSnapshot::of(*c));
  }
  EXPECT_TRUE(differs);  // gaze events and the curious person's approach draw from the seed
}

TEST(RobotReaction, IgnoreIsTheWorldWithoutReactions) {
  // People who never reacted and people set back to ignore move alike, step for step, and
  // report the gaze they always did.
  auto never = room(12.0, 7), reset = reacting_crowd(7, true);
  add_ari(*never, 2.0, 6.0, 0.0);
  for (int i = 0; i < 4; ++i) {
    HumanSpec spec = person(5.0 + 1.5 * i, 3.0 + 2.0 * i, 0.0, ReactionProfile::kIgnore);
    spec.id = static_cast<model::ObjectId>(10 + i);
    never->add_human(spec);
  }
  for (int i = 0; i < 300; ++i) {
    for (Simulation* sim : {never.get(), reset.get()}) {
      sim->command_ari_twist(0.4, 0.1);
      sim->step();
    }
    ASSERT_EQ(test::hash_of(WorldSnapshot::of(*never)), test::hash_of(WorldSnapshot::of(*reset)))
        << i;
  }
  EXPECT_EQ(never->find_human(10)->reaction(), nullptr);  // no component at all
  EXPECT_EQ(WorldSnapshot::of(*reset).humans[0].reaction, ReactionProfile::kIgnore);
}

TEST(RobotReaction, RequestsNameTheUnknownIdOrProfile) {
  auto sim = room();
  add_ari(*sim, 2.0, 6.0, 0.0);
  sim->add_human(person(6.0, 6.0, 0.0, ReactionProfile::kIgnore));
  EXPECT_EQ(test::refusal_text([&] { sim->set_human_reaction(99, "yield"); }),
            "set_reaction: id: no human with id 99");
  EXPECT_EQ(test::refusal_text([&] { sim->set_human_reaction(kPerson, "shy"); }),
            "set_reaction: profile: expected ignore, yield, curious, avoid or block, got 'shy'");
  EXPECT_EQ(test::refusal_text([&] { sim->set_human_reaction(kAri, "yield"); }),
            "set_reaction: id: no human with id 1");
  EXPECT_EQ(sim->find_human(kPerson)->reaction_profile(), ReactionProfile::kIgnore);
  sim->set_human_reaction(kPerson, "block");
  EXPECT_EQ(sim->find_human(kPerson)->reaction_profile(), ReactionProfile::kBlock);
  EXPECT_EQ(WorldSnapshot::of(*sim).humans[0].reaction, ReactionProfile::kBlock);
}

TEST(RobotReaction, ParametersAreCheckedAsFilesAreRead) {
  HumanSpec spec = person(6.0, 6.0, 0.0, ReactionProfile::kCurious);
  spec.reaction_params = ReactionParams{};
  EXPECT_EQ(test::refusal_text([&] { spec.validate(); }), "");
  spec.reaction_params->avoid_distance_m = 0.0;
  EXPECT_EQ(test::refusal_text([&] { spec.validate(); }),
            "reaction_params.avoid_distance: expected a number (0, 20], got 0");
  spec.reaction_params = ReactionParams{};
  spec.reaction_params->curious_min_distance_m = 1.5;
  EXPECT_EQ(test::refusal_text([&] { spec.validate(); }),
            "reaction_params.curious_min_distance: expected a number <= curious_distance (1.2), "
            "got 1.5");
  spec.reaction_params = ReactionParams{};
  spec.reaction_params->curious_look_share = 1.5;
  EXPECT_EQ(test::refusal_text([&] { spec.validate(); }),
            "reaction_params.curious_look_share: expected a number [0, 1], got 1.5");

  // A human written with its reaction reads back the same.
  spec.reaction_params = ReactionParams{};
  spec.reaction_params->block_distance_m = 0.8;
  const HumanSpec read =
      core::read_fields<HumanSpec>(core::YamlMap::parse(core::write_fields(spec), "written"));
  EXPECT_EQ(read.reaction, ReactionProfile::kCurious);
  ASSERT_TRUE(read.reaction_params.has_value());
  EXPECT_EQ(read.reaction_params->block_distance_m, 0.8);
}

TEST(RobotReaction, SceneFilesNameTheBadReactionField) {
  const std::string path = ::testing::TempDir() + "reaction_scene.yaml";
  const std::string head = "world: " + std::string(ARI_SOURCE_DIR) +
                           "/worlds/room_6x6.yaml\nseed: 3\nhumans:\n  - {id: 10, position: [3, 3]";
  auto load = [&](const std::string& entry) {
    std::ofstream(path) << head << entry << "}\n";
    return [&] { build_simulation(load_scene_file(path), SimulationConfig{}); };
  };
  test::expect_config_error(load(", reaction: shy"), path,
                            {"humans[0].reaction",
                             "expected ignore, yield, curious, avoid or "
                             "block, got 'shy'"});
  test::expect_config_error(load(", reaction: avoid, reaction_params: {avoid_distance: -1}"), path,
                            {"humans[0].reaction_params.avoid_distance", "(0, 20]", "-1"});
  test::expect_config_error(load(", reaction_params: {notice: 3}"), path,
                            {"humans[0].reaction_params", "unknown field(s) notice"});
  std::ofstream(path) << head << ", reaction: yield, reaction_params: {corridor_margin: 0.6}}\n";
  const auto sim = build_simulation(load_scene_file(path), SimulationConfig{});
  const Human& h = *sim->find_human(10);
  EXPECT_EQ(h.reaction_profile(), ReactionProfile::kYield);
  ASSERT_NE(h.reaction(), nullptr);
  EXPECT_EQ(h.reaction()->params().corridor_margin_m, 0.6);
}

}  // namespace
}  // namespace ari_social_sim::world
