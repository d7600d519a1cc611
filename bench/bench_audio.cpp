// Speed of the microphone array's audio: a scene of ten people talking in turns and ARI answering,
// all six channels rendered in sim time, as audio_node and the engine render them; and
// speech_recognition_node's recogniser (pocketsphinx with the dialogue domain's language model) on
// that scene's processed channel. Reports real-time factors (sim seconds per CPU second);
// synthesis is included in the first iteration (cold cache) and cached after it, as in a run.
#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/audio/domain_grammar.hpp"
#include "ari_social_sim/audio/speech_recognizer.hpp"
#include "ari_social_sim/audio/world_audio.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "scene_builders.hpp"

namespace {

using namespace ari_social_sim;

const std::vector<std::string> kLines = {
    "good morning how are you today",       "could you tell me where the pharmacy is",
    "i have an appointment at ten o'clock", "the waiting room is very busy this morning",
    "my daughter will pick me up later",    "do you know how long the wait is",
    "i think they called my name",          "the coffee machine is broken again",
    "have you seen the new robot here",     "we should sit down over there"};

// One of the ten people starts a line every 2.5 s of sim time, in turn, and ARI answers every
// fourth turn; `take` gets the chunks each step renders.
void run_turns(world::Simulation& simulation, audio::WorldAudio& audio, double seconds,
               const std::function<void(std::vector<audio::ArrayChunk>)>& take) {
  const double start_s = simulation.time_s();
  int turn = 0;
  while (simulation.time_s() - start_s < seconds) {
    if (simulation.time_s() - start_s >= turn * 2.5) {
      const model::ObjectId speaker = turn % 4 == 3 ? 1 : 10 + turn % 10;
      simulation.say(speaker, "INFORM:SMALLTALK", kLines[turn % kLines.size()]);
      ++turn;
    }
    simulation.step();
    const world::WorldSnapshot snapshot = world::WorldSnapshot::of(simulation);
    audio.observe(snapshot);
    take(audio.chunks_until(snapshot.time_s));
  }
}

// Ten people on a 2.5 m circle around ARI in a 10 m room.
std::unique_ptr<world::Simulation> ten_people_around_ari() {
  auto simulation = std::make_unique<world::Simulation>(world::test::square_room(10.0),
                                                        world::SimulationConfig{});
  world::AriSpec ari;
  ari.pose = {{5.0, 5.0}, 0.0};
  simulation->add_ari(ari);
  for (int i = 0; i < 10; ++i) {
    world::HumanSpec human;
    human.id = 10 + i;
    const double angle = i * 2.0 * M_PI / 10.0;
    human.pose = {{5.0 + 2.5 * std::cos(angle), 5.0 + 2.5 * std::sin(angle)}, angle + M_PI};
    human.gender = i % 2 == 0 ? model::Gender::kFemale : model::Gender::kMale;
    simulation->add_human(human);
  }
  return simulation;
}

void BM_TenPeopleTalking(benchmark::State& state) {
  const std::unique_ptr<world::Simulation> simulation = ten_people_around_ari();
  audio::WorldAudio audio(audio::RoomSettings{}, audio::walls_of(simulation->world()), 1,
                          std::make_shared<audio::SpeechSynthesizer>());
  constexpr double kSecondsPerIteration = 30.0;
  for (auto _ : state) {
    run_turns(*simulation, audio, kSecondsPerIteration,
              [](std::vector<audio::ArrayChunk> chunks) { benchmark::DoNotOptimize(chunks); });
  }
  state.counters["real_time_factor"] = benchmark::Counter(
      kSecondsPerIteration * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_TenPeopleTalking)->Unit(benchmark::kMillisecond)->MinTime(10.0);

// The same scene's processed channel, 30 s of it, through one recogniser fed 1024-sample chunks
// as speech_recognition_node feeds it.
void BM_RecognizerOnChannelZero(benchmark::State& state) {
  const std::unique_ptr<world::Simulation> simulation = ten_people_around_ari();
  audio::WorldAudio audio(audio::RoomSettings{}, audio::walls_of(simulation->world()), 1,
                          std::make_shared<audio::SpeechSynthesizer>());
  std::vector<int16_t> channel;
  run_turns(*simulation, audio, 30.0, [&channel](const std::vector<audio::ArrayChunk>& chunks) {
    for (const audio::ArrayChunk& chunk : chunks) {
      channel.insert(channel.end(), chunk.channels[0].begin(), chunk.channels[0].end());
    }
  });
  const std::string config = std::string(ARI_SOURCE_DIR) + "/config/dialogue/";
  size_t left_out = 0;
  audio::SpeechRecognizer recognizer(
      {audio::kPocketsphinxModelDir,
       audio::language_model_for(audio::read_domain_sentences(config + "nlg_templates.yaml",
                                                              config + "hospital_domain.yaml"),
                                 audio::kPocketsphinxModelDir, &left_out)});
  for (auto _ : state) {
    for (size_t i = 0; i + audio::kChunkSamples <= channel.size(); i += audio::kChunkSamples) {
      benchmark::DoNotOptimize(recognizer.process(channel.data() + i, audio::kChunkSamples));
    }
    benchmark::DoNotOptimize(recognizer.flush());
  }
  state.counters["real_time_factor"] =
      benchmark::Counter(static_cast<double>(channel.size()) / audio::kSampleRateHz *
                             static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

BENCHMARK(BM_RecognizerOnChannelZero)->Unit(benchmark::kMillisecond)->MinTime(10.0);

}  // namespace

BENCHMARK_MAIN();
