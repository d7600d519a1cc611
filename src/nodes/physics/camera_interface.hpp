#pragma once

#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <optional>
#include <vector>

#include "ari_social_sim/mapping/octomap_mapper.hpp"
#include "ari_social_sim/physics/ari_physics.hpp"
#include "ari_social_sim/physics/physics_run_config.hpp"
#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"

namespace ari_social_sim::nodes {

/// ARI's cameras and the mapping mode on the ROS graph (docs/cameras.md, docs/physics.md): renders
/// each enabled camera at its rate from the physics' frames, for as long as someone subscribes to
/// one of its topics, and publishes image, /compressed (colour cameras), camera_info and the
/// aligned depth. In mapping mode the torso depth also fills an OctoMap, projected to /map.
class CameraInterface {
 public:
  /// Throws core::ConfigError for bad camera or mapping parameters and physics::RenderError when no
  /// headless OpenGL context can be made.
  CameraInterface(ros::NodeHandle& nh, const physics::PhysicsRunConfig& config,
                  const model::WorldDescription& world, const physics::AriPhysics& physics);

  /// Renders and publishes what is due at the physics' time, stamped `stamp`.
  void update(const ros::Time& stamp);

 private:
  struct Publishers {
    ros::Publisher image, compressed, info, depth, depth_info;
  };

  bool wanted(size_t camera) const;
  void publish_map(const ros::Time& stamp);
  bool save_map(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);

  const physics::AriPhysics& physics_;
  rendering::SceneStyle style_;
  rendering::PeopleFigures figures_;
  rendering::CameraRig rig_;
  std::vector<Publishers> publishers_;
  rendering::CameraFrame frame_;
  // Mapping mode.
  std::optional<mapping::OctomapMapper> mapper_;
  std::optional<size_t> mapping_camera_;  // the torso RGB-D camera
  model::WorldDescription world_;
  std::string map_file_;
  double next_map_s_{0.0};
  ros::Publisher map_pub_, voxels_pub_;
  ros::ServiceServer save_service_;
};

}  // namespace ari_social_sim::nodes
