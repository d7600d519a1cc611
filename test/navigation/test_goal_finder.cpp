// The goal finder on hand-made people and groups: where ARI stands for a pose, a person and a
// group, which gap it picks, and why it refuses.

#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/navigation/goal_finder.hpp"
#include "navigation_fixtures.hpp"

namespace ari_social_sim::navigation {
namespace {

const FootprintModel kFootprint = FootprintModel::covering(model::AriFootprint{}, 3);
// ARI's body centre is 0.22 m behind base_footprint (model::AriFootprint: x -0.60..+0.16).
constexpr double kCentreBehindBase = 0.22;

class GoalFinderTest : public ::testing::Test {
 protected:
  GoalFinderTest() : sdf_(signed_distance_field(test::room_map(8.0))) {}

  // A group of members at the given angles (deg) on a circle of `radius` around `centre`, each
  // facing the centre.
  void add_group(const std::string& id, const Eigen::Vector2d& centre, double radius,
                 const std::vector<double>& angles_deg, int first_member) {
    GroupEstimate group;
    group.id = id;
    group.centre = centre;
    group.radius_m = radius;
    for (size_t i = 0; i < angles_deg.size(); ++i) {
      const double a = angles_deg[i] * M_PI / 180.0;
      const std::string person_id = "human" + std::to_string(first_member + i);
      scene_.people.push_back(test::person(person_id, centre.x() + radius * std::cos(a),
                                           centre.y() + radius * std::sin(a), a + M_PI));
      group.members.push_back(person_id);
    }
    scene_.groups.push_back(group);
  }

  // The goal found; a failure fails the test (and gives a default goal).
  Goal find(const NavigationTarget& target, const core::Pose2& robot = test::pose(1, 1, 0),
            const std::optional<Goal>& previous = std::nullopt) {
    GoalSearch search = finder_.find(target, scene_, sdf_, robot, previous);
    if (const auto* failure = std::get_if<GoalFailure>(&search)) {
      ADD_FAILURE() << "no goal for " << describe(target) << ": " << failure->reason;
      return {};
    }
    return std::get<Goal>(std::move(search));
  }

  // Why there is no goal; a goal fails the test (and gives an empty failure).
  GoalFailure failure(const NavigationTarget& target) {
    const GoalSearch search = finder_.find(target, scene_, sdf_, test::pose(1, 1, 0));
    if (const auto* failure = std::get_if<GoalFailure>(&search)) {
      return *failure;
    }
    ADD_FAILURE() << "found a goal for " << describe(target);
    return {};
  }

  GridField sdf_;
  PerceivedScene scene_;
  GoalFinder finder_{GoalFinderConfig{}, kFootprint, PersonalSpaceParams{}};
};

TEST_F(GoalFinderTest, PoseGoalIsThePoseUnlessTheFootprintHitsSomething) {
  const Goal goal = find(PoseTarget{test::pose(4.0, 4.0, 1.0)});
  EXPECT_DOUBLE_EQ(goal.pose.position.x(), 4.0);
  EXPECT_DOUBLE_EQ(goal.pose.theta, 1.0);
  EXPECT_FALSE(goal.look_at);
  // Facing the west wall (inner face x = 0.05) from 0.2 m: the front is clear, but the body
  // behind base_footprint reaches x = 0.8... facing east from x = 0.3 puts the rear in the wall.
  const GoalFailure in_wall = failure(PoseTarget{test::pose(0.3, 4.0, 0.0)});
  EXPECT_EQ(in_wall.kind, GoalFailure::Kind::kUnreachable);
  EXPECT_NE(in_wall.reason.find("overlaps a wall or furniture"), std::string::npos);
  const GoalFailure off_map = failure(PoseTarget{test::pose(20.0, 4.0, 0.0)});
  EXPECT_EQ(off_map.kind, GoalFailure::Kind::kUnreachable);
  // room_map(8.0): the 8 m room's walls and margin, from -0.2 to 8.2 m.
  EXPECT_NE(off_map.reason.find("(20.00, 4.00) is outside the map, which spans x [-0.20, "
                                "8.20] and y [-0.20, 8.20]"),
            std::string::npos)
      << off_map.reason;
}

TEST_F(GoalFinderTest, PersonIsApproachedFromTheFrontAtTheComfortableDistance) {
  scene_.people.push_back(test::person("human10", 4.0, 4.0, 0.0));  // facing east
  const Goal goal = find(PersonTarget{"human10"}, test::pose(6.0, 3.0, 0.0));
  // base_footprint 1.1 m straight ahead of them, facing them.
  EXPECT_NEAR(goal.pose.position.x(), 5.1, 1e-9);
  EXPECT_NEAR(goal.pose.position.y(), 4.0, 1e-9);
  EXPECT_NEAR(std::abs(goal.pose.theta), M_PI, 1e-9);
  ASSERT_TRUE(goal.look_at);
  EXPECT_NEAR((*goal.look_at - Eigen::Vector2d(4.0, 4.0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(goal.target_people, std::vector<std::string>{"human10"});
}

TEST_F(GoalFinderTest, SomeoneInFrontOfThePersonMovesAriToTheSideOfTheirView) {
  // A bystander stands where ARI would stand straight ahead: the finder moves round the person,
  // within 30 deg of their facing direction, to a place whose footprint clears the bystander.
  scene_.people.push_back(test::person("human10", 4.0, 4.0, 0.0));
  scene_.people.push_back(test::person("human11", 5.1, 4.0, M_PI));
  const Goal goal = find(PersonTarget{"human10"}, test::pose(6.0, 7.0, 0.0));
  const Eigen::Vector2d d = goal.pose.position - Eigen::Vector2d(4.0, 4.0);
  const double off_facing = std::abs(std::atan2(d.y(), d.x()));
  EXPECT_LE(off_facing, GoalFinderConfig{}.approach_max_angle + 1e-9);
  EXPECT_GT(off_facing, 0.2);
  EXPECT_GE(kFootprint.distance_to(goal.pose, {5.1, 4.0}), 0.2 + 0.05 - 1e-9);
  // Facing the person, and on the side nearer ARI (north).
  EXPECT_NEAR(std::remainder(goal.pose.theta - std::atan2(-d.y(), -d.x()), 2 * M_PI), 0.0, 1e-9);
  EXPECT_GT(goal.pose.position.y(), 4.0);
}

TEST_F(GoalFinderTest, GroupIsJoinedAtTheBisectorOfItsWidestGapFacingTheCentre) {
  // Three members at 90, 180 and 270 deg: gaps of 90, 90 and 180 deg; the widest is centred on
  // 0 deg, so ARI's body centre goes to centre + r (1, 0), facing -x.
  add_group("g1", {4.0, 4.0}, 0.64, {90, 180, 270}, 10);
  const Goal goal = find(GroupTarget{"g1"});
  EXPECT_NEAR(goal.gap_angle, 0.0, 1e-9);
  EXPECT_NEAR(goal.gap_width, M_PI, 1e-9);
  EXPECT_FALSE(goal.outside_circle);
  EXPECT_NEAR(std::abs(goal.pose.theta), M_PI, 1e-9);
  EXPECT_NEAR(goal.pose.position.x(), 4.0 + 0.64 - kCentreBehindBase, 1e-9);
  EXPECT_NEAR(goal.pose.position.y(), 4.0, 1e-9);
  EXPECT_NEAR(kFootprint.centre(goal.pose).x(), 4.64, 1e-9);
  EXPECT_EQ(goal.group_id, "g1");
  EXPECT_EQ(goal.target_people.size(), 3u);
  // Joining the group of person human11 is the same.
  const Goal via_member = find(GroupOfPersonTarget{"human11"});
  EXPECT_NEAR((via_member.pose.position - goal.pose.position).norm(), 0.0, 1e-12);
}

TEST_F(GoalFinderTest, WidestGapAgainstAWallGivesWayToTheNextOne) {
  // Centre 1.0 m from the west wall; members at 0, 100 and 260 deg: the widest gap (100..260 deg,
  // 160 deg) opens toward the wall, where ARI's body cannot stand; the next ones (100 deg each)
  // are centred on 50 and -50 deg.
  add_group("g1", {1.2, 4.0}, 0.64, {0, 100, 260}, 10);
  const Goal goal = find(GroupTarget{"g1"}, test::pose(4.0, 6.0, 0.0));
  EXPECT_NEAR(std::abs(goal.gap_angle), 50.0 * M_PI / 180.0, 1e-9);
  EXPECT_NEAR(goal.gap_width, 100.0 * M_PI / 180.0, 1e-9);
  // Of the two equally wide gaps, the one toward ARI (north-east, ARI at y = 6) wins.
  EXPECT_GT(goal.gap_angle, 0.0);
}

TEST_F(GoalFinderTest, EquallyWideGapsGoToTheOneNearestAri) {
  // A pair facing each other along y: gaps centred on 0 and 180 deg, both 180 deg wide.
  add_group("g1", {4.0, 4.0}, 0.55, {90, 270}, 10);
  EXPECT_NEAR(find(GroupTarget{"g1"}, test::pose(7.0, 4.5, 0.0)).gap_angle, 0.0, 1e-9);
  EXPECT_NEAR(std::abs(find(GroupTarget{"g1"}, test::pose(1.0, 4.5, 0.0)).gap_angle), M_PI, 1e-9);
  // Members at 90 + d and 270 - d deg leave gaps of 180 - 2d (around 180) and 180 + 2d (around
  // 0). The gap around 180 deg 17 deg (0.30 rad) wider still counts as equally wide (tolerance
  // 0.35 rad), so ARI in the east takes the eastern one ...
  scene_ = PerceivedScene{};
  add_group("g1", {4.0, 4.0}, 0.55, {85.75, 274.25}, 10);  // 188.5 vs 171.5 deg
  EXPECT_NEAR(find(GroupTarget{"g1"}, test::pose(7.0, 4.5, 0.0)).gap_angle, 0.0, 1e-9);
  // ... but one 24 deg (0.42 rad) wider wins wherever ARI is.
  scene_ = PerceivedScene{};
  add_group("g1", {4.0, 4.0}, 0.55, {84, 276}, 10);  // 192 vs 168 deg
  EXPECT_NEAR(std::abs(find(GroupTarget{"g1"}, test::pose(7.0, 4.5, 0.0)).gap_angle), M_PI, 1e-9);
}

TEST_F(GoalFinderTest, KeepsTheGapChosenBeforeWhileItHasRoom) {
  add_group("g1", {4.0, 4.0}, 0.55, {90, 270}, 10);
  const Goal east = find(GroupTarget{"g1"}, test::pose(7.0, 4.5, 0.0));
  ASSERT_NEAR(east.gap_angle, 0.0, 1e-9);
  // ARI has driven round to the west, but the east gap stays chosen.
  EXPECT_NEAR(find(GroupTarget{"g1"}, test::pose(1.0, 4.5, 0.0), east).gap_angle, 0.0, 1e-9);
}

TEST_F(GoalFinderTest, NoGapWithRoomPutsAriJustOutsideTheCircle) {
  // Four members 0.5 m from the centre: each 90 deg gap is 0.79 m of arc, less than ARI's 0.54 m
  // plus 2 x 0.3 m. ARI goes outside the circle on a gap's bisector, facing the centre: with its
  // body centre 0.7, 0.8 or 0.9 m out its front corners come within 0.19-0.24 m of a member's
  // centre (< 0.2 m body + 0.05 m margin); at 1.0 m they are 0.28 m away.
  add_group("g1", {4.0, 4.0}, 0.5, {0, 90, 180, 270}, 10);
  const Goal goal = find(GroupTarget{"g1"});
  EXPECT_TRUE(goal.outside_circle);
  const Eigen::Vector2d body = kFootprint.centre(goal.pose);
  EXPECT_NEAR((body - Eigen::Vector2d(4.0, 4.0)).norm(), 1.0, 1e-9);
  const Eigen::Vector2d to_centre = Eigen::Vector2d(4.0, 4.0) - body;
  EXPECT_NEAR(std::remainder(goal.pose.theta - std::atan2(to_centre.y(), to_centre.x()), 2 * M_PI),
              0.0, 1e-9);
}

TEST_F(GoalFinderTest, UnknownIdsAndCrowdedPlacesAreRefusedWithAReason) {
  add_group("g1", {4.0, 4.0}, 0.64, {90, 180, 270}, 10);
  scene_.people.push_back(test::person("human20", 6.5, 6.5, 0.0));
  auto expect = [&](const NavigationTarget& target, const std::string& text, bool unknown) {
    const GoalFailure refused = failure(target);
    EXPECT_EQ(refused.kind,
              unknown ? GoalFailure::Kind::kUnknownTarget : GoalFailure::Kind::kUnreachable)
        << refused.reason;
    EXPECT_NE(refused.reason.find(text), std::string::npos) << refused.reason;
  };
  expect(PersonTarget{"human99"}, "person human99 is not tracked", true);
  expect(GroupTarget{"g7"}, "group g7 is not reported", true);
  expect(GroupOfPersonTarget{"human20"}, "person human20 is in no group", true);
  // Someone standing in a closet just big enough for them: no place in front.
  scene_.people.push_back(test::person("human30", 0.3, 0.3, M_PI));
  expect(PersonTarget{"human30"}, "no free place in front of person human30", false);
}

}  // namespace
}  // namespace ari_social_sim::navigation
