#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

HumanSpec person(ObjectId id, double x, double y, double theta = 0.0) {
  HumanSpec spec;
  spec.id = id;
  spec.pose = {{x, y}, theta};
  return spec;
}

// FNV-1a over every number of a snapshot: equal hashes mean equal runs.
uint64_t hash_of(const WorldSnapshot& s) {
  uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](double value) {
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int i = 0; i < 8; ++i) {
      h = (h ^ ((bits >> (8 * i)) & 0xff)) * 1099511628211ULL;
    }
  };
  for (const HumanSnapshot& human : s.humans) {
    mix(human.pose.position.x());
    mix(human.pose.position.y());
    mix(human.pose.theta);
    mix(human.gaze.target);
    mix(human.gaze.direction_rad);
    mix(human.gaze.since_s);
  }
  return h;
}

std::unique_ptr<Simulation> crowd(uint64_t seed) {
  auto simulation =
      std::make_unique<Simulation>(test::square_room(8.0), SimulationConfig{0.05, seed, 0.05});
  core::Rng layout(99);  // the same people in every run; only the simulation seed differs
  const std::vector<ObjectId> ids = test::add_random_humans(*simulation, 8, 8.0, 0.5, layout);
  for (ObjectId id : ids) {
    GazeModel gaze;
    gaze.targets = {{ids[(id + 1) % ids.size()], 0.6}, {ids[(id + 2) % ids.size()], 0.4}};
    gaze.mean_duration_s = 1.0;
    simulation->find_human(id)->set_gaze_model(gaze);
  }
  GroupSpec group;
  group.id = 1;
  group.members = {ids[0], ids[1], ids[2]};
  group.centre = {4.0, 4.0};
  simulation->add_group(group);
  simulation->find_human(ids[5])->set_goal({{1.0, 7.0}, 0.0});
  return simulation;
}

TEST(Simulation, SameSeedSameRunOtherSeedOtherRun) {
  auto a = crowd(7), b = crowd(7), c = crowd(8);
  bool differs = false;
  for (int i = 0; i < 600; ++i) {
    a->step();
    b->step();
    c->step();
    const uint64_t ha = hash_of(WorldSnapshot::of(*a));
    ASSERT_EQ(ha, hash_of(WorldSnapshot::of(*b))) << "step " << i;
    differs = differs || ha != hash_of(WorldSnapshot::of(*c));
  }
  EXPECT_TRUE(differs);
}

TEST(Simulation, WallsStopHumansWalkingIntoThem) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  Human& human = simulation.add_human(person(10, 3.0, 3.0));
  human.set_velocity({1.5, 0.0}, 0.0);
  for (int i = 0; i < 100; ++i) {
    simulation.step();
    ASSERT_LT(simulation.static_penetration_m(human), 0.005);
  }
  // East wall inner face at x = 5.95; the body's radius 0.2 keeps the centre at <= 5.75 (+ slop).
  EXPECT_NEAR(human.pose().position.x(), 5.75, 0.02);
}

TEST(Simulation, HumanNavigationReachesItsGoalPose) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  Human& human = simulation.add_human(person(10, 1.0, 1.0));
  human.set_goal({{4.0, 5.0}, M_PI / 2});
  for (int i = 0; i < 200; ++i) {  // 10 s for a 5 m walk at 1 m/s
    simulation.step();
  }
  EXPECT_LT((human.pose().position - Eigen::Vector2d(4.0, 5.0)).norm(), 0.02);
  EXPECT_NEAR(human.pose().theta, M_PI / 2, 0.01);
}

TEST(Simulation, RepulsionKeepsWalkersApartWhenCrossing) {
  Simulation simulation(test::square_room(8.0), SimulationConfig{});
  Human& a = simulation.add_human(person(10, 1.0, 4.0));
  Human& b = simulation.add_human(person(11, 7.0, 4.05));
  a.set_goal({{7.0, 4.0}, 0.0});
  b.set_goal({{1.0, 4.0}, M_PI});
  double closest = 10.0;
  for (int i = 0; i < 400; ++i) {
    simulation.step();
    closest = std::min(closest, (a.pose().position - b.pose().position).norm());
  }
  // Head on, the seed's repulsion has no sideways part: the walkers meet, and the contact (bodies
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

TEST(Simulation, AGoalTakesAHumanOutOfItsGroupAndSpeechIsFoundById) {
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
  EXPECT_EQ(simulation.find_human(10)->group_id(), kNoObject);
  EXPECT_EQ(simulation.find_human(10)->motion_mode(), MotionMode::kNavigation);
  EXPECT_EQ(simulation.find_group(1)->members(), std::vector<ObjectId>{11});
  EXPECT_THROW(simulation.set_human_goal(12, {{1.0, 5.0}, 0.0}), core::RequestError);
  EXPECT_EQ(&simulation.speech_of(1), &simulation.ari()->speech());
  EXPECT_EQ(&simulation.speech_of(11), &simulation.find_human(11)->speech());
  EXPECT_THROW(simulation.speech_of(1002), core::RequestError);  // a wall says nothing
}

}  // namespace
}  // namespace ari_social_sim::world
