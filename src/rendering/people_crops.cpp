#include "ari_social_sim/rendering/people_crops.hpp"

#include "ari_social_sim/rendering/region_crops.hpp"

namespace ari_social_sim::rendering {

std::map<uint32_t, PixelBox> face_boxes(const std::vector<PosedPerson>& posed,
                                        const PinholeModel& camera,
                                        const Eigen::Isometry3d& X_map_optical) {
  std::map<uint32_t, PixelBox> boxes;
  for (const PosedPerson& person : posed) {
    if (const std::optional<PixelBox> box =
            face_region(*person.figure, person.pose, camera, X_map_optical)) {
      boxes[person.id] = *box;
    }
  }
  return boxes;
}

std::optional<FaceImages> face_images(const PosedPerson& person, const CameraView& view,
                                      int face_size, FaceImagesWanted wanted) {
  const std::optional<PixelBox> box =
      face_region(*person.figure, person.pose, view.camera, view.X_map_optical);
  if (!box) {
    return std::nullopt;
  }
  FaceImages images;
  if (wanted.cropped) {
    images.cropped = letterboxed(view.image, *box, face_size);
  }
  if (wanted.aligned) {
    if (const std::optional<std::array<Eigen::Vector2d, 2>> eyes =
            eye_pixels(*person.figure, person.pose, view.camera, view.X_map_optical)) {
      images.aligned = aligned_face(view.image, *box, (*eyes)[0], (*eyes)[1], face_size);
    }
  }
  return images;
}

std::optional<cv::Mat> body_image(const PosedPerson& person, const CameraView& view) {
  const std::optional<PixelBox> box =
      posed_body_region(*person.figure, person.pose, view.camera, view.X_map_optical);
  if (!box) {
    return std::nullopt;
  }
  return cut_out(view.image, *box);
}

}  // namespace ari_social_sim::rendering
