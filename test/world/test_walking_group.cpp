#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <vector>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "ari_social_sim/world/service_requests.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/walking_group.hpp"
#include "expect_config_error.hpp"
#include "refusal_text.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

const std::string kWorlds = std::string(ARI_SOURCE_DIR) + "/worlds/";

// Humans 10, 11, ... standing abreast `spacing` apart across +x, centred on `centre`.
std::vector<model::ObjectId> add_row(Simulation& simulation, size_t count,
                                     const Eigen::Vector2d& centre, double spacing) {
  std::vector<model::ObjectId> ids;
  for (size_t i = 0; i < count; ++i) {
    HumanSpec spec;
    spec.id = static_cast<model::ObjectId>(10 + i);
    spec.pose = {centre + Eigen::Vector2d(0.0, (0.5 * (count - 1) - i) * spacing), 0.0};
    simulation.add_human(spec);
    ids.push_back(spec.id);
  }
  return ids;
}

std::vector<Eigen::Vector2d> positions_of(const Simulation& simulation,
                                          const std::vector<model::ObjectId>& ids) {
  std::vector<Eigen::Vector2d> out;
  for (model::ObjectId id : ids) {
    out.push_back(simulation.find_human(id)->pose().position);
  }
  return out;
}

Eigen::Vector2d centroid_of(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) {
    sum += p;
  }
  return sum / static_cast<double>(points.size());
}

// max - min of the points projected on `axis`.
double spread_along(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& axis) {
  double low = INFINITY;
  double high = -INFINITY;
  for (const Eigen::Vector2d& p : points) {
    low = std::min(low, p.dot(axis));
    high = std::max(high, p.dot(axis));
  }
  return high - low;
}

// A point's place relative to a route: arc length (m) of the closest route point, and the signed
// distance (m, left positive) from it.
Eigen::Vector2d route_coordinates(const WalkingRoute& route, const Eigen::Vector2d& p) {
  const std::vector<Eigen::Vector2d>& points = route.points();
  double best = INFINITY;
  Eigen::Vector2d coordinates = Eigen::Vector2d::Zero();
  double arc = 0.0;
  for (size_t k = 1; k < points.size(); ++k) {
    const Eigen::Vector2d segment = points[k] - points[k - 1];
    const double length = segment.norm();
    if (length < 1e-9) {
      continue;
    }
    const Eigen::Vector2d along = segment / length;
    const double t = std::clamp((p - points[k - 1]).dot(along), 0.0, length);
    const Eigen::Vector2d off = p - (points[k - 1] + t * along);
    if (off.norm() < best) {
      best = off.norm();
      coordinates = {arc + t, along.x() * off.y() - along.y() * off.x()};
    }
    arc += length;
  }
  return coordinates;
}

WalkingGroupSpec walking(std::vector<model::ObjectId> members, const Eigen::Vector2d& goal) {
  WalkingGroupSpec spec;
  spec.id = 5;
  spec.members = std::move(members);
  spec.goal = {goal, 0.0};
  return spec;
}

// An open 20 m room: a group abreast walks 15 m along +x at 1 m/s.
class AbreastInTheOpen : public ::testing::TestWithParam<size_t> {};

TEST_P(AbreastInTheOpen, KeepsItsSpacingAndReachesTheGoalInTime) {
  const size_t n = GetParam();
  Simulation simulation(test::square_room(20.0), SimulationConfig{});
  const std::vector<model::ObjectId> ids = add_row(simulation, n, {2.0, 10.0}, 0.75);
  WalkingGroupSpec spec = walking(ids, {17.0, 10.0});
  spec.speed_mps = 1.0;
  simulation.add_walking_group(spec);

  double arrival_s = -1.0;
  double worst_gap_error = 0.0;
  double worst_lateral_error = 0.0;
  double worst_along = 0.0;
  while (simulation.time_s() < 30.0 && arrival_s < 0.0) {
    simulation.step();
    const std::vector<Eigen::Vector2d> p = positions_of(simulation, ids);
    if ((centroid_of(p) - Eigen::Vector2d(17.0, 10.0)).norm() < 0.5) {
      arrival_s = simulation.time_s();
    }
    if (simulation.time_s() < 1.0) {
      continue;  // the first second: setting off
    }
    // Neighbours across the walking direction (+x), ordered by y.
    std::vector<double> y;
    for (const Eigen::Vector2d& q : p) {
      y.push_back(q.y());
    }
    std::sort(y.begin(), y.end());
    for (size_t i = 1; i < n; ++i) {
      worst_gap_error = std::max(worst_gap_error, std::abs(y[i] - y[i - 1] - 0.75));
    }
    // A row of n: lateral spread (n - 1) x 0.75 m, nobody ahead of the others.
    worst_lateral_error =
        std::max(worst_lateral_error, std::abs(spread_along(p, {0.0, 1.0}) - (n - 1) * 0.75));
    worst_along = std::max(worst_along, spread_along(p, {1.0, 0.0}));
    const WalkingGroup& group = *simulation.find_walking_group(5);
    EXPECT_EQ(group.formation(), WalkingFormation::kSideBySide);
  }
  EXPECT_LT(worst_gap_error, 0.3);
  EXPECT_LT(worst_lateral_error, 0.3);
  EXPECT_LT(worst_along, 0.3);
  // 15 m at 1 m/s, less the 0.5 m tolerance: 14.5 s +- 20 %.
  EXPECT_GT(arrival_s, 0.8 * 14.5);
  EXPECT_LT(arrival_s, 1.2 * 14.5);
  std::printf(
      "%zu abreast: arrived after %.2f s (14.5 expected), worst gap error %.3f m, lateral "
      "spread error %.3f m, along spread %.3f m\n",
      n, arrival_s, worst_gap_error, worst_lateral_error, worst_along);
}

INSTANTIATE_TEST_SUITE_P(TwoToFour, AbreastInTheOpen, ::testing::Values(2, 3, 4));

TEST(WalkingGroup, FormsTheRowFromAScatteredStart) {
  // Four people standing anyhow within 1.5 m of (3, 10) set off for (17, 10) together.
  Simulation simulation(test::square_room(20.0), SimulationConfig{});
  const std::vector<Eigen::Vector2d> starts = {{3.0, 9.2}, {2.2, 10.6}, {3.6, 10.9}, {2.5, 9.9}};
  std::vector<model::ObjectId> ids;
  for (size_t i = 0; i < starts.size(); ++i) {
    HumanSpec spec;
    spec.id = static_cast<model::ObjectId>(10 + i);
    spec.pose = {starts[i], 1.0 * i};
    simulation.add_human(spec);
    ids.push_back(spec.id);
  }
  const WalkingGroup& group = simulation.add_walking_group(walking(ids, {17.0, 10.0}));
  double worst_gap_error = 0.0;
  double worst_along = 0.0;
  while (!group.has_arrived() && simulation.time_s() < 30.0) {
    simulation.step();
    // Forming the row: one 0.8 m behind its place closes up at 1.3 - 1.05 = 0.25 m/s.
    if (simulation.time_s() < 5.0) {
      continue;
    }
    const std::vector<Eigen::Vector2d> p = positions_of(simulation, ids);
    std::vector<double> y;
    for (const Eigen::Vector2d& q : p) {
      y.push_back(q.y());
    }
    std::sort(y.begin(), y.end());
    for (size_t i = 1; i < y.size(); ++i) {
      worst_gap_error = std::max(worst_gap_error, std::abs(y[i] - y[i - 1] - 0.75));
    }
    worst_along = std::max(worst_along, spread_along(p, {1.0, 0.0}));
  }
  EXPECT_TRUE(group.has_arrived());
  EXPECT_LT(worst_gap_error, 0.3);
  EXPECT_LT(worst_along, 0.3);
  std::printf(
      "4 from a scattered start: after 5 s worst gap error %.3f m, along spread %.3f m; "
      "arrived after %.2f s\n",
      worst_gap_error, worst_along, simulation.time_s());
}

TEST(WalkingGroup, LineWalksOneBehindTheOther) {
  Simulation simulation(test::square_room(20.0), SimulationConfig{});
  const std::vector<model::ObjectId> ids = add_row(simulation, 3, {2.0, 10.0}, 0.75);
  WalkingGroupSpec spec = walking(ids, {17.0, 10.0});
  spec.formation = WalkingFormation::kLine;
  simulation.add_walking_group(spec);
  for (int i = 0; i < 200; ++i) {  // 10 s
    simulation.step();
  }
  const std::vector<Eigen::Vector2d> p = positions_of(simulation, ids);
  // Three 1 m apart along +x: 2 m along, nothing across.
  EXPECT_NEAR(spread_along(p, {1.0, 0.0}), 2.0, 0.3);
  EXPECT_LT(spread_along(p, {0.0, 1.0}), 0.3);
}

// Two and three people walk from the kitchen of two_room_flat through the 1 m door (x = 5,
// y 1..2) to the middle of the living room, 2 m from anything.
class ThroughTheDoor : public ::testing::TestWithParam<size_t> {};

TEST_P(ThroughTheDoor, FallsIntoALineAndReformsAfter) {
  const size_t n = GetParam();
  Simulation simulation(model::load_world_file(kWorlds + "two_room_flat.yaml"), SimulationConfig{});
  const std::vector<model::ObjectId> ids = add_row(simulation, n, {6.5, 4.2}, 0.75);
  const Eigen::Vector2d goal(3.0, 3.0);
  const WalkingGroup& group = simulation.add_walking_group(walking(ids, goal));

  int door_steps = 0;
  int in_line_at_door = 0;
  double worst_lateral_at_door = 0.0;
  double least_along_at_door = INFINITY;
  double deepest_m = -INFINITY;
  double arrival_s = -1.0;
  while (simulation.time_s() < 40.0 && arrival_s < 0.0) {
    simulation.step();
    const std::vector<Eigen::Vector2d> p = positions_of(simulation, ids);
    for (model::ObjectId id : ids) {
      deepest_m = std::max(deepest_m, simulation.static_penetration_m(*simulation.find_human(id)));
    }
    const bool at_door = std::any_of(
        p.begin(), p.end(), [](const Eigen::Vector2d& q) { return std::abs(q.x() - 5.0) < 0.2; });
    if (at_door) {
      // Spreads along the route and across it, in route coordinates.
      ++door_steps;
      in_line_at_door += group.formation() == WalkingFormation::kLine ? 1 : 0;
      std::vector<Eigen::Vector2d> on_route;
      for (const Eigen::Vector2d& q : p) {
        on_route.push_back(route_coordinates(group.route(), q));
      }
      least_along_at_door = std::min(least_along_at_door, spread_along(on_route, {1.0, 0.0}));
      worst_lateral_at_door = std::max(worst_lateral_at_door, spread_along(on_route, {0.0, 1.0}));
    }
    if (group.has_arrived()) {
      arrival_s = simulation.time_s();
    }
  }
  ASSERT_GT(arrival_s, 0.0) << "the group did not arrive";
  EXPECT_GT(door_steps, 0);
  EXPECT_EQ(in_line_at_door, door_steps);
  EXPECT_GT(least_along_at_door, worst_lateral_at_door);
  EXPECT_LT(worst_lateral_at_door, 0.5);  // inside the 1 m door, bodies 0.4 m wide
  // No member into a wall or furniture beyond Box2D's contact slop (0.005 m).
  EXPECT_LT(deepest_m, 0.01);
  // In the living room the row is back: abreast at the goal.
  EXPECT_EQ(group.formation(), WalkingFormation::kSideBySide);
  const std::vector<Eigen::Vector2d> p = positions_of(simulation, ids);
  const double theta = group.heading_rad();
  const Eigen::Vector2d left(-std::sin(theta), std::cos(theta));
  EXPECT_NEAR(spread_along(p, left), (n - 1) * 0.75, 0.3);
  EXPECT_LT((centroid_of(p) - goal).norm(), 0.5);
  // At 1.05 m/s the last of the line walks the route and the line's length, (n - 1) x 1 m, to
  // its place in the row at the goal (+- 20 %).
  const double expected_s = (group.route().length_m() + (n - 1) * 1.0) / 1.05;
  EXPECT_GT(arrival_s, 0.8 * expected_s);
  EXPECT_LT(arrival_s, 1.2 * expected_s);
  std::printf(
      "%zu through the door: %d steps at the door, all in line; along spread >= %.2f m, "
      "lateral <= %.2f m; deepest %.4f m into walls; arrived after %.2f s (route %.2f m, "
      "%.2f s expected)\n",
      n, door_steps, least_along_at_door, worst_lateral_at_door, deepest_m, arrival_s,
      group.route().length_m(), expected_s);
}

INSTANTIATE_TEST_SUITE_P(TwoAndThree, ThroughTheDoor, ::testing::Values(2, 3));

TEST(WalkingGroup, WaitsForAMemberWhoFallsBehind) {
  Simulation simulation(test::square_room(20.0), SimulationConfig{});
  // Member 11 stands 4 m behind member 10 on the way (+x): 2 m behind its place in the row
  // centred between them, beyond 2 x wait_distance (1.5 m).
  HumanSpec ahead;
  ahead.id = 10;
  ahead.pose = {{4.5, 10.375}, 0.0};
  HumanSpec behind;
  behind.id = 11;
  behind.pose = {{0.5, 9.625}, 0.0};
  simulation.add_human(ahead);
  simulation.add_human(behind);
  simulation.add_walking_group(walking({10, 11}, {17.0, 10.0}));
  simulation.step();
  const WalkingGroup& group = *simulation.find_walking_group(5);
  EXPECT_TRUE(group.is_waiting());
  EXPECT_EQ(group.progress_m(), 0.0);
  int waiting_steps = 1;
  double ahead_walked_back = 0.0;
  for (int i = 0; i < 200; ++i) {  // 10 s
    simulation.step();
    waiting_steps += group.is_waiting() ? 1 : 0;
    ahead_walked_back =
        std::max(ahead_walked_back, 4.5 - simulation.find_human(10)->pose().position.x());
  }
  // The one behind walks up at 1.3 m/s while the leader stands, until it is within 1.5 m of its
  // place: 0.5 m, 7 to 8 steps of 0.05 s. The one ahead waits where it is. Then the group walks
  // on abreast, 0.75 m apart.
  EXPECT_GE(waiting_steps, 6);
  EXPECT_LE(waiting_steps, 10);
  EXPECT_LT(ahead_walked_back, 0.05);
  std::printf("waited %d steps for the one behind; the one ahead went back %.3f m\n", waiting_steps,
              ahead_walked_back);
  EXPECT_FALSE(group.is_waiting());
  EXPECT_GT(group.progress_m(), 5.0);
  const std::vector<Eigen::Vector2d> p = positions_of(simulation, {10, 11});
  EXPECT_NEAR((p[0] - p[1]).norm(), 0.75, 0.3);
  EXPECT_LT(std::abs(p[0].x() - p[1].x()), 0.3);
}

TEST(WalkingGroup, ConversesOnArrivalInTheRequestedArrangement) {
  Simulation simulation(test::square_room(12.0), SimulationConfig{});
  const std::vector<model::ObjectId> ids = add_row(simulation, 2, {2.0, 6.0}, 0.75);
  WalkingGroupSpec spec = walking(ids, {8.0, 6.0});
  spec.on_arrival = ArrivalAction::kConverse;
  spec.arrangement = model::Arrangement::kVisAVis;
  simulation.add_walking_group(spec);
  while (simulation.find_walking_group(5) != nullptr && simulation.time_s() < 20.0) {
    simulation.step();
  }
  ASSERT_EQ(simulation.find_walking_group(5), nullptr);
  const GroupNavigation* group = simulation.find_group(5);
  ASSERT_NE(group, nullptr);
  EXPECT_EQ(group->arrangement(), model::Arrangement::kVisAVis);
  EXPECT_EQ(group->members(), ids);
  EXPECT_EQ(group->centre(), Eigen::Vector2d(8.0, 6.0));
  for (model::ObjectId id : ids) {
    EXPECT_EQ(simulation.find_human(id)->group_id(), 5u);
  }
  for (int i = 0; i < 300; ++i) {  // 15 s to settle
    simulation.step();
  }
  // Vis-a-vis: each faces the other across the centre, within 0.3 rad and its seeded stance
  // (facing_spread, sd 15 deg; docs/world.md section 4.5).
  const Human& a = *simulation.find_human(10);
  const Human& b = *simulation.find_human(11);
  const Eigen::Vector2d ab = b.pose().position - a.pose().position;
  const double stance_tolerance = 0.3 + 2.0 * core::deg_to_rad(GroupSpec{}.facing_spread_deg);
  EXPECT_LT(std::abs(core::angle_difference(std::atan2(ab.y(), ab.x()), a.pose().theta)),
            stance_tolerance);
  EXPECT_LT(std::abs(core::angle_difference(std::atan2(-ab.y(), -ab.x()), b.pose().theta)),
            stance_tolerance);
  EXPECT_LT(((a.pose().position + b.pose().position) / 2 - group->centre()).norm(), 0.3);
}

TEST(WalkingGroup, StopsFacingTheGoalHeading) {
  Simulation simulation(test::square_room(12.0), SimulationConfig{});
  const std::vector<model::ObjectId> ids = add_row(simulation, 2, {2.0, 6.0}, 0.75);
  WalkingGroupSpec spec = walking(ids, {8.0, 6.0});
  spec.goal.theta = 1.0;
  simulation.add_walking_group(spec);
  for (int i = 0; i < 400; ++i) {  // 20 s: 6 m at 1.05 m/s, and the turn
    simulation.step();
  }
  const WalkingGroup& group = *simulation.find_walking_group(5);
  EXPECT_TRUE(group.has_arrived());
  for (model::ObjectId id : ids) {
    const Human& human = *simulation.find_human(id);
    EXPECT_NEAR(human.pose().theta, 1.0, 0.05);
    EXPECT_LT(human.velocity().norm(), 0.05);
  }
}

TEST(WalkingGroup, SameSeedSameRun) {
  auto run = [] {
    Simulation simulation(model::load_world_file(kWorlds + "two_room_flat.yaml"),
                          SimulationConfig{});
    const std::vector<model::ObjectId> ids = add_row(simulation, 3, {6.5, 4.2}, 0.75);
    simulation.add_walking_group(walking(ids, {3.0, 3.0}));
    for (int i = 0; i < 300; ++i) {
      simulation.step();
    }
    return positions_of(simulation, ids);
  };
  const std::vector<Eigen::Vector2d> a = run();
  const std::vector<Eigen::Vector2d> b = run();
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i], b[i]);
  }
}

TEST(WalkingGroup, RequestsAreCheckedAndRefusalsNamed) {
  const auto world = test::request_world();  // humans 10, 11 in group 1; 12 alone; floor 6.2
  Simulation& simulation = *world;
  auto refusal = [&](WalkingGroupSpec spec) {
    return test::refusal_text([&] { simulation.add_walking_group(spec); });
  };
  WalkingGroupSpec spec = walking({10, 12}, {5.0, 5.0});
  WalkingGroupSpec bad = spec;
  bad.members = {10};
  EXPECT_EQ(refusal(bad), "create_walking_group: members: expected 2 to 4 humans, got 1");
  bad.members = {10, 11, 12, 10, 11};
  EXPECT_EQ(refusal(bad), "create_walking_group: members: expected 2 to 4 humans, got 5");
  bad.members = {10, 10};
  EXPECT_EQ(refusal(bad),
            "create_walking_group: members: expected each human once, got a human "
            "listed twice");
  bad.members = {10, 98};
  EXPECT_EQ(refusal(bad), "create_walking_group: members[1]: no human with id 98");
  bad = spec;
  bad.goal.position = {9.0, 5.0};
  EXPECT_EQ(refusal(bad),
            "create_walking_group: goal.x: expected a finite number inside the "
            "world [-0.2, 6.2], got 9");
  bad.goal.position = {5.0, NAN};
  EXPECT_EQ(refusal(bad),
            "create_walking_group: goal.y: expected a finite number inside the "
            "world [-0.2, 6.2], got nan");
  bad = spec;
  bad.speed_mps = 1.5;
  EXPECT_EQ(refusal(bad),
            "create_walking_group: speed: expected at most the slowest member's "
            "max_speed (1.3 m/s), got 1.5");
  bad.speed_mps = 0.0;
  EXPECT_NE(refusal(bad).find("create_walking_group: speed: expected a number (0, 2]"),
            std::string::npos);
  bad = spec;
  bad.spacing_m = 0.1;
  EXPECT_EQ(refusal(bad), "create_walking_group: spacing: expected a number [0.4, 2], got 0.1");
  bad = spec;
  bad.id = 1;  // conversation group 1
  EXPECT_EQ(refusal(bad),
            "create_walking_group: id: expected an id no other group (walking or "
            "conversing) uses, got 1");
  // A goal inside the floor's corner, 0.05 m from two walls: nowhere near keeps 0.3 m clear.
  bad = spec;
  bad.goal.position = {-0.15, -0.15};
  EXPECT_NE(refusal(bad).find("create_walking_group: goal: expected a goal the members can walk "
                              "to from their centroid"),
            std::string::npos);
  EXPECT_EQ(simulation.walking_groups().size(), 0u);  // nothing changed

  // Accepted: 10 leaves conversation group 1, which keeps 11; the walking group takes id 2.
  spec.id = model::kNoObject;
  const WalkingGroup& group = simulation.add_walking_group(spec);
  EXPECT_EQ(group.id(), 2u);
  EXPECT_EQ(simulation.find_human(10)->group_id(), 2u);
  EXPECT_EQ(simulation.find_group(1)->members(), std::vector<model::ObjectId>{11});
  // Conversation groups cannot take a walking group's id, and the next one gets 3.
  GroupSpec conversation;
  conversation.id = 2;
  conversation.members = {11};
  conversation.centre = {3.0, 2.0};
  EXPECT_EQ(test::refusal_text([&] { simulation.add_group(conversation); }),
            "create_group: id: expected an id no other group uses, got 2");
  conversation.id = model::kNoObject;
  EXPECT_EQ(simulation.add_group(conversation).id(), 3u);
  // A member sent elsewhere leaves the walking group; removed, the last one ends it.
  simulation.set_human_goal(12, {{1.0, 1.0}, 0.0});
  EXPECT_EQ(simulation.find_walking_group(2)->members(), std::vector<model::ObjectId>{10});
  simulation.remove_human(10);
  EXPECT_EQ(simulation.find_walking_group(2), nullptr);
}

TEST(WalkingGroup, ShippedDemoSceneEndsInAConversation) {
  const auto simulation = build_simulation(
      load_scene_file(std::string(ARI_SOURCE_DIR) + "/scenes/walking_group_demo.yaml"),
      SimulationConfig{});
  while (simulation->find_group(1) == nullptr && simulation->time_s() < 30.0) {
    simulation->step();
  }
  ASSERT_NE(simulation->find_group(1), nullptr);
  const double formed_s = simulation->time_s();
  for (int i = 0; i < 300; ++i) {  // 15 s to settle
    simulation->step();
  }
  const Eigen::Vector2d a = simulation->find_human(10)->pose().position;
  const Eigen::Vector2d b = simulation->find_human(11)->pose().position;
  const double gap = (a - b).norm();
  // Face to face across the o-space centre (3.0, 3.2).
  EXPECT_LT(((a + b) / 2 - Eigen::Vector2d(3.0, 3.2)).norm(), 0.3);
  EXPECT_EQ(simulation->find_group(1)->arrangement(), model::Arrangement::kVisAVis);
  std::printf(
      "walking_group_demo: conversation group formed after %.2f s; 15 s later %.2f m "
      "apart\n",
      formed_s, gap);
}

TEST(WalkingGroup, ServiceFieldsBecomeTheSpec) {
  WalkingGroupRequest request;
  request.members = {10, 11};
  request.goal = {{1.0, 2.0}, 0.5};
  // Zero and empty fields are the defaults.
  WalkingGroupSpec spec = request.spec();
  EXPECT_EQ(spec.id, model::kNoObject);
  EXPECT_EQ(spec.formation, WalkingFormation::kSideBySide);
  EXPECT_EQ(spec.speed_mps, 1.05);
  EXPECT_EQ(spec.spacing_m, 0.75);
  EXPECT_EQ(spec.on_arrival, ArrivalAction::kStop);
  EXPECT_EQ(spec.arrangement, model::Arrangement::kCircle);
  EXPECT_EQ(spec.goal.theta, 0.5);
  request.formation = "line";
  request.speed_mps = 0.8;
  request.spacing_m = 0.9;
  request.on_arrival = "converse";
  request.arrangement = "l-shape";
  spec = request.spec();
  EXPECT_EQ(spec.formation, WalkingFormation::kLine);
  EXPECT_EQ(spec.speed_mps, 0.8);
  EXPECT_EQ(spec.spacing_m, 0.9);
  EXPECT_EQ(spec.on_arrival, ArrivalAction::kConverse);
  EXPECT_EQ(spec.arrangement, model::Arrangement::kLShape);
  request.on_arrival = "talk";
  EXPECT_EQ(test::refusal_text([&] { request.spec(); }),
            "create_walking_group: on_arrival: expected stop or converse, got 'talk'");
}

TEST(WalkingGroup, SceneFilesListWalkingGroups) {
  const std::string path = ::testing::TempDir() + "walking_scene.yaml";
  auto write = [&](const std::string& walking_groups) {
    std::ofstream(path) << "world: " << kWorlds << "two_room_flat.yaml\nseed: 3\n"
                        << "humans:\n  - {id: 10, position: [2.5, 3.2]}\n"
                        << "  - {id: 11, position: [2.5, 2.4]}\n"
                        << "walking_groups:\n"
                        << walking_groups;
  };
  write(
      "  - {id: 4, members: [10, 11], formation: line, goal: {position: [7.6, 4.2]}, "
      "on_arrival: converse, arrangement: l-shape}\n");
  const auto simulation = build_simulation(load_scene_file(path), SimulationConfig{});
  const WalkingGroup& group = *simulation->find_walking_group(4);
  EXPECT_EQ(group.spec().formation, WalkingFormation::kLine);
  EXPECT_EQ(group.spec().on_arrival, ArrivalAction::kConverse);
  EXPECT_EQ(group.spec().arrangement, model::Arrangement::kLShape);

  auto rejected = [&](const std::string& entry, const std::vector<std::string>& fragments) {
    write(entry);
    test::expect_config_error([&] { build_simulation(load_scene_file(path), SimulationConfig{}); },
                              path, fragments);
  };
  rejected("  - {id: 4, members: [10, 11], formation: abreast, goal: {position: [7, 4]}}\n",
           {"walking_groups[0]", "formation", "side-by-side or line", "'abreast'"});
  rejected("  - {id: 4, members: [10, 11], goal: {position: [7, 4]}, on_arrival: talk}\n",
           {"walking_groups[0]", "on_arrival", "stop or converse", "'talk'"});
  rejected("  - {id: 4, members: [10, 11]}\n", {"walking_groups[0]", "goal"});
  rejected("  - {id: 4, members: [10, 11], goal: {position: [7, 4]}, speed: -1}\n",
           {"walking_groups[0]", "speed", "(0, 2]", "-1"});
  rejected("  - {id: 4, members: [10, 12], goal: {position: [7, 4]}}\n",
           {"walking_groups[0]", "create_walking_group: members[1]: no human with id 12"});
  rejected("  - {id: 4, members: [10, 11], goal: {position: [7.5, 2.5]}}\n",
           {"walking_groups[0]",
            "create_walking_group: goal: expected a goal the members can "
            "walk to"});
}

}  // namespace
}  // namespace ari_social_sim::world
