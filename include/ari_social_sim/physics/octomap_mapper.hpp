#pragma once

#include <octomap/OcTree.h>

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/physics/camera_model.hpp"

namespace ari_social_sim::physics {

/// Parameters of the mapping mode (D6.4 §3.5.1: ARI maps with its torso RGB-D camera).
struct MappingConfig {
  double resolution_m{0.05};  // voxel edge, also the 2D map's cell size
  double max_range_m{4.0};    // rays beyond are cleared up to here and leave no obstacle
  int pixel_stride{4};        // every n-th pixel of every n-th row goes into the map
  double min_height_m{0.1};   // heights projected into the 2D map: above the floor's voxels...
  double max_height_m{2.0};   // ...and up to ARI's height

  /// Optional keys resolution_m, max_range_m, pixel_stride, min_height_m, max_height_m; unknown
  /// keys, out-of-range values and min_height_m >= max_height_m throw core::ConfigError.
  static MappingConfig from_yaml(const core::YamlMap& map);
};

/// An occupied voxel for display: centre in the map frame and edge length (m).
struct Voxel {
  Eigen::Vector3d centre;
  double size_m;
};

/// A 3D occupancy map (OctoMap's probabilistic octree) filled from depth images, with the 2D
/// projection ARI's navigation uses.
class OctomapMapper {
 public:
  explicit OctomapMapper(const MappingConfig& config);

  /// Casts the rays of a depth image (CV_32FC1 metres along the optical axis, NaN invalid) taken
  /// through `model` from the optical frame X_map_optical: free space along each ray, an obstacle
  /// at its end when it is within max_range_m.
  void insert_depth(const cv::Mat& depth_m, const PinholeModel& model,
                    const Eigen::Isometry3d& X_map_optical);

  /// Writes the map as an OctoMap binary (.bt) file; throws core::Error when it cannot.
  void save_binary(const std::string& path) const;

  /// The 2D occupancy grid over the given cells (aligned to the voxel grid when origin is a
  /// multiple of the resolution): a cell is occupied when a voxel of its column within
  /// [min_height_m, max_height_m] is, free when the column has only free voxels there, unknown
  /// when none was observed.
  model::OccupancyGrid project_to_grid(const Eigen::Vector2d& origin, int width, int height) const;

  /// Occupied voxels (leaves, merged where the tree pruned them), for rviz markers.
  std::vector<Voxel> occupied_voxels() const;

  const octomap::OcTree& tree() const { return tree_; }
  const MappingConfig& config() const { return config_; }

 private:
  MappingConfig config_;
  octomap::OcTree tree_;
};

}  // namespace ari_social_sim::physics
