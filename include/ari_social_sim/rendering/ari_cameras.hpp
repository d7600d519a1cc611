#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"

namespace ari_social_sim::rendering {

enum class CameraKind {
  kColour,   // pinhole colour image
  kRgbd,     // pinhole colour plus depth aligned to it (same optical frame and intrinsics)
  kFisheye,  // equidistant fisheye colour image
};

/// One of ARI's cameras: where it is mounted, what it produces and under which names. Defaults
/// come from ari_robot and ari_simulation (see docs/cameras.md for the choices made).
struct CameraSpec {
  std::string name;  // ROS namespace without the leading slash, e.g. "head_front_camera"
  CameraKind kind{CameraKind::kColour};
  std::string
      mount_frame;  // "base_footprint" (fixed mounts) or "head_2_link" (moves with the head)
  Eigen::Isometry3d X_mount_optical{Eigen::Isometry3d::Identity()};
  std::string optical_frame;  // frame_id of the images (REP-103: z forward, x right, y down)
  int width{0};               // pixels
  int height{0};
  double hfov_rad{0.0};  // horizontal field of view across the full width
  double rate_hz{0.0};
  bool enabled{true};
  double min_range_m{0.0};  // depth cameras: readings outside [min, max] are invalid
  double max_range_m{0.0};
  // ARI's topics, relative to the root namespace.
  std::string image_topic;
  std::string info_topic;
  std::string depth_topic;       // depth cameras only
  std::string depth_info_topic;  // depth cameras only
};

/// ARI v1's cameras with their default resolution, rate and mount: head_front_camera (moves with
/// pan and tilt), torso_front_camera (D435, RGB-D), front_fisheye_camera, rear_fisheye_camera and
/// the T265 pair torso_back_camera/fisheye1 and fisheye2 (the last four disabled, as on ARI without
/// spring_cameras).
std::vector<CameraSpec> ari_camera_specs();

/// Pose of head_2_link in base_footprint at the given head joint angles (ari_robot: pan about z,
/// positive to the left; tilt positive looking down).
Eigen::Isometry3d X_footprint_head_2(double head_1_rad, double head_2_rad);

/// Pose of a camera's optical frame in base_footprint at the given head joint angles (only the
/// head camera depends on them).
Eigen::Isometry3d X_footprint_optical(const CameraSpec& spec, double head_1_rad, double head_2_rad);

/// The same in the world, for ARI's base_footprint at a planar pose on the floor (2D mode, tests
/// and tools; with the 3D body the node takes the optical frames' poses from the physics core).
Eigen::Isometry3d X_world_optical(const CameraSpec& spec, const core::Pose2& X_world_footprint,
                                  double head_1_rad, double head_2_rad);

}  // namespace ari_social_sim::rendering
