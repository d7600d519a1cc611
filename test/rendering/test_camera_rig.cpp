#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"
#include "render_test_scenes.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr size_t kHead = 0;  // enabled cameras by default: head, then torso
constexpr size_t kTorso = 1;

model::WorldDescription waiting_room() {
  return model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml");
}

// Must-show 3: ARI faces the north wall of the waiting room (near face y = 8.95 m) from 1.5 m
// away; every torso depth pixel on the wall reads the distance along the optical axis to the point
// where its ray meets the wall plane, within 1 cm, in metres and in millimetres.
TEST(CameraRig, TorsoDepthShowsTheWallAtItsDistance) {
  for (const DepthEncoding encoding : {DepthEncoding::kMetres32F, DepthEncoding::kMillimetres16U}) {
    CameraRigConfig config;
    config.depth_encoding = encoding;
    CameraRig rig(config);
    ASSERT_EQ(rig.cameras()[kTorso].name, "torso_front_camera");
    rig.set_world(waiting_room(), SceneStyle{});
    rig.set_dynamic_mesh({});

    const core::Pose2 ari{{9.5, 8.95 - 1.5}, M_PI / 2};  // clear of the north table
    const Eigen::Isometry3d X_world_optical =
        rendering::X_world_optical(rig.cameras()[kTorso], ari, 0.0, 0.0);
    CameraFrame frame;
    rig.render(kTorso, X_world_optical, frame);
    ASSERT_EQ(frame.depth.cols, 848);
    ASSERT_EQ(frame.depth.rows, 480);
    ASSERT_EQ(frame.colour.size(), frame.depth.size());

    const CameraInfo& info = rig.info(kTorso);
    const PinholeModel model{info.width, info.height, info.K[0], info.K[4], info.K[2], info.K[5]};
    int wall_pixels = 0;
    double worst_error_m = 0.0;
    for (int v = 0; v < model.height; ++v) {
      for (int u = 0; u < model.width; ++u) {
        const Eigen::Vector3d ray = X_world_optical.linear() * model.ray(u, v);
        const Eigen::Vector3d origin = X_world_optical.translation();
        const double t = (8.95 - origin.y()) / ray.y();  // optical depth of the wall hit
        const double hit_z = origin.z() + t * ray.z();
        if (t <= 0.0 || hit_z < 0.01) {
          continue;  // the ray reaches the floor first
        }
        const double depth = encoding == DepthEncoding::kMetres32F
                                 ? frame.depth.at<float>(v, u)
                                 : 0.001 * frame.depth.at<uint16_t>(v, u);
        worst_error_m = std::max(worst_error_m, std::abs(depth - t));
        ++wall_pixels;
      }
    }
    std::printf("%s: %d wall pixels, worst depth error %.4f m\n", encoding_name(encoding),
                wall_pixels, worst_error_m);
    // The camera looks 42.5 deg down, so the wall fills the top of the image only.
    EXPECT_GT(wall_pixels, 30000);
    EXPECT_LT(worst_error_m, 0.01);
  }
}

// Must-show 3: a person 2.5 m ahead of the head camera, which is panned and tilted, appears where
// camera_info's K projects their head centre, within 3 pixels.
TEST(CameraRig, PersonInFrontOfAriAppearsWhereCameraInfoProjectsThem) {
  CameraRig rig(CameraRigConfig{});
  rig.set_world(waiting_room(), SceneStyle{});
  const core::Pose2 ari{{3.0, 2.5}, 0.2};
  const double pan = 0.35, tilt = 0.05;
  const Eigen::Isometry3d X_world_optical =
      rendering::X_world_optical(rig.cameras()[kHead], ari, pan, tilt);

  // The person stands 2.5 m out along the head's heading, 0.3 m to its right, facing ARI.
  const double heading = ari.theta + pan;
  const Eigen::Vector2d position = ari.position +
                                   2.5 * Eigen::Vector2d(std::cos(heading), std::sin(heading)) +
                                   0.3 * Eigen::Vector2d(std::sin(heading), -std::cos(heading));
  const Eigen::Vector2d to_ari = X_world_optical.translation().head<2>() - position;
  const double facing = std::atan2(to_ari.y(), to_ari.x());
  FigureInput person;
  person.pose = {position, facing};
  person.face_yaw_rad = facing;
  PeopleFigures figures;
  figures.update(0.0, {person});
  rig.set_dynamic_mesh(figures.mesh());

  CameraFrame frame;
  rig.render(kHead, X_world_optical, frame, /*labels=*/true);
  ASSERT_EQ(frame.colour.cols, 1280);
  ASSERT_TRUE(frame.depth.empty());

  // The face's pixels (labelled) centre where camera_info's K projects the face's middle (halfway
  // from the hairline to the chin).
  const PosedPerson& posed = figures.posed()[0];
  const cv::Moments face = cv::moments(frame.labels == posed.face_label, true);
  const CameraInfo& info = rig.info(kHead);
  const std::vector<Eigen::Vector3d>& outline = posed.figure->face_outline();
  const Eigen::Vector3d head_optical = X_world_optical.inverse() *
                                       posed.figure->head_frame(posed.pose) *
                                       (0.5 * (outline[0] + outline[1]));
  const double u = info.K[0] * head_optical.x() / head_optical.z() + info.K[2];
  const double v = info.K[4] * head_optical.y() / head_optical.z() + info.K[5];
  std::printf("face at (%.2f, %.2f) px, its middle projected (%.2f, %.2f) px, %.0f face pixels\n",
              face.m10 / face.m00, face.m01 / face.m00, u, v, face.m00);
  ASSERT_GT(face.m00, 1500);  // a 0.15 m wide face at 2.5 m: about 60 px across
  EXPECT_NEAR(face.m10 / face.m00, u, 4.0);
  EXPECT_NEAR(face.m01 / face.m00, v, 4.0);
}

TEST(CameraRig, FramesAreDueAtEachCamerasRate) {
  CameraRig rig(CameraRigConfig{});  // head 10 Hz, torso 15 Hz
  std::vector<int> frames(2, 0);
  for (int step = 0; step < 1000; ++step) {  // 1 s at 1 kHz
    for (const size_t i : rig.due(step * 0.001)) {
      ++frames[i];
    }
  }
  EXPECT_EQ(frames[kHead], 10);
  EXPECT_EQ(frames[kTorso], 15);
}

TEST(CameraRig, ARestartedScheduleGivesFrameZeroAgain) {
  CameraRig rig(CameraRigConfig{});
  rig.due(0.0);
  rig.due(7.3);
  // A new episode's clock: nothing due at 0 until the schedule restarts.
  EXPECT_TRUE(rig.due(0.0).empty());
  rig.restart(1);
  EXPECT_EQ(rig.due(0.0), (std::vector<size_t>{kHead, kTorso}));
  EXPECT_TRUE(rig.due(0.05).empty());
}

// An episode's images depend on its seed alone, not on what the rig rendered before: shards of a
// batch give the bytes of one process.
TEST(CameraRig, ARestartedRigRendersAnEpisodesFramesAgain) {
  const core::Pose2 ari{{9.5, 6.0}, M_PI / 2};
  auto head_frames = [&](CameraRig& rig) {
    std::vector<cv::Mat> frames;
    for (int k = 0; k < 2; ++k) {
      CameraFrame frame;
      rig.render(kHead, rendering::X_world_optical(rig.cameras()[kHead], ari, 0.1 * k, 0.0), frame);
      frames.push_back(frame.colour);
    }
    return frames;
  };
  CameraRig rig(CameraRigConfig{}, 1);
  CameraRig fresh(CameraRigConfig{}, 1);
  for (CameraRig* each : {&rig, &fresh}) {
    each->set_world(waiting_room(), SceneStyle{});
    each->set_dynamic_mesh({});
  }
  rig.restart(4);
  const std::vector<cv::Mat> first = head_frames(rig);
  head_frames(rig);  // the rest of that episode
  rig.restart(5);
  const std::vector<cv::Mat> other_seed = head_frames(rig);
  rig.restart(4);
  fresh.restart(4);
  for (const std::vector<cv::Mat>& again : {head_frames(rig), head_frames(fresh)}) {
    for (size_t k = 0; k < first.size(); ++k) {
      EXPECT_EQ(cv::norm(first[k], again[k], cv::NORM_INF), 0.0) << "frame " << k;
    }
  }
  EXPECT_GT(cv::norm(first[0], other_seed[0], cv::NORM_L1), 0.0);  // other noise
}

}  // namespace
}  // namespace ari_social_sim::rendering
