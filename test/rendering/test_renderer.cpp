#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ari_social_sim/rendering/people_figures.hpp"
#include "ari_social_sim/rendering/renderer.hpp"
#include "ari_social_sim/rendering/world_scene.hpp"
#include "render_test_scenes.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(Renderer, OpensAHeadlessContext) {
  Renderer renderer;
  EXPECT_FALSE(renderer.device_name().empty());
  std::printf("renderer: %s\n", renderer.device_name().c_str());
}

TEST(Renderer, WallFacingTheCameraAtItsDistance) {
  Renderer renderer;
  // The wall's near face is the plane x = 3.0 m; the camera at the origin, 1 m up, faces +x.
  renderer.set_static_primitives({test::box({3.1, 0.0, 1.5}, {0.2, 20.0, 3.0})});
  const PinholeModel model = PinholeModel::from_horizontal_fov(848, 480, 69.4 * kDeg);
  RenderedImage image;
  ViewOptions options;
  options.depth = true;
  renderer.render(model, test::level_camera_facing_x({0.0, 0.0, 1.0}), options, image);
  ASSERT_EQ(image.depth.rows, 480);
  ASSERT_EQ(image.depth.cols, 848);
  // Depth is along the optical axis, so every pixel on a plane facing the camera reads 3.0 m. The
  // wall spans z in [0, 3] m: rows from v = 0 down to where the ray reaches z = 0, at
  // v = cy + fy * 1 / 3 = 239.5 + 611.4 / 3 = 443.3.
  double worst_error = 0.0;
  int wall_pixels = 0;
  for (int v = 0; v < image.depth.rows; ++v) {
    for (int u = 0; u < image.depth.cols; ++u) {
      const float depth = image.depth.at<float>(v, u);
      if (std::isfinite(depth)) {
        ++wall_pixels;
        worst_error = std::max(worst_error, std::abs(depth - 3.0));
      }
    }
  }
  EXPECT_LT(worst_error, 0.01);
  EXPECT_NEAR(wall_pixels, 444 * 848, 2 * 848);
}

TEST(Renderer, SlantedWallDepthMatchesRayIntersection) {
  Renderer renderer;
  // A wall turned 30 deg about z through (4, 0.5): the near face is the plane n . p = d.
  const double yaw = 30.0 * kDeg;
  const Eigen::Vector3d centre(4.0, 0.5, 1.5);
  renderer.set_static_primitives({test::box(centre, {0.2, 30.0, 3.0}, yaw)});
  const Eigen::Vector3d normal(std::cos(yaw), std::sin(yaw), 0.0);
  const double plane = normal.dot(centre) - 0.1;

  const PinholeModel model = PinholeModel::from_horizontal_fov(640, 480, 80.0 * kDeg);
  const Eigen::Isometry3d X_world_optical = test::level_camera_facing_x({0.0, 0.0, 1.2});
  RenderedImage image;
  ViewOptions options;
  options.depth = true;
  renderer.render(model, X_world_optical, options, image);
  double worst_error = 0.0;
  int checked = 0;
  for (int v = 0; v < model.height; v += 7) {
    for (int u = 0; u < model.width; u += 7) {
      // Intersect the pixel's ray (z = 1 in the optical frame) with the plane, in the world.
      const Eigen::Vector3d ray_world = X_world_optical.linear() * model.ray(u, v);
      const Eigen::Vector3d origin = X_world_optical.translation();
      const double t = (plane - normal.dot(origin)) / normal.dot(ray_world);
      const Eigen::Vector3d hit = origin + t * ray_world;
      const float depth = image.depth.at<float>(v, u);
      if (hit.z() < 0.02 || hit.z() > 2.98) {
        continue;  // off the wall's top or bottom edge
      }
      ASSERT_TRUE(std::isfinite(depth)) << "pixel " << u << "," << v;
      worst_error = std::max(worst_error, std::abs(depth - t));  // t is the optical z of the hit
      ++checked;
    }
  }
  EXPECT_GT(checked, 3000);
  EXPECT_LT(worst_error, 0.01);
}

TEST(Renderer, PersonAppearsWhereTheProjectionPutsThem) {
  Renderer renderer;
  renderer.set_static_primitives({});
  const Eigen::Isometry3d X_world_optical = test::level_camera_facing_x({0.0, 0.0, 1.5});
  // A person 3 m ahead and 0.6 m to the left, facing the camera.
  const Eigen::Vector2d position(3.0, 0.6);
  const double facing = std::atan2(-position.y(), -position.x());
  FigureInput person;
  person.traits.id = 4;
  person.pose = {position, facing};
  person.face_yaw_rad = facing;
  PeopleFigures figures;
  figures.update(0.0, {person});
  renderer.set_dynamic_mesh(figures.mesh());

  const PinholeModel model = PinholeModel::from_horizontal_fov(1280, 960, 62.2 * kDeg);
  RenderedImage image;
  ViewOptions options;
  options.labels = true;
  renderer.render(model, X_world_optical, options, image);
  // The face's labelled pixels centre on the projection of the face's middle (halfway from the
  // hairline to the chin, below the head's centre), within a tenth of the head's width.
  const PosedPerson& posed = figures.posed()[0];
  const cv::Mat face = image.labels == posed.face_label;
  const cv::Moments moments = cv::moments(face, true);
  ASSERT_GT(moments.m00, 1000);
  const std::vector<Eigen::Vector3d>& outline = posed.figure->face_outline();
  const Eigen::Vector3d head_world =
      posed.figure->head_frame(posed.pose) * (0.5 * (outline[0] + outline[1]));
  const Eigen::Vector2d expected = *model.project(X_world_optical.inverse() * head_world);
  const double head_width_px =
      model.fx * posed.figure->appearance().head_height_m * 0.68 / position.norm();
  std::printf(
      "face centroid (%.1f, %.1f), face's middle projected (%.1f, %.1f), head %.0f px wide\n",
      moments.m10 / moments.m00, moments.m01 / moments.m00, expected.x(), expected.y(),
      head_width_px);
  EXPECT_NEAR(moments.m10 / moments.m00, expected.x(), 0.1 * head_width_px);
  EXPECT_NEAR(moments.m01 / moments.m00, expected.y(), 0.1 * head_width_px);
  // The label image and the colour image agree on where the person is: labelled pixels are
  // exactly those not of the background's colour.
  const cv::Vec3b background = image.colour.at<cv::Vec3b>(0, 0);
  int disagreements = 0;
  for (int v = 0; v < image.colour.rows; ++v) {
    for (int u = 0; u < image.colour.cols; ++u) {
      const bool drawn = image.colour.at<cv::Vec3b>(v, u) != background;
      disagreements += drawn != (image.labels.at<uint16_t>(v, u) > 0) ? 1 : 0;
    }
  }
  EXPECT_EQ(disagreements, 0);
}

// A camera at `position` looking straight down, image x along world -y and image y along -x.
Eigen::Isometry3d camera_looking_down(const Eigen::Vector3d& position) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear().col(0) = -Eigen::Vector3d::UnitY();
  X.linear().col(1) = -Eigen::Vector3d::UnitX();
  X.linear().col(2) = -Eigen::Vector3d::UnitZ();
  X.translation() = position;
  return X;
}

RenderPrimitive floor_slab() {
  RenderPrimitive floor = test::box({0.0, 0.0, -0.01}, {20.0, 20.0, 0.02});
  floor.surface = Surface::kFloor;
  floor.max_facet_m = 0.125;  // lit per vertex, as world_scene facets floors
  return floor;
}

// Mean grey level of the floor's pixels between `inner` and `outer` metres of `centre` (z = 0),
// leaving out labelled pixels (people).
double floor_brightness(const RenderedImage& image, const PinholeModel& model,
                        const Eigen::Isometry3d& X_world_optical, const Eigen::Vector2d& centre,
                        double inner, double outer) {
  cv::Mat grey;
  cv::cvtColor(image.colour, grey, cv::COLOR_RGB2GRAY);
  double sum = 0.0;
  int count = 0;
  for (int v = 0; v < grey.rows; ++v) {
    for (int u = 0; u < grey.cols; ++u) {
      // The ray through (u, v) meets the floor at z = 0.
      const Eigen::Vector3d ray =
          X_world_optical.linear() *
          Eigen::Vector3d((u - model.cx) / model.fx, (v - model.cy) / model.fy, 1.0);
      const Eigen::Vector3d origin = X_world_optical.translation();
      const Eigen::Vector2d hit = (origin + ray * (-origin.z() / ray.z())).head<2>();
      const double distance = (hit - centre).norm();
      const bool person = !image.labels.empty() && image.labels.at<uint16_t>(v, u) > 0;
      if (distance >= inner && distance < outer && !person) {
        sum += grey.at<uint8_t>(v, u);
        ++count;
      }
    }
  }
  return count > 0 ? sum / count : 0.0;
}

TEST(Renderer, LampsLightTheFloorUnderThemMost) {
  Renderer renderer;
  RenderPrimitive lamp = test::box({0.0, 0.0, 2.49}, {0.6, 1.2, 0.02});
  lamp.surface = Surface::kLamp;
  renderer.set_static_primitives({floor_slab(), lamp});
  const PinholeModel model = PinholeModel::from_horizontal_fov(640, 480, 100.0 * kDeg);
  const Eigen::Isometry3d X_world_optical = camera_looking_down({0.0, 0.0, 2.0});
  RenderedImage image;
  renderer.render(model, X_world_optical, ViewOptions{}, image);
  const double under = floor_brightness(image, model, X_world_optical, {0.0, 0.0}, 0.0, 0.3);
  const double beside = floor_brightness(image, model, X_world_optical, {0.0, 0.0}, 1.5, 1.8);
  std::printf("floor under the lamp %.1f, 1.5-1.8 m from its foot %.1f\n", under, beside);
  // Lamp light (2.4 cos^2 / d^2) falls from 0.38 under a lamp 2.5 m up to about 0.19 at 1.65 m
  // from its foot; with bounced and fill light the floor's light falls by about a third, its
  // display value (light^(1/2.2)) by about 15 %.
  EXPECT_LT(beside, 0.92 * under);
  EXPECT_GT(beside, 0.7 * under);
}

// The room's vertices are lit by its lamps once, when it is set (LampLightBake); a person's every
// frame. A wall and a table lit either way look the same.
TEST(Renderer, TheRoomLitOnceLooksAsLitEveryFrame) {
  RenderPrimitive lamp = test::box({2.0, 0.0, 2.49}, {0.6, 1.2, 0.02});
  lamp.surface = Surface::kLamp;
  RenderPrimitive wall = test::box({4.0, 0.0, 1.5}, {0.2, 6.0, 3.0});
  wall.surface = Surface::kWall;
  wall.max_facet_m = 0.25;
  RenderPrimitive table = test::box({2.5, 0.5, 0.4}, {0.8, 0.8, 0.8});
  table.surface = Surface::kWood;
  table.max_facet_m = 0.25;
  const PinholeModel model = PinholeModel::from_horizontal_fov(320, 240, 90.0 * kDeg);
  const Eigen::Isometry3d camera = test::level_camera_facing_x({0.0, 0.0, 1.2});
  RenderedImage once, every_frame;
  Renderer renderer;
  renderer.set_static_primitives({floor_slab(), lamp, wall, table});
  ViewOptions with_depth;
  with_depth.depth = true;
  renderer.render(model, camera, with_depth, once);
  renderer.set_static_primitives({floor_slab(), lamp});
  renderer.set_dynamic_primitives({wall, table});
  renderer.render(model, camera, ViewOptions{}, every_frame);
  // The floor is left out: a static table shades it (FloorShade), one drawn every frame does not.
  cv::Mat off_floor(model.height, model.width, CV_8U);
  for (int v = 0; v < model.height; ++v) {
    for (int u = 0; u < model.width; ++u) {
      const double height_m = 1.2 - once.depth.at<float>(v, u) * (v - model.cy) / model.fy;
      off_floor.at<uint8_t>(v, u) = height_m > 0.01 ? 255 : 0;
    }
  }
  cv::Mat difference;
  cv::absdiff(once.colour, every_frame.colour, difference);
  double largest = 0.0;
  cv::Mat off_floor_rgb;
  cv::merge(std::vector<cv::Mat>(3, off_floor), off_floor_rgb);
  cv::minMaxLoc(difference.reshape(1), nullptr, &largest, nullptr, nullptr,
                off_floor_rgb.reshape(1));
  const double mean = cv::mean(difference, off_floor)[0];
  std::printf(
      "[ measured ] lit once against lit every frame: largest difference %.0f, mean %.4f "
      "grey levels\n",
      largest, mean);
  // Float rounding of the same sums at most. A bake that failed (the lamps' light left at 0)
  // would show as the lamp's whole light on the wall and the table
  // (LampsLightTheFloorUnderThemMost checks the lit-once floor against the lamp's fall-off).
  EXPECT_LE(largest, 1.0);
}

TEST(Renderer, PeopleCastSoftContactShadowsOnTheFloor) {
  Renderer renderer;
  renderer.set_static_primitives({floor_slab()});
  const PinholeModel model = PinholeModel::from_horizontal_fov(640, 480, 90.0 * kDeg);
  const Eigen::Isometry3d X_world_optical = camera_looking_down({0.0, 0.0, 3.5});
  ViewOptions options;
  options.labels = true;
  RenderedImage alone, with_person;
  renderer.render(model, X_world_optical, options, alone);
  FigureInput person;
  person.traits.id = 2;
  PeopleFigures figures;
  figures.update(0.0, {person});
  renderer.set_dynamic_mesh(figures.mesh());
  renderer.render(model, X_world_optical, options, with_person);
  const auto ring = [&](const RenderedImage& image, double inner, double outer) {
    return floor_brightness(image, model, X_world_optical, {0.0, 0.0}, inner, outer);
  };
  const double near_before = ring(alone, 0.3, 0.4), near_after = ring(with_person, 0.3, 0.4);
  const double far_before = ring(alone, 1.5, 1.7), far_after = ring(with_person, 1.5, 1.7);
  std::printf("floor 0.3-0.4 m from the feet %.1f -> %.1f, 1.5-1.7 m %.1f -> %.1f\n", near_before,
              near_after, far_before, far_after);
  // Beside the feet the floor sees less light; a metre and a half away the shadow is gone.
  EXPECT_LT(near_after, 0.95 * near_before);
  EXPECT_NEAR(far_after, far_before, 0.5);
}

TEST(Renderer, FurnitureOfTheRoomShadesTheFloorRoundIt) {
  // A cabinet 0.3 m square standing on the floor, seen from 3.5 m above: as part of the room it
  // darkens the floor round its foot (FloorShade); drawn every frame (as a person is), it does not.
  const RenderPrimitive cabinet = test::box({0.0, 0.0, 0.3}, {0.3, 0.3, 0.6});
  const PinholeModel model = PinholeModel::from_horizontal_fov(640, 480, 90.0 * kDeg);
  const Eigen::Isometry3d X_world_optical = camera_looking_down({0.0, 0.0, 3.5});
  Renderer renderer;
  RenderedImage unshaded, shaded;
  renderer.set_static_primitives({floor_slab()});
  renderer.set_dynamic_primitives({cabinet});
  renderer.render(model, X_world_optical, ViewOptions{}, unshaded);
  renderer.set_static_primitives({floor_slab(), cabinet});
  renderer.set_dynamic_primitives({});
  renderer.render(model, X_world_optical, ViewOptions{}, shaded);
  const auto ring = [&](const RenderedImage& image, double inner, double outer) {
    return floor_brightness(image, model, X_world_optical, {0.0, 0.0}, inner, outer);
  };
  // The rays through the cabinet's top meet the floor under it: the rings start past its corners.
  const double near_unshaded = ring(unshaded, 0.26, 0.32), near_shaded = ring(shaded, 0.26, 0.32);
  const double far_unshaded = ring(unshaded, 1.5, 1.7), far_shaded = ring(shaded, 1.5, 1.7);
  std::printf(
      "[ measured ] floor 0.26-0.32 m from the cabinet's centre %.1f -> %.1f, 1.5-1.7 m "
      "%.1f -> %.1f\n",
      near_unshaded, near_shaded, far_unshaded, far_shaded);
  EXPECT_LT(near_shaded, 0.95 * near_unshaded);
  EXPECT_NEAR(far_shaded, far_unshaded, 0.5);
}

// What cloth's folds do to a cylinder's pixels: its image over the same cylinder's in matte (both
// grey, 0 where the cylinder is not seen). The cylinder (a trouser leg, 0.3 m across and 1 m long)
// is placed by X_world_part, as posing places a figure's parts.
cv::Mat fold_shading(const Eigen::Isometry3f& X_world_part,
                     const Eigen::Isometry3d& X_world_optical) {
  RenderPrimitive leg = test::box({0.0, 0.0, 0.0}, {0.3, 0.3, 1.0});
  leg.shape = PrimitiveShape::kCylinder;
  leg.round_segments = 8;
  const PinholeModel model = PinholeModel::from_horizontal_fov(400, 400, 30.0 * kDeg);
  ViewOptions options;
  options.labels = true;
  Renderer renderer;
  renderer.set_static_primitives({});
  cv::Mat grey[2];
  cv::Mat seen;
  for (const Surface surface : {Surface::kCloth, Surface::kMatte}) {
    leg.surface = surface;
    RenderMesh mesh;
    append_moved(mesh_of({leg}), X_world_part, 1.0f, mesh);
    renderer.set_dynamic_mesh(mesh);
    RenderedImage image;
    renderer.render(model, X_world_optical, options, image);
    cv::Mat one;
    cv::cvtColor(image.colour, one, cv::COLOR_RGB2GRAY);
    one.convertTo(grey[surface == Surface::kCloth ? 0 : 1], CV_32F);
    seen = image.labels == 1;
  }
  cv::Mat ratio = cv::Mat::zeros(grey[0].size(), CV_32F);
  cv::divide(grey[0], cv::max(grey[1], 1.0f), ratio);
  ratio.setTo(0.0f, ~seen);
  return ratio;
}

// The mean absolute difference of two fold shadings where both see the cylinder.
double shading_difference(const cv::Mat& a, const cv::Mat& b) {
  const cv::Mat both = (a > 0.0f) & (b > 0.0f);
  cv::Mat difference;
  cv::absdiff(a, b, difference);
  return cv::mean(difference, both)[0];
}

TEST(Renderer, ClothFoldsShadeThePartAndTurnWithIt) {
  const Eigen::Isometry3d camera = test::level_camera_facing_x({0.0, 0.0, 1.0});
  // The same camera after a half turn about the leg's axis (x = 2 m): it looks back along -x.
  Eigen::Isometry3d opposite = camera;
  opposite.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()) * camera.linear();
  opposite.translation() = Eigen::Vector3d(4.0, 0.0, 1.0);
  const Eigen::Isometry3f placed(Eigen::Translation3f(2.0f, 0.0f, 1.0f));
  const Eigen::Isometry3f turned =
      placed *
      Eigen::Isometry3f(Eigen::AngleAxisf(static_cast<float>(M_PI), Eigen::Vector3f::UnitZ()));
  const cv::Mat front = fold_shading(placed, camera);
  const cv::Mat turned_back = fold_shading(turned, opposite);
  const cv::Mat turned_front = fold_shading(turned, camera);
  double darkest = 0.0;
  cv::minMaxLoc(front, &darkest, nullptr, nullptr, nullptr, front > 0.0f);
  cv::Scalar mean, spread;
  cv::meanStdDev(front, mean, spread, front > 0.0f);
  const double same_folds = shading_difference(front, turned_back);
  const double other_folds = shading_difference(front, turned_front);
  std::printf(
      "[ measured ] cloth over matte: mean %.3f, sd %.3f, darkest %.3f; after a half turn, "
      "from behind %.4f apart, from the front %.4f\n",
      mean[0], spread[0], darkest, same_folds, other_folds);
  // Folds darken the cloth by up to a fifth and vary across it.
  EXPECT_LT(darkest, 0.93);
  EXPECT_GT(mean[0], 0.85);
  EXPECT_GT(spread[0], 0.01);
  // Turned with the part, the folds show again where the part's own side faces the camera, and
  // the side that came round shows other folds.
  EXPECT_LT(same_folds, 0.4 * other_folds);
}

}  // namespace
}  // namespace ari_social_sim::rendering
