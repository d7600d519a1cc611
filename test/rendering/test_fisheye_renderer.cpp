#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/rendering/fisheye_renderer.hpp"
#include "render_test_scenes.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(FisheyeRenderer, FacesAreARightHandedCube) {
  for (int face = 0; face < 6; ++face) {
    const Eigen::Matrix3d R = FisheyeRenderer::R_optical_face(face);
    EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
  }
}

TEST(FisheyeRenderer, A180DegreeLensDrawsFiveFaces) {
  const FisheyeRenderer fisheye(FisheyeModel::from_horizontal_fov(320, 240, M_PI));
  EXPECT_EQ(fisheye.faces_drawn(), 5);  // everything but the back face
  // Face resolution matches the centre of the fisheye: 2 f = 2 * 320 / pi = 203.7 -> 204.
  EXPECT_EQ(fisheye.face_size_px(), 204);
}

// Small red balls at known directions appear where the equidistant model projects them, across
// face boundaries and out to 80 degrees off-axis.
TEST(FisheyeRenderer, KnownDirectionsLandWhereTheModelProjectsThem) {
  Renderer renderer;
  renderer.set_static_primitives({});
  const FisheyeModel model = FisheyeModel::from_horizontal_fov(1280, 960, M_PI);
  FisheyeRenderer fisheye(model);
  const Eigen::Isometry3d X_world_optical = test::level_camera_facing_x({0.0, 0.0, 1.0});

  struct Direction {
    double azimuth_deg;  // in the image, from +u towards +v
    double theta_deg;    // off the optical axis
  };
  for (const Direction d : {Direction{0, 0}, Direction{0, 60}, Direction{-90, 44},
                            Direction{30, 47}, Direction{180, 80}, Direction{135, 70}}) {
    const double azimuth = d.azimuth_deg * kDeg, theta = d.theta_deg * kDeg;
    const Eigen::Vector3d ray_optical(std::sin(theta) * std::cos(azimuth),
                                      std::sin(theta) * std::sin(azimuth), std::cos(theta));
    const Eigen::Vector3d centre = X_world_optical * (3.0 * ray_optical);
    RenderPrimitive ball;
    ball.shape = PrimitiveShape::kSphere;
    ball.X_world_shape = Eigen::Translation3d(centre) * Eigen::Isometry3d::Identity();
    ball.size = Eigen::Vector3d::Constant(0.1);
    ball.colour = Eigen::Vector3f(1.0f, 0.0f, 0.0f);
    renderer.set_dynamic_primitives({ball});

    cv::Mat image;
    fisheye.render(renderer, X_world_optical, image);
    const auto [centroid, count] = test::centroid_of(
        image, [](const cv::Vec3b& rgb) { return rgb[0] > 100 && rgb[1] < 60 && rgb[2] < 60; });
    const Eigen::Vector2d expected = *model.project(ray_optical);
    ASSERT_GT(count, 20) << "ball at azimuth " << d.azimuth_deg << ", theta " << d.theta_deg;
    EXPECT_NEAR(centroid.x(), expected.x(), 3.0) << "theta " << d.theta_deg;
    EXPECT_NEAR(centroid.y(), expected.y(), 3.0) << "theta " << d.theta_deg;
    // Outside the lens circle the image is black.
    EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
  }
}

}  // namespace
}  // namespace ari_social_sim::rendering
