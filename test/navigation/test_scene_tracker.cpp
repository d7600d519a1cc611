#include "ari_social_sim/navigation/scene_tracker.hpp"

#include <gtest/gtest.h>

namespace ari_social_sim::navigation {
namespace {

TEST(SceneTracker, EstimatesWalkingVelocityFromPositions) {
  SceneTracker tracker{SceneTrackerConfig{}};
  // 1 m/s along x, reported at 10 Hz for 3 s: the smoothed estimate settles on 1 m/s (a constant
  // velocity is a fixed point of the filter; the start-up transient decays as exp(-t / 0.5 s)).
  for (int i = 0; i <= 30; ++i) {
    tracker.observe_person("human1", 0.1 * i, {0.1 * i, 2.0}, 0.0);
  }
  const PerceivedScene scene = tracker.scene(3.0);
  ASSERT_EQ(scene.people.size(), 1u);
  EXPECT_NEAR(scene.people[0].velocity.x(), 1.0, 1e-9);
  EXPECT_NEAR(scene.people[0].velocity.y(), 0.0, 1e-9);
  // A person who stops: each 0.1 s report keeps exp(-0.1 / 0.5) of the estimate, so after 1 s
  // it has fallen to exp(-2) = 0.135 m/s.
  for (int i = 1; i <= 10; ++i) {
    tracker.observe_person("human1", 3.0 + 0.1 * i, {3.0, 2.0}, 0.0);
  }
  EXPECT_NEAR(tracker.scene(4.0).people[0].velocity.x(), std::exp(-2.0), 1e-9);
}

TEST(SceneTracker, DropsWhatPerceptionStoppedReporting) {
  SceneTracker tracker{SceneTrackerConfig{}};
  tracker.observe_person("human1", 0.0, {1.0, 1.0}, 0.0);
  tracker.observe_person("human2", 0.0, {2.0, 1.0}, M_PI);
  tracker.observe_person("human3", 0.0, {5.0, 5.0}, 0.0);
  tracker.observe_group("g1", 0.0, {"human1", "human2", "robot"});  // "robot" is no person
  tracker.observe_group("g2", 0.0, {"human3", "human9"});           // one known member only
  PerceivedScene scene = tracker.scene(0.5);
  EXPECT_EQ(scene.people.size(), 3u);
  ASSERT_EQ(scene.groups.size(), 1u);
  EXPECT_EQ(scene.groups[0].id, "g1");
  EXPECT_EQ(scene.groups[0].members.size(), 2u);
  // Facing each other 1 m apart, stride 0.5 m: both candidate centres at (1.5, 1), radius 0.5.
  EXPECT_NEAR(scene.groups[0].centre.x(), 1.5, 1e-12);
  EXPECT_NEAR(scene.groups[0].radius_m, 0.5, 1e-12);
  // 1 s timeouts: at 1.2 s only human3, seen again at 0.8 s, remains; no group has two members.
  tracker.observe_person("human3", 0.8, {5.0, 5.0}, 0.0);
  scene = tracker.scene(1.2);
  ASSERT_EQ(scene.people.size(), 1u);
  EXPECT_EQ(scene.people[0].id, "human3");
  EXPECT_TRUE(scene.groups.empty());
}

}  // namespace
}  // namespace ari_social_sim::navigation
