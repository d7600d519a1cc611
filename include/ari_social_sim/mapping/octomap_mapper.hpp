#pragma once

#include <octomap/OcTree.h>

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/rendering/camera_model.hpp"

namespace ari_social_sim::mapping {

/// Parameters of the mapping mode (D6.4 §3.5.1: ARI maps with its torso RGB-D camera).
struct MappingConfig {
  double resolution_m{0.05};
  double max_range_m{4.0};
  int pixel_stride{4};
  double min_height_m{0.1};
  double max_height_m{2.0};

  template <class V>
  void visit(V& v) {
    v.field("resolution_m", resolution_m, "voxel edge (m), also the 2D map's cell size",
            model::kMapResolutionBounds);
    v.field("max_range_m", max_range_m,
            "m; rays beyond are cleared up to here and leave no obstacle", core::positive());
    v.field("pixel_stride", pixel_stride, "every n-th pixel of every n-th row goes into the map",
            core::between(1.0, 64.0));
    v.field("min_height_m", min_height_m,
            "heights projected into the 2D map: above the floor's voxels ...");
    v.field("max_height_m", max_height_m, "... and up to ARI's height");
    v.rule("max_height_m", min_height_m < max_height_m,
           "a height above min_height_m (" + core::number_text(min_height_m) + ")",
           core::number_text(max_height_m));
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
  /// Reads the optional keys visit lists; unknown keys, out-of-range values and
  /// min_height_m >= max_height_m throw core::ConfigError.
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
  /// Throws core::ConfigError for an invalid config (MappingConfig::validate).
  explicit OctomapMapper(const MappingConfig& config);

  /// Casts the rays of a depth image (CV_32FC1 metres along the optical axis, NaN invalid) taken
  /// through `model` from the optical frame X_map_optical: free space along each ray, an obstacle
  /// at its end when it is within max_range_m.
  void insert_depth(const cv::Mat& depth_m, const rendering::PinholeModel& model,
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

}  // namespace ari_social_sim::mapping
