#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/rendering/camera_model.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(PinholeModel, HeadCameraIntrinsicsFromFieldOfView) {
  const PinholeModel head = PinholeModel::from_horizontal_fov(1280, 960, 62.2 * kDeg);
  // fx = 640 / tan(31.1 deg) = 1060.9; principal point at the centre of pixel (639.5, 479.5).
  EXPECT_NEAR(head.fx, 1060.9, 0.1);
  EXPECT_DOUBLE_EQ(head.fy, head.fx);
  EXPECT_DOUBLE_EQ(head.cx, 639.5);
  EXPECT_DOUBLE_EQ(head.cy, 479.5);
  // Vertical FoV: 2 atan(480 / 1060.9) = 48.7 deg (the IMX219's 48.8 deg).
  EXPECT_NEAR(head.vertical_fov_rad() / kDeg, 48.7, 0.1);
}

TEST(PinholeModel, ProjectsAndCastsRaysConsistently) {
  const PinholeModel model = PinholeModel::from_horizontal_fov(848, 480, 69.4 * kDeg);
  // The edge of the field of view lands on the outer edge of the border pixel.
  const auto edge = model.project({std::tan(34.7 * kDeg), 0.0, 1.0});
  ASSERT_TRUE(edge.has_value());
  EXPECT_NEAR(edge->x(), 847.5, 1e-9);
  EXPECT_NEAR(edge->y(), 239.5, 1e-9);
  const Eigen::Vector3d point(0.4, -0.25, 2.5);
  const auto pixel = model.project(point);
  ASSERT_TRUE(pixel.has_value());
  EXPECT_TRUE(model.contains(*pixel));
  EXPECT_LT((model.ray(pixel->x(), pixel->y()) * point.z() - point).norm(), 1e-12);
  EXPECT_FALSE(model.project({0.0, 0.0, -1.0}).has_value());  // behind the camera
}

TEST(FisheyeModel, EquidistantProjectionOfKnownDirections) {
  const FisheyeModel model = FisheyeModel::from_horizontal_fov(1280, 960, M_PI);
  // f = 1280 / pi = 407.4 px per radian.
  EXPECT_NEAR(model.f, 407.44, 0.01);
  auto pixel_at = [&](double azimuth, double theta) {
    const Eigen::Vector3d ray(std::sin(theta) * std::cos(azimuth),
                              std::sin(theta) * std::sin(azimuth), std::cos(theta));
    const auto pixel = model.project(3.0 * ray);
    EXPECT_TRUE(pixel.has_value());
    return pixel.value_or(Eigen::Vector2d::Constant(-1.0));
  };
  // Straight ahead: the principal point.
  EXPECT_LT((pixel_at(0.0, 0.0) - Eigen::Vector2d(639.5, 479.5)).norm(), 1e-9);
  // 90 deg to the right: r = f pi / 2 = 640 px, the right edge of the image.
  EXPECT_LT((pixel_at(0.0, M_PI / 2) - Eigen::Vector2d(1279.5, 479.5)).norm(), 1e-9);
  // 45 deg up (optical -y): r = f pi / 4 = 320 px above the centre.
  EXPECT_LT((pixel_at(-M_PI / 2, M_PI / 4) - Eigen::Vector2d(639.5, 159.5)).norm(), 1e-9);
  // 60 deg off-axis at azimuth 30 deg: r = 426.7 px along (cos 30, sin 30).
  const double r = model.f * M_PI / 3;
  EXPECT_LT((pixel_at(M_PI / 6, M_PI / 3) -
             Eigen::Vector2d(639.5 + r * std::cos(M_PI / 6), 479.5 + r * std::sin(M_PI / 6)))
                .norm(),
            1e-9);
  // Behind the lens: outside the 180 deg field.
  EXPECT_FALSE(model.project({0.0, 0.1, -1.0}).has_value());
}

TEST(FisheyeModel, UnprojectInvertsProject) {
  const FisheyeModel model = FisheyeModel::from_horizontal_fov(1280, 960, M_PI);
  for (const Eigen::Vector2d& pixel :
       {Eigen::Vector2d(100, 300), Eigen::Vector2d(639.5, 479.5), Eigen::Vector2d(1000, 900)}) {
    const auto ray = model.unproject(pixel.x(), pixel.y());
    ASSERT_TRUE(ray.has_value());
    EXPECT_NEAR(ray->norm(), 1.0, 1e-12);
    EXPECT_LT((*model.project(*ray) - pixel).norm(), 1e-9);
  }
  // The image corner is 800 px from the centre: theta = 1.96 rad > pi / 2, outside the lens.
  EXPECT_FALSE(model.unproject(0.0, 0.0).has_value());
}

TEST(CameraInfo, MatchesTheModels) {
  const PinholeModel pinhole = PinholeModel::from_horizontal_fov(640, 480, 1.0);
  const CameraInfo info = camera_info_of(pinhole);
  EXPECT_EQ(info.distortion_model, "plumb_bob");
  EXPECT_EQ(info.D.size(), 5u);
  EXPECT_DOUBLE_EQ(info.K[0], pinhole.fx);
  EXPECT_DOUBLE_EQ(info.K[2], pinhole.cx);
  EXPECT_DOUBLE_EQ(info.K[4], pinhole.fy);
  EXPECT_DOUBLE_EQ(info.K[5], pinhole.cy);
  EXPECT_DOUBLE_EQ(info.P[0], pinhole.fx);
  EXPECT_DOUBLE_EQ(info.P[3], 0.0);  // monocular: no baseline term
  EXPECT_DOUBLE_EQ(info.P[10], 1.0);
  EXPECT_DOUBLE_EQ(info.R[4], 1.0);

  const FisheyeModel fisheye = FisheyeModel::from_horizontal_fov(1280, 960, M_PI);
  const CameraInfo fisheye_info = camera_info_of(fisheye);
  EXPECT_EQ(fisheye_info.distortion_model, "equidistant");
  EXPECT_EQ(fisheye_info.D.size(), 4u);
  EXPECT_DOUBLE_EQ(fisheye_info.K[0], fisheye.f);
  EXPECT_EQ(fisheye_info.width, 1280);
}

}  // namespace
}  // namespace ari_social_sim::rendering
