// render_cameras: renders one image from each of ARI's cameras in a world with a few people, and
// writes them as PNG files (the pictures in docs/cameras.md). Depth is written false-coloured.
// Each picture is written whole or not at all (core::OutputFile); SIGINT or SIGTERM stops between
// two pictures, keeping those written, and exits with 128 + the signal's number.

#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/core/stop_signal.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"

namespace {

using namespace ari_social_sim;

constexpr int kUsageError = 2;
// Picks the people's looks; fixed so that the pictures stay the same from run to run.
constexpr uint64_t kAppearanceSeed = 1;
// How long the pictures' walkers have walked: half a second, mid-stride.
constexpr double kWalkedS = 0.5;

constexpr const char* kUsage = R"(Usage:
  render_cameras --world WORLD_YAML --out DIR [--overwrite]

Renders ARI's head camera, torso RGB-D camera (colour and depth), front and rear fisheyes and the
T265 fisheye pair once, with ARI at (6.0, 2.6) facing north-west in the world and seven people
around it (one speaking, one in a mask, one walking, two seated), and writes DIR/camera_head.png,
camera_torso_rgb.png, camera_torso_depth.png (0 to 5 m false-coloured, black where invalid),
camera_fisheye_front.png, camera_fisheye_rear.png, camera_t265_fisheye1.png and
camera_t265_fisheye2.png; then the head and torso colour cameras of four more scenes, as
camera_head_SCENE.png and camera_torso_rgb_SCENE.png: a conversation of three (group), someone
walking past (walking), a patient in a mask (mask) and patients seated on a row of chairs with a
companion standing by (seated). The people are placed for the waiting room
(worlds/hospital_waiting_room.yaml); in another world they stand where they stand. DIR is
created when missing; pictures
already there are replaced only with --overwrite (checked before rendering). Each picture
appears under its name only once it is whole. SIGINT (Ctrl-C) or SIGTERM stops between two
pictures: those written are kept, the others are not rendered. A second Ctrl-C kills at once.

Exit status: 0 on success, 2 on bad arguments, an unreadable world or an output folder that
cannot be written, 1 when rendering or writing a picture fails, 130 after SIGINT and 143 after
SIGTERM.
)";

// File name of each camera's picture.
std::string picture_name(const std::string& camera) {
  if (camera == "head_front_camera")
    return "camera_head";
  if (camera == "torso_front_camera")
    return "camera_torso_rgb";
  if (camera == "front_fisheye_camera")
    return "camera_fisheye_front";
  if (camera == "rear_fisheye_camera")
    return "camera_fisheye_rear";
  if (camera == "torso_back_camera/fisheye1")
    return "camera_t265_fisheye1";
  return "camera_t265_fisheye2";
}

// Depth in metres as a turbo-coloured picture over 0..5 m; invalid pixels black.
cv::Mat false_colour(const cv::Mat& depth_m) {
  cv::Mat scaled(depth_m.size(), CV_8UC1);
  cv::Mat invalid(depth_m.size(), CV_8UC1);
  for (int v = 0; v < depth_m.rows; ++v) {
    for (int u = 0; u < depth_m.cols; ++u) {
      const float d = depth_m.at<float>(v, u);
      invalid.at<uint8_t>(v, u) = std::isfinite(d) ? 0 : 255;
      scaled.at<uint8_t>(v, u) =
          static_cast<uint8_t>(std::lround(std::clamp(d / 5.0f, 0.0f, 1.0f) * 255.0f));
    }
  }
  cv::Mat coloured;
  cv::applyColorMap(scaled, coloured, cv::COLORMAP_TURBO);
  coloured.setTo(cv::Scalar(0, 0, 0), invalid);
  return coloured;
}

// Encodes the picture as PNG (OpenCV's default settings, as cv::imwrite uses) and writes it whole
// or not at all (core::OutputFile): a failure or a stop never leaves half a picture under its name.
void write_png(const std::string& path, const cv::Mat& bgr) {
  std::vector<uint8_t> bytes;
  try {
    if (!cv::imencode(".png", bgr, bytes)) {
      throw core::Error(path + ": cannot encode the picture as PNG");
    }
  } catch (const cv::Exception& e) {
    throw core::Error(path + ": cannot encode the picture as PNG: " + e.what());
  }
  core::OutputFile file("--out", path);
  file.stream().write(reinterpret_cast<const char*>(bytes.data()),
                      static_cast<std::streamsize>(bytes.size()));
  file.commit();
  std::printf("wrote %s (%dx%d)\n", path.c_str(), bgr.cols, bgr.rows);
}

// One scene the tool renders: where ARI looks from, who is around and which pictures it makes.
struct Shot {
  std::string suffix;  // empty: the overview, every camera under its own name
  core::Pose2 ari;
  double head_pan{0.0};
  double head_tilt{0.0};
  std::vector<rendering::FigureInput> people;
};

rendering::FigureInput person(uint32_t id, double age, model::Gender gender, bool mask,
                              const core::Pose2& pose, double face_yaw,
                              const Eigen::Vector2d& velocity = Eigen::Vector2d::Zero(),
                              bool speaking = false) {
  rendering::FigureInput input;
  input.traits = {id, age, gender, mask};
  input.pose = pose;
  input.face_yaw_rad = face_yaw;
  input.velocity_mps = velocity;
  input.walked_m = kWalkedS * velocity.norm();
  input.speaking = speaking;
  return input;
}

// Someone sitting on the seat at `seat`, facing `facing`.
rendering::FigureInput seated_person(uint32_t id, double age, model::Gender gender,
                                     const Eigen::Vector2d& seat, double facing) {
  rendering::FigureInput input = person(id, age, gender, false, {seat, facing}, facing);
  input.seated = 1.0;
  return input;
}

std::vector<Shot> shots() {
  using model::Gender;
  // Overview: ARI faces north-west towards the middle rows of chairs; two people talk in front
  // of it (one speaking, one in a mask), one walks past on its left, two wait nearby and two sit
  // on the south row's seats (every half metre from x = 2.75 m, facing south).
  Shot overview{"", {{6.0, 2.6}, 2.0}, 0.15, 0.05, {}};
  overview.people = {person(1, 34, Gender::kFemale, false, {{5.1, 4.2}, -0.9}, -1.1,
                            Eigen::Vector2d::Zero(), true),
                     person(2, 61, Gender::kMale, true, {{4.5, 3.7}, 0.2}, 0.5),
                     person(3, 27, Gender::kMale, false, {{4.3, 2.0}, 1.6}, 1.6, {0.0, 1.2}),
                     person(4, 45, Gender::kFemale, false, {{7.2, 0.9}, 2.3}, 2.5),
                     person(5, 9, Gender::kMale, false, {{6.9, 3.4}, -2.0}, -2.2),
                     seated_person(6, 74, Gender::kFemale, {2.75, 5.0}, -M_PI / 2),
                     seated_person(7, 52, Gender::kMale, {3.75, 5.0}, -M_PI / 2)};
  // A conversation of three, 2.2 m ahead of ARI in the open middle of the room: one speaks.
  Shot group{"group", {{6.0, 4.0}, M_PI}, 0.0, 0.1, {}};
  const Eigen::Vector2d centre(3.8, 4.1);
  const double bearings[3] = {-0.3, 2.0, 4.1};
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d at =
        centre + 0.6 * Eigen::Vector2d(std::cos(bearings[i]), std::sin(bearings[i]));
    const double to_centre = bearings[i] + M_PI;
    group.people.push_back(person(11 + i, 30.0 + 12 * i, i == 1 ? Gender::kMale : Gender::kFemale,
                                  false, {at, to_centre}, to_centre, Eigen::Vector2d::Zero(),
                                  i == 0));
  }
  // Someone walking across ARI's view at 1.2 m/s, 3.5 m ahead.
  Shot walking{"walking", {{6.0, 4.0}, M_PI}, 0.0, 0.15, {}};
  walking.people = {
      person(21, 40, Gender::kMale, false, {{2.5, 3.2}, M_PI / 2}, M_PI / 2, {0.0, 1.2})};
  // A patient in a surgical mask facing ARI from 1.3 m.
  Shot masked{"mask", {{6.0, 4.0}, M_PI}, 0.0, 0.0, {}};
  masked.people = {person(37, 58, Gender::kFemale, true, {{4.6, 4.0}, 0.0}, 0.0)};
  // Waiting patients on the south row 1.7 m ahead of ARI, a companion standing by them.
  Shot seated{"seated", {{3.6, 3.3}, M_PI / 2}, 0.0, 0.15, {}};
  seated.people = {
      seated_person(41, 79, Gender::kFemale, {3.25, 5.0}, -M_PI / 2),
      seated_person(42, 35, Gender::kMale, {4.25, 5.0}, -M_PI / 2),
      person(43, 50, Gender::kMale, false, {{2.8, 4.6}, 0.3}, 0.5, Eigen::Vector2d::Zero(), true)};
  return {overview, group, walking, masked, seated};
}

// The pictures a shot makes: every camera for the overview, head and torso for the others.
std::vector<std::string> pictures_of(const Shot& shot, const std::string& camera) {
  if (shot.suffix.empty()) {
    return {picture_name(camera)};
  }
  if (camera == "head_front_camera" || camera == "torso_front_camera") {
    return {picture_name(camera) + "_" + shot.suffix};
  }
  return {};
}

// A checked command line, ready to render.
struct Job {
  model::WorldDescription world;
  std::string out_dir;
  rendering::CameraRigConfig config;
  std::vector<std::string> pictures;  // every file the job writes
};

// Checks the world and every picture's place before the renderer starts. Throws core::Error.
Job prepare(const std::string& world_path, const std::string& out_dir, bool overwrite) {
  core::check_input_file("--world", world_path);
  Job job;
  job.world = model::load_world_file(world_path);
  job.out_dir = out_dir;
  for (rendering::CameraSpec& spec : job.config.cameras) {
    spec.enabled = true;
  }
  core::prepare_output_directory("--out", out_dir);
  job.pictures = {out_dir + "/camera_torso_depth.png"};
  for (const Shot& shot : shots()) {
    for (const rendering::CameraSpec& spec : job.config.cameras) {
      for (const std::string& name : pictures_of(shot, spec.name)) {
        job.pictures.push_back(out_dir + "/" + name + ".png");
      }
    }
  }
  for (const std::string& picture : job.pictures) {
    core::check_output_file("--out", picture, overwrite);
  }
  return job;
}

// After a stop signal: what is kept. Returns the exit code.
int report_stop(const Job& job, size_t written) {
  const int signal = core::g_stop_signal;
  std::fprintf(stderr,
               "render_cameras: interrupted by %s after %zu of %zu pictures, written whole in %s; "
               "the others were not rendered (rerun with --overwrite to render them all)\n",
               core::stop_signal_name(signal), written, job.pictures.size(), job.out_dir.c_str());
  return core::stopped_exit_code(signal);
}

// Renders every shot's pictures, one whole file at a time, until done (0) or a stop signal comes
// (the exit code of report_stop). Throws core::Error when rendering or writing fails.
int render(const Job& job) {
  rendering::CameraRig rig(job.config);
  std::printf("renderer: %s\n", rig.renderer().device_name().c_str());
  rig.set_world(job.world, rendering::SceneStyle{});
  size_t written = 0;
  rendering::CameraFrame frame;
  for (const Shot& shot : shots()) {
    rendering::PeopleFigures figures(kAppearanceSeed);
    // Half a second so that speakers gesture (walkers have walked for kWalkedS).
    for (double t = 0.0; t <= kWalkedS; t += 0.05) {
      figures.update(t, shot.people);
    }
    rig.set_dynamic_mesh(figures.mesh());
    for (size_t i = 0; i < rig.cameras().size(); ++i) {
      const rendering::CameraSpec& spec = rig.cameras()[i];
      const std::vector<std::string> names = pictures_of(shot, spec.name);
      if (names.empty()) {
        continue;
      }
      if (core::g_stop_signal != 0) {
        return report_stop(job, written);
      }
      rig.render(i, rendering::X_world_optical(spec, shot.ari, shot.head_pan, shot.head_tilt),
                 frame);
      cv::Mat bgr;
      cv::cvtColor(frame.colour, bgr, cv::COLOR_RGB2BGR);
      write_png(job.out_dir + "/" + names.front() + ".png", bgr);
      ++written;
      if (shot.suffix.empty() && !frame.depth.empty()) {
        write_png(job.out_dir + "/camera_torso_depth.png", false_colour(frame.depth));
        ++written;
      }
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string world_path, out_dir;
  bool overwrite = false;
  Job job;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--help") {
        std::fputs(kUsage, stdout);
        return 0;
      }
      if (arg == "--overwrite") {
        overwrite = true;
      } else if (arg == "--world" || arg == "--out") {
        (arg == "--world" ? world_path : out_dir) = core::option_value(argc, argv, i);
      } else {
        throw core::ConfigError("unknown argument '" + arg + "'");
      }
    }
    if (world_path.empty() || out_dir.empty()) {
      throw core::ConfigError("--world and --out are required");
    }
    job = prepare(world_path, out_dir, overwrite);
  } catch (const core::ConfigError& error) {
    std::fprintf(stderr, "render_cameras: %s\n(see render_cameras --help)\n", error.what());
    return kUsageError;
  } catch (const core::Error& error) {
    std::fprintf(stderr, "render_cameras: %s\n", error.what());
    return 1;
  }
  core::install_stop_handler();
  try {
    return render(job);
  } catch (const core::Error& error) {
    // A picture that cannot be written (core::OutputFile's core::ConfigError) too: by now it is a
    // failure, not bad input.
    std::fprintf(stderr, "render_cameras: %s\n", error.what());
    return 1;
  }
}
