#include "ari_social_sim/mapping/octomap_mapper.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::mapping {

void MappingConfig::validate() const {
  core::check_fields(*this, "MappingConfig");
}

MappingConfig MappingConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<MappingConfig>(map);
}

OctomapMapper::OctomapMapper(const MappingConfig& config)
    : config_(core::validated(config)), tree_(config.resolution_m) {}

void OctomapMapper::insert_depth(const cv::Mat& depth_m, const rendering::PinholeModel& model,
                                 const Eigen::Isometry3d& X_map_optical) {
  octomap::Pointcloud cloud;
  const int stride = config_.pixel_stride;
  for (int v = stride / 2; v < depth_m.rows; v += stride) {
    const float* row = depth_m.ptr<float>(v);
    for (int u = stride / 2; u < depth_m.cols; u += stride) {
      const float depth = row[u];
      if (!std::isfinite(depth)) {
        continue;
      }
      const Eigen::Vector3d point = X_map_optical * (model.ray(u, v) * depth);
      cloud.push_back(static_cast<float>(point.x()), static_cast<float>(point.y()),
                      static_cast<float>(point.z()));
    }
  }
  const Eigen::Vector3d origin = X_map_optical.translation();
  // Points beyond max_range_m clear their ray up to it and mark nothing (OctoMap's maxrange);
  // discretising merges rays ending in the same voxel, which a dense depth image has many of.
  tree_.insertPointCloud(
      cloud,
      octomap::point3d(static_cast<float>(origin.x()), static_cast<float>(origin.y()),
                       static_cast<float>(origin.z())),
      config_.max_range_m, false, true);
}

void OctomapMapper::save_binary(const std::string& path) const {
  // The const writer thresholds each leaf on the way out; writeBinary would first turn the tree
  // itself to maximum likelihood and lose the probabilities mapping goes on updating.
  if (!tree_.writeBinaryConst(path)) {
    throw core::Error("cannot write the OctoMap to '" + path + "'");
  }
}

model::OccupancyGrid OctomapMapper::project_to_grid(const Eigen::Vector2d& origin, int width,
                                                    int height) const {
  model::OccupancyGrid grid;
  grid.origin = origin;
  grid.resolution_m = config_.resolution_m;
  grid.width = width;
  grid.height = height;
  grid.cells.assign(static_cast<size_t>(width) * height, model::OccupancyGrid::kUnknown);
  const double r = config_.resolution_m;
  const octomap::point3d low(static_cast<float>(origin.x()), static_cast<float>(origin.y()),
                             static_cast<float>(config_.min_height_m));
  const octomap::point3d high(static_cast<float>(origin.x() + width * r),
                              static_cast<float>(origin.y() + height * r),
                              static_cast<float>(config_.max_height_m));
  for (auto it = tree_.begin_leafs_bbx(low, high); it != tree_.end_leafs_bbx(); ++it) {
    const double half = 0.5 * it.getSize();
    // Leaves only touching the band's limits (the floor's voxels end at z = 0.05) do not count.
    if (it.getZ() + half <= config_.min_height_m + 1e-6 ||
        it.getZ() - half >= config_.max_height_m - 1e-6) {
      continue;
    }
    const bool occupied = tree_.isNodeOccupied(*it);
    // A pruned leaf covers several cells.
    const int x0 =
        std::max(0, static_cast<int>(std::floor((it.getX() - half - origin.x()) / r + 1e-6)));
    const int y0 =
        std::max(0, static_cast<int>(std::floor((it.getY() - half - origin.y()) / r + 1e-6)));
    const int x1 = std::min(
        width - 1, static_cast<int>(std::ceil((it.getX() + half - origin.x()) / r - 1e-6)) - 1);
    const int y1 = std::min(
        height - 1, static_cast<int>(std::ceil((it.getY() + half - origin.y()) / r - 1e-6)) - 1);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        int8_t& cell = grid.cells[static_cast<size_t>(y) * width + x];
        if (occupied) {
          cell = model::OccupancyGrid::kOccupied;
        } else if (cell == model::OccupancyGrid::kUnknown) {
          cell = model::OccupancyGrid::kFree;
        }
      }
    }
  }
  return grid;
}

std::vector<Voxel> OctomapMapper::occupied_voxels() const {
  std::vector<Voxel> voxels;
  for (auto it = tree_.begin_leafs(); it != tree_.end_leafs(); ++it) {
    if (tree_.isNodeOccupied(*it)) {
      voxels.push_back({Eigen::Vector3d(it.getX(), it.getY(), it.getZ()), it.getSize()});
    }
  }
  return voxels;
}

}  // namespace ari_social_sim::mapping
