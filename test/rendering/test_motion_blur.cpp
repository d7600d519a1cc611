#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/rendering/frame_motion.hpp"
#include "ari_social_sim/rendering/motion_blur.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr uint16_t kPerson = 5;

// A 200 x 200 grey (60) image with a bright (200) 60 x 60 square labelled kPerson in the middle.
struct SquareScene {
  cv::Mat rgb{200, 200, CV_8UC3, cv::Scalar::all(60)};
  cv::Mat labels{200, 200, CV_16UC1, cv::Scalar(0)};
  SquareScene() {
    const cv::Rect square(70, 70, 60, 60);
    rgb(square).setTo(cv::Scalar::all(200));
    labels(square).setTo(cv::Scalar(kPerson));
  }
};

// Pixels along a row (or a column) strictly between the two levels of an edge: the edge's width.
int edge_width(const cv::Mat& rgb, int index, bool along_row) {
  int width = 0;
  for (int k = 0; k < 200; ++k) {
    const int value = along_row ? rgb.at<cv::Vec3b>(index, k)[1] : rgb.at<cv::Vec3b>(k, index)[1];
    width += value > 64 && value < 196 ? 1 : 0;
  }
  return width / 2;  // two edges, before and after the square
}

double light_above_background(const cv::Mat& rgb, int row) {
  double sum = 0.0;
  for (int u = 0; u < rgb.cols; ++u) {
    sum += rgb.at<cv::Vec3b>(row, u)[1] - 60.0;
  }
  return sum;
}

TEST(MotionBlur, APersonMovingSidewaysIsSmearedAlongTheMotionAlone) {
  SquareScene scene;
  const double light_before = light_above_background(scene.rgb, 100);
  ImageMotion motion;
  motion.labelled[kPerson] = Eigen::Vector2f(12.0f, 0.0f);
  apply_motion_blur(scene.rgb, scene.labels, motion);
  // A 12 px smear ramps each side edge over about 12 px; the top and bottom edges stay sharp.
  EXPECT_NEAR(edge_width(scene.rgb, 100, /*along_row=*/true), 11, 1);
  EXPECT_LE(edge_width(scene.rgb, 100, /*along_row=*/false), 1);
  // The person's light is spread, not lost or made: the row's sum above the background holds.
  EXPECT_NEAR(light_above_background(scene.rgb, 100), light_before, 0.02 * light_before);
  // Away from the person nothing changes.
  EXPECT_EQ(scene.rgb.at<cv::Vec3b>(100, 20)[1], 60);
  EXPECT_EQ(scene.rgb.at<cv::Vec3b>(20, 100)[1], 60);
}

TEST(MotionBlur, TheCamerasOwnMotionSmearsTheWholeFrame) {
  SquareScene scene;
  ImageMotion motion;
  motion.background = Eigen::Vector2f(0.0f, 8.0f);  // the camera tilting
  apply_motion_blur(scene.rgb, scene.labels, motion);
  EXPECT_NEAR(edge_width(scene.rgb, 100, /*along_row=*/false), 7, 1);
  EXPECT_LE(edge_width(scene.rgb, 100, /*along_row=*/true), 1);

  // A diagonal motion keeps its length: 8 px at 45 degrees ramps each axis over about 5.7 px.
  SquareScene diagonal;
  motion.background = Eigen::Vector2f(8.0f, 8.0f) / std::sqrt(2.0f);
  apply_motion_blur(diagonal.rgb, diagonal.labels, motion);
  EXPECT_NEAR(edge_width(diagonal.rgb, 100, /*along_row=*/true), 5, 1);
  EXPECT_NEAR(edge_width(diagonal.rgb, 100, /*along_row=*/false), 5, 1);
}

TEST(MotionBlur, MotionUnderAPixelLeavesTheImageAsItIs) {
  SquareScene scene;
  const cv::Mat before = scene.rgb.clone();
  ImageMotion motion;
  motion.background = Eigen::Vector2f(0.6f, 0.5f);
  motion.labelled[kPerson] = Eigen::Vector2f(0.9f, 0.0f);
  apply_motion_blur(scene.rgb, scene.labels, motion);
  EXPECT_EQ(cv::norm(scene.rgb, before, cv::NORM_INF), 0.0);
}

// A 1280 x 960 camera at the origin looking along optical z; frames at 30 Hz.
class FrameMotionTest : public ::testing::Test {
 protected:
  const PinholeModel pinhole = PinholeModel::from_horizontal_fov(1280, 960, 1.2);
  const double period_s = 1.0 / 30.0;
  FrameMotion motion;
};

TEST_F(FrameMotionTest, APersonWalkingAcrossMovesByTheirImageSpeed) {
  const Eigen::Isometry3d X_world_optical = Eigen::Isometry3d::Identity();
  // 1.5 m/s sideways, 3 m ahead: fx * 1.5 / 3 pixels per second.
  const auto centres_at = [](double t) {
    return std::map<uint16_t, Eigen::Vector3f>{{kPerson, Eigen::Vector3f(1.5f * t, 0.0f, 3.0f)}};
  };
  EXPECT_TRUE(motion.per_second(0.0, period_s, X_world_optical, pinhole, centres_at(0.0))
                  .labelled.empty());  // a first frame: nothing to compare with
  const ImageMotion second =
      motion.per_second(period_s, period_s, X_world_optical, pinhole, centres_at(period_s));
  ASSERT_EQ(second.labelled.count(kPerson), 1u);
  EXPECT_NEAR(second.labelled.at(kPerson).x(), pinhole.fx * 1.5 / 3.0, 1.0);
  EXPECT_NEAR(second.labelled.at(kPerson).y(), 0.0, 1e-3);
  EXPECT_LT(second.background.norm(), 1e-3);
  // A label that jumps 2 m in a period belongs to someone else now: no smear.
  EXPECT_TRUE(motion
                  .per_second(2 * period_s, period_s, X_world_optical, pinhole,
                              {{kPerson, Eigen::Vector3f(2.0f, 0.0f, 3.0f)}})
                  .labelled.empty());
  // After a gap of three periods the last frame is too old to tell a speed.
  EXPECT_TRUE(
      motion.per_second(4 * period_s, period_s, X_world_optical, pinhole, centres_at(4 * period_s))
          .labelled.empty());
}

TEST_F(FrameMotionTest, ACameraPanningMovesTheBackgroundTheOtherWay) {
  // Turning right (about optical y) at 1 rad/s: a far point moves left by about fx per second.
  const auto turned = [](double t) {
    return Eigen::Isometry3d(Eigen::AngleAxisd(1.0 * t, Eigen::Vector3d::UnitY()));
  };
  motion.per_second(0.0, period_s, turned(0.0), pinhole, {});
  const ImageMotion panning = motion.per_second(period_s, period_s, turned(period_s), pinhole, {});
  EXPECT_NEAR(panning.background.x(), -pinhole.fx * std::tan(period_s) / period_s, 1.0);
  EXPECT_NEAR(panning.background.y(), 0.0, 1e-3);
}

TEST(LabelCentres, EachLabelsVerticesAveraged) {
  RenderMesh mesh;
  const auto add_vertex = [&](const Eigen::Vector3f& p, float label) {
    std::vector<float> vertex(RenderMesh::kFloatsPerVertex, 0.0f);
    vertex[0] = p.x();
    vertex[1] = p.y();
    vertex[2] = p.z();
    vertex[RenderMesh::kLabelOffset] = label;
    mesh.vertices.insert(mesh.vertices.end(), vertex.begin(), vertex.end());
  };
  add_vertex({0, 0, 0}, 3);
  add_vertex({2, 0, 0}, 3);
  add_vertex({0, 4, 0}, 4);
  add_vertex({9, 9, 9}, 0);  // a wall: nobody
  const std::map<uint16_t, Eigen::Vector3f> centres = label_centres(mesh);
  ASSERT_EQ(centres.size(), 2u);
  EXPECT_TRUE(centres.at(3).isApprox(Eigen::Vector3f(1, 0, 0)));
  EXPECT_TRUE(centres.at(4).isApprox(Eigen::Vector3f(0, 4, 0)));
}

// Horizontal and vertical gradient energy (green channel, squared: a blurred edge keeps its total
// gradient but spreads it, so its squares fall) inside a box.
std::pair<double, double> gradient_energy(const cv::Mat& rgb, const cv::Rect& box) {
  cv::Mat green, dx, dy;
  cv::extractChannel(rgb(box), green, 1);
  cv::Sobel(green, dx, CV_32F, 1, 0);
  cv::Sobel(green, dy, CV_32F, 0, 1);
  return {cv::norm(dx, cv::NORM_L2SQR), cv::norm(dy, cv::NORM_L2SQR)};
}

// The head camera's two frames, 0.1 s apart, of a person crossing 2.5 m ahead at 1.5 m/s in the
// waiting room, with and without motion blur: the second frame's person is smeared sideways.
TEST(MotionBlur, TheRigSmearsAWalkerCrossingTheHeadCamerasView) {
  const model::WorldDescription world =
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml");
  const core::Pose2 ari{{9.5, 5.0}, M_PI / 2};
  std::array<CameraFrame, 2> last;  // without, with motion blur
  for (const bool blur : {false, true}) {
    CameraRigConfig config;
    config.effects.motion_blur = blur;
    CameraRig rig(config);
    rig.set_world(world, SceneStyle{});
    const Eigen::Isometry3d X_world_head = X_world_optical(rig.cameras()[0], ari, 0.0, 0.0);
    PeopleFigures figures;
    for (const double t : {0.0, 0.1}) {
      FigureInput walker;
      walker.traits.id = 1;
      walker.pose = {{9.3 + 1.5 * t, 7.5}, 0.0};  // walking east, across the view
      walker.face_yaw_rad = 0.0;
      figures.update(t, {walker});
      rig.set_dynamic_mesh(figures.mesh());
      ASSERT_EQ(rig.due(t), (std::vector<size_t>{0, 1}));
      rig.render(0, X_world_head, last[blur], /*labels=*/true);
    }
  }
  const cv::Rect box = cv::boundingRect(last[0].labels > 0);
  ASSERT_GT(box.area(), 5000);
  const auto [sharp_x, sharp_y] = gradient_energy(last[0].colour, box);
  const auto [blurred_x, blurred_y] = gradient_energy(last[1].colour, box);
  std::printf("person box %dx%d: gradient energy with blur / without: across %.2f, up %.2f\n",
              box.width, box.height, blurred_x / sharp_x, blurred_y / sharp_y);
  EXPECT_LT(blurred_x / sharp_x, 0.7);
  EXPECT_LT(blurred_x / sharp_x, 0.8 * (blurred_y / sharp_y));
}

// Nothing moves, the camera stands still: the frames are the same with motion blur on or off.
TEST(MotionBlur, AStillSceneIsTheSameWithMotionBlurOn) {
  const model::WorldDescription world =
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml");
  const core::Pose2 ari{{9.5, 5.0}, M_PI / 2};
  std::array<CameraFrame, 2> last;
  for (const bool blur : {false, true}) {
    CameraRigConfig config;
    config.effects.motion_blur = blur;
    CameraRig rig(config);
    rig.set_world(world, SceneStyle{});
    FigureInput person;
    person.traits.id = 2;
    person.pose = {{9.5, 7.5}, -M_PI / 2};
    person.face_yaw_rad = -M_PI / 2;
    PeopleFigures figures;
    for (const double t : {0.0, 0.1}) {
      figures.update(t, {person});
      rig.set_dynamic_mesh(figures.mesh());
      rig.due(t);
      rig.render(0, X_world_optical(rig.cameras()[0], ari, 0.0, 0.0), last[blur]);
    }
  }
  EXPECT_EQ(cv::norm(last[0].colour, last[1].colour, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace ari_social_sim::rendering
