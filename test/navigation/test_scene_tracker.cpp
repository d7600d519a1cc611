#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/navigation/scene_tracker.hpp"

namespace ari_social_sim::navigation {
namespace {

TEST(SceneTracker, EstimatesWalkingVelocityFromPositions) {
  SceneTracker tracker{SceneTrackerConfig{}};
  // 1 m/s along x, reported exactly at 10 Hz for 3 s: the filter settles on 1 m/s; unseen for
  // the next 0.5 s, the person is carried on to x = 3.5.
  for (int i = 0; i <= 30; ++i) {
    tracker.observe_person("human1", 0.1 * i, {0.1 * i, 2.0}, 0.0);
  }
  PerceivedScene scene = tracker.scene(3.0);
  ASSERT_EQ(scene.people.size(), 1u);
  EXPECT_NEAR(scene.people[0].velocity.x(), 1.0, 0.02);
  EXPECT_NEAR(scene.people[0].velocity.y(), 0.0, 1e-9);
  EXPECT_NEAR(scene.people[0].position.x(), 3.0, 0.01);
  EXPECT_NEAR(tracker.scene(3.5).people[0].position.x(), 3.5, 0.02);
  // The person stops: within 1.5 s the estimate is below a fifth of the walking speed.
  for (int i = 1; i <= 15; ++i) {
    tracker.observe_person("human1", 3.0 + 0.1 * i, {3.0, 2.0}, 0.0);
  }
  EXPECT_LT(std::abs(tracker.scene(4.5).people[0].velocity.x()), 0.2);
}

TEST(SceneTracker, SteadiesNoisyReportsOfSomeoneStandingStill) {
  // Perception's positions scattered by 0.1 m per axis at 10 Hz: differencing them would give
  // velocities of 0.1 sqrt(2) / 0.1 = 1.4 m/s std, the look of a walker. Filtered (seed 3, 20 s,
  // the first 5 s of settling left out), the speed stays under 0.2 m/s RMS, so a standing person
  // is seen standing, and the position error falls from the reports' 0.14 m RMS to under 0.09 m.
  SceneTracker tracker{SceneTrackerConfig{}};
  core::Rng rng(3);
  double speed2 = 0.0, error2 = 0.0;
  int samples = 0;
  for (int i = 0; i <= 200; ++i) {
    const double t = 0.1 * i;
    tracker.observe_person("human1", t, {2.0 + rng.normal(0.0, 0.1), 3.0 + rng.normal(0.0, 0.1)},
                           rng.normal(0.0, 0.05));
    if (t >= 5.0) {
      const PersonEstimate p = tracker.scene(t).people[0];
      speed2 += p.velocity.squaredNorm();
      error2 += (p.position - Eigen::Vector2d(2.0, 3.0)).squaredNorm();
      ++samples;
    }
  }
  EXPECT_LT(std::sqrt(speed2 / samples), 0.2);
  EXPECT_LT(std::sqrt(error2 / samples), 0.09);
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
  // 2 s timeouts: at 2.2 s only human3, seen again at 1.6 s, remains; no group has two members.
  tracker.observe_person("human3", 1.6, {5.0, 5.0}, 0.0);
  scene = tracker.scene(2.2);
  ASSERT_EQ(scene.people.size(), 1u);
  EXPECT_EQ(scene.people[0].id, "human3");
  EXPECT_TRUE(scene.groups.empty());
}

TEST(SceneTracker, AMemberMissedForAFrameStaysInTheGroup) {
  SceneTracker tracker{SceneTrackerConfig{}};
  for (const double t : {0.0, 0.1, 0.2}) {
    tracker.observe_person("human1", t, {1.0, 1.0}, 0.0);
    tracker.observe_person("human2", t, {2.0, 1.0}, M_PI);
    tracker.observe_person("human3", t, {1.5, 1.6}, -M_PI / 2);
  }
  tracker.observe_group("g1", 0.0, {"human1", "human2", "human3"});
  tracker.observe_group("g1", 0.1, {"human1", "human2"});  // GCFF left human3 out once
  EXPECT_EQ(tracker.scene(0.2).groups[0].members.size(), 3u);
  // Left out for longer than the 2 s group timeout, they are gone from it.
  tracker.observe_group("g1", 2.2, {"human1", "human2"});
  for (const double t : {2.2}) {
    tracker.observe_person("human1", t, {1.0, 1.0}, 0.0);
    tracker.observe_person("human2", t, {2.0, 1.0}, M_PI);
    tracker.observe_person("human3", t, {1.5, 1.6}, -M_PI / 2);
  }
  EXPECT_EQ(tracker.scene(2.2).groups[0].members.size(), 2u);
}

TEST(SceneTracker, ForgetsWhatTheSceneLeavesOutSoMemoryFollowsWhoIsAround) {
  // 500 people and 250 groups come and go, one person every 0.5 s, each reported once with the
  // group of them and the one before: with 2 s timeouts and forget() each cycle, at most the
  // people of the last 2 s stay held (2 / 0.5 + 1 = 5), and as many groups.
  SceneTracker tracker{SceneTrackerConfig{}};
  size_t most_people = 0, most_groups = 0;
  for (int i = 0; i < 500; ++i) {
    const double t = 0.5 * i;
    const std::string id = "p" + std::to_string(i);
    tracker.observe_person(id, t, {0.1 * i, 0.0}, 0.0);
    tracker.observe_group("g" + std::to_string(i), t, {id, "p" + std::to_string(i - 1)});
    tracker.forget(t);
    most_people = std::max(most_people, tracker.person_count());
    most_groups = std::max(most_groups, tracker.group_count());
  }
  EXPECT_EQ(most_people, 5u);
  EXPECT_EQ(most_groups, 5u);
  // What forget() drops is what scene() already left out: the same scene before and after.
  const PerceivedScene before = tracker.scene(250.0);
  tracker.forget(250.0);
  const PerceivedScene after = tracker.scene(250.0);
  EXPECT_EQ(before.people.size(), 4u);  // reported at 248, 248.5, 249 and 249.5 s
  EXPECT_EQ(before.groups.size(), 3u);  // g497-g499; g496's p495 is out
  EXPECT_EQ(after.people.size(), before.people.size());
  EXPECT_EQ(after.groups.size(), before.groups.size());
  EXPECT_EQ(tracker.person_count(), 4u);
  tracker.forget(300.0);
  EXPECT_EQ(tracker.person_count() + tracker.group_count(), 0u);
}

// A body frame at inf or 1e300 used to be filtered in: the track held inf, then NaN (inf - inf)
// for as long as the person was perceived.
TEST(SceneTracker, AbsurdReportsNeverReachATrack) {
  SceneTracker tracker{SceneTrackerConfig{}};
  tracker.observe_person("human1", 0.0, {1.0, 2.0}, 0.0);
  tracker.observe_person("human1", 0.1, {1e300, 2.0}, 0.0);
  tracker.observe_person("human1", 0.2, {INFINITY, 2.0}, 0.0);
  tracker.observe_person("human1", 0.3, {1.0, NAN}, 0.0);
  tracker.observe_person("human1", 0.4, {1.0, 2.0}, NAN);
  tracker.observe_person("human1", NAN, {1.0, 2.0}, 0.0);
  tracker.observe_person("human2", 0.1, {2e4, 2.0}, 0.0);  // beyond kMaxMapCoordinateM
  tracker.observe_person("human1", 0.5, {1.05, 2.0}, 0.0);
  const PerceivedScene scene = tracker.scene(0.5);
  ASSERT_EQ(scene.people.size(), 1u);
  EXPECT_NEAR(scene.people[0].position.x(), 1.05, 0.05);
  EXPECT_TRUE(scene.people[0].velocity.allFinite());
  EXPECT_LT(scene.people[0].velocity.norm(), 0.5);
}

// A world reset late in a run (sim time 1145 s back to 0): people reported before it are
// forgotten at once, and one reported again starts a fresh track where they now stand.
TEST(SceneTracker, TimeGoingBackForgetsWhatWasReportedBefore) {
  SceneTracker tracker{SceneTrackerConfig{}};
  for (int i = 0; i <= 10; ++i) {
    tracker.observe_person("ghost", 1144.0 + 0.1 * i, {20.0, 20.0}, 0.0);
    tracker.observe_person("human1", 1144.0 + 0.1 * i, {1.0 + 0.1 * i, 2.0}, 0.0);
  }
  tracker.observe_group("group1", 1145.0, {"ghost", "human1"});
  tracker.observe_person("human1", 0.1, {4.0, 4.0}, 0.0);
  tracker.forget(0.1);
  EXPECT_EQ(tracker.person_count(), 1u);
  EXPECT_EQ(tracker.group_count(), 0u);
  const PerceivedScene scene = tracker.scene(0.1);
  ASSERT_EQ(scene.people.size(), 1u);
  EXPECT_EQ(scene.people[0].id, "human1");
  EXPECT_EQ(scene.people[0].position, Eigen::Vector2d(4.0, 4.0));
  EXPECT_EQ(scene.people[0].velocity, Eigen::Vector2d::Zero());
}

}  // namespace
}  // namespace ari_social_sim::navigation
