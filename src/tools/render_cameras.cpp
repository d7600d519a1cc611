// render_cameras: renders one image from each of ARI's cameras in a world with a few people, and
// writes them as PNG files (the pictures in docs/cameras.md). Depth is written false-coloured.

#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/physics/camera_rig.hpp"
#include "ari_social_sim/physics/people_figures.hpp"

namespace {

using namespace ari_social_sim;

constexpr int kUsageError = 2;
// Picks the people's looks; fixed so that the pictures stay the same from run to run.
constexpr uint64_t kAppearanceSeed = 1;

constexpr const char* kUsage = R"(Usage:
  render_cameras --world WORLD_YAML --out DIR [--overwrite]

Renders ARI's head camera, torso RGB-D camera (colour and depth), front and rear fisheyes and the
T265 fisheye pair once, with ARI at (6.0, 2.6) facing north-west in the world and five people
around it (one speaking, one in a mask, one walking), and writes DIR/camera_head.png, camera_torso_rgb.png, camera_torso_depth.png (0 to 5 m
false-coloured, black where invalid), camera_fisheye_front.png, camera_fisheye_rear.png,
camera_t265_fisheye1.png and camera_t265_fisheye2.png. DIR is created when missing; pictures
already there are replaced only with --overwrite (checked before rendering).

Exit status: 0 on success, 2 on bad arguments, an unreadable world or an output folder that
cannot be written, 1 when rendering or writing a picture fails.
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
          static_cast<uint8_t>(std::clamp(d / 5.0f, 0.0f, 1.0f) * 255.0f + 0.5f);
    }
  }
  cv::Mat coloured;
  cv::applyColorMap(scaled, coloured, cv::COLORMAP_TURBO);
  coloured.setTo(cv::Scalar(0, 0, 0), invalid);
  return coloured;
}

void write_png(const std::string& path, const cv::Mat& bgr) {
  bool written = false;
  try {
    written = cv::imwrite(path, bgr);
  } catch (const cv::Exception& e) {
    throw core::Error(path + ": cannot write the picture: " + e.what());
  }
  if (!written) {
    throw core::Error(path + ": cannot write the picture");
  }
  std::printf("wrote %s (%dx%d)\n", path.c_str(), bgr.cols, bgr.rows);
}

int run(const std::string& world_path, const std::string& out_dir, bool overwrite) {
  core::check_input_file("--world", world_path);
  const model::WorldDescription world = model::load_world_file(world_path);
  physics::CameraRigConfig config;
  for (physics::CameraSpec& spec : config.cameras) {
    spec.enabled = true;
  }
  // Every picture's place is checked before the renderer starts.
  core::prepare_output_directory("--out", out_dir);
  std::vector<std::string> pictures{out_dir + "/camera_torso_depth.png"};
  for (const physics::CameraSpec& spec : config.cameras) {
    pictures.push_back(out_dir + "/" + picture_name(spec.name) + ".png");
  }
  for (const std::string& picture : pictures) {
    core::check_output_file("--out", picture, overwrite);
  }
  physics::CameraRig rig(config);
  std::printf("renderer: %s\n", rig.renderer().device_name().c_str());
  const physics::SceneStyle style;
  rig.set_world(world, style);

  // ARI faces north-west towards the middle rows of chairs; two people talk in front of it (one
  // speaking, one in a mask), one walks past on its left and two wait nearby.
  const core::Pose2 ari{{6.0, 2.6}, 2.0};
  const double head_pan = 0.15, head_tilt = 0.05;
  std::vector<physics::FigureInput> people;
  auto add = [&](uint32_t id, double age, model::Gender gender, bool mask,
                 const core::Pose2& pose, double face_yaw, const Eigen::Vector2d& velocity,
                 bool speaking) {
    physics::FigureInput person;
    person.traits = {id, age, gender, mask};
    person.pose = pose;
    person.face_yaw_rad = face_yaw;
    person.velocity_mps = velocity;
    person.speaking = speaking;
    people.push_back(person);
  };
  const Eigen::Vector2d standing = Eigen::Vector2d::Zero();
  add(1, 34, model::Gender::kFemale, false, {{5.1, 4.2}, -0.9}, -1.1, standing, true);
  add(2, 61, model::Gender::kMale, true, {{4.5, 3.7}, 0.2}, 0.5, standing, false);
  add(3, 27, model::Gender::kMale, false, {{4.3, 2.0}, 1.6}, 1.6, {0.0, 1.2}, false);
  add(4, 45, model::Gender::kFemale, false, {{7.2, 0.9}, 2.3}, 2.5, standing, false);
  add(5, 9, model::Gender::kMale, false, {{6.9, 3.4}, -2.0}, -2.2, standing, false);
  physics::PeopleFigures figures(kAppearanceSeed);
  // Half a second of walking so that the walker is mid-stride.
  for (double t = 0.0; t <= 0.5; t += 0.05) {
    figures.update(t, people);
  }
  rig.set_dynamic_mesh(figures.mesh());

  physics::CameraFrame frame;
  for (size_t i = 0; i < rig.cameras().size(); ++i) {
    const physics::CameraSpec& spec = rig.cameras()[i];
    rig.render(i, physics::X_world_optical(spec, ari, head_pan, head_tilt), frame);
    cv::Mat bgr;
    cv::cvtColor(frame.colour, bgr, cv::COLOR_RGB2BGR);
    write_png(out_dir + "/" + picture_name(spec.name) + ".png", bgr);
    if (!frame.depth.empty()) {
      write_png(out_dir + "/camera_torso_depth.png", false_colour(frame.depth));
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string world_path, out_dir;
  bool overwrite = false;
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
    return run(world_path, out_dir, overwrite);
  } catch (const core::ConfigError& error) {
    std::fprintf(stderr, "render_cameras: %s\n(see render_cameras --help)\n", error.what());
    return kUsageError;
  } catch (const core::Error& error) {
    std::fprintf(stderr, "render_cameras: %s\n", error.what());
    return 1;
  }
}
