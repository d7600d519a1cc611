// Render rates of ARI's cameras on the headless renderer (llvmpipe without a GPU), and the
// real-time factor they allow. llvmpipe rasterises on its own worker threads, so every case is
// timed in wall-clock time (UseRealTime): thread CPU time would miss the rendering.

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/physics/camera_rig.hpp"
#include "ari_social_sim/physics/octomap_mapper.hpp"

namespace {

using namespace ari_social_sim;

// ARI in the waiting room with five people in view of the head camera, as in docs/camera_*.png.
const core::Pose2 kAri{{6.0, 2.6}, 2.0};

std::vector<physics::RenderPrimitive> people_at(double t_s) {
  const physics::SceneStyle style;
  std::vector<physics::RenderPrimitive> people;
  // The people sway a little every tick so the dynamic mesh is rebuilt and uploaded, as in a run.
  const double sway = 0.1 * std::sin(t_s);
  physics::append_person({{5.1 + sway, 4.2}, -0.9}, -1.1, 0, style.person, people);
  physics::append_person({{4.5, 3.7 + sway}, 0.2}, 0.5, 1, style.person, people);
  physics::append_person({{4.3, 2.0 + t_s * 0.01}, 1.6}, 1.6, 2, style.person, people);
  physics::append_person({{7.2, 0.9}, 2.3}, 2.5, 3, style.person, people);
  physics::append_person({{6.9, 3.4}, -2.0}, -2.2 + sway, 4, style.person, people);
  return people;
}

// A rig with only the named cameras enabled, sized as given.
physics::CameraRig rig_with(const std::vector<std::string>& names, int width, int height) {
  physics::CameraRigConfig config;
  for (physics::CameraSpec& spec : config.cameras) {
    spec.enabled = false;
    for (const std::string& name : names) {
      if (spec.name == name) {
        spec.enabled = true;
        spec.width = width > 0 ? width : spec.width;
        spec.height = height > 0 ? height : spec.height;
      }
    }
  }
  physics::CameraRig rig(config);
  rig.set_world(
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml"),
      physics::SceneStyle{});
  return rig;
}

// One frame of one camera per iteration, people updated each frame; items = frames.
void render_frames(benchmark::State& state, const std::string& camera) {
  physics::CameraRig rig =
      rig_with({camera}, static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const Eigen::Isometry3d X = physics::X_world_optical(rig.cameras()[0], kAri, 0.15, 0.05);
  physics::CameraFrame frame;
  double t = 0.0;
  rig.set_dynamic_primitives(people_at(t));
  rig.render(0, X, frame);  // first frame allocates framebuffers and compiles the pipeline
  for (auto _ : state) {
    t += 0.1;
    rig.set_dynamic_primitives(people_at(t));
    rig.render(0, X, frame);
    benchmark::DoNotOptimize(frame.colour.data);
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(rig.renderer().device_name());
}

void BM_HeadCamera(benchmark::State& state) {
  render_frames(state, "head_front_camera");
}
BENCHMARK(BM_HeadCamera)
    ->ArgNames({"w", "h"})
    ->Args({1280, 960})
    ->Args({640, 480})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

void BM_TorsoRgbd(benchmark::State& state) {
  render_frames(state, "torso_front_camera");
}
BENCHMARK(BM_TorsoRgbd)
    ->ArgNames({"w", "h"})
    ->Args({848, 480})
    ->Args({424, 240})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

void BM_FisheyeFront(benchmark::State& state) {
  render_frames(state, "front_fisheye_camera");
}
BENCHMARK(BM_FisheyeFront)
    ->ArgNames({"w", "h"})
    ->Args({1280, 960})
    ->Args({640, 480})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// One sim second with the head camera at 10 Hz and the torso RGB-D at 15 Hz, stepped at 1 kHz
// through the rig's schedule: items per second = the real-time factor the cameras allow on their
// own (physics excluded; see docs/PERFORMANCE.md for the combination).
void BM_HeadAndRgbdSimSecond(benchmark::State& state) {
  physics::CameraRig rig = rig_with({"head_front_camera", "torso_front_camera"}, 0, 0);
  physics::CameraFrame frame;
  double t = 0.0;
  for (auto _ : state) {
    for (int step = 0; step < 1000; ++step, t += 0.001) {
      const std::vector<size_t> due = rig.due(t);
      if (due.empty()) {
        continue;
      }
      rig.set_dynamic_primitives(people_at(t));
      for (const size_t i : due) {
        rig.render(i, physics::X_world_optical(rig.cameras()[i], kAri, 0.15, 0.05), frame);
      }
    }
  }
  state.SetItemsProcessed(state.iterations());  // sim seconds
}
BENCHMARK(BM_HeadAndRgbdSimSecond)->UseRealTime()->Unit(benchmark::kMillisecond);

// Inserting one torso depth image (848 x 480, every 4th pixel, 4 m rays) into the OctoMap.
void BM_OctomapInsert(benchmark::State& state) {
  physics::CameraRig rig = rig_with({"torso_front_camera"}, 0, 0);
  rig.set_dynamic_primitives(people_at(0.0));
  const Eigen::Isometry3d X = physics::X_world_optical(rig.cameras()[0], kAri, 0.0, 0.0);
  physics::CameraFrame frame;
  rig.render(0, X, frame);
  const physics::CameraInfo& info = rig.info(0);
  const physics::PinholeModel model{info.width, info.height, info.K[0],
                                    info.K[4],  info.K[2],   info.K[5]};
  physics::OctomapMapper mapper(physics::MappingConfig{});
  for (auto _ : state) {
    mapper.insert_depth(frame.depth, model, X);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OctomapInsert)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
