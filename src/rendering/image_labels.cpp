#include "ari_social_sim/rendering/image_labels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ari_social_sim::rendering {
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

}  // namespace

std::vector<PersonLabel> label_people(Renderer& renderer, const PinholeModel& model,
                                      const Eigen::Isometry3d& X_world_optical,
                                      const PeopleFigures& people, const cv::Mat& labels,
                                      const LabelOptions& options) {
  const std::vector<Region> seen = regions_of(labels, people);
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
    label.truncated = full.reaches_border(model.width, model.height);
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
      label.face_box = face_outline_region(*person.figure, person.pose, model, X_world_optical);
    }
    label.distance_m = (camera.head<2>() - person.pose.body.position).norm();
    label.mask = person.figure->appearance().mask;
    label.skin_tone = person.figure->appearance().skin_tone;
    label.seated = person.pose.seated >= 0.5;
    out.push_back(label);
  }
  return out;
}

}  // namespace ari_social_sim::rendering
