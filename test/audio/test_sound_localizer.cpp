#include <gtest/gtest.h>

#include <algorithm>

#include "ari_social_sim/audio/sound_localizer.hpp"
#include "audio_scenes.hpp"

namespace ari_social_sim::audio {
namespace {

using test::array_at_origin;
using test::noise_burst;
using test::record;

// The localiser's error (degrees) for a source at `azimuth_deg`, `distance_m` away at mouth
// height, over the frames of half a second.
std::vector<double> errors_deg(const RoomSettings& settings, double azimuth_deg,
                               double distance_m) {
  const std::vector<Wall> room{{{-4.0, -3.0}, {4.0, -3.0}},
                               {{4.0, -3.0}, {4.0, 3.0}},
                               {{4.0, 3.0}, {-4.0, 3.0}},
                               {{-4.0, 3.0}, {-4.0, -3.0}}};
  ArrayMixer mixer(settings, room, 2);
  mixer.set_array_pose(array_at_origin());
  mixer.add({1, noise_burst(0.6, 9), 0, false});
  const double azimuth = azimuth_deg * M_PI / 180.0;
  mixer.set_source_position(1,
                            {distance_m * std::cos(azimuth), distance_m * std::sin(azimuth), 1.6});
  const auto heard = record(mixer, 0.5);
  std::vector<double> errors;
  for (size_t start = 1024; start + 1024 <= heard[1].size(); start += 1024) {
    std::array<std::vector<float>, 4> frame;
    for (size_t m = 0; m < 4; ++m) {
      frame[m].assign(heard[1 + m].begin() + start, heard[1 + m].begin() + start + 1024);
    }
    const std::optional<SoundDirection> found = locate_sound(frame);
    if (found) {
      errors.push_back(std::abs(std::remainder(found->azimuth_rad - azimuth, 2.0 * M_PI)) * 180.0 /
                       M_PI);
    }
  }
  return errors;
}

double percentile(std::vector<double> values, double share) {
  std::sort(values.begin(), values.end());
  return values[static_cast<size_t>(share * (values.size() - 1))];
}

// In a room with walls, floor, a 0.5 s tail and noise at -65 dBFS: speakers all round, 1-4 m.
TEST(SoundLocalizer, FindsSpeakersAllRoundInAReverberantRoom) {
  const RoomSettings room;
  std::vector<double> errors;
  for (double distance : {1.0, 2.0, 2.8}) {
    for (int azimuth = 0; azimuth < 360; azimuth += 30) {
      const std::vector<double> found = errors_deg(room, azimuth + 7.0, distance);
      errors.insert(errors.end(), found.begin(), found.end());
    }
  }
  ASSERT_GT(errors.size(), 100u);
  std::printf("direction error over %zu frames: median %.1f deg, 90th percentile %.1f deg\n",
              errors.size(), percentile(errors, 0.5), percentile(errors, 0.9));
  EXPECT_LT(percentile(errors, 0.5), 5.0);
  EXPECT_LT(percentile(errors, 0.9), 20.0);
}

// Two people talking at once, 1.5 m at 30 deg and 2.5 m at -100 deg: each frame's direction is
// one of theirs, mostly the nearer, louder one's.
TEST(SoundLocalizer, WithTwoTalkersFindsOneOfThemInEachFrame) {
  const std::vector<Wall> room{{{-4.0, -3.0}, {4.0, -3.0}},
                               {{4.0, -3.0}, {4.0, 3.0}},
                               {{4.0, 3.0}, {-4.0, 3.0}},
                               {{-4.0, 3.0}, {-4.0, -3.0}}};
  ArrayMixer mixer(RoomSettings{}, room, 2);
  mixer.set_array_pose(array_at_origin());
  const double azimuths[2] = {30.0 * M_PI / 180.0, -100.0 * M_PI / 180.0};
  const double distances[2] = {1.5, 2.5};
  for (uint64_t talker = 0; talker < 2; ++talker) {
    mixer.add({talker + 1, noise_burst(1.2, 20 + talker), 0, false});
    mixer.set_source_position(talker + 1, {distances[talker] * std::cos(azimuths[talker]),
                                           distances[talker] * std::sin(azimuths[talker]), 1.6});
  }
  const auto heard = record(mixer, 1.1);
  std::vector<double> errors;
  int nearer = 0;
  for (size_t start = 1024; start + 1024 <= heard[1].size(); start += 1024) {
    std::array<std::vector<float>, 4> frame;
    for (size_t m = 0; m < 4; ++m) {
      frame[m].assign(heard[1 + m].begin() + start, heard[1 + m].begin() + start + 1024);
    }
    const std::optional<SoundDirection> found = locate_sound(frame);
    ASSERT_TRUE(found.has_value());
    double error_deg[2];
    for (size_t talker = 0; talker < 2; ++talker) {
      error_deg[talker] =
          std::abs(std::remainder(found->azimuth_rad - azimuths[talker], 2.0 * M_PI)) * 180.0 /
          M_PI;
    }
    nearer += error_deg[0] <= error_deg[1] ? 1 : 0;
    errors.push_back(std::min(error_deg[0], error_deg[1]));
  }
  std::printf(
      "two talkers: %zu frames, %d on the nearer; error to the closer talker median %.1f "
      "deg, 90th percentile %.1f deg\n",
      errors.size(), nearer, percentile(errors, 0.5), percentile(errors, 0.9));
  EXPECT_LT(percentile(errors, 0.5), 5.0);
  EXPECT_LT(percentile(errors, 0.9), 20.0);
  EXPECT_GT(nearer, static_cast<int>(errors.size()) / 2);
}

TEST(SoundLocalizer, SilenceHasNoDirection) {
  std::array<std::vector<float>, 4> silent;
  for (auto& channel : silent) {
    channel.assign(1024, 0.0f);
  }
  EXPECT_FALSE(locate_sound(silent).has_value());
}

}  // namespace
}  // namespace ari_social_sim::audio
