// Render rates of ARI's cameras on the headless renderer (llvmpipe without a GPU), and the
// real-time factor they allow. llvmpipe rasterises on its own worker threads, so every case is
// timed in wall-clock time (UseRealTime): thread CPU time would miss the rendering.

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "ari_social_sim/mapping/octomap_mapper.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/rendering/motion_blur.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"

namespace {

using namespace ari_social_sim;

// ARI in the waiting room with five people in view of the head camera, as in docs/camera_*.png.
const core::Pose2 kAri{{6.0, 2.6}, 2.0};

// Where the ten people stand at sim time t: five in front of ARI as in docs/camera_*.png, five
// more behind them. They sway a little so that the dynamic mesh is rebuilt and uploaded every
// frame, as in a run; one walks.
struct Placement {
  core::Pose2 pose;
  double face_yaw;
};
std::vector<Placement> placements_at(double t_s) {
  const double sway = 0.1 * std::sin(t_s);
  return {{{{5.1 + sway, 4.2}, -0.9}, -1.1},
          {{{4.5, 3.7 + sway}, 0.2}, 0.5},
          {{{4.3, 2.0 + t_s * 0.01}, 1.6}, 1.6},
          {{{7.2, 0.9}, 2.3}, 2.5},
          {{{6.9, 3.4}, -2.0}, -2.2 + sway},
          {{{3.6, 4.9}, -0.5}, -0.5},
          {{{4.2, 5.3 - sway}, -1.2}, -1.0},
          {{{2.9, 3.2}, 0.0}, 0.3},
          {{{5.6, 5.6}, -1.8}, -1.8},
          {{{3.3, 2.4 + sway}, 0.6}, 0.6}};
}

// The people as the simulator draws them: articulated figures, posed per frame.
rendering::RenderMesh figures_at(double t_s, size_t count, rendering::PeopleFigures& figures) {
  std::vector<rendering::FigureInput> people;
  const std::vector<Placement> placements = placements_at(t_s);
  for (size_t i = 0; i < count; ++i) {
    rendering::FigureInput person;
    person.traits = {static_cast<uint32_t>(i + 1), 20.0 + 5.0 * i,
                     i % 2 == 0 ? model::Gender::kFemale : model::Gender::kMale, i == 1};
    person.pose = placements[i].pose;
    person.face_yaw_rad = placements[i].face_yaw;
    person.velocity_mps = i == 2 ? Eigen::Vector2d(0.0, 1.2) : Eigen::Vector2d::Zero();
    person.walked_m = person.velocity_mps.norm() * t_s;
    person.speaking = i == 0;
    people.push_back(person);
  }
  figures.update(t_s, people);
  return figures.mesh();
}

// The baseline the figures are weighed against: the shapes people had before them (an elliptic
// body cylinder, a head sphere, a face plate and two eye boxes), tessellated every frame.
rendering::RenderMesh shapes_at(double t_s, size_t count) {
  auto solid = [](rendering::PrimitiveShape shape, const Eigen::Isometry3d& X,
                  const Eigen::Vector3d& size) {
    rendering::RenderPrimitive primitive;
    primitive.shape = shape;
    primitive.X_world_shape = X;
    primitive.size = size;
    return primitive;
  };
  std::vector<rendering::RenderPrimitive> primitives;
  const std::vector<Placement> placements = placements_at(t_s);
  for (size_t i = 0; i < count; ++i) {
    const Placement& p = placements[i];
    auto planar = [&p](double z, double yaw) {
      return Eigen::Translation3d(p.pose.position.x(), p.pose.position.y(), z) *
             Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
    };
    primitives.push_back(solid(rendering::PrimitiveShape::kCylinder, planar(0.725, p.pose.theta),
                               {0.26, 0.42, 1.45}));
    const Eigen::Isometry3d head = planar(1.6, p.face_yaw);
    primitives.push_back(solid(rendering::PrimitiveShape::kSphere, head, {0.22, 0.22, 0.22}));
    primitives.push_back(solid(rendering::PrimitiveShape::kBox,
                               head * Eigen::Translation3d(0.0935, 0.0, 0.0), {0.04, 0.132, 0.11}));
    for (double side : {-1.0, 1.0}) {
      primitives.push_back(solid(rendering::PrimitiveShape::kBox,
                                 head * Eigen::Translation3d(0.1185, side * 0.03, 0.02),
                                 {0.012, 0.022, 0.018}));
    }
  }
  return rendering::mesh_of(primitives);
}

// A rig with only the named cameras enabled, sized as given, with the default camera effects
// unless `effects` says otherwise.
rendering::CameraRig rig_with(const std::vector<std::string>& names, int width, int height,
                              const rendering::CameraEffects& effects = {}) {
  rendering::CameraRigConfig config;
  config.effects = effects;
  for (rendering::CameraSpec& spec : config.cameras) {
    spec.enabled = false;
    for (const std::string& name : names) {
      if (spec.name == name) {
        spec.enabled = true;
        spec.width = width > 0 ? width : spec.width;
        spec.height = height > 0 ? height : spec.height;
      }
    }
  }
  rendering::CameraRig rig(config);
  rig.set_world(
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml"),
      rendering::SceneStyle{});
  return rig;
}

// One frame of one camera per iteration, the five people in front posed each frame; items =
// frames.
void render_frames(benchmark::State& state, const std::string& camera) {
  rendering::CameraRig rig =
      rig_with({camera}, static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const Eigen::Isometry3d X = rendering::X_world_optical(rig.cameras()[0], kAri, 0.15, 0.05);
  rendering::PeopleFigures figures;
  rendering::CameraFrame frame;
  double t = 0.0;
  rig.set_dynamic_mesh(figures_at(t, 5, figures));
  rig.render(0, X, frame);  // first frame allocates framebuffers and compiles the pipeline
  for (auto _ : state) {
    t += 0.1;
    rig.set_dynamic_mesh(figures_at(t, 5, figures));
    rig.render(0, X, frame);
    benchmark::DoNotOptimize(frame.colour.data);
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(rig.renderer().device_name());
}

// Frames of the head camera at 1280x960 with ten people walking, as articulated figures posed per
// frame or as the earlier shapes; items = frames. Each frame is the one due at its time (10 Hz),
// as in a run, so that motion blur sees the people move.
void render_ten_people(benchmark::State& state, rendering::CameraRig& rig, bool use_figures) {
  const Eigen::Isometry3d X = rendering::X_world_optical(rig.cameras()[0], kAri, 0.15, 0.05);
  rendering::PeopleFigures figures;
  rendering::CameraFrame frame;
  double t = 0.0;
  auto people = [&] { return use_figures ? figures_at(t, 10, figures) : shapes_at(t, 10); };
  rig.set_dynamic_mesh(people());
  rig.due(t);
  rig.render(0, X, frame);
  for (auto _ : state) {
    t += 0.1;
    rig.set_dynamic_mesh(people());
    rig.due(t);
    rig.render(0, X, frame);
    benchmark::DoNotOptimize(frame.colour.data);
  }
  state.SetItemsProcessed(state.iterations());
}

// Ten people drawn as the earlier shapes (figures:0) or as articulated figures (figures:1): the
// figures' cost relative to the shapes.
void BM_HeadCameraTenPeople(benchmark::State& state) {
  rendering::CameraRig rig = rig_with({"head_front_camera"}, 0, 0);
  render_ten_people(state, rig, state.range(0) == 1);
}
BENCHMARK(BM_HeadCameraTenPeople)
    ->ArgNames({"figures"})
    ->Arg(0)
    ->Arg(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// Posing ten figures (the people's mesh of a frame), all standing with their weight on both legs
// (weight:0) or each on one leg (weight:1, WeightShifts): the cost of the legs' reach to the feet.
void BM_PoseTenFigures(benchmark::State& state) {
  std::vector<rendering::HumanFigure> figures;
  for (uint32_t id = 1; id <= 10; ++id) {
    figures.emplace_back(rendering::appearance_of({id, 40.0, model::Gender::kFemale, false}, 1));
  }
  rendering::FigurePose pose;
  pose.weight_side = static_cast<double>(state.range(0));
  rendering::RenderMesh mesh;
  for (auto _ : state) {
    mesh.vertices.clear();
    for (const rendering::HumanFigure& figure : figures) {
      figure.append_posed(pose, 1.0f, 2.0f, mesh);
    }
    benchmark::DoNotOptimize(mesh.vertices.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PoseTenFigures)->ArgNames({"weight"})->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// Ten figures with the camera effects: effects:0 none (the renderer's image as drawn), 1 the
// sensor alone (no anti-aliasing, the default), 2 the sensor with 4-sample anti-aliasing, 3 the
// sensor with motion blur (one person walking, the others swaying).
void BM_HeadCameraEffects(benchmark::State& state) {
  rendering::CameraEffects effects;
  effects.enabled = state.range(0) > 0;
  effects.antialiasing_samples = state.range(0) == 2 ? 4 : 1;
  effects.motion_blur = state.range(0) == 3;
  rendering::CameraRig rig = rig_with({"head_front_camera"}, 0, 0, effects);
  render_ten_people(state, rig, /*use_figures=*/true);
}
BENCHMARK(BM_HeadCameraEffects)
    ->ArgNames({"effects"})
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// Motion blur's smearing alone on a head camera frame (1280x960): `people` people of 120x480
// pixels (a person 2.5 m away) each crossing at 11 px an exposure (1.5 m/s), and with turning:1
// the camera turning too (15 px over the whole frame); items = frames.
void BM_MotionBlurSmear(benchmark::State& state) {
  cv::Mat rgb(960, 1280, CV_8UC3, cv::Scalar(120, 110, 100));
  cv::Mat labels(960, 1280, CV_16UC1, cv::Scalar(0));
  rendering::ImageMotion motion;
  for (int person = 0; person < state.range(0); ++person) {
    const auto label = static_cast<uint16_t>(2 * person + 1);
    const cv::Rect body(100 + 220 * person, 300, 120, 480);
    rgb(body).setTo(cv::Scalar(40 + 30 * person, 160, 90));
    labels(body).setTo(cv::Scalar(label));
    motion.labelled[label] = Eigen::Vector2f(11.0f, 0.0f);
  }
  motion.background = Eigen::Vector2f(state.range(1) == 1 ? 15.0f : 0.0f, 0.0f);
  for (auto _ : state) {
    cv::Mat frame = rgb.clone();
    rendering::apply_motion_blur(frame, labels, motion);
    benchmark::DoNotOptimize(frame.data);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MotionBlurSmear)
    ->ArgNames({"people", "turning"})
    ->Args({1, 0})
    ->Args({5, 0})
    ->Args({5, 1})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

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
// through the rig's schedule, ten people posed for every rendering tick: items per second = the
// real-time factor the cameras allow on their own (physics excluded; see docs/PERFORMANCE.md for
// the combination).
void BM_HeadAndRgbdSimSecond(benchmark::State& state) {
  rendering::CameraRig rig = rig_with({"head_front_camera", "torso_front_camera"}, 0, 0);
  rendering::PeopleFigures figures;
  rendering::CameraFrame frame;
  double t = 0.0;
  for (auto _ : state) {
    for (int step = 0; step < 1000; ++step, t += 0.001) {
      const std::vector<size_t> due = rig.due(t);
      if (due.empty()) {
        continue;
      }
      rig.set_dynamic_mesh(figures_at(t, 10, figures));
      for (const size_t i : due) {
        rig.render(i, rendering::X_world_optical(rig.cameras()[i], kAri, 0.15, 0.05), frame);
      }
    }
  }
  state.SetItemsProcessed(state.iterations());  // sim seconds
}
BENCHMARK(BM_HeadAndRgbdSimSecond)->UseRealTime()->Unit(benchmark::kMillisecond);

// Inserting one torso depth image (848 x 480, every 4th pixel, 4 m rays) into the OctoMap.
void BM_OctomapInsert(benchmark::State& state) {
  rendering::CameraRig rig = rig_with({"torso_front_camera"}, 0, 0);
  rendering::PeopleFigures figures;
  rig.set_dynamic_mesh(figures_at(0.0, 5, figures));
  const Eigen::Isometry3d X = rendering::X_world_optical(rig.cameras()[0], kAri, 0.0, 0.0);
  rendering::CameraFrame frame;
  rig.render(0, X, frame);
  const rendering::CameraInfo& info = rig.info(0);
  const rendering::PinholeModel model{info.width, info.height, info.K[0],
                                      info.K[4],  info.K[2],   info.K[5]};
  mapping::OctomapMapper mapper(mapping::MappingConfig{});
  for (auto _ : state) {
    mapper.insert_depth(frame.depth, model, X);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OctomapInsert)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
