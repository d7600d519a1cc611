#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "../rendering/render_test_scenes.hpp"
#include "ari_social_sim/mapping/octomap_mapper.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/world/map_sensor.hpp"

namespace ari_social_sim::mapping {
namespace {

int8_t cell_at(const model::OccupancyGrid& grid, double x, double y) {
  int cx = 0, cy = 0;
  EXPECT_TRUE(grid.cell_of({x, y}, cx, cy));
  return grid.at(cx, cy);
}

// A mapper that has seen one depth image reading `depth_m` on every pixel, taken by a level camera
// 1 m up facing +x.
OctomapMapper mapper_after_uniform_depth(const rendering::PinholeModel& model, float depth_m,
                                         const MappingConfig& config) {
  const cv::Mat depth(model.height, model.width, CV_32FC1, cv::Scalar(depth_m));
  OctomapMapper mapper(config);
  mapper.insert_depth(depth, model, rendering::test::level_camera_facing_x({0.0, 0.0, 1.0}));
  return mapper;
}

// A synthetic depth image of a wall 2 m ahead: free space up to it, occupied at it, unknown
// behind it.
TEST(OctomapMapper, WallAheadIsOccupiedWithFreeSpaceBeforeIt) {
  // Every pixel: at 2 m the pixels are 2 / 146.4 = 0.014 m apart, so every cell gets rays (a
  // stride of 4 would leave 0.055 m gaps, wider than a cell).
  MappingConfig config;
  config.pixel_stride = 1;
  // The wall plane is x = 2.0 (inside voxel [2.0, 2.05)).
  const OctomapMapper mapper = mapper_after_uniform_depth(
      rendering::PinholeModel::from_horizontal_fov(160, 120, 1.0), 2.0f, config);
  const model::OccupancyGrid grid = mapper.project_to_grid({-1.0, -2.0}, 80, 80);
  EXPECT_EQ(cell_at(grid, 2.02, 0.0), model::OccupancyGrid::kOccupied);
  EXPECT_EQ(cell_at(grid, 1.0, 0.0), model::OccupancyGrid::kFree);
  EXPECT_EQ(cell_at(grid, 0.2, 0.0), model::OccupancyGrid::kFree);
  EXPECT_EQ(cell_at(grid, 2.5, 0.0), model::OccupancyGrid::kUnknown);
  EXPECT_EQ(cell_at(grid, -0.5, 0.0), model::OccupancyGrid::kUnknown);
  // The wall's image spans 2 * 2 tan(0.5) = 2.19 m across: about 44 occupied cells in one column.
  int occupied = 0;
  for (int y = 0; y < grid.height; ++y) {
    int x = 0, unused = 0;
    grid.cell_of({2.02, 0.0}, x, unused);
    occupied += grid.at(x, y) == model::OccupancyGrid::kOccupied ? 1 : 0;
  }
  EXPECT_NEAR(occupied, 44, 2);
  EXPECT_GT(mapper.occupied_voxels().size(), 400u);  // the wall's 2.19 x 1.2 m patch
}

TEST(OctomapMapper, RangesBeyondMaxRangeClearWithoutMarking) {
  MappingConfig config;
  config.max_range_m = 4.0;
  const OctomapMapper mapper = mapper_after_uniform_depth(
      rendering::PinholeModel::from_horizontal_fov(80, 60, 0.5), 9.0f, config);
  EXPECT_TRUE(mapper.occupied_voxels().empty());
  const model::OccupancyGrid grid = mapper.project_to_grid({-1.0, -2.0}, 200, 80);
  EXPECT_EQ(cell_at(grid, 3.5, 0.0), model::OccupancyGrid::kFree);
  EXPECT_EQ(cell_at(grid, 5.0, 0.0), model::OccupancyGrid::kUnknown);
}

TEST(OctomapMapper, SavesAReadableBinaryOctomap) {
  OctomapMapper mapper = mapper_after_uniform_depth(
      rendering::PinholeModel::from_horizontal_fov(160, 120, 1.0), 2.0f, {});
  const std::string path = ::testing::TempDir() + "/test_map.bt";
  mapper.save_binary(path);
  octomap::OcTree loaded(0.1);
  ASSERT_TRUE(loaded.readBinary(path));
  EXPECT_DOUBLE_EQ(loaded.getResolution(), 0.05);
  size_t occupied = 0;
  for (auto it = loaded.begin_leafs(); it != loaded.end_leafs(); ++it) {
    occupied += loaded.isNodeOccupied(*it) ? 1 : 0;
  }
  EXPECT_EQ(occupied, mapper.occupied_voxels().size());
  std::remove(path.c_str());
  EXPECT_THROW(mapper.save_binary("/nonexistent/dir/map.bt"), core::Error);
}

TEST(MappingConfig, RejectsBadFields) {
  EXPECT_NO_THROW(MappingConfig::from_yaml(core::YamlMap::parse("{}", "m")));
  EXPECT_THROW(MappingConfig::from_yaml(core::YamlMap::parse("{resolution_m: 0}", "m")),
               core::ConfigError);
  EXPECT_THROW(
      MappingConfig::from_yaml(core::YamlMap::parse("{min_height_m: 2, max_height_m: 1}", "m")),
      core::ConfigError);
  EXPECT_THROW(MappingConfig::from_yaml(core::YamlMap::parse("{max_rnage_m: 3}", "m")),
               core::ConfigError);
}

TEST(MappingConfig, ValidateRefusesABadValueBuiltInCode) {
  MappingConfig config;
  EXPECT_NO_THROW(config.validate());
  config.min_height_m = 2.5;
  // The mapper checks the config it is given.
  try {
    OctomapMapper mapper(config);
    ADD_FAILURE() << "accepted min_height_m above max_height_m";
  } catch (const core::ConfigError& e) {
    EXPECT_STREQ(e.what(),
                 "MappingConfig: max_height_m: expected a height above min_height_m (2.5), got 2");
  }
}

// ARI's route through the waiting room: waypoints of base_footprint, with a full turn on the spot
// at each one so that the torso camera (pitched 42.5 deg down, seeing 0.5 to 2.8 m ahead) sweeps
// around.
std::vector<core::Pose2> waiting_room_drive() {
  const std::vector<Eigen::Vector2d> waypoints{{2.0, 1.5},  {6.0, 1.5}, {7.5, 3.0}, {10.0, 3.2},
                                               {10.5, 5.5}, {9.0, 7.0}, {6.0, 7.0}, {3.0, 7.0},
                                               {1.5, 5.0},  {1.8, 2.5}, {4.0, 3.5}};
  std::vector<core::Pose2> poses;
  for (size_t i = 0; i < waypoints.size(); ++i) {
    const Eigen::Vector2d& from = waypoints[i];
    for (int k = 0; k < 12; ++k) {
      poses.push_back({from, k * M_PI / 6});
    }
    if (i + 1 == waypoints.size()) {
      break;
    }
    const Eigen::Vector2d leg = waypoints[i + 1] - from;
    const double heading = std::atan2(leg.y(), leg.x());
    for (double s = 0.0; s < leg.norm(); s += 0.25) {
      poses.push_back({from + s * leg.normalized(), heading});
    }
  }
  return poses;
}

// Must-show 4: the projected OctoMap agrees with the world's rasterised map on at least 90% of the
// cells it observed.
TEST(OctomapMapper, DrivingThroughTheWaitingRoomMatchesTheRasterisedMap) {
  const model::WorldDescription world =
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml");
  rendering::CameraRigConfig rig_config;
  for (rendering::CameraSpec& spec : rig_config.cameras) {
    spec.enabled = spec.name == "torso_front_camera";
  }
  rendering::CameraRig rig(rig_config);
  rig.set_world(world, rendering::SceneStyle{});
  rig.set_dynamic_mesh({});
  const rendering::CameraInfo& info = rig.info(0);
  const rendering::PinholeModel model{info.width, info.height, info.K[0],
                                      info.K[4],  info.K[2],   info.K[5]};

  OctomapMapper mapper(MappingConfig{});
  rendering::CameraFrame frame;
  const std::vector<core::Pose2> drive = waiting_room_drive();
  for (const core::Pose2& pose : drive) {
    const Eigen::Isometry3d X_world_optical =
        rendering::X_world_optical(rig.cameras()[0], pose, 0, 0);
    rig.render(0, X_world_optical, frame);
    mapper.insert_depth(frame.depth, model, X_world_optical);
  }

  const model::OccupancyGrid truth = world::rasterize_static_map(world, 0.05);
  const model::OccupancyGrid built =
      mapper.project_to_grid(truth.origin, truth.width, truth.height);
  size_t observed = 0, agree = 0, observed_occupied = 0, agree_occupied = 0;
  for (size_t i = 0; i < built.cells.size(); ++i) {
    if (built.cells[i] == model::OccupancyGrid::kUnknown) {
      continue;
    }
    ++observed;
    agree += built.cells[i] == truth.cells[i] ? 1 : 0;
    if (built.cells[i] == model::OccupancyGrid::kOccupied) {
      ++observed_occupied;
      agree_occupied += truth.cells[i] == model::OccupancyGrid::kOccupied ? 1 : 0;
    }
  }
  const double agreement = static_cast<double>(agree) / observed;
  std::printf(
      "%zu poses; %zu of %zu cells observed (%.1f%%); agreement %.2f%%; built occupied cells "
      "%zu, of which %.2f%% occupied in the rasterised map\n",
      drive.size(), observed, built.cells.size(), 100.0 * observed / built.cells.size(),
      100.0 * agreement, observed_occupied, 100.0 * agree_occupied / observed_occupied);
  EXPECT_GT(observed, built.cells.size() / 4);  // a real part of the room was seen
  EXPECT_GE(agreement, 0.90);
  EXPECT_GT(observed_occupied, 500u);
}

}  // namespace
}  // namespace ari_social_sim::mapping
