// people_crops: the REP-155 face and body images of posed people, cut where their boxes are.

#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/rendering/people_crops.hpp"
#include "render_test_scenes.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr int kFaceSize = 128;  // hri_face_detect's default

// ARI's head camera size, level at 1.4 m at the origin, looking along +x.
const PinholeModel kCamera = PinholeModel::from_horizontal_fov(1280, 960, 62.2 * kDeg);
const Eigen::Isometry3d kCameraPose = test::level_camera_facing_x({0.0, 0.0, 1.4});

// One person standing at `position`, facing the camera.
struct Scene {
  explicit Scene(const Eigen::Vector2d& position) {
    FigureInput person;
    person.traits.id = 3;
    person.traits.age_years = 30.0;
    const double facing = std::atan2(-position.y(), -position.x());
    person.pose = {position, facing};
    person.face_yaw_rad = facing;
    figures.update(0.0, {person});
  }
  const PosedPerson& person() const { return figures.posed().front(); }

  PeopleFigures figures{1};
};

// An image whose pixel (u, v) is (u mod 256, v mod 256, 77): a crop tells where it was cut.
cv::Mat coordinate_image() {
  cv::Mat image(kCamera.height, kCamera.width, CV_8UC3);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      image.at<cv::Vec3b>(v, u) = cv::Vec3b(u % 256, v % 256, 77);
    }
  }
  return image;
}

TEST(PeopleCrops, FaceImagesAreSquaresOfTheFaceBox) {
  const Scene scene({2.0, 0.0});
  const std::map<uint32_t, PixelBox> boxes =
      face_boxes(scene.figures.posed(), kCamera, kCameraPose);
  ASSERT_EQ(boxes.count(3), 1u);
  const PixelBox& box = boxes.at(3);
  // A face of ~0.15 m at 2 m, straight ahead: some 50 px wide, about the head's column (the
  // person stands with their weight on one leg, the head a few centimetres off the image's centre).
  EXPECT_GT(box.width, 30);
  EXPECT_LT(box.width, 90);
  const Eigen::Vector3d head_centre =
      scene.person().figure->head_frame(scene.person().pose).translation();
  const double head_u = kCamera.project(kCameraPose.inverse() * head_centre)->x();
  EXPECT_NEAR(box.x + 0.5 * box.width, head_u, 10.0);

  const cv::Mat image(kCamera.height, kCamera.width, CV_8UC3, cv::Scalar(10, 200, 30));
  const CameraView view{image, kCamera, kCameraPose};
  const std::optional<FaceImages> images =
      face_images(scene.person(), view, kFaceSize, {true, true});
  ASSERT_TRUE(images);
  for (const cv::Mat& face : {images->cropped, images->aligned}) {
    EXPECT_EQ(face.rows, kFaceSize);
    EXPECT_EQ(face.cols, kFaceSize);
    EXPECT_EQ(face.type(), CV_8UC3);
    EXPECT_EQ(face.at<cv::Vec3b>(kFaceSize / 2, kFaceSize / 2), cv::Vec3b(10, 200, 30));
  }
  // Letterboxed keeping the aspect: the longer side fills the square, the shorter is centred
  // between black bars.
  const bool taller = box.height > box.width;
  const int bar = static_cast<int>(std::floor(
      0.5 * (kFaceSize - std::lround(kFaceSize * (taller ? double(box.width) / box.height
                                                         : double(box.height) / box.width)))));
  ASSERT_GT(bar, 0);
  const cv::Vec3b in_bar =
      images->cropped.at<cv::Vec3b>(taller ? 0 : bar - 1, taller ? bar - 1 : 0);
  const cv::Vec3b past_bar = images->cropped.at<cv::Vec3b>(taller ? 0 : bar, taller ? bar : 0);
  EXPECT_EQ(in_bar, cv::Vec3b(0, 0, 0));
  EXPECT_EQ(past_bar, cv::Vec3b(10, 200, 30));
}

TEST(PeopleCrops, OnlyTheWantedFaceImagesAreMade) {
  const Scene scene({2.0, 0.0});
  const cv::Mat image = coordinate_image();
  const CameraView view{image, kCamera, kCameraPose};
  const std::optional<FaceImages> cropped_only =
      face_images(scene.person(), view, kFaceSize, {true, false});
  ASSERT_TRUE(cropped_only);
  EXPECT_FALSE(cropped_only->cropped.empty());
  EXPECT_TRUE(cropped_only->aligned.empty());
  const std::optional<FaceImages> none = face_images(scene.person(), view, kFaceSize, {});
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->cropped.empty());
  EXPECT_TRUE(none->aligned.empty());
}

TEST(PeopleCrops, TheBodyIsCutAtTheImagesResolution) {
  const Scene scene({2.5, 0.3});
  const std::optional<PixelBox> box =
      posed_body_region(*scene.person().figure, scene.person().pose, kCamera, kCameraPose);
  ASSERT_TRUE(box);
  const cv::Mat image = coordinate_image();
  const std::optional<cv::Mat> body = body_image(scene.person(), {image, kCamera, kCameraPose});
  ASSERT_TRUE(body);
  EXPECT_EQ(body->cols, box->width);
  EXPECT_EQ(body->rows, box->height);
  EXPECT_EQ(body->at<cv::Vec3b>(0, 0), cv::Vec3b(box->x % 256, box->y % 256, 77));
  // A person of ~1.7 m at 2.5 m is some 500 px tall: cut at the image's bottom edge, the feet
  // below the camera's view.
  EXPECT_GT(box->height, 300);
  EXPECT_LE(box->y + box->height, kCamera.height);
}

TEST(PeopleCrops, CropsAreClampedAtTheImageBorder) {
  // Straight ahead at 2 m, the image's left edge is 1.21 m to the side: a face at 1.2 m is half
  // outside.
  const Scene centred({2.0, 0.0});
  const Scene at_edge({2.0, 1.2});
  const std::map<uint32_t, PixelBox> full =
      face_boxes(centred.figures.posed(), kCamera, kCameraPose);
  const std::map<uint32_t, PixelBox> cut =
      face_boxes(at_edge.figures.posed(), kCamera, kCameraPose);
  ASSERT_EQ(cut.count(3), 1u);
  EXPECT_EQ(cut.at(3).x, 0);
  EXPECT_LT(cut.at(3).width, full.at(3).width);
  const cv::Mat image = coordinate_image();
  const CameraView view{image, kCamera, kCameraPose};
  const std::optional<FaceImages> images =
      face_images(at_edge.person(), view, kFaceSize, {true, true});
  ASSERT_TRUE(images);
  EXPECT_EQ(images->cropped.rows, kFaceSize);
  EXPECT_EQ(images->cropped.cols, kFaceSize);
  const std::optional<cv::Mat> body = body_image(at_edge.person(), view);
  ASSERT_TRUE(body);
  EXPECT_EQ(body->at<cv::Vec3b>(0, 0)[0], 0);  // from column 0
  EXPECT_LE(body->cols, kCamera.width);
}

TEST(PeopleCrops, NothingIsCutOfSomeoneBehindTheCamera) {
  const Scene behind({-2.0, 0.0});
  EXPECT_TRUE(face_boxes(behind.figures.posed(), kCamera, kCameraPose).empty());
  const cv::Mat image = coordinate_image();
  const CameraView view{image, kCamera, kCameraPose};
  EXPECT_FALSE(face_images(behind.person(), view, kFaceSize, {true, true}));
  EXPECT_FALSE(body_image(behind.person(), view));
}

}  // namespace
}  // namespace ari_social_sim::rendering
