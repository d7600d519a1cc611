#include <gtest/gtest.h>

#include "audio_scenes.hpp"

namespace ari_social_sim::audio {
namespace {

using test::anechoic;
using test::array_at_origin;
using test::noise_burst;
using test::record;
using test::rms;

// The lag (samples, sub-sample by a parabola through the peak) by which `b` trails `a`.
double lag_of(const std::vector<float>& a, const std::vector<float>& b, int max_lag) {
  std::vector<double> correlation(2 * max_lag + 1, 0.0);
  for (int lag = -max_lag; lag <= max_lag; ++lag) {
    for (size_t i = max_lag; i + max_lag < a.size(); ++i) {
      correlation[lag + max_lag] += double(a[i]) * b[i + lag];
    }
  }
  const int best = static_cast<int>(std::max_element(correlation.begin(), correlation.end()) -
                                    correlation.begin());
  if (best == 0 || best == 2 * max_lag) {
    return best - max_lag;
  }
  const double left = correlation[best - 1], centre = correlation[best],
               right = correlation[best + 1];
  return best - max_lag + 0.5 * (left - right) / (left - 2.0 * centre + right);
}

ArrayMixer one_source(const RoomSettings& settings, const Eigen::Vector3d& at,
                      std::vector<Wall> walls = {}) {
  ArrayMixer mixer(settings, std::move(walls), 1);
  mixer.set_array_pose(array_at_origin());
  mixer.add({1, noise_burst(1.0, 5), 0, false});
  mixer.set_source_position(1, at);
  return mixer;
}

// A source 2 m ahead reaches the front microphone (channel 3, x = +32 mm) 64 mm / 343 m/s =
// 2.99 samples before the back one (channel 1).
TEST(ArrayMixer, TheMicrophonesHearTheDelaysOfTheArraysGeometry) {
  ArrayMixer mixer = one_source(anechoic(), {2.0, 0.0, 0.928});
  const auto channels = record(mixer, 1.0);
  const double lag = lag_of(channels[3], channels[1], 8);
  std::printf("back microphone trails the front one by %.2f samples (geometry: 2.99)\n", lag);
  EXPECT_NEAR(lag, 0.064 / kSpeedOfSoundMps * 16000, 0.2);
  // Sideways (+y): channels 2 (y = -32 mm) and 4 (y = +32 mm) differ, 1 and 3 do not.
  ArrayMixer side = one_source(anechoic(), {0.0, 2.0, 0.928});
  const auto heard = record(side, 1.0);
  EXPECT_NEAR(lag_of(heard[4], heard[2], 8), 2.99, 0.2);
  EXPECT_NEAR(lag_of(heard[3], heard[1], 8), 0.0, 0.2);
}

// Spherical spreading: twice as far, half the amplitude; and the sound arrives after the
// distance's travel time.
TEST(ArrayMixer, AmplitudeFallsWithDistanceAndSoundTakesItsTravelTime) {
  ArrayMixer near = one_source(anechoic(), {1.0, 0.0, 0.928});
  ArrayMixer far = one_source(anechoic(), {2.0, 0.0, 0.928});
  const auto at_1m = record(near, 1.0);
  const auto at_2m = record(far, 1.0);
  const double ratio = rms(at_1m[1], 1600, 14000) / rms(at_2m[1], 1600, 14000);
  std::printf("rms at 1 m / at 2 m: %.3f\n", ratio);
  EXPECT_NEAR(ratio, 2.0, 0.05);
  // 2 m at 343 m/s is 93 samples; the 1 m source is 46.6 samples earlier.
  EXPECT_NEAR(lag_of(at_1m[1], at_2m[1], 80), 1.0 / kSpeedOfSoundMps * 16000, 0.5);
}

// A wall 1.5 m behind the array adds the image source's arrival: the source 1 m ahead has its
// image 4 m behind, 3.968 m from the back microphone against 1.032 m for the direct sound.
TEST(ArrayMixer, AWallAddsItsImageSourcesEcho) {
  RoomSettings settings = anechoic();
  settings.wall_reflection = 0.8;
  const Wall behind{{-1.5, -5.0}, {-1.5, 5.0}};
  ArrayMixer with_wall = one_source(settings, {1.0, 0.0, 0.928}, {behind});
  ArrayMixer without = one_source(settings, {1.0, 0.0, 0.928});
  const auto echoing = record(with_wall, 1.0);
  const auto dry = record(without, 1.0);
  std::vector<float> echo(echoing[1].size());
  for (size_t i = 0; i < echo.size(); ++i) {
    echo[i] = echoing[1][i] - dry[1][i];
  }
  const double lag = lag_of(dry[1], echo, 200);
  const double expected = (3.968 - 1.032) / kSpeedOfSoundMps * 16000;
  std::printf("echo trails the direct sound by %.1f samples (geometry: %.1f)\n", lag, expected);
  EXPECT_NEAR(lag, expected, 0.5);
  EXPECT_NEAR(rms(echo) / rms(dry[1]), 0.8 * 1.032 / 3.968, 0.02);
}

// The late tail decays by 60 dB in the room's RT60 (Schroeder's backward integration of an
// impulse's response after its direct sound).
TEST(ArrayMixer, TheTailDecaysInTheRoomsReverberationTime) {
  RoomSettings settings = anechoic();
  settings.reverb_level = 0.3;
  settings.rt60_s = 0.6;
  ArrayMixer mixer(settings, {}, 1);
  mixer.set_array_pose(array_at_origin());
  auto click = std::make_shared<std::vector<float>>(std::vector<float>{1.0f});
  mixer.add({1, click, 0, false});
  mixer.set_source_position(1, {1.0, 0.0, 0.928});
  const auto heard = record(mixer, 1.5);
  const std::vector<float> tail(heard[1].begin() + 800, heard[1].end());  // after 50 ms
  std::vector<double> remaining(tail.size() + 1, 0.0);
  for (size_t i = tail.size(); i-- > 0;) {
    remaining[i] = remaining[i + 1] + double(tail[i]) * tail[i];
  }
  // The time from -5 dB to -25 dB, times 3 (T20).
  size_t at_5 = 0, at_25 = 0;
  for (size_t i = 0; i < tail.size(); ++i) {
    const double db = 10.0 * std::log10(remaining[i] / remaining[0] + 1e-30);
    at_5 = db > -5.0 ? i : at_5;
    at_25 = db > -25.0 ? i : at_25;
  }
  const double rt60 = 3.0 * (at_25 - at_5) / 16000.0;
  std::printf("measured RT60 %.2f s (set 0.60)\n", rt60);
  EXPECT_NEAR(rt60, 0.6, 0.12);
}

// ARI's voice is on the playback channel and at the microphones, not on the processed channel.
TEST(ArrayMixer, AriIsHeardOnThePlaybackChannelNotTheProcessedOne) {
  ArrayMixer mixer(anechoic(), {}, 1);
  mixer.set_array_pose(array_at_origin());
  mixer.add({9, noise_burst(1.0, 3), 0, true});
  mixer.set_source_position(9, {0.05, 0.0, 1.3});
  const auto heard = record(mixer, 1.0);
  EXPECT_GT(rms(heard[5]), 0.01);
  EXPECT_GT(rms(heard[1]), 0.01);
  EXPECT_LT(rms(heard[0]), 1e-4);
  EXPECT_FALSE(mixer.voice_at(100));
}

// The same sounds and seed give the same samples whether rendered in 1024- or 4096-sample chunks.
TEST(ArrayMixer, ChunkSizesDoNotChangeTheSamples) {
  RoomSettings settings;  // reflections, tail and noise
  const std::vector<Wall> walls{{{-3.0, -3.0}, {3.0, -3.0}}, {{3.0, -3.0}, {3.0, 3.0}}};
  const auto run = [&](size_t chunk) {
    ArrayMixer mixer(settings, walls, 11);
    mixer.set_array_pose(array_at_origin());
    mixer.add({1, noise_burst(0.5, 5), 100, false});
    mixer.set_source_position(1, {1.5, 1.0, 1.6});
    std::vector<int16_t> samples;
    while (samples.size() < 8192) {
      const ArrayChunk out = mixer.render(chunk);
      samples.insert(samples.end(), out.channels[2].begin(), out.channels[2].end());
    }
    return samples;
  };
  EXPECT_EQ(run(1024), run(4096));
}

}  // namespace
}  // namespace ari_social_sim::audio
