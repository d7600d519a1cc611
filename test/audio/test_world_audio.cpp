#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ari_social_sim/audio/sound_localizer.hpp"
#include "ari_social_sim/audio/world_audio.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::audio {
namespace {

const std::string kQuestion = "excuse me where is the toilet please";

// What a run of `seconds` records: the six channels, and each word's world time.
struct Recording {
  std::array<std::vector<float>, 6> channels;
  std::vector<double> word_times_s;
};

// ARI at (1, 3) facing +x; woman 10 two metres ahead, facing it, asks kQuestion at 0.5 s; ARI
// answers at 3.5 s when `ari_answers`.
Recording record_question(bool ari_answers, double seconds) {
  world::Simulation simulation(world::test::square_room(6.0), world::SimulationConfig{});
  world::AriSpec ari;
  ari.pose = {{1.0, 3.0}, 0.0};
  simulation.add_ari(ari);
  world::HumanSpec woman;
  woman.id = 10;
  woman.pose = {{3.0, 3.0}, M_PI};
  woman.gender = model::Gender::kFemale;
  simulation.add_human(woman);
  WorldAudio audio(RoomSettings{}, walls_of(simulation.world()), 4,
                   std::make_shared<SpeechSynthesizer>());
  Recording recording;
  bool asked = false, answered = false;
  while (simulation.time_s() < seconds) {
    if (!asked && simulation.time_s() >= 0.5) {
      simulation.say(10, "QUESTION:TOILET", kQuestion);
      asked = true;
    }
    if (ari_answers && !answered && simulation.time_s() >= 3.5) {
      simulation.say(1, "INFORM:TOILET", "the toilet is down the corridor");
      answered = true;
    }
    simulation.step();
    const world::WorldSnapshot snapshot = world::WorldSnapshot::of(simulation);
    const world::SpeechSnapshot& speech = snapshot.humans[0].speech;
    if (speech.is_speaking && recording.word_times_s.size() == speech.word_index) {
      recording.word_times_s.push_back(speech.start_s +
                                       speech.word_index * 60.0 / speech.words_per_minute);
    }
    audio.observe(snapshot);
    for (const ArrayChunk& chunk : audio.chunks_until(snapshot.time_s)) {
      for (size_t c = 0; c < 6; ++c) {
        for (const int16_t s : chunk.channels[c]) {
          recording.channels[c].push_back(s / 32768.0f);
        }
      }
    }
  }
  return recording;
}

double rms_over(const std::vector<float>& signal, size_t from, size_t count) {
  double sum = 0.0;
  for (size_t i = from; i < std::min(signal.size(), from + count); ++i) {
    sum += double(signal[i]) * signal[i];
  }
  return std::sqrt(sum / count);
}

// Each word of the world's speech is heard at the array within 50 ms of the world's word event
// (2 m of travel, 5.8 ms, included): the 10 ms energy first reaches a tenth of the utterance's
// loudest after the event.
TEST(WorldAudio, EachWordIsHeardWithin50MsOfTheWorldsWordEvent) {
  const Recording recording = record_question(false, 3.2);
  const std::vector<float>& mic = recording.channels[1];
  ASSERT_EQ(recording.word_times_s.size(), 7u);
  double loudest = 0.0;
  for (size_t i = 0; i + 160 < mic.size(); i += 80) {
    loudest = std::max(loudest, rms_over(mic, i, 160));
  }
  double worst_ms = 0.0;
  for (const double word_s : recording.word_times_s) {
    size_t i = static_cast<size_t>(word_s * 16000);
    while (i + 160 < mic.size() && rms_over(mic, i, 160) < 0.1 * loudest) {
      i += 16;
    }
    worst_ms = std::max(worst_ms, (i / 16000.0 - word_s) * 1000.0);
  }
  std::printf("latest word heard %.1f ms after its world event\n", worst_ms);
  EXPECT_LT(worst_ms, 50.0);
  // Before the question only the room's noise (-65 dBFS) is heard.
  EXPECT_LT(rms_over(mic, 0, 6000), 0.001);
}

TEST(WorldAudio, TheSameRunGivesTheSameSamples) {
  const Recording first = record_question(true, 2.0);
  const Recording second = record_question(true, 2.0);
  for (size_t c = 0; c < 6; ++c) {
    EXPECT_EQ(first.channels[c], second.channels[c]) << "channel " << c;
  }
}

// The woman is straight ahead of the array; ARI's answer is on the playback channel and not on
// the processed one.
TEST(WorldAudio, TheSpeakerIsLocatedAndAriIsHeardOnThePlaybackChannel) {
  const Recording recording = record_question(true, 6.0);
  std::vector<double> errors;
  for (size_t start = 16000; start + 1024 < 3 * 16000; start += 1024) {
    std::array<std::vector<float>, 4> frame;
    for (size_t m = 0; m < 4; ++m) {
      frame[m].assign(recording.channels[1 + m].begin() + start,
                      recording.channels[1 + m].begin() + start + 1024);
    }
    if (const auto found = locate_sound(frame); found && found->coherence > 0.2) {
      errors.push_back(std::abs(found->azimuth_rad) * 180.0 / M_PI);
    }
  }
  ASSERT_GT(errors.size(), 10u);
  std::sort(errors.begin(), errors.end());
  std::printf("woman 2 m ahead: median direction error %.1f deg over %zu frames\n",
              errors[errors.size() / 2], errors.size());
  EXPECT_LT(errors[errors.size() / 2], 5.0);
  const size_t answer = 4 * 16000;
  EXPECT_GT(rms_over(recording.channels[5], answer, 16000), 0.01);
  EXPECT_LT(rms_over(recording.channels[0], answer, 16000), 0.002);
  EXPECT_GT(rms_over(recording.channels[1], answer, 16000), 0.01);
}

}  // namespace
}  // namespace ari_social_sim::audio
