#include "ari_social_sim/physics/image_labels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ari_social_sim::physics {
namespace {

// Pixel counts and bounds of one label value's region.
struct Region {
  int pixels{0};
  int face_pixels{0};
  int min_u{std::numeric_limits<int>::max()}, min_v{std::numeric_limits<int>::max()};
  int max_u{-1}, max_v{-1};

  void add(int u, int v, bool face) {
    ++pixels;
    face_pixels += face ? 1 : 0;
    min_u = std::min(min_u, u);
    min_v = std::min(min_v, v);
    max_u = std::max(max_u, u);
    max_v = std::max(max_v, v);
  }
  PixelBox box() const {
    return pixels == 0 ? PixelBox{} : PixelBox{min_u, min_v, max_u - min_u + 1, max_v - min_v + 1};
  }
};

std::vector<Region> regions_of(const cv::Mat& labels, const PeopleFigures& people) {
  std::vector<Region> regions(people.posed().size());
  for (int v = 0; v < labels.rows; ++v) {
    const uint16_t* row = labels.ptr<uint16_t>(v);
    for (int u = 0; u < labels.cols; ++u) {
      if (row[u] == 0) {
        continue;
      }
      if (const auto owner = people.owner_of(row[u])) {
        regions[owner->person].add(u, v, owner->face);
      }
    }
  }
  return regions;
}

// The box around the face outline's pixels, clipped to the image; nullopt when a point is
// behind the camera or nothing is left inside.
std::optional<PixelBox> face_box_of(const PinholeModel& model,
                                    const Eigen::Isometry3d& X_optical_head,
                                    const std::vector<Eigen::Vector3d>& outline) {
  double min_u = std::numeric_limits<double>::max(), min_v = min_u;
  double max_u = std::numeric_limits<double>::lowest(), max_v = max_u;
  for (const Eigen::Vector3d& point : outline) {
    const std::optional<Eigen::Vector2d> pixel = model.project(X_optical_head * point);
    if (!pixel) {
      return std::nullopt;
    }
    min_u = std::min(min_u, pixel->x());
    min_v = std::min(min_v, pixel->y());
    max_u = std::max(max_u, pixel->x());
    max_v = std::max(max_v, pixel->y());
  }
  const int x0 = std::max(0, static_cast<int>(std::lround(min_u)));
  const int y0 = std::max(0, static_cast<int>(std::lround(min_v)));
  const int x1 = std::min(model.width, static_cast<int>(std::lround(max_u)) + 1);
  const int y1 = std::min(model.height, static_cast<int>(std::lround(max_v)) + 1);
  if (x1 <= x0 || y1 <= y0) {
    return std::nullopt;
  }
  return PixelBox{x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

double PixelBox::iou(const PixelBox& other) const {
  const int x0 = std::max(x, other.x), y0 = std::max(y, other.y);
  const int x1 = std::min(x + width, other.x + other.width);
  const int y1 = std::min(y + height, other.y + other.height);
  const double overlap = std::max(0, x1 - x0) * static_cast<double>(std::max(0, y1 - y0));
  const double total = area() + other.area() - overlap;
  return total > 0.0 ? overlap / total : 0.0;
}

std::vector<PersonLabel> label_people(Renderer& renderer, const PinholeModel& model,
                                      const Eigen::Isometry3d& X_world_optical,
                                      const PeopleFigures& people, const cv::Mat& labels,
                                      const LabelOptions& options) {
  const std::vector<Region> seen = regions_of(labels, people);
  const Eigen::Isometry3d X_optical_world = X_world_optical.inverse();
  const Eigen::Vector3d camera = X_world_optical.translation();
  std::vector<PersonLabel> out;
  RenderedImage alone;
  ViewOptions solo;
  solo.colour = false;
  solo.labels = true;
  for (size_t i = 0; i < seen.size(); ++i) {
    if (seen[i].pixels < options.min_visible_pixels) {
      continue;
    }
    const PosedPerson& person = people.posed()[i];
    solo.only_dynamic = person.vertices;
    renderer.render(model, X_world_optical, solo, alone);
    const Region whole = regions_of(alone.labels, people)[i];

    PersonLabel label;
    label.person_id = person.id;
    label.body_box = seen[i].box();
    label.visible_pixels = seen[i].pixels;
    label.occlusion =
        whole.pixels > 0 ? std::clamp(1.0 - double(seen[i].pixels) / whole.pixels, 0.0, 1.0) : 0.0;
    const PixelBox full = whole.box();
    label.truncated = full.x == 0 || full.y == 0 || full.x + full.width == model.width ||
                      full.y + full.height == model.height;
    label.face_occlusion =
        whole.face_pixels > 0
            ? std::clamp(1.0 - double(seen[i].face_pixels) / whole.face_pixels, 0.0, 1.0)
            : 1.0;
    const Eigen::Isometry3d X_world_head = person.figure->head_frame(person.pose);
    const Eigen::Vector3d to_camera = (camera - X_world_head.translation()).normalized();
    label.face_yaw_deg =
        std::acos(std::clamp(X_world_head.linear().col(0).dot(to_camera), -1.0, 1.0)) * 180.0 /
        M_PI;
    if (label.face_yaw_deg < 90.0 && label.face_occlusion <= options.max_face_occlusion) {
      label.face_box =
          face_box_of(model, X_optical_world * X_world_head, person.figure->face_outline());
    }
    label.distance_m = (camera.head<2>() - person.pose.body.position).norm();
    label.mask = person.figure->appearance().mask;
    out.push_back(label);
  }
  return out;
}

}  // namespace ari_social_sim::physics
