// The learning environments' speed (docs/PERFORMANCE.md, "Learning environments"): steps per
// second of one environment and of a vector environment, and the cost of a reset, with perception
// (error models on) and group detection at every step.

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "ari_social_sim/learning/nav_env.hpp"
#include "ari_social_sim/learning/vector_nav_env.hpp"

namespace {

using namespace ari_social_sim;

// join_group episodes hold 4 to 7 people in their two groups; walkers bring them to about N.
std::shared_ptr<const learning::NavEnvSetup> setup_for(int walkers) {
  return learning::NavEnvSetup::load(
      ARI_SOURCE_DIR, std::string(ARI_SOURCE_DIR) + "/config/learning/join_group.yaml",
      "{walkers: " + std::to_string(walkers) + ", terminate_on_collision: false}", "bench");
}

// A policy's stand-in: drives and turns in slow waves, so that ARI moves among the people.
void wave_action(int step, float* action) {
  action[0] = 0.3f + 0.3f * static_cast<float>(std::sin(0.05 * step));
  action[1] = 0.6f * static_cast<float>(std::cos(0.03 * step));
  action[2] = 0.4f * static_cast<float>(std::sin(0.02 * step));
}

// Steps of one environment, reset when an episode ends (resets included in the time).
void BM_NavEnvStep(benchmark::State& state) {
  learning::NavEnv env(setup_for(static_cast<int>(state.range(0))));
  std::vector<float> observation(env.observation_size());
  env.reset(1, observation.data());
  float action[learning::kActionSize];
  int step = 0;
  double people = 0.0;
  for (auto _ : state) {
    wave_action(step++, action);
    env.step(action, observation.data());
    people += env.simulation().humans().size();
    if (env.done()) {
      env.reset(std::nullopt, observation.data());
    }
  }
  state.counters["people"] = people / step;
  state.counters["steps_per_s"] = benchmark::Counter(step, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NavEnvStep)->ArgName("walkers")->Arg(5)->Arg(45)->Unit(benchmark::kMicrosecond);

void BM_NavEnvReset(benchmark::State& state) {
  learning::NavEnv env(setup_for(static_cast<int>(state.range(0))));
  std::vector<float> observation(env.observation_size());
  uint64_t seed = 1;
  for (auto _ : state) {
    env.reset(seed++, observation.data());
  }
}
BENCHMARK(BM_NavEnvReset)->ArgName("walkers")->Arg(5)->Arg(45)->Unit(benchmark::kMicrosecond);

// One call steps all 16 environments; steps_per_s counts environment steps.
void BM_VectorNavEnvStep(benchmark::State& state) {
  const int envs = 16;
  learning::VectorNavEnv vec(setup_for(static_cast<int>(state.range(0))), envs,
                             static_cast<int>(state.range(1)));
  const size_t size = vec.observation_size();
  std::vector<float> observations(envs * size), finals(envs * size), actions(envs * 3);
  std::vector<double> rewards(envs);
  bool terminated[envs], truncated[envs];
  vec.reset(1, observations.data());
  int step = 0;
  for (auto _ : state) {
    for (int i = 0; i < envs; ++i) {
      wave_action(step + 13 * i, actions.data() + 3 * i);
    }
    ++step;
    vec.step(actions.data(),
             {observations.data(), rewards.data(), terminated, truncated, finals.data()});
  }
  state.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(step) * envs, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_VectorNavEnvStep)
    ->ArgNames({"walkers", "threads"})
    ->Args({5, 1})
    ->Args({45, 1})
    ->Args({5, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
