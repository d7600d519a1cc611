#include "camera_interface.hpp"

#include <visualization_msgs/MarkerArray.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/rendering/physics_primitives.hpp"
#include "node_support/frames.hpp"
#include "node_support/image.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

// How often the mapping mode republishes /map and the voxels (Hz of sim time).
constexpr double kMapRateHz = 1.0;
constexpr char kTorsoCamera[] = "torso_front_camera";

rendering::CameraRigConfig rig_config(const physics::PhysicsRunConfig& config) {
  return config.cameras ? rendering::CameraRigConfig::from_yaml(*config.cameras)
                        : rendering::CameraRigConfig{};
}

// The mapper takes metres with NaN for no reading; the rig may give millimetres with 0.
cv::Mat depth_in_metres(const cv::Mat& depth) {
  if (depth.type() == CV_32FC1) {
    return depth;
  }
  cv::Mat metres;
  depth.convertTo(metres, CV_32FC1, 0.001);
  metres.setTo(std::numeric_limits<float>::quiet_NaN(), depth == 0);
  return metres;
}

}  // namespace

CameraInterface::CameraInterface(ros::NodeHandle& nh, const physics::PhysicsRunConfig& config,
                                 const model::WorldDescription& world,
                                 const physics::AriPhysics& physics)
    : physics_(physics),
      figures_(config.appearance_seed),
      rig_(rig_config(config), config.physics.seed),
      world_(world),
      map_file_(config.map_file) {
  // A relative map file lands in ROS_HOME (~/.ros), where ROS puts what nodes write.
  if (!map_file_.empty() && map_file_.front() != '/') {
    const char* ros_home = std::getenv("ROS_HOME");
    const char* home = std::getenv("HOME");
    map_file_ = (ros_home != nullptr ? std::string(ros_home)
                                     : std::string(home != nullptr ? home : ".") + "/.ros") +
                "/" + map_file_;
  }
  rig_.set_world(world, style_);
  for (size_t i = 0; i < rig_.cameras().size(); ++i) {
    const rendering::CameraSpec& camera = rig_.cameras()[i];
    if (physics.model().link_index(camera.optical_frame) < 0) {
      throw core::ConfigError(camera.name + ": the robot model has no frame '" +
                              camera.optical_frame + "'");
    }
    Publishers out;
    out.image = nh.advertise<sensor_msgs::Image>("/" + camera.image_topic, 2);
    out.info = nh.advertise<sensor_msgs::CameraInfo>("/" + camera.info_topic, 2);
    if (camera.kind != rendering::CameraKind::kFisheye) {
      // ARI relays its head camera compressed only; every colour camera gets both here.
      out.compressed =
          nh.advertise<sensor_msgs::CompressedImage>("/" + camera.image_topic + "/compressed", 2);
    }
    if (camera.kind == rendering::CameraKind::kRgbd) {
      out.depth = nh.advertise<sensor_msgs::Image>("/" + camera.depth_topic, 2);
      out.depth_info = nh.advertise<sensor_msgs::CameraInfo>("/" + camera.depth_info_topic, 2);
      if (camera.name == kTorsoCamera) {
        mapping_camera_ = i;
      }
    }
    publishers_.push_back(out);
  }
  if (config.mapping) {
    if (!mapping_camera_) {
      throw core::ConfigError("mapping: needs the torso_front_camera, which is disabled");
    }
    mapper_.emplace(config.mapping_params
                        ? mapping::MappingConfig::from_yaml(*config.mapping_params)
                        : mapping::MappingConfig{});
    map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("/map", 1, /*latch=*/true);
    // octomap_server's topic for the occupied voxels.
    voxels_pub_ = nh.advertise<visualization_msgs::MarkerArray>("/occupied_cells_vis_array", 1);
    ros::NodeHandle private_handle("~");
    save_service_ = private_handle.advertiseService("save_map", &CameraInterface::save_map, this);
  }
}

bool CameraInterface::wanted(size_t camera) const {
  const Publishers& p = publishers_[camera];
  const auto listened = [](const ros::Publisher& publisher) {
    return publisher && publisher.getNumSubscribers() > 0;
  };
  return listened(p.image) || listened(p.compressed) || listened(p.info) || listened(p.depth) ||
         listened(p.depth_info) || (mapper_ && mapping_camera_ == camera);
}

void CameraInterface::update(const ros::Time& stamp) {
  const std::vector<size_t> due = rig_.due(physics_.time_s());
  bool scene_ready = false;
  for (const size_t i : due) {
    if (!wanted(i)) {
      continue;
    }
    if (!scene_ready) {
      // The moving part of the scene, once per tick that renders: people and ARI's own body.
      std::vector<rendering::FigureInput> people;
      for (const physics::PersonState& person : physics_.people_states()) {
        people.push_back(rendering::figure_input_of(person));
      }
      figures_.update(physics_.time_s(), people);
      rendering::RenderMesh moving = figures_.mesh();
      for (const rendering::RenderPrimitive& part :
           rendering::robot_primitives(physics_.model(), physics_.link_poses())) {
        rendering::append_primitive(part, moving);
      }
      rig_.set_dynamic_mesh(moving);
      scene_ready = true;
    }
    const rendering::CameraSpec& camera = rig_.cameras()[i];
    const Eigen::Isometry3d X_map_optical = physics_.frame_pose(camera.optical_frame);
    rig_.render(i, X_map_optical, frame_);
    std_msgs::Header header;
    header.stamp = stamp;
    header.frame_id = camera.optical_frame;
    sensor_msgs::CameraInfo info = to_msg(rig_.info(i));
    info.header = header;
    const Publishers& p = publishers_[i];
    if (p.image.getNumSubscribers() > 0) {
      sensor_msgs::Image image = to_image_msg(frame_.colour);
      image.header = header;
      p.image.publish(image);
    }
    if (p.compressed && p.compressed.getNumSubscribers() > 0) {
      sensor_msgs::CompressedImage compressed = to_compressed_msg(frame_.colour);
      compressed.header = header;
      p.compressed.publish(compressed);
    }
    p.info.publish(info);
    if (camera.kind == rendering::CameraKind::kRgbd) {
      if (p.depth.getNumSubscribers() > 0) {
        sensor_msgs::Image depth = to_image_msg(frame_.depth);
        depth.header = header;
        p.depth.publish(depth);
      }
      p.depth_info.publish(info);
    }
    if (mapper_ && mapping_camera_ == i) {
      mapper_->insert_depth(depth_in_metres(frame_.depth),
                            rendering::PinholeModel::from_horizontal_fov(
                                camera.width, camera.height, camera.hfov_rad),
                            X_map_optical);
    }
  }
  if (mapper_ && physics_.time_s() >= next_map_s_) {
    next_map_s_ = physics_.time_s() + 1.0 / kMapRateHz;
    publish_map(stamp);
  }
}

void CameraInterface::publish_map(const ros::Time& stamp) {
  // The world's floor rectangle, in whole cells of the map's resolution.
  const double resolution = mapper_->config().resolution_m;
  const int width = static_cast<int>(std::ceil(world_.size.x() / resolution));
  const int height = static_cast<int>(std::ceil(world_.size.y() / resolution));
  map_pub_.publish(
      to_msg(mapper_->project_to_grid(world_.origin, width, height), kMapFrame, stamp.toSec()));
  if (voxels_pub_.getNumSubscribers() == 0) {
    return;
  }
  // One cube list per voxel size: the octree merges uniform regions into larger leaves. Only the
  // voxels of the height band that makes /map: the floor's would hide the map under them.
  std::map<double, visualization_msgs::Marker> by_size;
  for (const mapping::Voxel& voxel : mapper_->occupied_voxels()) {
    if (voxel.centre.z() < mapper_->config().min_height_m) {
      continue;
    }
    visualization_msgs::Marker& cubes = by_size[voxel.size_m];
    if (cubes.points.empty()) {
      cubes.header.frame_id = kMapFrame;
      cubes.header.stamp = stamp;
      cubes.ns = "occupied";
      cubes.id = static_cast<int>(by_size.size());
      cubes.type = visualization_msgs::Marker::CUBE_LIST;
      cubes.scale.x = cubes.scale.y = cubes.scale.z = voxel.size_m;
      cubes.pose.orientation.w = 1.0;
      cubes.color.r = 0.2f;
      cubes.color.g = 0.6f;
      cubes.color.b = 1.0f;
      cubes.color.a = 0.8f;
    }
    geometry_msgs::Point point;
    point.x = voxel.centre.x();
    point.y = voxel.centre.y();
    point.z = voxel.centre.z();
    cubes.points.push_back(point);
  }
  visualization_msgs::MarkerArray markers;
  for (auto& [size, cubes] : by_size) {
    markers.markers.push_back(cubes);
  }
  voxels_pub_.publish(markers);
}

bool CameraInterface::save_map(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  try {
    mapper_->save_binary(map_file_);
    response.success = true;
    response.message = "saved " + map_file_;
  } catch (const core::Error& e) {
    response.success = false;
    response.message = e.what();
  }
  return true;
}

}  // namespace ari_social_sim::nodes
