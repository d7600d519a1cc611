#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "ari_social_sim/perception/body_tracker.hpp"
#include "perception_scenes.hpp"

namespace ari_social_sim::perception {
namespace {

using test::human_at;
using test::snapshot_with_ari;

class BodyTrackerTest : public ::testing::Test {
 protected:
  void make(const PerceptionConfig& config) {
    harness_ = std::make_unique<test::TrackerHarness<BodyTracker, PerceivedBody>>(config);
  }
  std::vector<PerceivedBody> perceive(const world::WorldSnapshot& snapshot,
                                      const model::OccupancyGrid* grid = nullptr) {
    return harness_->perceive(snapshot, grid);
  }

  std::unique_ptr<test::TrackerHarness<BodyTracker, PerceivedBody>> harness_;
};

TEST_F(BodyTrackerTest, WithoutErrorsBodiesAreTheGroundTruth) {
  make(test::config_without_errors());
  world::WorldSnapshot snapshot = snapshot_with_ari();
  snapshot.humans = {human_at(10, 3.0, 1.0, 2.0), human_at(11, 0.5, -4.0, -1.0)};
  const std::vector<PerceivedBody> bodies = perceive(snapshot);
  ASSERT_EQ(bodies.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(bodies[i].human, snapshot.humans[i].id);
    EXPECT_EQ(bodies[i].person_id, "");  // the person manager links bodies to persons
    EXPECT_EQ(bodies[i].X_map_body.position, snapshot.humans[i].pose.position);
    EXPECT_EQ(bodies[i].X_map_body.theta, snapshot.humans[i].pose.theta);
    EXPECT_DOUBLE_EQ(bodies[i].visible_fraction, 1.0);
  }
  EXPECT_NE(bodies[0].body_id, bodies[1].body_id);
  // The same ids in the next frame.
  const std::vector<PerceivedBody> again = perceive(snapshot);
  EXPECT_EQ(again[0].body_id, bodies[0].body_id);
  EXPECT_EQ(again[1].body_id, bodies[1].body_id);
}

TEST_F(BodyTrackerTest, ABodyShowsTheWorldsPostureEvenWithErrorsOn) {
  make(PerceptionConfig{});
  world::WorldSnapshot snapshot = snapshot_with_ari();
  snapshot.humans = {human_at(10, 2.0, 1.0, 0.0), human_at(11, 2.0, -1.0, 0.0),
                     human_at(12, 3.0, 0.0, 0.0)};
  snapshot.humans[1].posture = {world::Posture::kSitting, 1.0};
  // Sitting down, 0.3 of the way: still more standing than seated.
  snapshot.humans[2].posture = {world::Posture::kSitting, 0.3};
  std::map<model::ObjectId, world::Posture> seen;
  for (int frame = 0; frame < 20; ++frame) {
    for (const PerceivedBody& body : perceive(snapshot)) {
      seen[body.human] = body.posture;
    }
  }
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen[10], world::Posture::kStanding);
  EXPECT_EQ(seen[11], world::Posture::kSitting);
  EXPECT_EQ(seen[12], world::Posture::kStanding);
}

TEST_F(BodyTrackerTest, BehindAWallBehindARIOrBeyondRangeIsNotTracked) {
  make(test::config_without_errors());
  const model::OccupancyGrid grid = test::map_with_wall({2.0, -1.0}, {2.0, 1.0});
  world::WorldSnapshot snapshot = snapshot_with_ari();
  snapshot.humans = {human_at(10, 3.0, 0.0, 0.0),   // behind the wall
                     human_at(11, -1.0, 0.0, 0.0),  // behind ARI: outside the 180 deg fisheye
                     human_at(12, 10.5, 3.0, 0.0),  // 10.9 m away: beyond the 10 m range
                     human_at(13, 1.0, 2.0, 0.0)};  // in view
  const std::vector<PerceivedBody> bodies = perceive(snapshot, &grid);
  ASSERT_EQ(bodies.size(), 1u);
  EXPECT_EQ(bodies[0].human, 13u);
}

TEST_F(BodyTrackerTest, APersonHiddenByAnotherIsNotTracked) {
  make(test::config_without_errors());
  world::WorldSnapshot snapshot = snapshot_with_ari();
  // Both on the fisheye's axis (the sensor is at x = -0.142).
  snapshot.humans = {human_at(10, 2.0, 0.0, 0.0), human_at(11, 4.0, 0.0, 0.0)};
  const std::vector<PerceivedBody> bodies = perceive(snapshot);
  ASSERT_EQ(bodies.size(), 1u);
  EXPECT_EQ(bodies[0].human, 10u);
}

TEST_F(BodyTrackerTest, RegionCentredForAPersonStraightAhead) {
  make(test::config_without_errors());
  world::WorldSnapshot snapshot = snapshot_with_ari();
  snapshot.humans = {human_at(10, 2.858, 0.0, 0.0)};  // 3 m ahead of the fisheye
  const PerceivedBody body = perceive(snapshot).at(0);
  EXPECT_NEAR(0.5 * (body.roi.xmin + body.roi.xmax), 0.5, 1e-9);
  // Width: 2 asin(0.2 / 3) = 7.64 deg of 180.
  EXPECT_NEAR(body.roi.xmax - body.roi.xmin, 7.64 / 180.0, 1e-3);
  EXPECT_LT(body.roi.ymin, 0.5);  // the head is above the camera (1.72 m > 1.32 m)
  EXPECT_GT(body.roi.ymax, 0.5);
}

// Must-show 3 through the tracker: the base miss rate of a clearly visible person.
TEST_F(BodyTrackerTest, MeasuredMissRateMatchesTheConfiguredOne) {
  PerceptionConfig config = test::config_without_errors();
  config.body_errors.detection.miss_rate = 0.1;
  make(config);
  world::WorldSnapshot snapshot = snapshot_with_ari();
  snapshot.humans = {human_at(10, 2.0, 0.0, 0.0)};
  const int frames = 20000;
  int missed = 0;
  for (int i = 0; i < frames; ++i) {
    missed += perceive(snapshot).empty() ? 1 : 0;
  }
  const double rate = static_cast<double>(missed) / frames;
  EXPECT_NEAR(rate, 0.1, 0.01);
  std::printf("[ measured ] body miss rate %.4f (configured 0.10)\n", rate);
}

}  // namespace
}  // namespace ari_social_sim::perception
