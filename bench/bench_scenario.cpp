// Batch speed of the shipped scenarios: one whole episode per iteration, the cores composed as
// run_episodes composes them (bags and CSV left out: BM_GroupDiscussionEpisodeWithBag has them).
// Reports the real-time factor (sim seconds per wall second) and episodes per second.
#include <benchmark/benchmark.h>

#include <string>

#include "ari_social_sim/engine/episode.hpp"
#include "episode_bag/episode_bag.hpp"

namespace {

using namespace ari_social_sim;

const std::string kScenarios = std::string(ARI_SOURCE_DIR) + "/scenarios/";

// Runs episodes with seeds 1, 2, 3, ... of the named scenario.
void run_scenario(benchmark::State& state, const std::string& name, bool with_bag) {
  const scenario::Scenario loaded = scenario::load_scenario_file(kScenarios + name + ".yaml");
  const engine::EpisodeConfig config =
      engine::EpisodeConfig::load(std::string(ARI_SOURCE_DIR) + "/config");
  uint64_t seed = 1;
  double sim_s = 0.0;
  int successes = 0;
  for (auto _ : state) {
    engine::Episode episode(loaded, seed++, config);
    std::unique_ptr<tools::EpisodeBag> bag;
    if (with_bag) {
      bag = std::make_unique<tools::EpisodeBag>("/tmp/bench_scenario.bag", loaded.name);
    }
    while (!episode.finished()) {
      episode.step();
      if (bag) {
        bag->record_step(episode);
      }
    }
    if (bag) {
      bag->finish();  // as run_episodes does: close and rename
    }
    sim_s += episode.runner().outcome()->end_time_s;
    successes += episode.runner().outcome()->success ? 1 : 0;
  }
  state.counters["real_time_factor"] = benchmark::Counter(sim_s, benchmark::Counter::kIsRate);
  state.counters["episodes_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["success_rate"] = static_cast<double>(successes) / state.iterations();
}

void BM_GroupDiscussionEpisode(benchmark::State& state) {
  run_scenario(state, "group_discussion", false);
}
void BM_GroupDiscussionEpisodeWithBag(benchmark::State& state) {
  run_scenario(state, "group_discussion", true);
}
void BM_WaitingRoomEpisode(benchmark::State& state) {
  run_scenario(state, "waiting_room", false);
}
void BM_CorridorEpisode(benchmark::State& state) {
  run_scenario(state, "corridor", false);
}
void BM_JoinGroupEpisode(benchmark::State& state) {
  run_scenario(state, "join_group", false);
}

BENCHMARK(BM_GroupDiscussionEpisode)->Unit(benchmark::kMillisecond)->MinTime(5.0);
BENCHMARK(BM_GroupDiscussionEpisodeWithBag)->Unit(benchmark::kMillisecond)->MinTime(5.0);
BENCHMARK(BM_WaitingRoomEpisode)->Unit(benchmark::kMillisecond)->MinTime(5.0);
BENCHMARK(BM_CorridorEpisode)->Unit(benchmark::kMillisecond)->MinTime(5.0);
BENCHMARK(BM_JoinGroupEpisode)->Unit(benchmark::kMillisecond)->MinTime(5.0);

}  // namespace

BENCHMARK_MAIN();
