// The goal life cycle and control timer social_mpc_node and the batch tool share: which goal is
// pursued, how each ends and why, when the base is stopped, when cycles run, and what perception
// they see.

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "ari_social_sim/navigation/navigation_session.hpp"
#include "navigation_fixtures.hpp"

namespace ari_social_sim::navigation {
namespace {

// ARI standing at (1, 1) facing east in a 6 m room; nobody perceived.
SessionInputs at(double now_s) {
  SessionInputs inputs;
  inputs.now_s = now_s;
  inputs.robot = RobotObservation{test::pose(1.0, 1.0, 0.0)};
  inputs.perception.locate_body = [](const std::string&) { return std::nullopt; };
  return inputs;
}

// The same with person p1 (body b1) standing at (3, 3) facing west, placed at `now_s`.
SessionInputs with_p1(double now_s) {
  SessionInputs inputs = at(now_s);
  inputs.perception.persons = {{"p1", "b1"}};
  inputs.perception.locate_body = [now_s](const std::string& body) {
    return body == "b1" ? std::optional(model::BodyPlacement{now_s, test::pose(3.0, 3.0, M_PI)})
                        : std::nullopt;
  };
  return inputs;
}

std::vector<GoalChange> changes_of(const SessionOutput& out, GoalId goal) {
  std::vector<GoalChange> changes;
  for (const GoalChange& change : out.goals) {
    if (change.goal == goal) {
      changes.push_back(change);
    }
  }
  return changes;
}

const PoseTarget kFarCorner{test::pose(4.5, 4.5, 0.0)};

TEST(NavigationSession, GoalsBeforeTheMapOrAPoseOfAriAreAbortedWithTheReason) {
  NavigationSession session{NavigationConfig{}};
  SessionOutput out = session.request(kFarCorner, at(0.0));
  ASSERT_EQ(out.goals.size(), 2u);
  EXPECT_EQ(out.goals[0].status.state, GoalState::kPending);
  EXPECT_EQ(out.goals[1].goal, 1u);
  EXPECT_EQ(out.goals[1].status.state, GoalState::kAborted);
  EXPECT_EQ(out.goals[1].status.reason, "no map received on /map yet");
  EXPECT_TRUE(out.commands.empty());

  session.set_map(test::room_map(6.0));
  SessionInputs lost = at(0.0);
  lost.robot.reset();
  out = session.request(kFarCorner, lost);
  EXPECT_EQ(session.newest_goal(), 2u);
  EXPECT_EQ(out.goals.back().status.state, GoalState::kAborted);
  EXPECT_EQ(out.goals.back().status.reason, "no transform from map to base_footprint yet");
  EXPECT_EQ(session.pursued_goal(), 0u);
}

TEST(NavigationSession, ANewGoalPreemptsThePursuedOneAndOneThatCannotStartLeavesItPursued) {
  NavigationSession session{NavigationConfig{}};
  session.set_map(test::room_map(6.0));
  SessionOutput out = session.request(kFarCorner, at(0.0));
  EXPECT_EQ(out.goals.back().status.state, GoalState::kActive);
  EXPECT_EQ(session.pursued_goal(), 1u);

  // Inside the wall: aborted, and goal 1 goes on (its cycle still commands ARI).
  out = session.request(PoseTarget{test::pose(-1.0, 1.0, 0.0)}, at(0.05));
  ASSERT_EQ(out.goals.size(), 2u);
  EXPECT_EQ(out.goals[1].goal, 2u);
  EXPECT_EQ(out.goals[1].status.state, GoalState::kAborted);
  EXPECT_FALSE(out.goals[1].status.reason.empty());
  EXPECT_EQ(session.pursued_goal(), 1u);
  out = session.control(at(0.1));
  ASSERT_EQ(out.commands.size(), 1u);
  EXPECT_TRUE(out.commands[0].pan_rad.has_value());

  // A reachable one replaces goal 1 without stopping the base.
  out = session.request(PoseTarget{test::pose(3.0, 1.0, 0.0)}, at(0.15));
  const std::vector<GoalChange> first = changes_of(out, 1);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].status.state, GoalState::kCanceled);
  EXPECT_EQ(first[0].status.reason, "preempted by a new goal");
  EXPECT_EQ(changes_of(out, 3).back().status.state, GoalState::kActive);
  EXPECT_TRUE(out.commands.empty());
  EXPECT_EQ(session.pursued_goal(), 3u);
}

TEST(NavigationSession, CancelEndsTheGoalAndStopsTheBase) {
  NavigationSession session{NavigationConfig{}};
  session.set_map(test::room_map(6.0));
  session.request(kFarCorner, at(0.0));
  EXPECT_TRUE(session.cancel(7).goals.empty());  // no such goal
  const SessionOutput out = session.cancel(1);
  ASSERT_EQ(out.goals.size(), 1u);
  EXPECT_EQ(out.goals[0].status.state, GoalState::kCanceled);
  EXPECT_EQ(out.goals[0].status.reason, "canceled by the client");
  ASSERT_EQ(out.commands.size(), 1u);
  EXPECT_EQ(out.commands[0].linear_mps, 0.0);
  EXPECT_EQ(out.commands[0].angular_rps, 0.0);
  EXPECT_FALSE(out.commands[0].pan_rad.has_value());
  EXPECT_EQ(session.pursued_goal(), 0u);
  EXPECT_TRUE(session.control(at(0.1)).commands.empty());
}

TEST(NavigationSession, OneCycleInEachControlPeriodAtTheFirstCallInIt) {
  NavigationConfig config;  // 10 Hz
  NavigationSession session{config};
  session.set_map(test::room_map(6.0));
  session.request(kFarCorner, at(0.0));
  // Every world step of 0.05 s from 0.05 s to 1 s: periods 0 to 10 from sim time 0, a cycle
  // in each, at 0.05, 0.1, 0.2, ..., 1.0 s.
  int cycles = 0;
  for (int step = 1; step <= 20; ++step) {
    cycles += session.control(at(step * 0.05)).step.has_value();
  }
  EXPECT_EQ(cycles, 11);
  // A second call at the same time, or later in the same period, runs none.
  EXPECT_FALSE(session.control(at(1.0)).step.has_value());
  EXPECT_FALSE(session.control(at(1.09)).step.has_value());
  EXPECT_TRUE(session.control(at(1.1)).step.has_value());
  // Time going back (a world reset) aborts the goal (its progress is void); the next goal's
  // cycles count from the new time.
  EXPECT_EQ(session.control(at(0.2)).goals.at(0).status.state, GoalState::kAborted);
  session.request(kFarCorner, at(0.25));
  EXPECT_TRUE(session.control(at(0.3)).step.has_value());
}

TEST(NavigationSession, AGoalNamingSomeoneNotPerceivedWaitsForThemThenStarts) {
  NavigationSession session{NavigationConfig{}};
  session.set_map(test::room_map(6.0));
  SessionOutput out = session.request(PersonTarget{"p1"}, at(0.0));
  ASSERT_EQ(out.goals.size(), 1u);
  EXPECT_EQ(out.goals[0].status.state, GoalState::kPending);
  EXPECT_TRUE(session.control(at(0.5)).goals.empty());
  // p1 perceived at 1.5 s: the goal starts at that cycle.
  out = session.control(with_p1(1.5));
  ASSERT_EQ(out.goals.size(), 1u);
  EXPECT_EQ(out.goals[0].status.state, GoalState::kActive);
  EXPECT_EQ(session.pursued_goal(), 1u);
}

TEST(NavigationSession, PerceptionIsLookedAtTwicePerControlPeriod) {
  NavigationSession session{NavigationConfig{}};  // 10 Hz: looks at 20 Hz
  session.set_map(test::room_map(6.0));
  session.request(PersonTarget{"p1"}, at(0.0));
  EXPECT_TRUE(session.control(at(0.1)).goals.empty());
  // p1 reported only at 0.15 s, half way through a control period: no cycle, but a look.
  SessionOutput out = session.control(with_p1(0.15));
  EXPECT_TRUE(out.goals.empty());
  // The cycle at 0.2 s finds p1 known (kept for the tracker's 2 s) and starts the goal.
  out = session.control(at(0.2));
  ASSERT_EQ(out.goals.size(), 1u);
  EXPECT_EQ(out.goals[0].status.state, GoalState::kActive);
}

TEST(NavigationSession, AGoalWhoseTargetIsNeverPerceivedIsRejectedAfterTwoSeconds) {
  NavigationSession session{NavigationConfig{}};
  session.set_map(test::room_map(6.0));
  session.request(PersonTarget{"p9"}, at(1.0));
  EXPECT_TRUE(session.control(at(2.95)).goals.empty());
  const SessionOutput out = session.control(at(3.0));
  ASSERT_EQ(out.goals.size(), 1u);
  EXPECT_EQ(out.goals[0].status.state, GoalState::kRejected);
  EXPECT_EQ(out.goals[0].status.reason, "person p9 is not tracked");
  EXPECT_TRUE(out.commands.empty());

  // A newer request replaces a goal still waiting.
  session.request(PersonTarget{"p9"}, at(4.0));
  const SessionOutput next = session.request(kFarCorner, at(4.05));
  const std::vector<GoalChange> waiting = changes_of(next, 2);
  ASSERT_EQ(waiting.size(), 1u);
  EXPECT_EQ(waiting[0].status.state, GoalState::kRejected);
  EXPECT_EQ(waiting[0].status.reason, "preempted by a new goal before its target was perceived");
  EXPECT_EQ(session.pursued_goal(), 3u);
}

TEST(NavigationSession, GroupsReceivedReachTheSceneAtTheNextLookAtPerception) {
  NavigationSession session{NavigationConfig{}};
  session.set_map(test::room_map(6.0));
  SessionInputs two = at(0.1);
  two.perception.persons = {{"p1", "b1"}, {"p2", "b2"}};
  const std::map<std::string, core::Pose2> bodies = {{"b1", test::pose(3.0, 3.0, 0.0)},
                                                     {"b2", test::pose(4.0, 3.0, M_PI)}};
  two.perception.locate_body = [&bodies](const std::string& body) {
    const auto it = bodies.find(body);
    return it == bodies.end() ? std::nullopt : std::optional(model::BodyPlacement{0.1, it->second});
  };
  session.receive_group({"g1", 0.05, {"p1", "p2"}});
  session.control(two);
  const SessionOutput out = session.request(GroupTarget{"g1"}, two);
  EXPECT_EQ(out.goals.back().status.state, GoalState::kActive) << out.goals.back().status.reason;
}

TEST(NavigationSession, AGoalReachedEndsSucceededAndStopsTheBase) {
  NavigationSession session{NavigationConfig{}};
  session.set_map(test::room_map(6.0));
  session.request(PoseTarget{test::pose(1.0, 1.0, 0.0)}, at(0.0));
  const SessionOutput out = session.control(at(0.1));
  ASSERT_EQ(out.goals.size(), 1u);
  EXPECT_EQ(out.goals[0].status.state, GoalState::kSucceeded);
  ASSERT_EQ(out.commands.size(), 1u);
  EXPECT_FALSE(out.commands[0].pan_rad.has_value());
  ASSERT_TRUE(out.step.has_value());
  EXPECT_EQ(out.step->state, NavigationState::kSucceeded);
}

TEST(NavigationSession, WhatItIsToldAnUlpApartPlansAlike) {
  // Live, ARI's heading and the people reach the node through tf's quaternions, and a goal
  // heading of 3.1416 comes back from move_base's quaternion as 3.1416 - 2 pi.
  const auto ulp_off = [](double value) { return std::nextafter(value, 10.0); };
  NavigationSession batch{NavigationConfig{}}, live{NavigationConfig{}};
  batch.set_map(test::room_map(6.0));
  live.set_map(test::room_map(6.0));
  batch.request(PoseTarget{test::pose(4.5, 4.5, 3.1416)}, with_p1(0.0));
  live.request(PoseTarget{test::pose(4.5, 4.5, 3.1416 - 2.0 * M_PI)}, with_p1(0.0));
  for (int cycle = 1; cycle <= 10; ++cycle) {
    const double now_s = 0.1 * cycle;
    SessionInputs told = with_p1(now_s);
    told.now_s = ulp_off(now_s);
    told.robot->pose = test::pose(ulp_off(1.0), 1.0, ulp_off(0.0));
    told.perception.locate_body = [now_s, ulp_off](const std::string& body) {
      return body == "b1" ? std::optional(model::BodyPlacement{
                                now_s, test::pose(ulp_off(3.0), 3.0, ulp_off(M_PI))})
                          : std::nullopt;
    };
    const SessionOutput a = batch.control(with_p1(now_s));
    const SessionOutput b = live.control(told);
    ASSERT_EQ(a.commands.size(), 1u);
    ASSERT_EQ(b.commands.size(), 1u);
    EXPECT_EQ(a.commands[0].linear_mps, b.commands[0].linear_mps) << "cycle " << cycle;
    EXPECT_EQ(a.commands[0].angular_rps, b.commands[0].angular_rps) << "cycle " << cycle;
    EXPECT_EQ(*a.commands[0].pan_rad, *b.commands[0].pan_rad) << "cycle " << cycle;
  }
}

TEST(NavigationSession, ANewMapAbortsThePursuedGoal) {
  NavigationSession session{NavigationConfig{}};
  session.set_map(test::room_map(6.0));
  session.request(kFarCorner, at(0.0));
  const SessionOutput out = session.set_map(test::room_map(8.0));
  ASSERT_EQ(out.goals.size(), 1u);
  EXPECT_EQ(out.goals[0].status.state, GoalState::kAborted);
  EXPECT_EQ(out.goals[0].status.reason, "the map changed while navigating");
  ASSERT_EQ(out.commands.size(), 1u);
  EXPECT_EQ(session.pursued_goal(), 0u);
}

// A rogue transform (map -> odom or a body frame at 1e300 or inf) is no pose: while it lasts ARI
// is not placed and the person not updated; once good transforms return, the goal goes on and
// nothing kept holds the absurd value.
TEST(NavigationSession, AbsurdPosesOfAriAndOfBodiesAreIgnoredAndTheGoalGoesOn) {
  for (const double rogue : {1e300, double{INFINITY}, double{NAN}}) {
    NavigationSession session{NavigationConfig{}};
    session.set_map(test::room_map(6.0));
    session.request(kFarCorner, with_p1(0.0));
    ASSERT_EQ(session.pursued_goal(), 1u);
    SessionInputs told = with_p1(0.1);
    told.robot->pose.position.x() = rogue;
    told.perception.locate_body = [rogue](const std::string&) {
      return std::optional(model::BodyPlacement{0.1, test::pose(rogue, 3.0, 0.0)});
    };
    SessionOutput out = session.control(told);
    EXPECT_FALSE(out.step) << "ARI placed at x = " << rogue;
    EXPECT_TRUE(out.goals.empty()) << rogue;
    out = session.control(with_p1(0.2));
    ASSERT_TRUE(out.step) << rogue;
    EXPECT_EQ(out.step->state, NavigationState::kActive) << rogue;
    EXPECT_TRUE(std::isfinite(out.step->command.linear_mps)) << rogue;
    EXPECT_EQ(session.pursued_goal(), 1u) << rogue;
  }
}

TEST(NavigationSession, TimeGoingBackAbortsThePursuedGoalAndForgetsEveryone) {
  NavigationSession session{NavigationConfig{}};
  session.set_map(test::room_map(6.0));
  session.control(with_p1(1145.0));
  session.request(kFarCorner, with_p1(1145.05));
  ASSERT_EQ(session.pursued_goal(), 1u);
  // A world reset: sim time back to 0.1 s, p1 no longer perceived.
  SessionOutput out = session.control(at(0.1));
  const std::vector<GoalChange> changes = changes_of(out, 1);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].status.state, GoalState::kAborted);
  EXPECT_EQ(changes[0].status.reason,
            "sim time went back from 1145.05 s to 0.1 s (a world reset): the goal's progress is "
            "void");
  // p1, seen before the reset, is no longer known: an approach waits for them.
  out = session.request(PersonTarget{"p1"}, at(0.15));
  EXPECT_EQ(out.goals.back().status.state, GoalState::kPending);
  // A new goal after the reset is pursued as before it.
  out = session.request(kFarCorner, at(0.2));
  EXPECT_EQ(out.goals.back().status.state, GoalState::kActive);
}

}  // namespace
}  // namespace ari_social_sim::navigation
