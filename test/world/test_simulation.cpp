#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/box2d_shapes.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"
#include "scene_builders.hpp"
#include "snapshot_hash.hpp"

namespace ari_social_sim::world {
namespace {

HumanSpec person(model::ObjectId id, double x, double y, double theta = 0.0) {
  HumanSpec spec;
  spec.id = id;
  spec.pose = {{x, y}, theta};
  return spec;
}

std::unique_ptr<Simulation> crowd(uint64_t seed) {
  auto simulation =
      std::make_unique<Simulation>(test::square_room(8.0), SimulationConfig{0.05, seed, 0.05});
  core::Rng layout(99);  // the same people in every run; only the simulation seed differs
  const std::vector<model::ObjectId> ids =
      test::add_random_humans(*simulation, 8, 8.0, 0.5, layout);
  for (model::ObjectId id : ids) {
    GazeModel gaze;
    gaze.targets = {{ids[(id + 1) % ids.size()], 0.6}, {ids[(id + 2) % ids.size()], 0.4}};
    gaze.mean_duration_s = 1.0;
    simulation->set_human_gaze(id, gaze);
  }
  GroupSpec group;
  group.id = 1;
  group.members = {ids[0], ids[1], ids[2]};
  group.centre = {4.0, 4.0};
  simulation->add_group(group);
  simulation->set_human_goal(ids[5], {{1.0, 7.0}, 0.0});
  return simulation;
}

TEST(Simulation, SameSeedSameRunOtherSeedOtherRun) {
  auto a = crowd(7), b = crowd(7), c = crowd(8);
  bool differs = false;
  for (int i = 0; i < 600; ++i) {
    a->step();
    b->step();
    c->step();
    const uint64_t ha = test::hash_of(WorldSnapshot::of(*a));
    ASSERT_EQ(ha, test::hash_of(WorldSnapshot::of(*b))) << "step " << i;
    differs = differs || ha != test::hash_of(WorldSnapshot::of(*c));
  }
  EXPECT_TRUE(differs);
}

TEST(Simulation, WallsStopHumansWalkingIntoThem) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  HumanSpec runner = person(10, 3.0, 3.0);
  runner.motion.max_speed_mps = 1.5;
  const Human& human = simulation.add_human(runner);
  simulation.set_human_velocity(10, {1.5, 0.0}, 0.0);
  for (int i = 0; i < 100; ++i) {
    simulation.step();
    ASSERT_LT(simulation.static_penetration_m(human), 0.005);
  }
  // East wall inner face at x = 5.95; the body's radius 0.2 keeps the centre at <= 5.75 (+ slop).
  EXPECT_NEAR(human.pose().position.x(), 5.75, 0.02);
}

TEST(Simulation, NobodyLeavesTheFloorThroughAnOpening) {
  // A room without its east wall: the floor ends 0.2 m past where the wall would stand (x 6.2).
  model::WorldDescription open_room = test::square_room(6.0);
  open_room.objects.erase(
      std::remove_if(open_room.objects.begin(), open_room.objects.end(),
                     [](const model::StaticObject& wall) { return wall.pose.position.x() > 5.9; }),
      open_room.objects.end());
  ASSERT_EQ(open_room.objects.size(), 3u);
  Simulation simulation(open_room, SimulationConfig{});
  simulation.add_human(person(10, 3.0, 3.0));
  simulation.set_human_velocity(10, {1.3, 0.0}, 0.0);
  for (int i = 0; i < 200; ++i) {  // 10 s at 1.3 m/s: 13 m, far past the floor without a fence
    simulation.step();
  }
  // The floor's edge at x = 6.2 stops the body's radius of 0.2 short of it (+ Box2D's slop).
  EXPECT_NEAR(simulation.find_human(10)->pose().position.x(), 6.0, 0.02);
}

TEST(Simulation, HumanNavigationReachesItsGoalPose) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  const Human& human = simulation.add_human(person(10, 1.0, 1.0));
  simulation.set_human_goal(10, {{4.0, 5.0}, M_PI / 2});
  for (int i = 0; i < 200; ++i) {  // 10 s for a 5 m walk at 1 m/s
    simulation.step();
  }
  EXPECT_LT((human.pose().position - Eigen::Vector2d(4.0, 5.0)).norm(), 0.02);
  EXPECT_NEAR(human.pose().theta, M_PI / 2, 0.01);
}

TEST(Simulation, RepulsionKeepsWalkersApartWhenCrossing) {
  Simulation simulation(test::square_room(8.0), SimulationConfig{});
  const Human& a = simulation.add_human(person(10, 1.0, 4.0));
  const Human& b = simulation.add_human(person(11, 7.0, 4.05));
  simulation.set_human_goal(10, {{7.0, 4.0}, 0.0});
  simulation.set_human_goal(11, {{1.0, 4.0}, M_PI});
  double closest = 10.0;
  for (int i = 0; i < 400; ++i) {
    simulation.step();
    closest = std::min(closest, (a.pose().position - b.pose().position).norm());
  }
  // Head on, D6.4's repulsion has no sideways part: the walkers meet, and the contact (bodies
  // of radius 0.2 m, Box2D slop 5 mm) slides them past each other without passing through; both
  // arrive.
  EXPECT_GT(closest, 0.4 - 0.015);
  EXPECT_LT((a.pose().position - Eigen::Vector2d(7.0, 4.0)).norm(), 0.1);
  EXPECT_LT((b.pose().position - Eigen::Vector2d(1.0, 4.0)).norm(), 0.1);
}

TEST(Simulation, AriDrivesWithinItsLimitsAndStopsAfterTheCommandTimeout) {
  Simulation simulation(test::square_room(8.0), SimulationConfig{});
  AriSpec spec;
  spec.pose = {{2.0, 4.0}, 0.0};
  const Ari& ari = simulation.add_ari(spec);
  // 0.5 m/s held for 5 s (re-sent at 20 Hz): the 1 m/s^2 ramp reaches 0.05, 0.10, ... 0.5 m/s in
  // ten 0.05 s steps (0.1375 m), then 90 steps at 0.5 m/s cover 2.25 m: 2.3875 m.
  for (int i = 0; i < 100; ++i) {
    simulation.command_ari_twist(0.5, 0.0);
    simulation.step();
  }
  EXPECT_NEAR(ari.pose().position.x() - 2.0, 2.3875, 0.005);
  // Commands stop: after the 0.25 s timeout the base decelerates at 1 m/s^2 to rest.
  for (int i = 0; i < 40; ++i) {
    simulation.step();
  }
  EXPECT_NEAR(ari.drive().linear_mps(), 0.0, 1e-9);
  // Beyond the limits: 3 m/s and 5 rad/s are clamped to 1 m/s and 2.094 rad/s, and counted.
  const uint64_t clamped_before = simulation.diagnostics().clamped_commands;
  for (int i = 0; i < 60; ++i) {
    simulation.command_ari_twist(3.0, 5.0);
    simulation.step();
  }
  EXPECT_NEAR(ari.drive().linear_mps(), 1.0, 1e-9);
  EXPECT_NEAR(ari.drive().angular_rps(), 2.094, 1e-9);
  EXPECT_EQ(simulation.diagnostics().clamped_commands - clamped_before, 60u);
}

TEST(Simulation, AriCannotDriveThroughAWall) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  AriSpec spec;
  spec.pose = {{3.0, 3.0}, 0.0};
  const Ari& ari = simulation.add_ari(spec);
  for (int i = 0; i < 200; ++i) {
    simulation.command_ari_twist(1.0, 0.0);
    simulation.step();
  }
  // The front of the base (0.16 m ahead of base_footprint) stops at the wall's face, x = 5.95.
  EXPECT_NEAR(ari.pose().position.x(), 5.95 - 0.16 - 0.01, 0.02);
}

TEST(Simulation, AriFollowsThe3dBasesPose) {
  // 3D mode: each step lands ARI's 2D body on the pose ari_physics_node reported, 0.02 m and
  // 0.01 rad further each step, and reports the given twist.
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  AriSpec spec;
  spec.pose = {{3.0, 3.0}, 0.0};
  const Ari& ari = simulation.add_ari(spec);
  for (int i = 1; i <= 20; ++i) {
    simulation.follow_ari({{3.0 + 0.02 * i, 3.0}, 0.01 * i}, 0.4, 0.2);
    simulation.step();
  }
  EXPECT_NEAR(ari.pose().position.x(), 3.4, 1e-4);
  EXPECT_NEAR(ari.pose().theta, 0.2, 1e-4);
  EXPECT_DOUBLE_EQ(ari.linear_mps(), 0.4);
  EXPECT_TRUE(ari.is_following());
}

TEST(Simulation, SpawnRequestsAreCheckedAgainstWallsPeopleAndIds) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  simulation.add_human(person(10, 3.0, 3.0));
  EXPECT_THROW(simulation.add_human(person(11, 3.2, 3.0)), core::RequestError);  // overlaps 10
  EXPECT_THROW(simulation.add_human(person(10, 1.0, 1.0)), core::RequestError);  // id taken
  EXPECT_THROW(simulation.add_human(person(12, 0.1, 3.0)), core::RequestError);  // in the wall
  EXPECT_THROW(simulation.add_human(person(13, 9.0, 3.0)), core::RequestError);  // off the floor
  EXPECT_THROW(simulation.remove_human(99), core::RequestError);
  EXPECT_EQ(simulation.humans().size(), 1u);
  EXPECT_EQ(simulation.next_free_id(10), 11u);
}

// A removed human's id is never handed out again within a run, so that a consumer of
// /sim/world_state or a bag cannot mistake the next person for them: spawn (automatic id 10),
// remove 10, spawn again: 11, not 10. Asking for 10 by name is refused, naming it; a new
// simulation (what /sim/reset builds) starts over at 10.
TEST(Simulation, ARemovedHumansIdIsNotReused) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  const model::ObjectId first = simulation.add_human(person(model::kNoObject, 2.0, 3.0)).id();
  EXPECT_EQ(first, 10u);
  simulation.remove_human(first);
  const model::ObjectId second = simulation.add_human(person(model::kNoObject, 2.0, 3.0)).id();
  EXPECT_EQ(second, 11u);
  EXPECT_EQ(simulation.next_free_id(10), 12u);
  try {
    simulation.add_human(person(10, 4.0, 3.0));
    ADD_FAILURE() << "a removed human's id was accepted again";
  } catch (const core::RequestError& e) {
    EXPECT_NE(std::string(e.what()).find("id: expected an id not used earlier in this run"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("got 10"), std::string::npos) << e.what();
  }
  EXPECT_EQ(simulation.humans().size(), 1u);

  Simulation reset(test::square_room(6.0), SimulationConfig{});
  EXPECT_EQ(reset.add_human(person(model::kNoObject, 2.0, 3.0)).id(), 10u);
}

TEST(Simulation, AGoalTakesAHumanOutOfItsGroupAndSpeakersAreFoundById) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  simulation.add_human(person(10, 2.0, 3.0));
  simulation.add_human(person(11, 4.0, 3.0));
  AriSpec ari;
  ari.pose = {{1.0, 1.0}, 0.0};
  simulation.add_ari(ari);
  GroupSpec group;
  group.id = 1;
  group.members = {10, 11};
  group.centre = {3.0, 3.0};
  simulation.add_group(group);
  simulation.set_human_goal(10, {{1.0, 5.0}, 0.0});
  EXPECT_EQ(simulation.find_human(10)->group_id(), model::kNoObject);
  EXPECT_EQ(simulation.find_human(10)->motion_mode(), MotionMode::kNavigation);
  EXPECT_EQ(simulation.find_group(1)->members(), std::vector<model::ObjectId>{11});
  EXPECT_THROW(simulation.set_human_goal(12, {{1.0, 5.0}, 0.0}), core::RequestError);
  // Two words at the default 150 words per minute: 0.8 s.
  EXPECT_DOUBLE_EQ(simulation.say(1, "GREETING", "hello there"), 0.8);
  EXPECT_EQ(simulation.ari()->speech().content(), "hello there");
  EXPECT_DOUBLE_EQ(simulation.say(11, "INFORM", "one two three"), 1.2);
  EXPECT_EQ(simulation.find_human(11)->speech().act(), "INFORM");
  EXPECT_THROW(simulation.say(1002, "INFORM", "hello"), core::RequestError);  // a wall is mute
}

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// test::request_world, with 12 gazing at 10.
std::unique_ptr<Simulation> request_world() {
  auto simulation = test::request_world();
  GazeModel gaze;
  gaze.targets = {{10, 1.0}};
  simulation->set_human_gaze(12, gaze);
  return simulation;
}

// Every number of the ground truth, plus the modes, goals and groups: equal hashes, equal worlds.
uint64_t full_hash(const WorldSnapshot& s) {
  uint64_t h = test::hash_of(s);
  auto mix = [&h](double value) {
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    h = (h ^ bits) * 1099511628211ULL;
  };
  for (const HumanSnapshot& human : s.humans) {
    mix(human.velocity_mps.x());
    mix(human.velocity_mps.y());
    mix(human.angular_velocity_rps);
    mix(static_cast<double>(human.motion_mode));
    mix(human.group_id);
    mix(human.goal ? human.goal->position.x() : -1.0);
  }
  for (const GroupSnapshot& group : s.groups) {
    mix(group.id);
    mix(group.members.size());
    mix(group.centre.x());
    mix(group.centre.y());
    mix(group.ospace_radius_m);
  }
  mix(s.ari->pose.position.x());
  mix(s.ari->pose.position.y());
  mix(s.ari->pose.theta);
  mix(s.ari->linear_mps);
  mix(s.ari->head_pan_rad);
  return h;
}

bool all_finite(const WorldSnapshot& s) {
  bool finite = s.ari->pose.position.allFinite() && std::isfinite(s.ari->pose.theta) &&
                std::isfinite(s.ari->head_pan_rad) && std::isfinite(s.ari->linear_mps);
  for (const HumanSnapshot& human : s.humans) {
    finite = finite && human.pose.position.allFinite() && std::isfinite(human.pose.theta) &&
             human.velocity_mps.allFinite() && std::isfinite(human.gaze.direction_rad);
  }
  for (const GroupSnapshot& group : s.groups) {
    finite = finite && group.centre.allFinite() && std::isfinite(group.ospace_radius_m);
  }
  return finite;
}

struct BadRequest {
  std::string expected;  // the start of the refusal: request and field
  std::function<void(Simulation&)> send;
};

// One refused request per numeric field of every request world_node serves (and the ARI commands
// its topics give), NaN, infinity or out of range.
std::vector<BadRequest> bad_requests() {
  auto spawn = [](double x, double y, double theta, double age) {
    return [=](Simulation& sim) {
      HumanSpec spec = person(20, x, y, theta);
      spec.age_years = age;
      sim.add_human(spec);
    };
  };
  auto group = [](double cx, double cy, double radius) {
    return [=](Simulation& sim) {
      GroupSpec spec;
      spec.id = 2;
      spec.members = {12};
      spec.centre = {cx, cy};
      spec.ospace_radius_m = radius;
      sim.add_group(spec);
    };
  };
  auto gaze = [](double probability, double mean_duration_s) {
    return [=](Simulation& sim) {
      GazeModel model;
      model.targets = {{11, probability}};
      model.mean_duration_s = mean_duration_s;
      sim.set_human_gaze(12, model);
    };
  };
  const std::string floor = "expected a finite number inside the world [-0.2, 6.2], got ";
  return {
      {"spawn_human: pose.x: " + floor + "nan", spawn(kNan, 1.0, 0.0, 30.0)},
      {"spawn_human: pose.y: " + floor + "inf", spawn(1.0, kInf, 0.0, 30.0)},
      {"spawn_human: pose.x: " + floor + "20", spawn(20.0, 1.0, 0.0, 30.0)},
      {"spawn_human: pose.theta: expected a finite number [-1e+06, 1e+06] rad, got nan",
       spawn(1.0, 1.0, kNan, 30.0)},
      {"spawn_human: age: expected a number [0, 130], got nan", spawn(1.0, 1.0, 0.0, kNan)},
      {"spawn_human: age: expected a number [0, 130], got 200", spawn(1.0, 1.0, 0.0, 200.0)},
      {"set_goal: goal.x: " + floor + "nan",
       [](Simulation& sim) {
         sim.set_human_goal(10, {{kNan, 1.0}, 0.0});
       }},
      {"set_goal: goal.y: " + floor + "inf",
       [](Simulation& sim) {
         sim.set_human_goal(10, {{1.0, kInf}, 0.0});
       }},
      {"set_goal: goal.x: " + floor + "-50",
       [](Simulation& sim) {
         sim.set_human_goal(10, {{-50.0, 1.0}, 0.0});
       }},
      {"set_goal: goal.theta: expected a finite number [-1e+06, 1e+06] rad, got nan",
       [](Simulation& sim) {
         sim.set_human_goal(10, {{1.0, 1.0}, kNan});
       }},
      {"set_velocity: vx: expected a finite number, got nan",
       [](Simulation& sim) {
         sim.set_human_velocity(10, {kNan, 0.0}, 0.0);
       }},
      {"set_velocity: vy: expected a finite number, got -inf",
       [](Simulation& sim) {
         sim.set_human_velocity(10, {0.0, -kInf}, 0.0);
       }},
      // 1e300 is finite, and 1e300 m/s beyond the default max_speed of 1.3 m/s.
      {"set_velocity: (vx, vy): expected a speed of at most 1.3 m/s (human 10's max_speed), got "
       "1e+300 m/s",
       [](Simulation& sim) {
         sim.set_human_velocity(10, {1e300, 0.0}, 0.0);
       }},
      // (1, 1) m/s is 1.414 m/s.
      {"set_velocity: (vx, vy): expected a speed of at most 1.3 m/s (human 10's max_speed), got "
       "1.41421 m/s",
       [](Simulation& sim) {
         sim.set_human_velocity(10, {1.0, 1.0}, 0.0);
       }},
      {"set_velocity: omega: expected a finite number [-6.28319, 6.28319] rad/s, got nan",
       [](Simulation& sim) {
         sim.set_human_velocity(10, {0.5, 0.0}, kNan);
       }},
      {"set_pose: pose.x: " + floor + "nan",
       [](Simulation& sim) {
         sim.set_pose(10, {{kNan, 1.0}, 0.0});
       }},
      {"set_pose: pose.y: " + floor + "-inf",
       [](Simulation& sim) {
         sim.set_pose(1, {{1.0, -kInf}, 0.0});
       }},  // ARI
      {"set_pose: pose.theta: expected a finite number [-1e+06, 1e+06] rad, got 1e+300",
       [](Simulation& sim) {
         sim.set_pose(10, {{1.0, 1.0}, 1e300});
       }},
      {"create_group: centre.x: " + floor + "nan", group(kNan, 3.0, 0.0)},
      {"create_group: centre.y: " + floor + "inf", group(3.0, kInf, 0.0)},
      {"create_group: centre.x: " + floor + "7", group(7.0, 3.0, 0.0)},
      {"create_group: ospace_radius: expected a number [0, 10], got nan", group(3.0, 3.0, kNan)},
      {"create_group: ospace_radius: expected a number [0, 10], got inf", group(3.0, 3.0, kInf)},
      {"create_group: ospace_radius: expected a number [0, 10], got 11", group(3.0, 3.0, 11.0)},
      {"set_group_centre: centre.x: " + floor + "nan",
       [](Simulation& sim) {
         sim.set_group_centre(1, {kNan, 3.0});
       }},
      {"set_group_centre: centre.y: " + floor + "inf",
       [](Simulation& sim) {
         sim.set_group_centre(1, {3.0, kInf});
       }},
      {"set_gaze_targets: targets[0].probability: expected a number [0, 1], got nan",
       gaze(kNan, 1.0)},
      {"set_gaze_targets: mean_duration: expected a number (0, 86400], got nan", gaze(1.0, kNan)},
      {"set_gaze_targets: mean_duration: expected a number (0, 86400], got inf", gaze(1.0, kInf)},
      {"set_gaze_targets: mean_duration: expected a number (0, 86400], got 0", gaze(1.0, 0.0)},
      {"set_gaze_targets: targets[0]: expected another object of the world, got 12",
       [](Simulation& sim) {
         sim.set_human_gaze(12, {{{12, 1.0}}, std::nullopt, 1.0});
       }},
      {"cmd_vel: linear.x: expected a finite number, got nan",
       [](Simulation& sim) { sim.command_ari_twist(kNan, 0.0); }},
      {"cmd_vel: angular.z: expected a finite number, got inf",
       [](Simulation& sim) { sim.command_ari_twist(0.5, kInf); }},
      {"head_command: position: expected a finite number, got nan",
       [](Simulation& sim) { sim.command_ari_head_pan(kNan); }},
      {"head_command: velocity: expected a finite number, got -inf",
       [](Simulation& sim) { sim.command_ari_head_pan_velocity(-kInf); }},
      {"follow_ari: pose.x: expected a finite number, got nan",
       [](Simulation& sim) {
         sim.follow_ari({{kNan, 5.0}, 0.0}, 0.0, 0.0);
       }},
      {"follow_ari: linear: expected a finite number, got inf",
       [](Simulation& sim) {
         sim.follow_ari({{1.0, 5.0}, 0.0}, kInf, 0.0);
       }},
  };
}

TEST(Simulation, NonFiniteOrOutOfRangeRequestsAreRefusedAndChangeNothing) {
  // Each refused request leaves its world exactly as an untouched twin: same hash after the
  // refusal and after 40 more steps, every number still finite.
  for (const BadRequest& request : bad_requests()) {
    auto refused = request_world();
    auto untouched = request_world();
    refused->step();
    untouched->step();
    try {
      request.send(*refused);
      ADD_FAILURE() << "accepted: " << request.expected;
    } catch (const core::RequestError& e) {
      EXPECT_EQ(std::string(e.what()), request.expected);
    }
    EXPECT_EQ(full_hash(WorldSnapshot::of(*refused)), full_hash(WorldSnapshot::of(*untouched)))
        << request.expected;
    for (int i = 0; i < 40; ++i) {
      refused->step();
      untouched->step();
    }
    const WorldSnapshot after = WorldSnapshot::of(*refused);
    EXPECT_TRUE(all_finite(after)) << request.expected;
    EXPECT_EQ(full_hash(after), full_hash(WorldSnapshot::of(*untouched))) << request.expected;
  }
}

TEST(Simulation, ValidRequestsAtTheLimitsAreAccepted) {
  auto simulation = request_world();
  // 1.3 m/s is human 10's max_speed exactly; a goal and a centre on the floor's corners.
  simulation->set_group_centre(1, {-0.2, 6.2});
  simulation->set_human_velocity(10, {1.3, 0.0}, kMaxHumanTurnRateRps);
  simulation->set_human_goal(11, {{6.2, -0.2}, -3.0});
  for (int i = 0; i < 40; ++i) {
    simulation->step();
  }
  EXPECT_TRUE(all_finite(WorldSnapshot::of(*simulation)));
  // 10 and 11 left group 1 (velocity and goal requests take a human out), which was dropped empty.
  EXPECT_EQ(simulation->find_group(1), nullptr);
  EXPECT_EQ(simulation->find_human(10)->motion_mode(), MotionMode::kDirect);
}

TEST(Simulation, SetPoseTakesAHumanOutOfItsGroupOnlyWhenAccepted) {
  auto simulation = request_world();
  EXPECT_THROW(simulation->set_pose(10, {{4.0, 2.0}, 0.0}), core::RequestError);  // onto 11
  EXPECT_EQ(simulation->find_human(10)->group_id(), 1u);
  simulation->set_pose(10, {{1.0, 1.0}, 0.0});
  EXPECT_EQ(simulation->find_human(10)->group_id(), model::kNoObject);
  EXPECT_EQ(simulation->find_group(1)->members(), std::vector<model::ObjectId>{11});
}

TEST(Simulation, DebugBuildsCatchANanWhereItIsMade) {
#ifdef NDEBUG
  GTEST_SKIP() << "ARI_DCHECK is compiled out of release builds";
#else
  // Past the checked entry points (Simulation's requests), the core's own setters assert.
  Human human(person(10, 2.0, 2.0), core::Rng(1));
  EXPECT_DEATH(human.set_velocity({kNan, 0.0}, 0.0), "ARI_CHECK");
  EXPECT_DEATH(human.plan_motion({0.0, kInf}, 0.0), "ARI_CHECK");
  GroupSpec spec;
  spec.id = 1;
  spec.members = {10};
  GroupNavigation group(spec);
  EXPECT_DEATH(group.set_centre({kNan, 1.0}), "ARI_CHECK");
#endif
}

TEST(Simulation, GroupsAndWorldsHaveDocumentedMaxima) {
  // 51 humans in a 12 m room; a group of 50 takes no 51st member.
  Simulation simulation(test::square_room(12.0), SimulationConfig{});
  core::Rng rng(3);
  const std::vector<model::ObjectId> ids = test::add_random_humans(simulation, 51, 12.0, 0.5, rng);
  GroupSpec group;
  group.id = 1;
  group.members.assign(ids.begin(), ids.begin() + 50);
  group.centre = {6.0, 6.0};
  simulation.add_group(group);
  try {
    simulation.add_group_members(1, {ids[50], ids[0]});
    ADD_FAILURE() << "a 51st member was accepted";
  } catch (const core::RequestError& e) {
    EXPECT_EQ(std::string(e.what()),
              "add_group_members: members: expected at most 50 humans in a group, got 50 members "
              "and 1 joining");
  }
  // A list longer than any group is refused before it is searched (a client may send 1e6 ids).
  EXPECT_THROW(simulation.add_group_members(1, std::vector<model::ObjectId>(100000, ids[0])),
               core::RequestError);
  group.id = 2;
  group.members = ids;
  EXPECT_THROW(simulation.add_group(group), core::RequestError);
  EXPECT_EQ(simulation.find_human(ids[50])->group_id(), model::kNoObject);

  // A world of more than 200 m per side, or whose map would exceed 4096 x 4096 cells, is refused
  // before anything is allocated: 150 m at 0.01 m is 15000 x 15000 cells.
  model::WorldDescription huge = test::square_room(6.0);
  huge.size = {3000.0, 3000.0};
  EXPECT_THROW((Simulation{huge, SimulationConfig{}}), core::ConfigError);
  model::WorldDescription fine_grid = test::square_room(6.0);
  fine_grid.size = {150.0, 150.0};
  EXPECT_THROW((Simulation{fine_grid, SimulationConfig{0.05, 0, 0.01}}), core::ConfigError);
  EXPECT_NO_THROW((Simulation{fine_grid, SimulationConfig{0.05, 0, 0.05}}));  // 3000 x 3000 cells
}

// Every degenerate polygon class, built in code as the learning tasks and the engine build worlds:
// refused with a message, never handed to b2PolygonShape::Set (which aborted the process).
TEST(Simulation, ShapesBox2dCannotBuildAreRefusedNotAborted) {
  const std::vector<std::pair<std::vector<Eigen::Vector2d>, std::string>> degenerate = {
      {{{1.0, 1.0}, {1.001, 1.0}, {1.0, 1.001}}, "tiny: area 5e-07 m^2"},
      {{{1.0, 1.0}, {3.0, 1.0}, {2.0, 1.00000001}}, "tiny: area 1e-08 m^2"},
      {{{1.0, 1.0}, {3.0, 1.0}, {2.0, 1.0001}}, "sliver: 0.0001 m thin"},
      {{{1.0, 1.0}, {2.0, 1.0}, {3.0, 1.0}, {2.0, 2.0}}, "collinear: vertex 1 is 0 m off"},
      {{{1.0, 1.0}, {2.0, 1.0}, {2.001, 1.0}, {2.0, 2.0}}, "duplicate vertices: 1 and 2"},
  };
  for (const auto& [points, defect] : degenerate) {
    model::WorldDescription room = test::square_room(6.0);
    model::StaticObject shelf;
    shelf.id = 77;
    shelf.name = "shelf";
    shelf.type = model::ShapeType::kPolygon;
    shelf.points = points;
    room.objects.push_back(shelf);
    try {
      Simulation simulation(room, SimulationConfig{});
      ADD_FAILURE() << "accepted a polygon with " << defect;
    } catch (const core::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(defect), std::string::npos) << e.what();
    }
    // The map rasteriser builds the same shape without a Simulation: refused there too.
    EXPECT_THROW(make_static_shape(shelf), core::ConfigError) << defect;
  }
}

}  // namespace
}  // namespace ari_social_sim::world
