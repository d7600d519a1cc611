#include "ari_social_sim/rendering/frame_motion.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ari_social_sim::rendering {
namespace {

constexpr double kBackgroundDepthM = 3.0;  // a room's depth, for the camera's own travel
// Frames further apart tell where someone went, not how they moved while a shutter was open.
constexpr double kLongestGapPeriods = 2.0;
constexpr double kLongestGapS = 0.25;
// Faster than anyone runs indoors: a label that jumped further is someone else's now (labels
// follow the order people are given in), not a person in motion.
constexpr double kFastestPersonMps = 4.0;

// Where a world point lands in the image of a camera at X_world_optical; nothing behind it.
std::optional<Eigen::Vector2d> pixel_of(const Eigen::Vector3d& p_world,
                                        const Eigen::Isometry3d& X_world_optical,
                                        const PinholeModel& pinhole) {
  return pinhole.project(X_world_optical.inverse() * p_world);
}

}  // namespace

std::map<uint16_t, Eigen::Vector3f> label_centres(const RenderMesh& mesh) {
  // Indexed by label (a few per person): a map lookup per vertex cost more than the sums.
  std::vector<Eigen::Vector3d> sums;
  std::vector<size_t> counts;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const float* vertex = &mesh.vertices[v * RenderMesh::kFloatsPerVertex];
    const auto label = static_cast<uint16_t>(std::lround(vertex[RenderMesh::kLabelOffset]));
    if (label == 0) {
      continue;
    }
    if (label >= sums.size()) {
      sums.resize(label + 1, Eigen::Vector3d::Zero());
      counts.resize(label + 1, 0);
    }
    sums[label] += Eigen::Vector3d(vertex[0], vertex[1], vertex[2]);
    ++counts[label];
  }
  std::map<uint16_t, Eigen::Vector3f> centres;
  for (size_t label = 1; label < sums.size(); ++label) {
    if (counts[label] > 0) {
      centres[static_cast<uint16_t>(label)] = (sums[label] / counts[label]).cast<float>();
    }
  }
  return centres;
}

ImageMotion FrameMotion::per_second(double time_s, double period_s,
                                    const Eigen::Isometry3d& X_world_optical,
                                    const PinholeModel& pinhole,
                                    const std::map<uint16_t, Eigen::Vector3f>& label_centres) {
  ImageMotion motion;
  const double elapsed_s = last_time_s_ ? time_s - *last_time_s_ : 0.0;
  if (elapsed_s > 0.0 && elapsed_s <= std::min(kLongestGapPeriods * period_s, kLongestGapS)) {
    const auto moved = [&](const Eigen::Vector3d& before,
                           const Eigen::Vector3d& now) -> std::optional<Eigen::Vector2f> {
      const auto from = pixel_of(before, X_world_last_, pinhole);
      const auto to = pixel_of(now, X_world_optical, pinhole);
      if (!from || !to) {
        return std::nullopt;
      }
      return ((*to - *from) / elapsed_s).cast<float>();
    };
    const Eigen::Vector3d ahead = X_world_optical * Eigen::Vector3d(0.0, 0.0, kBackgroundDepthM);
    motion.background = moved(ahead, ahead).value_or(Eigen::Vector2f::Zero());
    for (const auto& [label, centre] : label_centres) {
      const auto last = last_centres_.find(label);
      if (last == last_centres_.end() ||
          (centre - last->second).norm() > kFastestPersonMps * elapsed_s) {
        continue;
      }
      if (const auto shift = moved(last->second.cast<double>(), centre.cast<double>())) {
        motion.labelled[label] = *shift;
      }
    }
  }
  last_time_s_ = time_s;
  X_world_last_ = X_world_optical;
  last_centres_ = label_centres;
  return motion;
}

}  // namespace ari_social_sim::rendering
