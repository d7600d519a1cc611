#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/perception/group_candidates.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"
#include "perception_scenes.hpp"

namespace {

using namespace ari_social_sim;

// A seeded crowd in metres: circles of 1-4 people (singletons included) 0.6-0.9 m around random
// centres in a square holding about one person per 4 m^2, each facing their circle's centre
// within ~10 degrees.
std::vector<perception::GcffPerson> make_crowd(size_t count, uint64_t seed) {
  core::Rng rng(seed);
  const double side_m = 2.0 * std::sqrt(static_cast<double>(count));
  std::vector<perception::GcffPerson> persons;
  while (persons.size() < count) {
    const size_t size = std::min<size_t>(count - persons.size(), 1 + rng.uniform_index(4));
    const double centre_x = rng.uniform(0.0, side_m);
    const double centre_y = rng.uniform(0.0, side_m);
    const double radius_m = rng.uniform(0.6, 0.9);
    const double phase = rng.uniform(0.0, 2.0 * core::kPi);
    for (size_t k = 0; k < size; ++k) {
      const double bearing = phase + 2.0 * core::kPi * static_cast<double>(k) / size;
      persons.push_back(
          {"p" + std::to_string(persons.size()), centre_x + radius_m * std::cos(bearing),
           centre_y + radius_m * std::sin(bearing), bearing + core::kPi + rng.normal(0.0, 0.17)});
    }
  }
  return persons;
}

// One frame of GCFF with the simulator's parameters (stride 0.6 m, mdl 0.8 m^2), detector and
// result reused as a perception node would; items = frames.
void BM_GcffDetect(benchmark::State& state) {
  const std::vector<perception::GcffPerson> persons =
      make_crowd(static_cast<size_t>(state.range(0)), 7);
  perception::GcffParams params;
  params.stride = 0.6;
  params.mdl = 0.8;
  perception::GcffDetector detector(params);
  perception::GcffResult result;
  detector.detect(persons, result);  // warm-up: sizes the buffers
  for (auto _ : state) {
    detector.detect(persons, result);
    benchmark::DoNotOptimize(result.labels.data());
  }
  state.counters["groups"] = static_cast<double>(result.groups.size());
  state.counters["outer_iterations"] = result.iterations;
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GcffDetect)->ArgName("people")->Arg(5)->Arg(20)->Arg(50);

// One perception cycle as the batch engine runs it (hri_perception_node's pipeline, then
// group_detection_node's GroupPerception on the perceived bodies): a crowd of talking groups in
// front of ARI (test/perception/perception_scenes.hpp) behind a wall segment in a 20 x 20 m map
// at 5 cm, with the default sensors and error models: bodies (raycast occlusion), faces, voices
// and ASR, persons and engagement, gaze relations, GCFF groups. The people stand still and time
// advances by 1/30 s per cycle, so trackers, speech and engagement keep their steady-state work.
// items = cycles.
void BM_PerceptionCycle(benchmark::State& state) {
  const size_t people = static_cast<size_t>(state.range(0));
  world::WorldSnapshot snapshot = perception::test::crowd_snapshot(people, 7);
  perception::PerceptionPipeline pipeline{perception::PerceptionConfig{}};
  pipeline.set_sight_map(perception::test::map_with_wall({5.0, -9.0}, {5.0, -4.5}));
  perception::GroupPerception group_detection(pipeline.config().groups);
  std::vector<perception::PerceivedGroup> groups;
  const double dt_s = 1.0 / 30.0;
  for (int warm_up = 0; warm_up < 30; ++warm_up) {
    snapshot.time_s += dt_s;
    group_detection.update(perception::group_candidates_of(pipeline.update(snapshot)), groups);
  }
  size_t bodies = 0;
  for (auto _ : state) {
    snapshot.time_s += dt_s;
    const perception::PerceptionFrame& frame = pipeline.update(snapshot);
    group_detection.update(perception::group_candidates_of(frame), groups);
    bodies = frame.bodies.size();
  }
  state.counters["bodies"] = static_cast<double>(bodies);
  state.counters["groups"] = static_cast<double>(groups.size());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PerceptionCycle)->ArgName("people")->Arg(10)->Arg(50)->Arg(100);

}  // namespace

BENCHMARK_MAIN();
