// One cycle of perception into the scene tracker: who is placed where, which groups, what is
// forgotten.

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "ari_social_sim/navigation/perception_report.hpp"

namespace ari_social_sim::navigation {
namespace {

// Bodies as perception placed them: b1 at (1, 1) facing east, b2 at (2, 1) facing west, both at
// 10 s; b3 at (5, 5) placed half a second earlier (its last transform).
model::BodyLocator bodies() {
  static const std::map<std::string, model::BodyPlacement> placed = {
      {"b1", {10.0, {{1.0, 1.0}, 0.0}}},
      {"b2", {10.0, {{2.0, 1.0}, M_PI}}},
      {"b3", {9.5, {{5.0, 5.0}, 0.0}}},
  };
  return [](const std::string& body_id) -> std::optional<model::BodyPlacement> {
    const auto it = placed.find(body_id);
    return it == placed.end() ? std::nullopt : std::optional(it->second);
  };
}

TEST(ObservePerception, TrackedPersonsStandAtTheirBodiesAndGroupsAreTheirMembers) {
  SceneTracker tracker{SceneTrackerConfig{}};
  PerceptionReport report;
  report.persons = {{"p1", "b1"}, {"p2", "b2"}, {"heard", ""}, {"p9", "b9"}};
  report.groups = {{"g1", 10.0, {"p1", "p2"}}};
  observe(tracker, report, bodies(), 10.0);
  // The person only heard and the one whose body cannot be placed are not in the scene.
  EXPECT_EQ(tracker.person_count(), 2u);
  const PerceivedScene scene = tracker.scene(10.0);
  ASSERT_EQ(scene.people.size(), 2u);
  const PersonEstimate* p2 = scene.find_person("p2");
  ASSERT_NE(p2, nullptr);
  EXPECT_DOUBLE_EQ(p2->position.x(), 2.0);
  EXPECT_DOUBLE_EQ(p2->position.y(), 1.0);
  EXPECT_NEAR(std::abs(p2->heading), M_PI, 1e-12);
  // Face to face 1 m apart: the o-space centre half way, 0.5 m from each (stride 0.5 m).
  ASSERT_EQ(scene.groups.size(), 1u);
  EXPECT_EQ(scene.groups[0].members, (std::vector<std::string>{"p1", "p2"}));
  EXPECT_NEAR(scene.groups[0].centre.x(), 1.5, 1e-12);
  EXPECT_NEAR(scene.groups[0].centre.y(), 1.0, 1e-12);
  EXPECT_NEAR(scene.groups[0].radius_m, 0.5, 1e-12);
}

TEST(ObservePerception, PersonsCountFromTheirBodysTimeAndTheUnreportedAreForgotten) {
  SceneTracker tracker{SceneTrackerConfig{}};  // person and group timeouts of 2 s
  PerceptionReport first;
  first.persons = {{"p1", "b1"}, {"p3", "b3"}};
  first.groups = {{"g1", 10.0, {"p1", "p3"}}};
  observe(tracker, first, bodies(), 10.0);
  EXPECT_EQ(tracker.person_count(), 2u);
  EXPECT_EQ(tracker.group_count(), 1u);
  // At 11.6 s with nobody reported: p3, last placed at 9.5 s (2.1 s before), is forgotten; p1,
  // placed at 10 s, and the group, reported at 10 s, are kept.
  observe(tracker, {}, bodies(), 11.6);
  EXPECT_EQ(tracker.person_count(), 1u);
  EXPECT_EQ(tracker.scene(11.6).people[0].id, "p1");
  EXPECT_EQ(tracker.group_count(), 1u);
  // At 12.01 s everyone is.
  observe(tracker, {}, bodies(), 12.01);
  EXPECT_EQ(tracker.person_count(), 0u);
  EXPECT_EQ(tracker.group_count(), 0u);
}

}  // namespace
}  // namespace ari_social_sim::navigation
