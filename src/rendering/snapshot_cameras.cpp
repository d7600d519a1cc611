#include "ari_social_sim/rendering/snapshot_cameras.hpp"

#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/rendering/ari_cameras.hpp"

namespace ari_social_sim::rendering {

SnapshotCameras::SnapshotCameras(CameraRig& rig, uint64_t seed) : rig_(rig), figures_(seed) {
  for (const CameraSpec& spec : rig_.cameras()) {
    if (spec.kind == CameraKind::kFisheye) {
      throw core::ConfigError(spec.name +
                              ": expected a pinhole camera (labels need one), got a fisheye");
    }
  }
  rig_.restart(seed);
}

std::vector<LabelledImage> SnapshotCameras::render_due(const world::WorldSnapshot& snapshot) {
  const std::vector<size_t> due = rig_.due(snapshot.time_s);
  std::vector<LabelledImage> images;
  if (due.empty()) {
    return images;
  }
  if (!snapshot.ari) {
    throw core::ConfigError("the world has no ARI: expected one, the cameras are ARI's");
  }
  people_.clear();
  for (const world::HumanSnapshot& human : snapshot.humans) {
    people_.push_back(figure_input_of(human));
  }
  // Posed only when a frame is due: the gait advances with the distance walked since the last
  // pose, however long ago that was.
  figures_.update(snapshot.time_s, people_);
  rig_.set_dynamic_mesh(figures_.mesh());
  for (size_t i : due) {
    const Eigen::Isometry3d X_world_optical = rendering::X_world_optical(
        rig_.cameras()[i], snapshot.ari->pose, snapshot.ari->head_pan_rad, /*head_2_rad=*/0.0);
    rig_.render(i, X_world_optical, frame_, /*labels=*/true);
    LabelledImage image;
    image.camera = i;
    image.time_s = snapshot.time_s;
    // A copy: the rig refills frame_'s buffers on the next render.
    image.colour = frame_.colour.clone();
    image.labels =
        label_people(rig_.renderer(), rig_.pinhole(i), X_world_optical, figures_, frame_.labels);
    images.push_back(std::move(image));
  }
  return images;
}

}  // namespace ari_social_sim::rendering
