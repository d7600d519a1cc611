// figure_regions: the boxes projected from a posed figure hold what the renderer draws of it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "ari_social_sim/rendering/figure_regions.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"
#include "ari_social_sim/rendering/region_crops.hpp"
#include "ari_social_sim/rendering/renderer.hpp"
#include "render_test_scenes.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct Case {
  const char* name;
  Eigen::Vector2d position;      // of the person; the camera is at the origin looking along +x
  double turn_rad;               // the person's heading away from facing the camera
  Eigen::Vector2d velocity_mps;  // drives the gait
  double camera_pitch_rad;       // > 0 looks down
  uint32_t id;
};

// Share of the label image's pixels equal to one of `labels` that fall in `box`, and their count.
std::pair<double, int> share_inside(const cv::Mat& image, std::initializer_list<uint16_t> labels,
                                    const PixelBox& box) {
  int total = 0, inside = 0;
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const uint16_t value = image.at<uint16_t>(v, u);
      bool match = false;
      for (const uint16_t label : labels) {
        match = match || (value != 0 && value == label);
      }
      if (match) {
        ++total;
        inside += box.contains(u, v) ? 1 : 0;
      }
    }
  }
  return {total > 0 ? double(inside) / total : 0.0, total};
}

TEST(FigureRegions, BoxesHoldTheRenderedFaceAndBody) {
  Renderer renderer;
  renderer.set_static_primitives({});
  const PinholeModel model = PinholeModel::from_horizontal_fov(1280, 960, 62.2 * kDeg);
  const Case cases[] = {
      {"frontal at 2 m", {2.0, 0.0}, 0.0, {0.0, 0.0}, 0.0, 1},
      {"turned 40 degrees, off centre", {2.5, 0.5}, 40 * kDeg, {0.0, 0.0}, 0.0, 2},
      {"walking across", {3.0, -0.4}, 20 * kDeg, {0.0, 1.2}, 0.0, 3},
      {"camera looking down 15 degrees", {1.6, 0.2}, 0.0, {0.0, 0.0}, 15 * kDeg, 4},
      {"close, cut by the image", {0.9, 0.0}, 0.0, {0.0, 0.0}, 0.0, 5},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Eigen::Isometry3d X_world_optical = test::level_camera_facing_x({0.0, 0.0, 1.4});
    // Pitching down turns the optical axis (z) towards the floor: about the optical x axis.
    X_world_optical.linear() =
        X_world_optical.linear() * Eigen::AngleAxisd(-c.camera_pitch_rad, Eigen::Vector3d::UnitX());
    const double facing = std::atan2(-c.position.y(), -c.position.x()) + c.turn_rad;
    FigureInput person;
    person.traits.id = c.id;
    person.pose = {c.position, facing};
    person.face_yaw_rad = facing;
    person.velocity_mps = c.velocity_mps;
    PeopleFigures figures(1);
    figures.update(0.0, {person});
    person.walked_m = 0.4 * c.velocity_mps.norm();  // a gait phase other than the first
    figures.update(0.4, {person});
    renderer.set_dynamic_mesh(figures.mesh());
    RenderedImage image;
    ViewOptions options;
    options.colour = false;
    options.labels = true;
    renderer.render(model, X_world_optical, options, image);

    const PosedPerson& posed = figures.posed()[0];
    const std::optional<PixelBox> face =
        face_region(*posed.figure, posed.pose, model, X_world_optical);
    const std::optional<PixelBox> body =
        body_region(figures.mesh(), posed.vertices, model, X_world_optical);
    ASSERT_TRUE(face && body);
    const auto [face_share, face_pixels] = share_inside(image.labels, {posed.face_label}, *face);
    const auto [body_share, body_pixels] =
        share_inside(image.labels, {posed.body_label, posed.face_label}, *body);
    // The outline's box (the image labels' face box) is the tighter one a detector draws.
    const std::optional<PixelBox> outline =
        face_outline_region(*posed.figure, posed.pose, model, X_world_optical);
    ASSERT_TRUE(outline);
    const double outline_share = share_inside(image.labels, {posed.face_label}, *outline).first;
    std::printf(
        "%-32s face box %4dx%-4d holds %5.1f %% of %6d face pixels (outline's %4dx%-4d "
        "%5.1f %%); body box %4dx%-4d holds %5.1f %% of %6d\n",
        c.name, face->width, face->height, 100 * face_share, face_pixels, outline->width,
        outline->height, 100 * outline_share, body->width, body->height, 100 * body_share,
        body_pixels);
    EXPECT_GT(face_pixels, 500);
    EXPECT_GE(face_share, 0.95);
    EXPECT_GE(body_share, 0.95);
    // Neither box is loose: the face box is mostly face, the body box not much wider than the
    // person's pixels.
    EXPECT_GT(face_pixels / face->area(), 0.5);
    EXPECT_GT(body_pixels / body->area(), 0.2);

    // The eyes are inside the face box, the person's right eye on the image's left when they face
    // the camera, and level with an upright head and a level camera.
    const std::optional<std::array<Eigen::Vector2d, 2>> eyes =
        eye_pixels(*posed.figure, posed.pose, model, X_world_optical);
    ASSERT_TRUE(eyes);
    for (const Eigen::Vector2d& eye : *eyes) {
      if (face->x > 0 && face->y > 0) {
        EXPECT_TRUE(face->contains(int(std::lround(eye.x())), int(std::lround(eye.y()))));
      }
    }
    EXPECT_LT((*eyes)[0].x(), (*eyes)[1].x());
    if (c.camera_pitch_rad == 0.0) {
      EXPECT_NEAR((*eyes)[0].y(), (*eyes)[1].y(), 0.05 * face->height);
    }
  }
}

// A walker posed from the distance they walked, as the physics draws them and as a reader of its
// images (hri_perception_node's crops) poses them: the box of the figure posed outside the mesh
// holds every pixel drawn of them, and little else.
TEST(FigureRegions, ThePosedBoxHoldsAWalkerDrawnFromTheSameWalkedDistance) {
  Renderer renderer;
  renderer.set_static_primitives({});
  const PinholeModel model = PinholeModel::from_horizontal_fov(1280, 960, 62.2 * kDeg);
  const Eigen::Isometry3d X_world_optical = test::level_camera_facing_x({0.0, 0.0, 1.4});
  FigureInput person;  // walking across the view, 2.5 m ahead
  person.traits.id = 3;
  person.pose = {{2.5, -0.3}, M_PI / 2};
  person.face_yaw_rad = M_PI;
  person.velocity_mps = {0.0, 1.3};
  for (const double walked_s : {0.13, 0.29, 0.47, 0.61}) {
    SCOPED_TRACE(walked_s);
    person.walked_m = 1.3 * walked_s;
    PeopleFigures drawn(1), ours(1);
    drawn.update(walked_s, {person});
    ours.update(0.0, {person});  // posed at another time, from the same input
    renderer.set_dynamic_mesh(drawn.mesh());
    RenderedImage image;
    ViewOptions options;
    options.colour = false;
    options.labels = true;
    renderer.render(model, X_world_optical, options, image);
    const PosedPerson& seen = drawn.posed()[0];
    const PosedPerson& posed = ours.posed()[0];
    ASSERT_EQ(seen.pose.gait_phase_rad, posed.pose.gait_phase_rad);
    const std::optional<PixelBox> box =
        posed_body_region(*posed.figure, posed.pose, model, X_world_optical);
    ASSERT_TRUE(box);
    const auto [share, pixels] =
        share_inside(image.labels, {seen.body_label, seen.face_label}, *box);
    std::printf("walked %.2f s: posed box %4dx%-4d holds %5.1f %% of %6d pixels (%.0f %% full)\n",
                walked_s, box->width, box->height, 100 * share, pixels, 100 * pixels / box->area());
    EXPECT_EQ(share, 1.0);
    EXPECT_GT(pixels / box->area(), 0.25);  // a person, not a stride's envelope
  }
}

TEST(FigureRegions, NothingBehindTheCamera) {
  const PinholeModel model = PinholeModel::from_horizontal_fov(640, 480, 60 * kDeg);
  const Eigen::Isometry3d X_world_optical = test::level_camera_facing_x({0.0, 0.0, 1.4});
  FigureInput person;
  person.traits.id = 7;
  person.pose = {{-2.0, 0.0}, 0.0};
  PeopleFigures figures(1);
  figures.update(0.0, {person});
  const PosedPerson& posed = figures.posed()[0];
  EXPECT_FALSE(face_region(*posed.figure, posed.pose, model, X_world_optical));
  EXPECT_FALSE(body_region(figures.mesh(), posed.vertices, model, X_world_optical));
  EXPECT_FALSE(eye_pixels(*posed.figure, posed.pose, model, X_world_optical));
}

TEST(FigureRegions, PixelBoxIou) {
  const PixelBox a{0, 0, 10, 10};
  EXPECT_DOUBLE_EQ(a.iou(a), 1.0);
  EXPECT_DOUBLE_EQ(a.iou({5, 0, 10, 10}), 50.0 / 150.0);
  EXPECT_DOUBLE_EQ(a.iou({20, 20, 5, 5}), 0.0);
  EXPECT_DOUBLE_EQ(PixelBox{}.iou(a), 0.0);
}

TEST(RegionCrops, LetterboxKeepsTheAspectInTheSquare) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(200, 100, 50));
  // A tall region: scaled to the square's height, centred, black on both sides.
  const cv::Mat tall = letterboxed(image, PixelBox{100, 50, 60, 120}, 128);
  ASSERT_EQ(tall.rows, 128);
  ASSERT_EQ(tall.cols, 128);
  EXPECT_EQ(tall.type(), CV_8UC3);
  EXPECT_EQ(tall.at<cv::Vec3b>(64, 10), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(tall.at<cv::Vec3b>(64, 64), cv::Vec3b(200, 100, 50));
  EXPECT_EQ(tall.at<cv::Vec3b>(0, 64), cv::Vec3b(200, 100, 50));
  // Bodies are cut at the image's resolution.
  const cv::Mat body = cut_out(image, PixelBox{10, 20, 30, 40});
  EXPECT_EQ(body.cols, 30);
  EXPECT_EQ(body.rows, 40);
}

TEST(RegionCrops, AlignedFaceHasItsEyesLevel) {
  // Two dark "eyes" on a line tilted by 20 degrees about the region's centre.
  cv::Mat image(400, 400, CV_8UC3, cv::Scalar(255, 255, 255));
  const Eigen::Vector2d centre(199.5, 199.5);
  const double tilt = 20 * kDeg;
  const Eigen::Vector2d half(40 * std::cos(tilt), 40 * std::sin(tilt));
  const Eigen::Vector2d left = centre - half, right = centre + half;
  for (const Eigen::Vector2d& eye : {left, right}) {
    cv::circle(image, cv::Point(int(std::lround(eye.x())), int(std::lround(eye.y()))), 6,
               cv::Scalar(0, 0, 0), cv::FILLED);
  }
  const PixelBox box{120, 120, 160, 160};
  for (const bool swapped : {false, true}) {
    const cv::Mat aligned = swapped ? aligned_face(image, box, right, left, 128)
                                    : aligned_face(image, box, left, right, 128);
    ASSERT_EQ(aligned.rows, 128);
    // Dark pixels in the left and right halves: their mean rows agree within a pixel, and both
    // lie on the middle row (the centre stays put).
    double rows[2] = {0, 0}, counts[2] = {0, 0};
    for (int v = 0; v < aligned.rows; ++v) {
      for (int u = 0; u < aligned.cols; ++u) {
        if (aligned.at<cv::Vec3b>(v, u)[0] < 80) {
          rows[u < 64 ? 0 : 1] += v;
          counts[u < 64 ? 0 : 1] += 1;
        }
      }
    }
    ASSERT_GT(counts[0], 20);
    ASSERT_GT(counts[1], 20);
    EXPECT_NEAR(rows[0] / counts[0], rows[1] / counts[1], 1.0);
    EXPECT_NEAR(rows[0] / counts[0], 63.5, 1.5);
  }
}

}  // namespace
}  // namespace ari_social_sim::rendering
