#include <gtest/gtest.h>

#include <type_traits>
#include <utility>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/service_requests.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "refusal_text.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

// Readers get const objects only, even from a mutable Simulation: changes go through requests.
static_assert(std::is_same_v<decltype(std::declval<Simulation&>().find_human(10)), const Human*>);
static_assert(
    std::is_same_v<decltype(std::declval<Simulation&>().find_group(1)), const GroupNavigation*>);
static_assert(std::is_same_v<decltype(std::declval<Simulation&>().find_object(1)), const Object*>);
static_assert(std::is_same_v<decltype(std::declval<Simulation&>().ari()), const Ari*>);
static_assert(
    std::is_same_v<decltype(*std::declval<Simulation&>().humans().begin()), const Human*>);
static_assert(std::is_same_v<decltype(*std::declval<Simulation&>().groups().begin()),
                             const GroupNavigation*>);
static_assert(
    std::is_same_v<decltype(std::declval<Simulation&>().add_human(HumanSpec{})), const Human&>);

HumanSpec person(model::ObjectId id, double x, double y) {
  HumanSpec spec;
  spec.id = id;
  spec.pose.position = {x, y};
  return spec;
}

GroupSpec group_of(model::ObjectId id, std::vector<model::ObjectId> members,
                   const Eigen::Vector2d& centre) {
  GroupSpec spec;
  spec.id = id;
  spec.members = std::move(members);
  spec.centre = centre;
  return spec;
}

GazeModel looking_at(model::ObjectId target) {
  GazeModel gaze;
  gaze.targets = {{target, 1.0}};
  gaze.mean_duration_s = 2.0;
  return gaze;
}

using test::refusal_text;

TEST(WorldRequests, UnknownIdsAreRefusedNamingTheRequestAndTheField) {
  auto sim = test::request_world();
  const core::Pose2 pose{{1.0, 1.0}, 0.0};
  EXPECT_EQ(refusal_text([&] { sim->remove_human(99); }), "remove_human: id: no human with id 99");
  EXPECT_EQ(refusal_text([&] { sim->set_human_goal(99, pose); }),
            "set_goal: id: no human with id 99");
  EXPECT_EQ(refusal_text([&] {
              sim->set_human_velocity(99, {0.1, 0.0}, 0.0);
            }),
            "set_velocity: id: no human with id 99");
  EXPECT_EQ(refusal_text([&] { sim->set_human_gaze(99, looking_at(10)); }),
            "set_gaze_targets: id: no human with id 99");
  // 1002 is a wall of square_room: neither a human nor ARI.
  EXPECT_EQ(refusal_text([&] { sim->set_pose(1002, pose); }),
            "set_pose: id: no human or ARI with id 1002");
  EXPECT_EQ(refusal_text([&] { sim->say(1002, "INFORM", "hello"); }),
            "say: speaker_id: no human or ARI with id 1002");
  EXPECT_EQ(refusal_text([&] { sim->add_group_members(7, {12}); }),
            "add_group_members: group_id: no group with id 7");
  EXPECT_EQ(refusal_text([&] {
              sim->add_group_members(1, {12, 99});
            }),
            "add_group_members: members[1]: no human with id 99");
  EXPECT_EQ(refusal_text([&] {
              sim->set_group_centre(7, {3.0, 3.0});
            }),
            "set_group_centre: group_id: no group with id 7");
  EXPECT_EQ(refusal_text([&] {
              sim->add_group(group_of(2, {12, 98}, {3.0, 4.0}));
            }),
            "create_group: members[1]: no human with id 98");
  // Nothing changed: three humans, group 1 of two, 12 in no group.
  EXPECT_EQ(sim->humans().size(), 3u);
  ASSERT_EQ(sim->groups().size(), 1u);
  EXPECT_EQ(sim->find_group(1)->members().size(), 2u);
  EXPECT_EQ(sim->find_human(12)->group_id(), model::kNoObject);
}

TEST(WorldRequests, TakenIdsAndGazeTargetsOutsideTheWorldAreRefused) {
  auto sim = test::request_world();
  EXPECT_EQ(refusal_text([&] { sim->add_human(person(10, 1.0, 1.0)); }),
            "spawn_human: id: expected an id no other object uses, got 10");
  EXPECT_EQ(refusal_text([&] { sim->add_human(person(1, 1.0, 1.0)); }),  // ARI's
            "spawn_human: id: expected an id no other object uses, got 1");
  EXPECT_EQ(refusal_text([&] {
              sim->add_group(group_of(1, {12}, {3.0, 4.0}));
            }),
            "create_group: id: expected an id no other group uses, got 1");
  HumanSpec watcher = person(20, 1.0, 1.0);
  watcher.gaze = looking_at(99);
  EXPECT_EQ(refusal_text([&] { sim->add_human(watcher); }),
            "spawn_human: targets[0]: expected another object of the world, got 99");
  watcher.gaze = looking_at(20);  // itself
  EXPECT_EQ(refusal_text([&] { sim->add_human(watcher); }),
            "spawn_human: targets[0]: expected another object of the world, got 20");
  EXPECT_EQ(refusal_text([&] { sim->set_human_gaze(12, looking_at(99)); }),
            "set_gaze_targets: targets[0]: expected another object of the world, got 99");
  EXPECT_EQ(sim->humans().size(), 3u);
  EXPECT_EQ(sim->groups().size(), 1u);
  EXPECT_EQ(sim->find_human(12)->gaze(), nullptr);
}

TEST(WorldRequests, SpawnWithoutAnIdTakesTheSmallestNeverUsedOneFromTen) {
  auto sim = test::request_world();
  HumanSpec watcher = person(model::kNoObject, 1.0, 1.0);
  watcher.gaze = looking_at(1);
  const Human& first = sim->add_human(watcher);
  EXPECT_EQ(first.id(), 13u);  // 10, 11 and 12 are taken
  ASSERT_NE(first.gaze(), nullptr);
  EXPECT_EQ(first.gaze()->model().targets[0].id, 1u);
  EXPECT_EQ(sim->add_human(person(model::kNoObject, 5.0, 5.0)).id(), 14u);
  sim->remove_human(11);
  // A removed human's id is not handed out again within the run: 15, not 11.
  EXPECT_EQ(sim->add_human(person(model::kNoObject, 5.0, 3.0)).id(), 15u);
  EXPECT_EQ(sim->humans().size(), 5u);
}

TEST(WorldRequests, GroupWithoutAnIdTakesOnePastTheHighestAndEmptiedGroupsAreDropped) {
  auto sim = test::request_world();
  EXPECT_EQ(sim->add_group(group_of(model::kNoObject, {12}, {3.0, 4.0})).id(), 2u);
  // 10 leaves group 1 for group 3; 11 stays in 1.
  EXPECT_EQ(sim->add_group(group_of(model::kNoObject, {10}, {2.0, 2.0})).id(), 3u);
  EXPECT_EQ(sim->find_group(1)->members(), std::vector<model::ObjectId>{11});
  // 11, the last of group 1, joins group 7: group 1 is dropped.
  sim->add_group(group_of(7, {11}, {4.0, 2.0}));
  EXPECT_EQ(sim->find_group(1), nullptr);
  EXPECT_EQ(sim->add_group(group_of(model::kNoObject, {12}, {3.0, 4.0})).id(), 8u);
  // 12 left group 2 for group 8: groups 3, 7 and 8 remain, one member each.
  ASSERT_EQ(sim->groups().size(), 3u);
  for (const GroupNavigation* group : sim->groups()) {
    EXPECT_EQ(group->members().size(), 1u) << "group " << group->id();
  }
}

TEST(WorldRequests, VelocityGoalAndPoseTakeAHumanOutOfItsGroupAndMoveItAsAsked) {
  auto sim = test::request_world();
  sim->set_human_velocity(10, {0.0, 0.5}, 0.0);
  EXPECT_EQ(sim->find_human(10)->group_id(), model::kNoObject);
  EXPECT_EQ(sim->find_human(10)->motion_mode(), MotionMode::kDirect);
  EXPECT_EQ(sim->find_group(1)->members(), std::vector<model::ObjectId>{11});
  for (int i = 0; i < 20; ++i) {  // 1 s at 0.5 m/s north
    sim->step();
  }
  EXPECT_NEAR(sim->find_human(10)->pose().position.x(), 2.0, 1e-3);
  EXPECT_NEAR(sim->find_human(10)->pose().position.y(), 2.5, 1e-3);

  sim->set_human_goal(11, {{5.0, 5.0}, 1.0});
  EXPECT_EQ(sim->find_group(1), nullptr);  // its last member left
  EXPECT_EQ(sim->find_human(11)->motion_mode(), MotionMode::kNavigation);
  ASSERT_TRUE(sim->find_human(11)->goal().has_value());
  EXPECT_DOUBLE_EQ(sim->find_human(11)->goal()->position.x(), 5.0);
  EXPECT_DOUBLE_EQ(sim->find_human(11)->goal()->theta, 1.0);

  sim->add_group(group_of(2, {12}, {3.0, 4.0}));
  sim->set_pose(12, {{1.0, 3.0}, 0.5});
  EXPECT_EQ(sim->find_group(2), nullptr);
  EXPECT_NEAR(sim->find_human(12)->pose().position.x(), 1.0, 1e-6);  // Box2D keeps floats
  EXPECT_NEAR(sim->find_human(12)->pose().position.y(), 3.0, 1e-6);
  EXPECT_DOUBLE_EQ(sim->find_human(12)->pose().theta, 0.5);
  sim->set_pose(1, {{5.0, 5.0}, -1.0});  // ARI
  EXPECT_NEAR(sim->ari()->pose().position.x(), 5.0, 1e-6);
  EXPECT_NEAR(sim->ari()->pose().theta, -1.0, 1e-6);
}

TEST(WorldRequests, MembersJoinLeaveAndFollowTheirCentre) {
  auto sim = test::request_world();
  sim->add_group_members(1, {12, 12});  // a repeat joins once
  EXPECT_EQ(sim->find_group(1)->members().size(), 3u);
  EXPECT_EQ(sim->find_human(12)->group_id(), 1u);
  EXPECT_EQ(sim->find_human(12)->motion_mode(), MotionMode::kGroup);
  sim->set_group_centre(1, {3.0, 3.0});
  EXPECT_DOUBLE_EQ(sim->find_group(1)->centre().x(), 3.0);
  EXPECT_DOUBLE_EQ(sim->find_group(1)->centre().y(), 3.0);
  sim->remove_human(11);
  EXPECT_EQ(sim->find_group(1)->members(), (std::vector<model::ObjectId>{10, 12}));
  EXPECT_EQ(sim->humans().size(), 2u);
  EXPECT_EQ(sim->find_object(11), nullptr);
  // 30 s: the two members settle on either side of the new centre (3, 3).
  for (int i = 0; i < 600; ++i) {
    sim->step();
  }
  const Eigen::Vector2d a = sim->find_human(10)->pose().position;
  const Eigen::Vector2d b = sim->find_human(12)->pose().position;
  EXPECT_NEAR((0.5 * (a + b) - Eigen::Vector2d(3.0, 3.0)).norm(), 0.0, 0.05);
}

TEST(WorldRequests, SayPlaysTheWordsOfAHumanOrAriAndReturnsTheirDuration) {
  auto sim = test::request_world();
  // Three words at the default 150 words per minute: 1.2 s; two: 0.8 s.
  EXPECT_DOUBLE_EQ(sim->say(10, "QUESTION:TIME", "what time is"), 1.2);
  EXPECT_TRUE(sim->find_human(10)->speech().is_speaking());
  EXPECT_EQ(sim->find_human(10)->speech().act(), "QUESTION:TIME");
  EXPECT_DOUBLE_EQ(sim->say(1, "GREETING", "hello there"), 0.8);
  EXPECT_EQ(sim->ari()->speech().content(), "hello there");
  EXPECT_EQ(refusal_text([&] { sim->say(11, "INFORM", "   "); }), "say: content has no words");
  // A NUL byte or another control character is no text (a log or bag reader would cut it).
  EXPECT_EQ(refusal_text([&] { sim->say(11, "INFORM", std::string("hi\0there", 8)); }),
            "say: content: expected no control characters, got byte 0x00 at offset 2");
  EXPECT_EQ(refusal_text([&] { sim->say(11, "INFORM\x1b[2J", "hi"); }),
            "say: act: expected no control characters, got byte 0x1b at offset 6");
  EXPECT_FALSE(sim->find_human(11)->speech().is_speaking());
  EXPECT_DOUBLE_EQ(sim->say(11, "INFORM", "two\nlines"), 0.8);  // whitespace splits words
}

TEST(ServiceRequests, SpawnFieldsLeftAtZeroTakeTheDefaults) {
  SpawnHumanRequest request;
  request.name = "Ana";
  request.pose = {{3.0, 2.0}, 0.5};
  HumanSpec spec = request.spec();
  EXPECT_EQ(spec.id, model::kNoObject);
  EXPECT_EQ(spec.name, "Ana");
  EXPECT_DOUBLE_EQ(spec.pose.position.x(), 3.0);
  EXPECT_DOUBLE_EQ(spec.age_years, 40.0);
  EXPECT_EQ(spec.gender, model::Gender::kNonIdentified);
  EXPECT_EQ(spec.emotion, model::Emotion::kNeutral);

  request.id = 21;
  request.age_years = 29.0;
  request.gender = "female";
  request.emotion = "happy";
  request.mask = true;
  spec = request.spec();
  EXPECT_EQ(spec.id, 21u);
  EXPECT_DOUBLE_EQ(spec.age_years, 29.0);
  EXPECT_EQ(spec.gender, model::Gender::kFemale);
  EXPECT_EQ(spec.emotion, model::Emotion::kHappy);
  EXPECT_TRUE(spec.mask);
}

TEST(ServiceRequests, UnknownGenderOrEmotionTextIsRefusedNamingTheField) {
  SpawnHumanRequest request;
  request.gender = "robot";
  EXPECT_EQ(refusal_text([&] { request.spec(); }),
            "spawn_human: gender: expected female, male or non-identified, got 'robot'");
  request.gender = "male";
  request.emotion = "sad";
  EXPECT_EQ(refusal_text([&] { request.spec(); }),
            "spawn_human: emotion: expected neutral, happy, angry or disturbed, got 'sad'");
}

TEST(ServiceRequests, GazeTargetsPairWithTheirProbabilitiesOrAreRefused) {
  const GazeModel model = GazeTargetsRequest{{10, 1}, {0.7, 0.3}, 2.5}.model();
  ASSERT_EQ(model.targets.size(), 2u);
  EXPECT_EQ(model.targets[1].id, 1u);
  EXPECT_DOUBLE_EQ(model.targets[1].probability, 0.3);
  EXPECT_DOUBLE_EQ(model.mean_duration_s, 2.5);
  EXPECT_FALSE(model.directions.has_value());
  EXPECT_EQ(refusal_text([] {
              GazeTargetsRequest{{10, 1}, {1.0}, 2.0}.model();
            }),
            "set_gaze_targets: probabilities: expected one per target (2), got 1");
}

}  // namespace
}  // namespace ari_social_sim::world
