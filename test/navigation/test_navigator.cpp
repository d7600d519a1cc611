// The control loop closed over a perfect unicycle: ARI reaches goals with every solver, keeps its
// distance from a person in its way, and aborts with a reason when it must.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/navigation/navigation_errors.hpp"
#include "ari_social_sim/navigation/navigator.hpp"
#include "navigation_fixtures.hpp"

namespace ari_social_sim::navigation {
namespace {

// Drives `navigator` from `start` for up to `limit_s`, integrating its commands exactly.
struct DriveResult {
  NavigationState state{NavigationState::kActive};
  std::string reason;
  double time_s{0.0};
  RobotObservation robot;
  double min_distance_to_person_m{1e9};
};

// The same, in a scene that changes with time: `scene_at(t)` is what perception reports at t.
DriveResult drive_through(Navigator& navigator, const core::Pose2& start,
                          const std::function<PerceivedScene(double)>& scene_at, double limit_s) {
  DriveResult run;
  run.robot.pose = start;
  const double dt = 1.0 / navigator.config().navigator.rate_hz;
  for (double t = 0.0; t < limit_s; t += dt) {
    const PerceivedScene scene = scene_at(t);
    const NavigatorStep step = navigator.update(t, run.robot, scene);
    run.time_s = t;
    if (step.state != NavigationState::kActive) {
      run.state = step.state;
      run.reason = step.reason;
      return run;
    }
    const double v = step.command.linear_mps, w = step.command.angular_rps;
    const double mid = run.robot.pose.theta + 0.5 * w * dt;
    run.robot.pose.position += v * dt * Eigen::Vector2d(std::cos(mid), std::sin(mid));
    run.robot.pose.theta = core::wrap_angle(run.robot.pose.theta + w * dt);
    run.robot.linear_mps = v;
    run.robot.angular_rps = w;
    run.robot.pan_rad = step.command.pan_rad;
    for (const PersonEstimate& person : scene.people) {
      run.min_distance_to_person_m =
          std::min(run.min_distance_to_person_m,
                   navigator.footprint().distance_to(run.robot.pose, person.position) - 0.2);
    }
  }
  run.state = navigator.state();
  return run;
}

DriveResult drive(Navigator& navigator, const core::Pose2& start, const PerceivedScene& scene,
                  double limit_s) {
  return drive_through(
      navigator, start, [&scene](double) { return scene; }, limit_s);
}

class EverySolver : public ::testing::TestWithParam<SolverKind> {};

TEST_P(EverySolver, ReachesAPoseAcrossAnEmptyRoom) {
  NavigationConfig config;
  config.mpc.solver = GetParam();
  Navigator navigator(config, test::room_map(6.0));
  const core::Pose2 start = test::pose(1.0, 1.0, 0.0);
  const core::Pose2 goal = test::pose(4.5, 4.0, M_PI / 2);
  navigator.start(PoseTarget{goal}, {}, RobotObservation{start}, 0.0);
  const DriveResult run = drive(navigator, start, {}, 30.0);
  ASSERT_EQ(run.state, NavigationState::kSucceeded) << run.reason;
  EXPECT_LE((run.robot.pose.position - goal.position).norm(), 0.15);
  EXPECT_LE(std::abs(core::angle_difference(goal.theta, run.robot.pose.theta)), 0.15);
  // 4.6 m at up to 0.8 m/s with 1 m/s^2 and the final turn: well under 15 s.
  EXPECT_LT(run.time_s, 15.0);
}

INSTANTIATE_TEST_SUITE_P(Solvers, EverySolver,
                         ::testing::Values(SolverKind::kLbfgs, SolverKind::kSlsqp,
                                           SolverKind::kMppi));

TEST(Navigator, GivesAPersonInTheWayMoreRoomThanTheNonSocialBaseline) {
  // Someone stands 0.2 m off the straight line from (1, 4) to (7, 4), facing it.
  PerceivedScene scene;
  scene.people.push_back(test::person("human1", 4.0, 4.2, -M_PI / 2));
  auto min_distance = [&](bool social) {
    NavigationConfig config;
    if (!social) {
      config.mpc.weights.personal_space = 0.0;
      config.mpc.weights.personal_space_edge = 0.0;
    }
    Navigator navigator(config, test::room_map(8.0));
    const core::Pose2 start = test::pose(1.0, 4.0, 0.0);
    navigator.start(PoseTarget{test::pose(7.0, 4.0, 0.0)}, scene, RobotObservation{start}, 0.0);
    const DriveResult run = drive(navigator, start, scene, 40.0);
    EXPECT_EQ(run.state, NavigationState::kSucceeded) << run.reason;
    return run.min_distance_to_person_m;
  };
  const double social = min_distance(true);
  const double baseline = min_distance(false);
  // The person's 2-sigma side edge is 0.8 m from their centre, 0.6 m from their body.
  EXPECT_GT(social, 0.5);
  EXPECT_GT(social, baseline + 0.2);
  EXPECT_GT(baseline, 0.0);  // the baseline still does not touch them
}

TEST(Navigator, KeepsTheWayItClaimedThroughAPersonalSpaceUntilClearOfIt) {
  // Someone stands in the way, facing south. Held still, ARI waits 4 s (patience), then their
  // personal space gives way, halving its weight every 2 s. Progress made inside their space
  // must not restore the weight (that would trap ARI inside); progress made clear of it does.
  PerceivedScene scene;
  scene.people.push_back(test::person("human1", 5.0, 4.0, -M_PI / 2));
  Navigator navigator(NavigationConfig{}, test::room_map(10.0));
  navigator.start(PoseTarget{test::pose(9.0, 4.0, 0.0)}, scene,
                  RobotObservation{test::pose(1.0, 4.0, 0.0)}, 0.0);
  auto space_scale_at = [&](double t, double x) {
    const NavigatorStep step =
        navigator.update(t, RobotObservation{test::pose(x, 4.0, 0.0)}, scene);
    EXPECT_EQ(step.state, NavigationState::kActive) << step.reason;
    return navigator.problem().people.at(0).space_scale;
  };
  for (double t = 0.1; t < 3.95; t += 0.1) {
    ASSERT_DOUBLE_EQ(space_scale_at(t, 1.0), 1.0) << "at " << t << " s";
  }
  EXPECT_NEAR(space_scale_at(7.0, 1.0), std::pow(0.5, 3.0 / 2.0), 1e-9);
  // ARI's front (0.16 m ahead of base_footprint) 0.64 m from their side, inside the 0.8 m edge:
  // still yielding, and further.
  EXPECT_NEAR(space_scale_at(7.2, 4.2), std::pow(0.5, 3.2 / 2.0), 1e-9);
  // 1.5 m to their side, ARI's 0.6 m rear clear of the edge: the way is passed.
  EXPECT_DOUBLE_EQ(space_scale_at(7.4, 6.5), 1.0);
}

TEST(Navigator, UnreachableGoalIsRefusedWithTheReason) {
  // A closed 2 m box in the room: a goal inside it has free floor but no way in.
  model::WorldDescription world = world::test::square_room(8.0);
  const double xs[4][4] = {{5.0, 4.0, 2.1, 0.0},
                           {5.0, 6.0, 2.1, 0.0},
                           {4.0, 5.0, 2.0, M_PI / 2},
                           {6.0, 5.0, 2.0, M_PI / 2}};
  for (int i = 0; i < 4; ++i) {
    model::StaticObject wall;
    wall.id = i + 1;
    wall.type = model::ShapeType::kWall;
    wall.pose = test::pose(xs[i][0], xs[i][1], xs[i][3]);
    wall.size = {xs[i][2], 0.1};
    world.objects.push_back(wall);
  }
  Navigator navigator(NavigationConfig{}, world::rasterize_static_map(world, 0.05));
  try {
    navigator.start(PoseTarget{test::pose(5.0, 5.0, 0.0)}, {},
                    RobotObservation{test::pose(1.5, 1.5, 0.0)}, 0.0);
    FAIL() << "accepted a goal inside a closed box";
  } catch (const GoalUnreachable& e) {
    EXPECT_NE(std::string(e.what()).find("no collision-free path from ARI at (1.50, 1.50)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(navigator.state(), NavigationState::kIdle);
}

TEST(Navigator, MalformedTargetsAreRefusedBeforeAnythingElse) {
  Navigator navigator(NavigationConfig{}, test::room_map(8.0));
  const RobotObservation robot{test::pose(1.0, 4.0, 0.0)};
  try {
    navigator.start(PoseTarget{test::pose(4.0, 4.0, std::nan(""))}, {}, robot, 0.0);
    FAIL() << "accepted a NaN heading";
  } catch (const core::RequestError& e) {
    // Not "overlaps a wall": the heading is named as what is wrong.
    EXPECT_STREQ(e.what(), "pose target: expected finite x, y and theta, got (4.00, 4.00, nan)");
  }
  EXPECT_THROW(navigator.start(PersonTarget{"human 3"}, {}, robot, 0.0), core::RequestError);
  EXPECT_EQ(navigator.state(), NavigationState::kIdle);
}

TEST(Navigator, AbortsWhenTheTargetIsLostBeyondTheTimeout) {
  Navigator navigator(NavigationConfig{}, test::room_map(8.0));
  PerceivedScene scene;
  scene.people.push_back(test::person("human3", 6.0, 4.0, M_PI));
  const RobotObservation robot{test::pose(1.0, 4.0, 0.0)};
  EXPECT_THROW(navigator.start(PersonTarget{"human9"}, scene, robot, 0.0), UnknownTarget);
  navigator.start(PersonTarget{"human3"}, scene, robot, 0.0);
  EXPECT_EQ(navigator.update(0.1, robot, scene).state, NavigationState::kActive);
  // Gone from perception: ARI keeps heading for the last goal for 5 s, then gives up.
  const PerceivedScene empty;
  EXPECT_EQ(navigator.update(4.0, robot, empty).state, NavigationState::kActive);
  EXPECT_EQ(navigator.update(5.0, robot, empty).phase, "waiting for the target");
  const NavigatorStep lost = navigator.update(5.2, robot, empty);
  EXPECT_EQ(lost.state, NavigationState::kAborted);
  EXPECT_NE(lost.reason.find("person human3 lost for 5.1 s"), std::string::npos) << lost.reason;
}

TEST(Navigator, ProgressTowardAGoalThatMovedAwayCounts) {
  // ARI comes within 0.4 m of the goal in front of Ana, who then steps 2 m back; ARI (placed by
  // hand) closes in on the new goal at 0.1 m/s. Against the best distance reached toward the old
  // goal that is no progress for 20 s, and the watchdog aborted (it did, in CI runs of
  // social_navigation.test, when group detection moved the joined group's goal); counted in the
  // new goal's field it is progress, and ARI arrives.
  const auto ana_at = [](double t) {
    PerceivedScene scene;
    scene.people.push_back(test::person("ana", t < 2.0 ? 4.0 : 6.0, 6.0, M_PI));
    return scene;
  };
  const auto ari_at = [](double x) { return RobotObservation{test::pose(x, 6.0, 0.0)}; };
  Navigator navigator(NavigationConfig{}, test::room_map(12.0));
  navigator.start(PersonTarget{"ana"}, ana_at(0.0), ari_at(1.0), 0.0);
  ASSERT_EQ(navigator.update(1.0, ari_at(2.5), ana_at(1.0)).state, NavigationState::kActive);
  for (double t = 2.0; t <= 24.0; t += 0.1) {
    const double x = 2.5 + 0.1 * std::max(0.0, t - 3.0);
    const NavigatorStep step = navigator.update(t, ari_at(x), ana_at(t));
    ASSERT_EQ(step.state, NavigationState::kActive) << step.reason << " at " << t << " s";
  }
  EXPECT_EQ(navigator.update(24.1, ari_at(4.9), ana_at(24.1)).state, NavigationState::kSucceeded);
}

TEST(Navigator, AbortsWhenAGoalThatKeepsMovingIsNeverCloser) {
  // A goal that jumps back and forth by 1 m every 2 s while ARI is held in place (its commands
  // ignored): moving goals restart the distance baseline, never the clock, so ARI still gives up.
  const auto jumping_at = [](double t) {
    PerceivedScene scene;
    scene.people.push_back(
        test::person("ana", static_cast<int>(t / 2.0) % 2 == 0 ? 6.0 : 7.0, 6.0, M_PI));
    return scene;
  };
  Navigator navigator(NavigationConfig{}, test::room_map(12.0));
  const RobotObservation held{test::pose(1.0, 6.0, 0.0)};
  navigator.start(PersonTarget{"ana"}, jumping_at(0.0), held, 0.0);
  NavigatorStep step;
  double t = 0.0;
  for (; t <= 40.0 && step.state != NavigationState::kAborted; t += 0.1) {
    step = navigator.update(t, held, jumping_at(t));
  }
  EXPECT_EQ(step.state, NavigationState::kAborted);
  EXPECT_NE(step.reason.find("no progress toward person ana"), std::string::npos) << step.reason;
  EXPECT_LT(t, 21.0);
}

TEST(Navigator, JoinsAGroupAndEndsFacingItsCentre) {
  PerceivedScene scene;
  for (int i = 0; i < 3; ++i) {
    const double a = M_PI / 2 + 2.0 * M_PI * i / 3.0;
    scene.people.push_back(test::person("human" + std::to_string(10 + i), 5.0 + 0.64 * std::cos(a),
                                        5.0 + 0.64 * std::sin(a), a + M_PI));
  }
  scene.groups.push_back(estimate_group("g1", scene.people, 0.64));
  Navigator navigator(NavigationConfig{}, test::room_map(8.0));
  const core::Pose2 start = test::pose(1.5, 1.5, 0.0);
  navigator.start(GroupTarget{"g1"}, scene, RobotObservation{start}, 0.0);
  const DriveResult run = drive(navigator, start, scene, 40.0);
  ASSERT_EQ(run.state, NavigationState::kSucceeded) << run.reason;
  // On the circle (body centre 0.64 m from the centre, within the 0.15 m tolerance), facing it.
  const Eigen::Vector2d body = navigator.footprint().centre(run.robot.pose);
  EXPECT_NEAR((body - Eigen::Vector2d(5.0, 5.0)).norm(), 0.64, 0.15);
  const Eigen::Vector2d to_centre = Eigen::Vector2d(5.0, 5.0) - run.robot.pose.position;
  EXPECT_LT(std::abs(core::angle_difference(std::atan2(to_centre.y(), to_centre.x()),
                                            run.robot.pose.theta)),
            0.2);
  EXPECT_GT(run.min_distance_to_person_m, 0.0);
}

// A group of three on a 0.64 m ring round (5, 5), translated by `shift`, facing its centre.
PerceivedScene group_of_three(const Eigen::Vector2d& shift) {
  PerceivedScene scene;
  for (int i = 0; i < 3; ++i) {
    const double a = M_PI / 2 + 2.0 * M_PI * i / 3.0;
    scene.people.push_back(test::person("human" + std::to_string(10 + i),
                                        5.0 + shift.x() + 0.64 * std::cos(a),
                                        5.0 + shift.y() + 0.64 * std::sin(a), a + M_PI));
  }
  scene.groups.push_back(estimate_group("g1", scene.people, 0.64));
  return scene;
}

TEST(Navigator, JoinArrivesOnlyWithinTheShortfallToleranceOfTheRing) {
  // The arrival tolerance of a join is asymmetric: 0.12 m to the side of the goal or past it
  // (into the ring) is arrived, 0.12 m short of it (outside the ring, where GCFF's o-space point
  // of ARI falls 0.12 m farther from the members') is not; a person approached keeps the
  // symmetric 0.15 m.
  const RobotObservation far{test::pose(1.5, 1.5, 0.0)};
  const auto state_at = [&](const NavigationTarget& target, const PerceivedScene& scene,
                            const Eigen::Vector2d& offset) {
    Navigator navigator(NavigationConfig{}, test::room_map(8.0));
    navigator.start(target, scene, far, 0.0);
    core::Pose2 at = navigator.goal()->pose;
    const Eigen::Vector2d ahead = at.heading();
    const Eigen::Vector2d left(-ahead.y(), ahead.x());
    at.position += offset.x() * ahead + offset.y() * left;
    return navigator.update(0.1, RobotObservation{at}, scene).state;
  };
  const PerceivedScene group = group_of_three(Eigen::Vector2d::Zero());
  const GroupTarget join{"g1"};
  EXPECT_EQ(state_at(join, group, {0.0, 0.0}), NavigationState::kSucceeded);
  EXPECT_EQ(state_at(join, group, {0.0, 0.12}), NavigationState::kSucceeded);
  EXPECT_EQ(state_at(join, group, {0.12, 0.0}), NavigationState::kSucceeded);
  EXPECT_EQ(state_at(join, group, {-0.09, 0.0}), NavigationState::kSucceeded);
  EXPECT_EQ(state_at(join, group, {-0.12, 0.0}), NavigationState::kActive);
  PerceivedScene ana;
  ana.people.push_back(test::person("ana", 5.0, 4.0, M_PI));
  EXPECT_EQ(state_at(PersonTarget{"ana"}, ana, {-0.12, 0.0}), NavigationState::kSucceeded);
}

TEST(Navigator, JoinGoalDoesNotChaseMembersSettlingByCentimetres) {
  // The members sway by up to 4 cm each way (a group settling round ARI; at most 9 cm from where
  // they were at the start): the goal pose and the geodesic
  // field's goal stay where they were, so the pose judged for arrival is the one the MPC's
  // progress term leads to; ARI arrives with its body at most the shortfall tolerance (plus the
  // body's swing within the yaw tolerance) outside the ring. A shift of 0.3 m moves the goal.
  const auto swaying_at = [](double t) {
    return group_of_three(0.04 * Eigen::Vector2d(std::sin(2.0 * t), std::cos(3.0 * t)));
  };
  Navigator navigator(NavigationConfig{}, test::room_map(8.0));
  const core::Pose2 start = test::pose(1.5, 1.5, 0.0);
  navigator.start(GroupTarget{"g1"}, swaying_at(0.0), RobotObservation{start}, 0.0);
  const core::Pose2 first = navigator.goal()->pose;
  double goal_moved_m = 0.0;
  const DriveResult run = drive_through(
      navigator, start,
      [&](double t) {
        if (navigator.goal()) {
          goal_moved_m =
              std::max(goal_moved_m, (navigator.goal()->pose.position - first.position).norm());
        }
        return swaying_at(t);
      },
      40.0);
  ASSERT_EQ(run.state, NavigationState::kSucceeded) << run.reason;
  EXPECT_LT(goal_moved_m, 1e-9);
  EXPECT_LT((navigator.geodesic()->goal() - first.position).norm(), 0.05);
  const double body_from_centre =
      (navigator.footprint().centre(run.robot.pose) - Eigen::Vector2d(5.0, 5.0)).norm();
  EXPECT_LT(body_from_centre, 0.64 + 0.1 + 0.04);
  EXPECT_GT(body_from_centre, 0.64 - 0.15 - 0.04);

  Navigator moved(NavigationConfig{}, test::room_map(8.0));
  moved.start(GroupTarget{"g1"}, group_of_three(Eigen::Vector2d::Zero()), RobotObservation{start},
              0.0);
  const Eigen::Vector2d before = moved.goal()->pose.position;
  moved.update(0.1, RobotObservation{start}, group_of_three({0.3, 0.0}));
  EXPECT_NEAR((moved.goal()->pose.position - before - Eigen::Vector2d(0.3, 0.0)).norm(), 0.0, 1e-9);
}

TEST(Navigator, FollowsATargetGroupThatPerceptionRelabels) {
  PerceivedScene scene;
  for (int i = 0; i < 3; ++i) {
    const double a = M_PI / 2 + 2.0 * M_PI * i / 3.0;
    scene.people.push_back(test::person("p" + std::to_string(i), 5.0 + 0.64 * std::cos(a),
                                        5.0 + 0.64 * std::sin(a), a + M_PI));
  }
  scene.groups.push_back(estimate_group("g1", scene.people, 0.64));
  Navigator navigator(NavigationConfig{}, test::room_map(8.0));
  const RobotObservation robot{test::pose(1.5, 1.5, 0.0)};
  navigator.start(GroupTarget{"g1"}, scene, robot, 0.0);
  // Group detection now reports the same three as g2 (and two others as g3): for 10 s, twice the
  // lost-target timeout, ARI keeps joining them under the new id.
  PerceivedScene relabelled = scene;
  relabelled.groups = {estimate_group("g2", scene.people, 0.64)};
  relabelled.people.push_back(test::person("q1", 2.0, 6.0, 0.0));
  relabelled.people.push_back(test::person("q2", 3.0, 6.0, M_PI));
  relabelled.groups.push_back(
      estimate_group("g3", {relabelled.people[3], relabelled.people[4]}, 0.5));
  for (double t = 0.5; t <= 10.0; t += 0.5) {
    ASSERT_EQ(navigator.update(t, robot, relabelled).state, NavigationState::kActive) << t;
  }
  EXPECT_EQ(std::get<GroupTarget>(*navigator.target()).group_id, "g2");
  // A group sharing a single member is not the target: ARI gives up after the timeout.
  PerceivedScene split = relabelled;
  split.groups = {estimate_group("g4", {relabelled.people[0], relabelled.people[3]}, 0.5)};
  NavigatorStep step;
  for (double t = 10.5; t <= 16.0 && step.state != NavigationState::kAborted; t += 0.5) {
    step = navigator.update(t, robot, split);
  }
  EXPECT_EQ(step.state, NavigationState::kAborted);
  EXPECT_NE(step.reason.find("group g2 lost for 5.5 s"), std::string::npos) << step.reason;
}

TEST(Navigator, FollowsATargetPersonThatThePersonManagerRenames) {
  const PerceivedScene scene = group_of_three(Eigen::Vector2d::Zero());
  Navigator navigator(NavigationConfig{}, test::room_map(8.0));
  const RobotObservation robot{test::pose(1.5, 1.5, 0.0)};
  navigator.start(GroupOfPersonTarget{"human11"}, scene, robot, 0.0);
  // The person manager now calls human11 anon_x, 0.1 m from where human11 stood: for 10 s, twice
  // the lost-target timeout, ARI keeps joining their group under the new id.
  PerceivedScene renamed = scene;
  renamed.people[1].id = "anon_x";
  renamed.people[1].position += Eigen::Vector2d(0.1, 0.0);
  renamed.groups = {estimate_group("g1", renamed.people, 0.64)};
  for (double t = 0.5; t <= 10.0; t += 0.5) {
    ASSERT_EQ(navigator.update(t, robot, renamed).state, NavigationState::kActive) << t;
  }
  EXPECT_EQ(std::get<GroupOfPersonTarget>(*navigator.target()).person_id, "anon_x");
  // Gone, and no one within 0.5 m of where they were (the two others are 1.1 m away): ARI gives
  // up after the timeout.
  PerceivedScene gone = scene;
  gone.people.erase(gone.people.begin() + 1);
  gone.groups = {estimate_group("g1", gone.people, 0.64)};
  NavigatorStep step;
  for (double t = 10.5; t <= 16.0 && step.state != NavigationState::kAborted; t += 0.5) {
    step = navigator.update(t, robot, gone);
  }
  EXPECT_EQ(step.state, NavigationState::kAborted);
  EXPECT_NE(step.reason.find("person anon_x is not tracked"), std::string::npos) << step.reason;
}

// ARI sets out from afar to join the group of `person` in `at_start`, then sees `after` for 10 s,
// twice the lost-target timeout: the id of the person whose group it still joins, or "" (with a
// test failure) if it gave up.
std::string group_joined_for_10_s(const PerceivedScene& at_start, const std::string& person,
                                  const PerceivedScene& after) {
  Navigator navigator(NavigationConfig{}, test::room_map(8.0));
  const RobotObservation robot{test::pose(1.5, 1.5, 0.0)};
  navigator.start(GroupOfPersonTarget{person}, at_start, robot, 0.0);
  for (double t = 0.5; t <= 10.0; t += 0.5) {
    const NavigatorStep step = navigator.update(t, robot, after);
    if (step.state != NavigationState::kActive) {
      ADD_FAILURE() << "not joining at " << t << " s: " << step.reason;
      return "";
    }
  }
  return std::get<GroupOfPersonTarget>(*navigator.target()).person_id;
}

TEST(Navigator, JoinsTheGroupOfAPersonTrackedTwiceUnderTheIdThatIsGrouped) {
  // Perception tracks Irene twice: as anon_x (her body, 0.1 m off) and, once her face is
  // recognised, as human11. ARI set out to join anon_x's group; group detection then groups
  // human11 instead and leaves anon_x in no group. ARI joins human11's group rather than giving
  // up after the lost-target timeout (as CI saw: "the group of person anonymous_person_cjaac lost
  // for 5.1 s (person anonymous_person_cjaac is in no group)").
  PerceivedScene body_grouped = group_of_three(Eigen::Vector2d::Zero());
  body_grouped.people[1].id = "anon_x";
  body_grouped.people[1].position += Eigen::Vector2d(0.1, 0.0);
  body_grouped.groups = {estimate_group("g1", body_grouped.people, 0.64)};
  PerceivedScene face_grouped = group_of_three(Eigen::Vector2d::Zero());
  face_grouped.people.push_back(body_grouped.people[1]);
  EXPECT_EQ(group_joined_for_10_s(body_grouped, "anon_x", face_grouped), "human11");
}

TEST(Navigator, JoinsTheGroupOfALostTargetWhoseFaceTrackTookTheirPlace) {
  // ARI joins anon_x's group; the person manager then ends anon_x's track, and human11, the same
  // person under the track of her recognised face, is grouped in her place 0.8 m from anon_x's
  // last estimate, farther than a relabelling moves a track (as CI saw: "the group of person
  // anonymous_person_hgdeb lost for 5.0 s (person anonymous_person_hgdeb is not tracked)").
  PerceivedScene body_tracked = group_of_three(Eigen::Vector2d::Zero());
  const Eigen::Vector2d face_position = body_tracked.people[1].position;
  body_tracked.people[1].id = "anon_x";
  // 0.8 m farther from the group's centre (at 5, 5), as a body track's depth errs.
  body_tracked.people[1].position += 0.8 * (face_position - Eigen::Vector2d(5.0, 5.0)).normalized();
  body_tracked.groups = {estimate_group("g1", body_tracked.people, 0.64)};
  PerceivedScene face_tracked = group_of_three(Eigen::Vector2d::Zero());
  face_tracked.groups[0].id = "g2";
  ASSERT_NEAR((face_position - body_tracked.people[1].position).norm(), 0.8, 1e-9);
  EXPECT_EQ(group_joined_for_10_s(body_tracked, "anon_x", face_tracked), "human11");
  // A group that shrank lost its member instead: FollowsATargetPersonThatThePersonManagerRenames.
}

}  // namespace
}  // namespace ari_social_sim::navigation
