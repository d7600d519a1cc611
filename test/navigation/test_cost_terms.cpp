// One test per cost term with hand-computed values, and a finite-difference check of every term's
// gradient through the dynamics.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/navigation/agent_clearance_cost.hpp"
#include "ari_social_sim/navigation/control_cost.hpp"
#include "ari_social_sim/navigation/goal_cost.hpp"
#include "ari_social_sim/navigation/group_space_cost.hpp"
#include "ari_social_sim/navigation/heading_cost.hpp"
#include "ari_social_sim/navigation/obstacle_cost.hpp"
#include "ari_social_sim/navigation/personal_space_cost.hpp"
#include "ari_social_sim/navigation/trajectory_cost.hpp"
#include "ari_social_sim/navigation/view_cost.hpp"
#include "navigation_fixtures.hpp"

namespace ari_social_sim::navigation {
namespace {

const FootprintModel kFootprint = FootprintModel::covering(model::AriFootprint{}, 3);
constexpr double kStep = 0.15;

// A rollout of `steps` steps that holds still at `start` (zero controls).
struct Still {
  UnicycleModel model{kStep, kFootprint};
  Eigen::VectorXd controls;
  Rollout rollout;
  Still(const RobotState& start, int steps) : controls(Eigen::VectorXd::Zero(3 * steps)) {
    model.rollout(start, controls, rollout);
  }
};

RobotState state(double x, double y, double theta, double pan = 0.0) {
  RobotState s;
  s.position = {x, y};
  s.theta = theta;
  s.pan = pan;
  return s;
}

TEST(GoalCost, HuberOfTheGeodesicDistanceAtEveryStepPlusTheTerminalWeight) {
  // Open room, goal 3 m straight ahead: the geodesic distance is the straight one (within the
  // fast marching error of about 2 %).
  test::RoomProblem room(8.0, test::pose(2.0, 4.0, 0.0), test::pose(5.0, 4.0, 0.0));
  Still still(room.problem.start, 4);
  const GoalCost cost(1.0, 4.0, 0.5);
  const double distance = room.geodesic->cost({2.0, 4.0});
  EXPECT_NEAR(distance, 3.0, 0.06);
  // 4 steps at weight 1 and one more at 4, each rho(d) = d - 0.25 above the Huber width.
  EXPECT_NEAR(cost.evaluate(room.problem, still.rollout, still.controls, nullptr),
              8.0 * (distance - 0.25), 1e-9);
  // At 0.2 m from the goal the quadratic part applies: d^2 / (2 * 0.5) per unit weight.
  const double near = room.geodesic->cost({4.8, 4.0});
  EXPECT_NEAR(near, 0.2, 0.015);
  Still close(state(4.8, 4.0, 0.0), 1);
  EXPECT_NEAR(cost.evaluate(room.problem, close.rollout, close.controls, nullptr),
              5.0 * near * near, 1e-9);
}

TEST(GeodesicField, LeadsAroundAWallInsteadOfThroughIt) {
  // A wall across the middle of an 8 m room from the south wall to y = 6: from (2, 1) to (6, 1)
  // the way goes over the wall's end, far longer than the 4 m straight line.
  model::WorldDescription world = world::test::square_room(8.0);
  model::StaticObject wall;
  wall.id = 1;
  wall.type = model::ShapeType::kWall;
  wall.pose.position = {4.0, 3.0};
  wall.pose.theta = M_PI / 2;
  wall.size = {6.0, 0.1};
  world.objects.push_back(wall);
  const model::OccupancyGrid map = world::rasterize_static_map(world, 0.05);
  const GridField sdf = signed_distance_field(map);
  const GeodesicField field(sdf, {6.0, 1.0}, GeodesicParams{});
  // Shortest way: up to the wall's end (6 m) and back down: about 2 * sqrt(2^2 + 5^2) = 10.8 m.
  const double around = field.cost({2.0, 1.0});
  EXPECT_GT(around, 10.5);
  EXPECT_LT(around, 13.5);  // the clearance penalty adds a little near the wall's end
  // Downhill from (2, 1) points up (toward the wall's end), not east into the wall.
  Eigen::Vector2d g;
  field.cost({2.0, 1.0}, &g);
  EXPECT_GT(-g.y(), std::abs(g.x()));
  EXPECT_TRUE(field.reachable({2.0, 1.0}));
}

TEST(GeodesicField, ClosedRoomIsUnreachable) {
  // A closed 2 m box inside the room: its inside is not joined to the outside.
  model::WorldDescription world = world::test::square_room(8.0);
  auto wall = [&](model::ObjectId id, double x, double y, double length, double theta) {
    model::StaticObject object;
    object.id = id;
    object.type = model::ShapeType::kWall;
    object.pose.position = {x, y};
    object.pose.theta = theta;
    object.size = {length, 0.1};
    world.objects.push_back(object);
  };
  wall(1, 5.0, 4.0, 2.1, 0.0);
  wall(2, 5.0, 6.0, 2.1, 0.0);
  wall(3, 4.0, 5.0, 2.0, M_PI / 2);
  wall(4, 6.0, 5.0, 2.0, M_PI / 2);
  const GridField sdf = signed_distance_field(world::rasterize_static_map(world, 0.05));
  const GeodesicField field(sdf, {5.0, 5.0}, GeodesicParams{});
  EXPECT_TRUE(field.reachable({5.0, 5.0}));
  EXPECT_FALSE(field.reachable({2.0, 2.0}));
  EXPECT_GT(field.cost({2.0, 2.0}), 20.0);  // finite, but only through the walls
}

TEST(SignedDistanceField, PositiveInFreeSpaceNegativeInWalls) {
  const GridField sdf = signed_distance_field(test::room_map(6.0));
  // The west wall's inner face is at x = 0.05.
  EXPECT_NEAR(sdf.sample({1.05, 3.0}), 1.0, 0.03);
  EXPECT_NEAR(sdf.sample({0.55, 3.0}), 0.5, 0.03);
  EXPECT_LT(sdf.sample({0.0, 3.0}), 0.0);
  Eigen::Vector2d g;
  sdf.sample({1.0, 3.0}, &g);
  EXPECT_NEAR(g.x(), 1.0, 0.05);  // distance grows away from the wall at 1 m/m
  EXPECT_NEAR(g.y(), 0.0, 0.05);
}

TEST(HeadingCost, PathDirectionOnTheWayArrivalHeadingAtTheGoal) {
  test::RoomProblem room(8.0, test::pose(2.0, 4.0, 0.0), test::pose(5.0, 4.0, M_PI / 2));
  const HeadingCost cost(2.0, 3.0, 0.5);
  // 3 m away facing the goal: nothing; facing away from it, the path term owes the U-turn:
  // 3 * (1 - 1 / (1 + 6^4)) * (1 - cos 180 deg) = 6.
  Still facing(state(2.0, 4.0, 0.0), 3);
  EXPECT_NEAR(cost.evaluate(room.problem, facing.rollout, facing.controls, nullptr), 0.0, 0.01);
  Still away(state(2.0, 4.0, M_PI), 3);
  EXPECT_NEAR(cost.evaluate(room.problem, away.rollout, away.controls, nullptr), 6.0, 0.02);
  // At the goal, 90 deg off its heading, on the way: the path term has faded, the goal heading
  // does not count yet.
  Still at_goal(state(5.0, 4.0, 0.0), 3);
  EXPECT_NEAR(cost.evaluate(room.problem, at_goal.rollout, at_goal.controls, nullptr), 0.0, 0.01);
  // Standing at the goal position, each of the 3 steps counts: 3 * 2 * (1 - cos 90 deg).
  room.problem.at_goal_position = true;
  EXPECT_NEAR(cost.evaluate(room.problem, at_goal.rollout, at_goal.controls, nullptr), 6.0, 1e-9);
  Still aligned(state(5.0, 4.0, M_PI / 2), 3);
  EXPECT_NEAR(cost.evaluate(room.problem, aligned.rollout, aligned.controls, nullptr), 0.0, 1e-9);
}

TEST(ObstacleCost, PenalisesFootprintCirclesInsideTheMargin) {
  test::RoomProblem room(6.0, test::pose(3.0, 3.0, 0.0), test::pose(4.0, 3.0, 0.0));
  const ObstacleCost cost(100.0, kFootprint, 0.05);
  // In the middle of the room, nothing.
  Still middle(state(3.0, 3.0, 0.0), 1);
  EXPECT_DOUBLE_EQ(cost.evaluate(room.problem, middle.rollout, middle.controls, nullptr), 0.0);
  // Facing north with base_footprint 0.25 m from the west wall's face (x = 0.30): every circle
  // centre is 0.25 m from the wall, reach 0.298 + 0.05, so 3 * 100 * 0.098^2 = 2.88.
  Still by_wall(state(0.30, 3.0, M_PI / 2), 1);
  const double expected = 3 * 100.0 * std::pow(kFootprint.circle_radius_m + 0.05 - 0.25, 2);
  EXPECT_NEAR(cost.evaluate(room.problem, by_wall.rollout, by_wall.controls, nullptr), expected,
              0.05 * expected);
}

TEST(AgentClearanceCost, PenalisesBodiesCloserThanTheMargin) {
  test::RoomProblem room(8.0, test::pose(2.0, 4.0, 0.0), test::pose(5.0, 4.0, 0.0));
  room.problem.people.push_back({test::person("p", 2.5, 4.0, M_PI), 1.0});
  const AgentClearanceCost cost(100.0, kFootprint, 0.2, 0.15, kStep);
  // The front circle (x = 2.033) is 0.467 m from the person: reach 0.298 + 0.2 + 0.15 = 0.648,
  // so 100 * 0.181^2 = 3.27; the middle circle at 2.78 - ... = 0.72 m is clear.
  Still still(state(2.0, 4.0, 0.0), 1);
  const double front_gap = 2.5 - (2.0 + kFootprint.circle_offsets_x_m[2]);
  const double expected = 100.0 * std::pow(kFootprint.circle_radius_m + 0.35 - front_gap, 2);
  EXPECT_NEAR(cost.evaluate(room.problem, still.rollout, still.controls, nullptr), expected, 1e-9);
  // A person walking away at 1 m/s is clear one step later: 0.467 + 0.15 > ... still inside, but
  // less.
  room.problem.people[0].estimate.velocity = {1.0, 0.0};
  EXPECT_LT(cost.evaluate(room.problem, still.rollout, still.controls, nullptr), expected);
}

TEST(PersonalSpaceCost, AsymmetricGaussianAtTheBodyEdge) {
  PersonalSpaceParams params;  // front 0.6, side 0.4, rear 0.3 m
  const PersonEstimate p = test::person("p", 0.0, 0.0, 0.0);
  // 1.2 m ahead is the 2 sigma edge: exp(-2) = 0.135; the same distance behind is 4 sigma.
  EXPECT_NEAR(personal_space_value(p, params, {1.2, 0.0}, 0.0), std::exp(-2.0), 1e-12);
  EXPECT_NEAR(personal_space_value(p, params, {-1.2, 0.0}, 0.0), std::exp(-8.0), 1e-12);
  EXPECT_NEAR(personal_space_value(p, params, {0.0, 0.8}, 0.0), std::exp(-2.0), 1e-12);
  EXPECT_NEAR(params.boundary_value(), std::exp(-2.0), 1e-12);
  // Walking at 1 m/s widens the front sigma to 0.9 m: 1.2 m ahead is then exp(-0.889).
  const PersonEstimate walker = test::person("w", 0.0, 0.0, 0.0, {1.0, 0.0});
  EXPECT_NEAR(personal_space_value(walker, params, {1.2, 0.0}, 0.0), std::exp(-0.5 * 1.44 / 0.81),
              1e-12);

  // The cost reads the circle point nearest the person: ARI facing away from a person 1.5 m
  // ahead of its base... put the person 1.0 m in front of ARI's front circle centre, facing ARI.
  test::RoomProblem room(8.0, test::pose(2.0, 4.0, 0.0), test::pose(5.0, 4.0, 0.0));
  const double front = 2.0 + kFootprint.circle_offsets_x_m[2];
  room.problem.people.push_back({test::person("p", front + 1.0, 4.0, M_PI), 0.5});
  const PersonalSpaceCost cost(3.0, 0.0, kFootprint, params, 0.2, kStep);
  Still still(state(2.0, 4.0, 0.0), 1);
  double expected = 0.0;
  for (double offset : kFootprint.circle_offsets_x_m) {
    const double edge_distance = front + 1.0 - (2.0 + offset) - kFootprint.circle_radius_m;
    expected += 3.0 * 0.5 * std::exp(-0.5 * edge_distance * edge_distance / 0.36);
  }
  EXPECT_NEAR(cost.evaluate(room.problem, still.rollout, still.controls, nullptr), expected, 1e-9);
}

TEST(PersonalSpaceCost, StiffEdgeGrowsWithTheSquaredDepthInsideTheSpaceOnly) {
  PersonalSpaceParams params;  // front sigma 0.6 m, edge at 2 sigma, stiff edge 0.2 sigma beyond
  test::RoomProblem room(8.0, test::pose(2.0, 4.0, 0.0), test::pose(5.0, 4.0, 0.0));
  const double front = 2.0 + kFootprint.circle_offsets_x_m[2];
  room.problem.people.push_back({test::person("p", front + 1.0, 4.0, M_PI), 0.5});
  const PersonalSpaceCost edge_only(0.0, 50.0, kFootprint, params, 0.2, kStep);
  Still still(state(2.0, 4.0, 0.0), 1);
  // Depth of each circle's nearest point, in ln f: (2.2^2 - m^2) / 2 with m its distance in front
  // sigmas; the front circle's edge is 0.7 m from the person (m = 1.17, depth 1.74).
  double expected = 0.0;
  for (double offset : kFootprint.circle_offsets_x_m) {
    const double m = (front + 1.0 - (2.0 + offset) - kFootprint.circle_radius_m) / 0.6;
    const double depth = std::max(0.0, 0.5 * (2.2 * 2.2 - m * m));
    expected += 50.0 * 0.5 * depth * depth;
  }
  const double front_m = (1.0 - kFootprint.circle_radius_m) / 0.6;
  EXPECT_GT(expected, 50.0 * 0.5 * std::pow(0.5 * (4.84 - front_m * front_m), 2) - 1e-9);
  EXPECT_NEAR(edge_only.evaluate(room.problem, still.rollout, still.controls, nullptr), expected,
              1e-9);
  // Beyond 2.2 front sigmas (1.32 m) of every circle it is exactly zero: the Gaussian's tail, not
  // the edge, is all that reaches there.
  room.problem.people[0].estimate.position.x() = front + kFootprint.circle_radius_m + 1.4;
  EXPECT_EQ(edge_only.evaluate(room.problem, still.rollout, still.controls, nullptr), 0.0);
}

TEST(GroupSpaceCost, KeepsOutOfOtherGroupsButNotTheOneJoined) {
  test::RoomProblem room(8.0, test::pose(2.0, 4.0, 0.0), test::pose(5.0, 4.0, 0.0));
  // Two people facing each other 1.2 m apart around (4, 4): radius 0.6, o-space disc 0.4 m.
  std::vector<PersonEstimate> members = {test::person("a", 3.4, 4.0, 0.0),
                                         test::person("b", 4.6, 4.0, M_PI)};
  const GroupEstimate group = estimate_group("g", members, 0.6);
  EXPECT_NEAR(group.centre.x(), 4.0, 1e-12);
  EXPECT_NEAR(group.radius_m, 0.6, 1e-12);
  room.problem.groups.push_back({group, false});
  const GroupSpaceCost cost(3.0, 200.0, kFootprint, PersonalSpaceParams{}, 0.1);
  // ARI's middle circle on the centre: soft term 3 (edge point = centre) plus the stiff edge
  // 200 * (0.4 + 0.1 + 0.298)^2 for it, and the two other circles partly.
  Still inside(state(4.22, 4.0, M_PI / 2), 1);
  const double inside_cost = cost.evaluate(room.problem, inside.rollout, inside.controls, nullptr);
  EXPECT_GT(inside_cost, 200.0 * std::pow(0.798, 2));
  // 3 m away only the soft tail remains: 3 circles, each below 3 exp(-2.4^2 / 0.72) ~ 0.001.
  Still away(state(7.0, 4.0, 0.0), 1);
  EXPECT_LT(cost.evaluate(room.problem, away.rollout, away.controls, nullptr), 0.01);
  room.problem.groups[0].is_target = true;
  EXPECT_DOUBLE_EQ(cost.evaluate(room.problem, inside.rollout, inside.controls, nullptr), 0.0);
}

TEST(ControlCost, EffortSmoothnessAccelerationAndReverse) {
  test::RoomProblem room(8.0, test::pose(2.0, 4.0, 0.0), test::pose(5.0, 4.0, 0.0));
  CostWeights w;
  w.effort_linear = 1.0;
  w.effort_angular = 0.0;
  w.effort_pan = 0.0;
  w.smooth_linear = 0.0;
  w.smooth_angular = 0.0;
  w.smooth_pan = 0.0;
  w.acceleration = 100.0;
  w.reverse = 10.0;
  const ControlCost cost(w, model::AriLimits{}, kStep);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
  // From standstill to 0.1 m/s: within 1 m/s^2 * 0.15 s, so only effort 0.01 for each step.
  u << 0.1, 0.0, 0.0, 0.1, 0.0, 0.0;
  Still still(room.problem.start, 2);
  EXPECT_NEAR(cost.evaluate(room.problem, still.rollout, u, nullptr), 0.02, 1e-12);
  // To 0.5 m/s at once: 0.35 m/s beyond the 0.15 m/s allowed, 100 * 0.35^2 = 12.25, + 2 * 0.25.
  u << 0.5, 0.0, 0.0, 0.5, 0.0, 0.0;
  EXPECT_NEAR(cost.evaluate(room.problem, still.rollout, u, nullptr), 12.25 + 0.5, 1e-9);
  // Backwards at -0.1 m/s: effort 0.01 + reverse 10 * 0.01, twice.
  u << -0.1, 0.0, 0.0, -0.1, 0.0, 0.0;
  EXPECT_NEAR(cost.evaluate(room.problem, still.rollout, u, nullptr), 2 * 0.11, 1e-12);
  // Smoothness against the measured start velocity.
  w.effort_linear = 0.0;
  w.smooth_linear = 2.0;
  w.reverse = 0.0;
  const ControlCost smooth(w, model::AriLimits{}, kStep);
  room.problem.start_linear_mps = 0.4;
  u << 0.4, 0.0, 0.0, 0.3, 0.0, 0.0;
  EXPECT_NEAR(smooth.evaluate(room.problem, still.rollout, u, nullptr), 2.0 * 0.01, 1e-12);
}

TEST(ViewCost, TargetBearingAgainstTheHeadCamera) {
  test::RoomProblem room(8.0, test::pose(2.0, 4.0, 0.0), test::pose(5.0, 4.0, 0.0));
  const ViewCost cost(1.0, 100.0, kFootprint, 1.259);
  // Target straight to the left of the head pan axis (x = 2 - 0.2255): head turned 90 deg to the
  // left sees it: cost 0; looking ahead costs 1 - cos 90 deg = 1.
  room.problem.look_at = Eigen::Vector2d(2.0 + kFootprint.head_offset_x_m, 6.0);
  Still looking(state(2.0, 4.0, 0.0, M_PI / 2), 1);
  // ... but 90 deg is beyond the 1.259 rad limit: 100 * (pi/2 - 1.259)^2.
  EXPECT_NEAR(cost.evaluate(room.problem, looking.rollout, looking.controls, nullptr),
              100.0 * std::pow(M_PI / 2 - 1.259, 2), 1e-9);
  Still ahead(state(2.0, 4.0, 0.0, 0.0), 1);
  EXPECT_NEAR(cost.evaluate(room.problem, ahead.rollout, ahead.controls, nullptr), 1.0, 1e-9);
  // Without a target the head should look ahead: 1 - cos(pan).
  room.problem.look_at.reset();
  Still panned(state(2.0, 4.0, 0.0, 0.5), 1);
  EXPECT_NEAR(cost.evaluate(room.problem, panned.rollout, panned.controls, nullptr),
              1.0 - std::cos(0.5), 1e-12);
}

// Every term's analytic gradient through the dynamics against central differences, on a busy
// problem where each term is active.
class TermGradient : public ::testing::TestWithParam<int> {};

TEST_P(TermGradient, MatchesFiniteDifferences) {
  test::RoomProblem room(6.0, test::pose(0.9, 1.0, 0.4), test::pose(4.5, 4.0, 1.0));
  MpcProblem& p = room.problem;
  p.start.pan = 0.4;
  p.start_linear_mps = 0.3;
  p.start_angular_rps = -0.2;
  p.look_at = Eigen::Vector2d(3.0, 3.5);
  p.people.push_back({test::person("a", 1.9, 1.6, 3.0, {-0.4, 0.1}), 1.0});
  p.people.push_back({test::person("b", 2.3, 2.2, -2.0), 0.1});
  std::vector<PersonEstimate> members = {test::person("c", 1.6, 2.6, 0.0),
                                         test::person("d", 2.6, 2.6, 3.14)};
  p.groups.push_back({estimate_group("g", members, 0.5), false});
  CostWeights weights;
  weights.acceleration = 10.0;
  const PersonalSpaceParams spaces;
  std::vector<std::unique_ptr<CostTerm>> terms;
  terms.push_back(std::make_unique<GoalCost>(1.0, 4.0, 0.5));
  terms.push_back(std::make_unique<HeadingCost>(2.0, 3.0, 3.0));
  terms.push_back(std::make_unique<ObstacleCost>(100.0, kFootprint, 0.3));
  terms.push_back(std::make_unique<AgentClearanceCost>(100.0, kFootprint, 0.2, 0.3, kStep));
  terms.push_back(std::make_unique<PersonalSpaceCost>(3.0, 50.0, kFootprint, spaces, 0.2, kStep));
  terms.push_back(std::make_unique<GroupSpaceCost>(3.0, 200.0, kFootprint, spaces, 0.1));
  terms.push_back(std::make_unique<ControlCost>(weights, model::AriLimits{}, kStep));
  terms.push_back(std::make_unique<ViewCost>(1.0, 100.0, kFootprint, 0.3));
  const CostTerm& term = *terms[GetParam()];

  const UnicycleModel model(kStep, kFootprint);
  core::Rng rng(GetParam() + 1);
  const int steps = 12;
  Eigen::VectorXd u(3 * steps);
  for (int t = 0; t < steps; ++t) {
    u.segment<3>(3 * t) << rng.uniform(0.1, 0.7), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0);
  }
  Rollout rollout;
  auto value = [&](const Eigen::VectorXd& controls) {
    model.rollout(p.start, controls, rollout);
    return term.evaluate(p, rollout, controls, nullptr);
  };
  RolloutGradient gradient;
  gradient.reset(steps);
  model.rollout(p.start, u, rollout);
  const double cost = term.evaluate(p, rollout, u, &gradient);
  EXPECT_GT(cost, 0.0) << term.name() << " is not active in this problem";
  model.backpropagate(rollout, u, gradient);
  const double h = 1e-6;
  for (int i = 0; i < u.size(); ++i) {
    Eigen::VectorXd plus = u, minus = u;
    plus[i] += h;
    minus[i] -= h;
    const double numeric = (value(plus) - value(minus)) / (2.0 * h);
    EXPECT_NEAR(gradient.controls[i], numeric, 1e-4 * std::max(1.0, std::abs(numeric)))
        << term.name() << " control " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTerm, TermGradient, ::testing::Range(0, 8));

}  // namespace
}  // namespace ari_social_sim::navigation
