// The frontal face cascades on lone heads turned from the camera (docs/detector_study_log.md, "Eyes
// and nose bridge toned down"): a quicker measure of a change to the faces than detector_study,
// whose turned heads come few to a frame. Each of the first N people of PeopleFigures stands alone
// in a world (by default the 6 x 6 m room, with walls, ceiling and lamps), `distance` east of a
// level 1280 x 960 camera of 62.2 degrees at the height of their head, with the default camera
// effects, and turns their face from it by each of the turns; odd people's faces look to the
// image's right, even people's to its left (the cascades are not symmetric: the default one fires
// more on faces looking to the image's left). Each cascade runs on the 600 x 600 pixels round the
// head, on the image as it is and after equalizeHist of the whole frame, as detector_study runs it.
// Prints a Markdown table of the views with a window at each turn.
//
// usage: lone_heads [--people N] [--distances a,b,...] [--turns a,b,...] [--world FILE]
//                   [--camera X,Y] [--seed N] [--views DIR]
//   --people: people 1 to N (default 48)
//   --distances: metres from the camera (default 1.0,1.5,2.0), each in [0.5, 5]
//   --turns: degrees from facing the camera (default 20,25,30,40,45,48,51,54,57,65,75), each in
//            [0, 180]
//   --world: a world file (default the package's worlds/room_6x6.yaml)
//   --camera: where the camera stands in the world's map frame, looking east (default 1,3: the
//             middle of room_6x6's west side)
//   --seed: the camera noise's seed (default 1); every view is exposed as the first frame of it
//   --views: write a crop of each view turned 45 degrees or more on which the default cascade
//            fires, its window drawn, into DIR (created when missing)

#include <cstdio>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../test/common/detector_scoring.hpp"
#include "../test/rendering/render_test_scenes.hpp"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/camera_sensor.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"
#include "ari_social_sim/rendering/renderer.hpp"
#include "ari_social_sim/rendering/world_scene.hpp"

namespace {

using namespace ari_social_sim;
using namespace ari_social_sim::rendering;

constexpr int kWidth = 1280, kHeight = 960;
constexpr double kHorizontalFovDeg = 62.2;
// The head's region: the image's middle, where a head 1 to 2 m away is whole.
const cv::Rect kHeadRegion(340, 180, 600, 600);
constexpr double kTurnedFromDeg = 45.0;  // the views --views keeps, and the table's last column

struct Options {
  int people{48};
  std::vector<double> distances_m{1.0, 1.5, 2.0};
  std::vector<double> turns_deg{20, 25, 30, 40, 45, 48, 51, 54, 57, 65, 75};
  std::string world{std::string(ARI_SOURCE_DIR) + "/worlds/room_6x6.yaml"};
  Eigen::Vector2d camera{1.0, 3.0};
  uint64_t seed{1};
  std::string views_dir;  // empty: no crops
};

const core::IntegerOption kPeople{"--people", 1, 10000};
const core::IntegerOption kSeed{"--seed", 0, 1000000000};
const core::NumberOption kDistance{"--distances", core::between(0.5, 5.0)};
const core::NumberOption kTurn{"--turns", core::between(0.0, 180.0)};
const core::NumberOption kCameraCoordinate{"--camera", core::between(-1000.0, 1000.0)};

std::vector<double> numbers(const core::NumberOption& option, const std::string& text) {
  std::vector<double> values;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    values.push_back(option.parse(item));
  }
  if (values.empty()) {
    throw core::ConfigError(std::string(option.name) + ": expected a comma-separated list");
  }
  return values;
}

// Throws core::ConfigError naming the option and what it expects.
Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    core::check_known_option(
        option, {"--people", "--distances", "--turns", "--world", "--camera", "--seed", "--views"});
    const std::string value = core::option_value(argc, argv, i);
    if (option == "--people") {
      options.people = static_cast<int>(kPeople.parse(value));
    } else if (option == "--distances") {
      options.distances_m = numbers(kDistance, value);
    } else if (option == "--turns") {
      options.turns_deg = numbers(kTurn, value);
    } else if (option == "--world") {
      core::check_input_file("--world", value);
      options.world = value;
    } else if (option == "--camera") {
      const std::vector<double> xy = numbers(kCameraCoordinate, value);
      if (xy.size() != 2) {
        throw core::ConfigError("--camera: expected X,Y, got '" + value + "'");
      }
      options.camera = {xy[0], xy[1]};
    } else if (option == "--seed") {
      options.seed = static_cast<uint64_t>(kSeed.parse(value));
    } else {
      core::prepare_output_directory("--views", value);
      options.views_dir = value;
    }
  }
  return options;
}

// The four counts of views with a window, at each turn.
struct Counts {
  static constexpr int kRows = 4;
  static constexpr const char* kNames[kRows] = {"alt2", "default", "alt2, equalizeHist",
                                                "default, equalizeHist"};
  std::vector<std::vector<int>> views;  // [row][turn]

  explicit Counts(size_t turns) : views(kRows, std::vector<int>(turns, 0)) {}
};

// One person turned `turn_deg` from the camera, `distance_m` away, posed alone.
RenderMesh lone_person(int id, double distance_m, double turn_deg, const Options& options,
                       double& head_z) {
  const double side = id % 2 == 1 ? 1.0 : -1.0;  // +1: the face turns to the camera's right
  const double facing_camera = M_PI;
  FigureInput input;
  input.traits.id = static_cast<uint32_t>(id);
  input.pose = {options.camera + Eigen::Vector2d(distance_m, 0.0),
                facing_camera + side * turn_deg * M_PI / 180.0};
  input.face_yaw_rad = input.pose.theta;
  PeopleFigures figures;
  figures.update(0.0, {input});
  PosedPerson person = figures.posed()[0];
  person.pose.weight_side = 0.0;  // upright: the head level with the camera
  RenderMesh mesh;
  person.figure->append_posed(person.pose, person.body_label, person.face_label, mesh);
  head_z = person.figure->head_frame(person.pose).translation().z();
  return mesh;
}

void save_view(const cv::Mat& rgb, const cv::Rect& window, const std::string& path) {
  const cv::Rect around = cv::Rect(window.x - window.width / 4, window.y - window.height / 4,
                                   window.width * 3 / 2, window.height * 3 / 2) &
                          cv::Rect(0, 0, rgb.cols, rgb.rows);
  cv::Mat crop;
  cv::cvtColor(rgb(around), crop, cv::COLOR_RGB2BGR);
  cv::rectangle(crop, window - around.tl(), {0, 0, 255}, 1);
  if (!cv::imwrite(path, crop)) {
    std::fprintf(stderr, "lone_heads: cannot write %s\n", path.c_str());
    std::exit(1);
  }
}

class LoneHeads {
 public:
  explicit LoneHeads(const Options& options)
      : options_(options),
        sensor_(CameraEffects(), kWidth, kHeight, kHorizontalFovDeg * M_PI / 180.0, options.seed,
                0),
        model_(
            PinholeModel::from_horizontal_fov(kWidth, kHeight, kHorizontalFovDeg * M_PI / 180.0)),
        alt2_(detector_scoring::kFrontalAlt2Cascade),
        default_(detector_scoring::kFrontalDefaultCascade) {
    if (alt2_.empty() || default_.empty()) {
      throw core::ConfigError("the OpenCV face cascades (opencv-data) are not installed");
    }
    renderer_.set_static_primitives(
        static_primitives_of(model::load_world_file(options.world), SceneStyle()));
  }

  Counts run() {
    Counts counts(options_.turns_deg.size());
    for (int id = 1; id <= options_.people; ++id) {
      for (double distance_m : options_.distances_m) {
        for (size_t t = 0; t < options_.turns_deg.size(); ++t) {
          view(id, distance_m, t, counts);
        }
      }
    }
    return counts;
  }

 private:
  void view(int id, double distance_m, size_t t, Counts& counts) {
    const double turn_deg = options_.turns_deg[t];
    double head_z = 0.0;
    renderer_.set_dynamic_mesh(lone_person(id, distance_m, turn_deg, options_, head_z));
    renderer_.render(
        model_, test::level_camera_facing_x({options_.camera.x(), options_.camera.y(), head_z}),
        ViewOptions(), image_);
    sensor_.restart(options_.seed);
    sensor_.expose(image_.colour);
    cv::Mat grey, equalised;
    cv::cvtColor(image_.colour, grey, cv::COLOR_RGB2GRAY);
    cv::equalizeHist(grey, equalised);
    const cv::Mat region = grey(kHeadRegion).clone();
    const cv::Mat equalised_region = equalised(kHeadRegion).clone();
    const std::vector<cv::Rect> default_windows = detector_scoring::cascade_faces(default_, region);
    counts.views[0][t] += !detector_scoring::cascade_faces(alt2_, region).empty();
    counts.views[1][t] += !default_windows.empty();
    counts.views[2][t] += !detector_scoring::cascade_faces(alt2_, equalised_region).empty();
    counts.views[3][t] += !detector_scoring::cascade_faces(default_, equalised_region).empty();
    if (!options_.views_dir.empty() && turn_deg >= kTurnedFromDeg && !default_windows.empty()) {
      char name[96];
      std::snprintf(name, sizeof name, "/person%02d_%.1fm_turn%02.0f.png", id, distance_m,
                    turn_deg);
      save_view(image_.colour(kHeadRegion), default_windows[0], options_.views_dir + name);
    }
  }

  const Options& options_;
  CameraSensor sensor_;
  PinholeModel model_;
  Renderer renderer_;
  RenderedImage image_;
  cv::CascadeClassifier alt2_, default_;
};

void print(const Counts& counts, const Options& options) {
  const size_t views = static_cast<size_t>(options.people) * options.distances_m.size();
  std::printf("%zu views at each turn (%d people at %zu distances)\n\n| cascade |", views,
              options.people, options.distances_m.size());
  for (double turn : options.turns_deg) {
    std::printf(" %.0f |", turn);
  }
  std::printf(" turned %.0f or more |\n|---|", kTurnedFromDeg);
  for (size_t t = 0; t <= options.turns_deg.size(); ++t) {
    std::printf("---:|");
  }
  std::printf("\n");
  for (int row = 0; row < Counts::kRows; ++row) {
    std::printf("| %s |", Counts::kNames[row]);
    int turned = 0;
    for (size_t t = 0; t < options.turns_deg.size(); ++t) {
      std::printf(" %d |", counts.views[row][t]);
      turned += options.turns_deg[t] >= kTurnedFromDeg ? counts.views[row][t] : 0;
    }
    std::printf(" %d |\n", turned);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parse(argc, argv);
    LoneHeads heads(options);
    print(heads.run(), options);
  } catch (const core::ConfigError& error) {
    std::fprintf(stderr,
                 "lone_heads: %s\nusage: lone_heads [--people N] [--distances a,b,...] "
                 "[--turns a,b,...] [--world FILE] [--camera X,Y] [--seed N] [--views DIR]\n",
                 error.what());
    return 2;
  }
  return 0;
}
