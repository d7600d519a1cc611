// Stock OpenCV detectors on the head camera's images, scored against the images' labels
// (docs/cameras.md, "People in the images"): HOG people detection (Dalal and Triggs' detector,
// HOGDescriptor::getDefaultPeopleDetector) and the Haar frontal-face cascade of Debian's
// opencv-data. Each study renders seeded frames of people placed at random in front of ARI in the
// waiting room and prints detection rates by distance, yaw and occlusion.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>
#include <string>
#include <vector>

#include "../common/detector_scoring.hpp"
#include "../tools/program_run.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/ari_cameras.hpp"
#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/rendering/image_labels.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"

namespace ari_social_sim::rendering {
namespace {

using namespace detector_scoring;

constexpr const char* kFaceCascade = kFrontalAlt2Cascade;
// HOG runs on the head camera's image scaled by this, so that people 2 to 6 m away are 105 to 315
// pixels tall and the renderer's hard edges are averaged away (INTER_AREA). Measured with the
// window stride below: 0.3, 0.35 and 0.5 found 87.9, 89.3 and 85.0 % of an earlier figure
// (docs/cameras.md).
constexpr double kHogScale = 0.35;

// One rendered head camera frame with its labels.
struct LabelledFrame {
  cv::Mat grey;
  std::vector<PersonLabel> labels;
};

// Renders the head camera (1280 x 960, ARI's default) from a random free spot of the waiting room.
class StudyScenes {
 public:
  StudyScenes() : rig_(head_only()) {
    rig_.set_world(
        model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml"),
        SceneStyle{});
  }

  struct Layout {
    int people{1};
    double min_m{1.0}, max_m{6.0};  // distance from the camera
    double facing_rad{0.0};         // 0: turned to the camera, pi: their backs to it
    double max_turn_rad{0.0};       // around facing_rad, drawn uniformly
    double tilt_rad{0.0};           // of ARI's head (head_2_joint); positive looks down
  };

  // People at random distances in the layout's range, within the image's width, turned as the
  // layout says (body and head), a third of them walking.
  LabelledFrame frame(uint64_t seed, const Layout& layout) {
    core::Rng rng(seed);
    const core::Pose2 ari{{rng.uniform(1.5, 10.5), rng.uniform(1.5, 7.5)},
                          rng.uniform(-M_PI, M_PI)};
    const Eigen::Isometry3d X_world_optical =
        rendering::X_world_optical(rig_.cameras()[0], ari, 0.0, layout.tilt_rad);
    const Eigen::Vector2d camera = X_world_optical.translation().head<2>();
    const double half_fov = 0.5 * rig_.cameras()[0].hfov_rad;
    std::vector<FigureInput> people;
    for (int i = 0; i < layout.people; ++i) {
      const double distance = rng.uniform(layout.min_m, layout.max_m);
      const double bearing = ari.theta + rng.uniform(-0.8, 0.8) * half_fov;
      FigureInput person;
      person.traits.id = static_cast<uint32_t>(seed * 8 + i);
      person.traits.age_years =
          rng.bernoulli(0.1) ? rng.uniform(6.0, 16.0) : rng.uniform(18.0, 85.0);
      person.traits.gender = rng.bernoulli(0.5) ? model::Gender::kFemale : model::Gender::kMale;
      person.traits.mask = rng.bernoulli(0.15);
      person.pose.position =
          camera + distance * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
      const double towards_camera =
          std::atan2(camera.y() - person.pose.position.y(), camera.x() - person.pose.position.x());
      person.pose.theta = towards_camera + layout.facing_rad +
                          rng.uniform(-layout.max_turn_rad, layout.max_turn_rad);
      person.face_yaw_rad = person.pose.theta + rng.uniform(-0.2, 0.2);
      if (rng.bernoulli(0.3)) {
        const double speed = rng.uniform(0.5, 1.4);
        person.velocity_mps =
            speed * Eigen::Vector2d(std::cos(person.pose.theta), std::sin(person.pose.theta));
      }
      people.push_back(person);
    }
    // A random moment of the gait: the figures are posed after a random walk time.
    figures_ = PeopleFigures(seed);
    const double walked_s = rng.uniform(0.0, 1.5);
    figures_.update(0.0, people);
    for (FigureInput& person : people) {
      person.walked_m = walked_s * person.velocity_mps.norm();
    }
    figures_.update(walked_s, people);
    rig_.set_dynamic_mesh(figures_.mesh());
    CameraFrame image;
    rig_.render(0, X_world_optical, image, /*labels=*/true);
    LabelledFrame out;
    cv::cvtColor(image.colour, out.grey, cv::COLOR_RGB2GRAY);
    out.labels =
        label_people(rig_.renderer(), rig_.pinhole(0), X_world_optical, figures_, image.labels);
    return out;
  }

 private:
  static CameraRigConfig head_only() {
    CameraRigConfig config;
    for (CameraSpec& spec : config.cameras) {
      spec.enabled = spec.name == "head_front_camera";
    }
    return config;
  }

  CameraRig rig_;
  PeopleFigures figures_;
};

TEST(DetectorStudy, HogFindsUprightFullyVisiblePeopleTwoToSixMetresAway) {
  StudyScenes scenes;
  cv::HOGDescriptor hog;
  hog.setSVMDetector(cv::HOGDescriptor::getDefaultPeopleDetector());
  RateTable by_distance("distance (m)", {1.5, 2, 3, 4, 5, 6, 7});
  RateTable by_occlusion("occlusion", {0.0, 0.01, 0.25, 0.5, 0.75, 1.01});
  int frames = 0, eligible = 0, found = 0;
  for (uint64_t seed = 1; frames < 300; ++seed) {
    StudyScenes::Layout layout;
    layout.people = 1 + static_cast<int>(seed % 3);
    layout.min_m = 1.5;
    layout.max_m = 7.0;
    layout.max_turn_rad = M_PI;
    layout.tilt_rad = 0.1 + 0.05 * static_cast<double>(seed % 4);
    const LabelledFrame frame = scenes.frame(seed, layout);
    ++frames;
    // HOG on the image at kHogScale: people 2 to 6 m away are 90 to 270 pixels tall there.
    cv::Mat small;
    cv::resize(frame.grey, small, cv::Size(), kHogScale, kHogScale, cv::INTER_AREA);
    std::vector<cv::Rect> windows;
    // A 4-pixel window stride (OpenCV's sample uses 8) puts more windows on each person, so that
    // more reach the grouping's threshold; padding 32 as in the sample.
    hog.detectMultiScale(small, windows, 0.0, cv::Size(4, 4), cv::Size(32, 32), 1.05, 2.0);
    for (const PersonLabel& label : frame.labels) {
      bool hit = false;
      for (const cv::Rect& window : windows) {
        const cv::Rect full(
            cv::Point(cvRound(window.x / kHogScale), cvRound(window.y / kHogScale)),
            cv::Size(cvRound(window.width / kHogScale), cvRound(window.height / kHogScale)));
        hit = hit || person_in_hog_window(full).iou(label.body_box) >= kMatchIou;
      }
      if (label.occlusion < 0.01 && !label.truncated) {
        by_distance.add(label.distance_m, hit);
      }
      if (!label.truncated && label.distance_m >= 2.0 && label.distance_m <= 6.0) {
        by_occlusion.add(label.occlusion, hit);
      }
      if (label.occlusion < 0.01 && !label.truncated && label.distance_m >= 2.0 &&
          label.distance_m <= 6.0) {
        ++eligible;
        found += hit ? 1 : 0;
      }
    }
  }
  by_distance.print("HOG");
  by_occlusion.print("HOG");
  const double rate = eligible > 0 ? double(found) / eligible : 0.0;
  std::printf("HOG: %d of %d fully visible people 2-6 m found (%.1f %%) in %d frames\n", found,
              eligible, 100.0 * rate, frames);
  EXPECT_GE(eligible, 100);
  EXPECT_GE(rate, 0.85);
}

TEST(DetectorStudy, HaarFindsFacesTurnedToTheCameraAndFiresRarelyWithoutThem) {
  StudyScenes scenes;
  cv::CascadeClassifier cascade;
  ASSERT_TRUE(cascade.load(kFaceCascade)) << kFaceCascade << " (Debian's opencv-data)";
  RateTable by_distance("distance (m)", {0.8, 1.2, 1.6, 2.0, 2.5, 3.0, 4.0});
  RateTable by_yaw("face yaw (deg)", {0, 10, 25, 40, 60, 90});
  int eligible = 0, found = 0, frames = 0, masked = 0, masked_found = 0;
  for (uint64_t seed = 1000; frames < 240; ++seed, ++frames) {
    StudyScenes::Layout layout;
    layout.people = 1 + static_cast<int>(seed % 2);
    layout.min_m = 0.8;
    layout.max_m = 4.0;
    layout.max_turn_rad = 0.9;
    const LabelledFrame frame = scenes.frame(seed, layout);
    std::vector<cv::Rect> faces;
    cascade.detectMultiScale(frame.grey, faces, 1.1, 3, 0, cv::Size(24, 24));
    for (const PersonLabel& label : frame.labels) {
      if (!label.face_box) {
        continue;
      }
      bool hit = false;
      for (const cv::Rect& face : faces) {
        hit = hit || box_of(face).iou(*label.face_box) >= kMatchIou;
      }
      if (label.face_yaw_deg <= 25.0) {
        by_distance.add(label.distance_m, hit);
      }
      if (label.distance_m >= 0.8 && label.distance_m <= 3.0) {
        by_yaw.add(label.face_yaw_deg, hit);
      }
      if (label.face_yaw_deg <= 25.0 && label.distance_m >= 0.8 && label.distance_m <= 3.0) {
        ++eligible;
        found += hit ? 1 : 0;
        masked += label.mask ? 1 : 0;
        masked_found += label.mask && hit ? 1 : 0;
      }
    }
  }
  by_distance.print("Haar");
  by_yaw.print("Haar");
  const double rate = eligible > 0 ? double(found) / eligible : 0.0;
  const double unmasked_rate = double(found - masked_found) / std::max(1, eligible - masked);
  std::printf(
      "Haar: %d of %d faces within 25 deg, 0.8-3 m found (%.1f %%) in %d frames; "
      "masked: %d of %d; without a mask %.1f %%\n",
      found, eligible, 100.0 * rate, frames, masked_found, masked, 100.0 * unmasked_rate);
  // The cascade misses nearly every masked face, as it misses real ones (it was trained on faces
  // without masks): 85 % holds for faces without a mask, and the floor of all faces is what the
  // figures reach with a mask on one person in seven (docs/cameras.md).
  EXPECT_GE(eligible, 100);
  EXPECT_GE(unmasked_rate, 0.85);
  EXPECT_GE(rate, 0.7);

  // Frames without a face: people seen from behind or from the side, and empty views of the
  // room; every detection is false.
  int false_detections = 0, empty_frames = 0;
  for (uint64_t seed = 5000; empty_frames < 200; ++seed, ++empty_frames) {
    StudyScenes::Layout layout;
    layout.people = static_cast<int>(seed % 3);
    layout.facing_rad = M_PI;
    layout.max_turn_rad = 0.9;
    const LabelledFrame frame = scenes.frame(seed, layout);
    std::vector<cv::Rect> faces;
    cascade.detectMultiScale(frame.grey, faces, 1.1, 3, 0, cv::Size(24, 24));
    false_detections += static_cast<int>(faces.size());
  }
  std::printf("Haar: %d false detections in %d frames without a face (%.3f per image)\n",
              false_detections, empty_frames, double(false_detections) / empty_frames);
  EXPECT_LE(double(false_detections) / empty_frames, 0.05);
}

// Heads turned 30 to 110 degrees from the camera (body turn; the gaze adds up to 0.2 rad), 0.8 to
// 3 m away: the profile cascade should find the turned faces, the frontal one should not fire on
// them.
TEST(DetectorStudy, ProfileCascadeFindsTurnedFacesAndTheFrontalOneDoesNot) {
  StudyScenes scenes;
  cv::CascadeClassifier frontal, profile;
  ASSERT_TRUE(frontal.load(kFaceCascade)) << kFaceCascade << " (Debian's opencv-data)";
  ASSERT_TRUE(profile.load(kProfileCascade)) << kProfileCascade << " (Debian's opencv-data)";
  RateTable profile_by_yaw("face yaw (deg)", {0, 25, 40, 60, 75, 90});
  RateTable centred_by_yaw("face yaw (deg)", {0, 25, 40, 60, 75, 90});
  RateTable frontal_by_yaw("face yaw (deg)", {0, 25, 40, 60, 75, 90});
  int eligible = 0, found = 0, found_centred = 0, frames = 0;
  int turned_frames = 0, frontal_on_turned = 0;
  for (uint64_t seed = 9000; frames < 300; ++seed, ++frames) {
    StudyScenes::Layout layout;
    layout.people = 1 + static_cast<int>(seed % 2);
    layout.min_m = 0.8;
    layout.max_m = 3.0;
    layout.facing_rad = (seed % 4 < 2 ? 1.0 : -1.0) * 70.0 * M_PI / 180.0;
    layout.max_turn_rad = 40.0 * M_PI / 180.0;
    const LabelledFrame frame = scenes.frame(seed, layout);
    const std::vector<cv::Rect> profiles = profile_faces(profile, frame.grey);
    std::vector<cv::Rect> frontals;
    frontal.detectMultiScale(frame.grey, frontals, 1.1, 3, 0, cv::Size(24, 24));
    bool all_turned = true;
    for (const PersonLabel& label : frame.labels) {
      all_turned = all_turned && label.face_yaw_deg > 45.0;
      if (!label.face_box || label.distance_m > 3.0) {
        continue;
      }
      auto hit_by = [&label](const std::vector<cv::Rect>& faces) {
        return std::any_of(faces.begin(), faces.end(), [&label](const cv::Rect& face) {
          return box_of(face).iou(*label.face_box) >= kMatchIou;
        });
      };
      const bool profile_hit = hit_by(profiles);
      const bool centred_hit =
          std::any_of(profiles.begin(), profiles.end(),
                      [&label](const cv::Rect& face) { return centred_on(face, *label.face_box); });
      profile_by_yaw.add(label.face_yaw_deg, profile_hit);
      centred_by_yaw.add(label.face_yaw_deg, centred_hit);
      frontal_by_yaw.add(label.face_yaw_deg, hit_by(frontals));
      if (label.face_yaw_deg >= 60.0 && !label.mask) {
        ++eligible;
        found += profile_hit ? 1 : 0;
        found_centred += centred_hit ? 1 : 0;
      }
    }
    if (all_turned) {
      ++turned_frames;
      frontal_on_turned += detections_on_people(frontals, frame.labels);
    }
  }
  profile_by_yaw.print("Haar profile, IoU >= 0.5");
  centred_by_yaw.print("Haar profile, centred");
  frontal_by_yaw.print("Haar frontal, IoU >= 0.5");
  const double recall = double(found) / std::max(1, eligible);
  const double centred_recall = double(found_centred) / std::max(1, eligible);
  const double false_rate = double(frontal_on_turned) / std::max(1, turned_frames);
  std::printf(
      "Haar profile: of %d faces without a mask turned 60-90 deg, 0.8-3 m, in %d frames: %d found "
      "with IoU >= 0.5 (%.1f %%), %d centred (%.1f %%)\nHaar frontal: %d detections in %d frames "
      "whose faces all turn more than 45 deg (%.3f per frame)\n",
      eligible, frames, found, 100.0 * recall, found_centred, 100.0 * centred_recall,
      frontal_on_turned, turned_frames, false_rate);
  // What the figures reach (docs/cameras.md: 45.9 % with IoU >= 0.5, 67.4 % centred, 0.014
  // frontal detections per frame); the aims, which they must keep: 60 % of the turned faces
  // (centred) and at most 0.02 frontal detections per frame.
  EXPECT_GE(eligible, 100);
  EXPECT_GE(recall, 0.39);
  EXPECT_GE(centred_recall, 0.60);
  EXPECT_LE(false_rate, 0.02);
}

}  // namespace
}  // namespace ari_social_sim::rendering

// The study over the shipped scenarios (bench/detector_study) and the lone heads' probe
// (bench/lone_heads) refuse bad options before they render anything, naming the option and what
// it expects.
TEST(DetectorStudy, TheStudyProgramsRefuseBadOptions) {
  struct Refusal {
    const char* program;
    const char* arguments;
    const char* message;
  };
  const Refusal refusals[] = {
      {ARI_DETECTOR_STUDY_BIN, "--misses /nonexistent/crops",
       "--misses: expected an existing directory, got '/nonexistent/crops'"},
      {ARI_DETECTOR_STUDY_BIN, "--frames 0",
       "--frames: expected a finite number in [1, 100000], got '0'"},
      {ARI_DETECTOR_STUDY_BIN, "--misses", "--misses"},
      {ARI_DETECTOR_STUDY_BIN, "--shots 3", "unknown option '--shots'"},
      {ARI_LONE_HEADS_BIN, "--people 0", "--people: expected an integer in [1, 10000], got '0'"},
      {ARI_LONE_HEADS_BIN, "--turns 20,x",
       "--turns: expected a finite number in [0, 180], got 'x'"},
      {ARI_LONE_HEADS_BIN, "--distances 9",
       "--distances: expected a finite number in [0.5, 5], got '9'"},
      {ARI_LONE_HEADS_BIN, "--camera 1", "--camera: expected X,Y, got '1'"},
      {ARI_LONE_HEADS_BIN, "--world /nonexistent/world.yaml", "--world"},
      {ARI_LONE_HEADS_BIN, "--views", "--views"},
      {ARI_LONE_HEADS_BIN, "--shots 3", "--shots: unknown option"},
  };
  for (const Refusal& refusal : refusals) {
    SCOPED_TRACE(std::string(refusal.program) + " " + refusal.arguments);
    ari_social_sim::tools::test::expect_refused(
        ari_social_sim::tools::test::run_program(refusal.program, refusal.arguments),
        refusal.message);
  }
}
