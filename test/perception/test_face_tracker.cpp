#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/expression.hpp"
#include "ari_social_sim/perception/face_tracker.hpp"
#include "perception_scenes.hpp"

namespace ari_social_sim::perception {
namespace {

using test::human_at;
using test::human_facing;
using test::snapshot_with_ari;

class FaceTrackerTest : public ::testing::Test {
 protected:
  void make(const PerceptionConfig& config) {
    harness_ = std::make_unique<test::TrackerHarness<FaceTracker, PerceivedFace>>(config);
  }
  std::vector<PerceivedFace> perceive(const world::WorldSnapshot& snapshot,
                                      const model::OccupancyGrid* grid = nullptr) {
    return harness_->perceive(snapshot, grid);
  }

  std::unique_ptr<test::TrackerHarness<FaceTracker, PerceivedFace>> harness_;
};

TEST_F(FaceTrackerTest, AFaceTurnedToARIReportsTheTruth) {
  make(test::config_without_errors());
  world::WorldSnapshot snapshot = snapshot_with_ari();
  world::HumanSnapshot human = human_facing(10, 1.5, 0.3, 0.0, 0.0);
  human.age_years = 78;
  human.gender = model::Gender::kMale;
  human.mask = true;
  human.emotion = model::Emotion::kDisturbed;
  human.gaze.target = test::kAriId;
  human.head_pitch_rad = 0.15;  // nodding
  snapshot.humans = {human};
  const std::vector<PerceivedFace> faces = perceive(snapshot);
  ASSERT_EQ(faces.size(), 1u);
  const PerceivedFace& face = faces[0];
  EXPECT_EQ(face.human, 10u);
  EXPECT_EQ(face.person_id, "");  // the person manager links faces to persons
  EXPECT_EQ(face.face_id.size(), 5u);
  EXPECT_DOUBLE_EQ(face.age_years, 78.0);
  EXPECT_EQ(face.gender, model::Gender::kMale);
  EXPECT_TRUE(face.mask);
  EXPECT_EQ(face.emotion, model::Emotion::kDisturbed);
  EXPECT_STREQ(expression_of(face.emotion).name, "scared");
  EXPECT_DOUBLE_EQ(face.age_confidence, 1.0);
  EXPECT_DOUBLE_EQ(face.gender_confidence, 1.0);
  EXPECT_DOUBLE_EQ(face.emotion_confidence, 1.0);
  EXPECT_EQ(face.X_map_face.position, human.pose.position);
  EXPECT_NEAR(face.X_map_face.theta, human.pose.theta, 1e-12);
  EXPECT_NEAR(face.gaze_rad, human.gaze.direction_rad, 1e-12);
  EXPECT_EQ(face.gaze_target, test::kAriId);
  EXPECT_DOUBLE_EQ(face.pitch_rad, 0.15);
}

TEST_F(FaceTrackerTest, NoFaceWhenTurnedAwayOutOfTheCameraOrTooFar) {
  make(test::config_without_errors());
  world::WorldSnapshot snapshot = snapshot_with_ari();
  snapshot.humans = {
      human_at(10, 1.5, 0.0, 0.0),            // facing away from ARI (along +x)
      human_facing(11, 0.5, 1.2, 0.0, 0.0),   // 63 deg off the camera axis (half-angle 31)
      human_facing(12, 2.5, 0.0, 0.0, 0.0)};  // 2.62 m from the camera: beyond 2 m
  EXPECT_TRUE(perceive(snapshot).empty());
}

TEST_F(FaceTrackerTest, TheHeadCameraFollowsThePan) {
  make(test::config_without_errors());
  world::WorldSnapshot snapshot = snapshot_with_ari(0.0, {}, core::deg_to_rad(60.0));
  snapshot.humans = {human_facing(11, 0.5, 1.2, 0.0, 0.0)};
  ASSERT_EQ(perceive(snapshot).size(), 1u);
}

TEST_F(FaceTrackerTest, TheHeadTurnsTowardTheGazeWithinItsLimit) {
  make(test::config_without_errors());
  world::WorldSnapshot snapshot = snapshot_with_ari();
  // Body facing +y (90 deg off ARI's direction); gaze on ARI. With a 60 deg head turn the face
  // points 30 deg away from the camera: seen (limit 60). Without head turn: 90 deg, not seen.
  world::HumanSnapshot human = human_at(10, 1.5, 0.0, core::kPi / 2);
  human.gaze.direction_rad = core::kPi;
  snapshot.humans = {human};
  EXPECT_NEAR(head_direction(human, core::deg_to_rad(60.0)), core::deg_to_rad(150.0), 1e-12);
  ASSERT_EQ(perceive(snapshot).size(), 1u);
  PerceptionConfig stiff = test::config_without_errors();
  stiff.human_model.head_turn_limit_deg = 0.0;
  make(stiff);
  EXPECT_TRUE(perceive(snapshot).empty());
}

// Must-show 3: soft biometric, mask and emotion error rates and the age noise, measured over many
// seeded frames, within 10 % (relative) of the configured values.
TEST_F(FaceTrackerTest, MeasuredAttributeErrorRatesMatchTheConfiguredOnes) {
  PerceptionConfig config = test::config_without_errors();
  config.face_errors.age_noise_years = 6.0;
  config.face_errors.gender_error_rate = 0.1;
  config.face_errors.mask_error_rate = 0.07;
  config.face_errors.emotion_confusion = PerceptionConfig().face_errors.emotion_confusion;
  make(config);
  const std::vector<model::Emotion> emotions = {model::Emotion::kNeutral, model::Emotion::kHappy,
                                                model::Emotion::kAngry, model::Emotion::kDisturbed};
  // 200 000 frames per emotion: a 0.01 entry has a binomial sd of 0.00022, a tenth of it 4.5 sd.
  const int frames = 200000;
  int gender_errors = 0, mask_errors = 0, faces_seen = 0;
  double age_sq = 0.0;
  for (model::Emotion emotion : emotions) {
    world::WorldSnapshot snapshot = snapshot_with_ari();
    world::HumanSnapshot human = human_facing(10, 1.0, 0.0, 0.0, 0.0);
    human.age_years = 50.0;
    human.emotion = emotion;
    snapshot.humans = {human};
    std::vector<int> counts(4, 0);
    for (int i = 0; i < frames; ++i) {
      const std::vector<PerceivedFace> faces = perceive(snapshot);
      ASSERT_EQ(faces.size(), 1u);
      ++faces_seen;
      gender_errors += faces[0].gender != human.gender;
      mask_errors += faces[0].mask != human.mask;
      age_sq += std::pow(faces[0].age_years - human.age_years, 2);
      ++counts[static_cast<size_t>(faces[0].emotion)];
    }
    const std::vector<double>& row = config.face_errors.emotion_confusion.row(emotion);
    for (size_t j = 0; j < 4; ++j) {
      const double rate = static_cast<double>(counts[j]) / frames;
      EXPECT_NEAR(rate, row[j], 0.1 * row[j])
          << "emotion " << static_cast<int>(emotion) << " perceived as " << j;
    }
    std::printf(
        "[ measured ] %-9s perceived as neutral/happy/angry/disturbed: %.4f %.4f %.4f "
        "%.4f (configured %.2f %.2f %.2f %.2f)\n",
        model::to_string(emotion), counts[0] / double(frames), counts[1] / double(frames),
        counts[2] / double(frames), counts[3] / double(frames), row[0], row[1], row[2], row[3]);
  }
  const double gender_rate = static_cast<double>(gender_errors) / faces_seen;
  const double mask_rate = static_cast<double>(mask_errors) / faces_seen;
  // Rounding to whole years adds a uniform error of variance 1/12.
  const double age_sd = std::sqrt(age_sq / faces_seen);
  const double expected_age_sd = std::sqrt(36.0 + 1.0 / 12.0);
  EXPECT_NEAR(gender_rate, 0.1, 0.01);
  EXPECT_NEAR(mask_rate, 0.07, 0.007);
  EXPECT_NEAR(age_sd, expected_age_sd, 0.1 * expected_age_sd);
  std::printf(
      "[ measured ] gender error %.4f (0.10), mask error %.4f (0.07), age sd %.3f years "
      "(%.3f)\n",
      gender_rate, mask_rate, age_sd, expected_age_sd);
}

}  // namespace
}  // namespace ari_social_sim::perception
