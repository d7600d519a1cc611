#include "ari_social_sim/physics/ari_cameras.hpp"

#include <cmath>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::physics {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Optical frame (z forward, x right, y down) relative to a body-style frame (x forward, y left,
// z up) at the same point: REP-103's fixed rotation between the two.
Eigen::Matrix3d R_body_optical() {
  Eigen::Matrix3d R;
  R.col(0) = -Eigen::Vector3d::UnitY();
  R.col(1) = -Eigen::Vector3d::UnitZ();
  R.col(2) = Eigen::Vector3d::UnitX();
  return R;
}

// A mount at `position`, turned by yaw then pitched (positive pitch looks down), in its parent.
Eigen::Isometry3d mount(const Eigen::Vector3d& position, double yaw_rad, double pitch_rad) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = position;
  X.linear() = (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()))
                   .toRotationMatrix() *
               R_body_optical();
  return X;
}

CameraSpec fisheye(const std::string& name, const Eigen::Isometry3d& X_footprint_optical) {
  CameraSpec spec;
  spec.name = name;
  spec.kind = CameraKind::kFisheye;
  spec.mount_frame = "base_footprint";
  spec.X_mount_optical = X_footprint_optical;
  spec.optical_frame = name + "_optical_frame";
  spec.width = 1280;  // the Gazebo model's; the real ELP streams 3264 x 2448 MJPEG
  spec.height = 960;
  spec.hfov_rad = M_PI;
  spec.rate_hz = 5.0;  // the relay rate of /front_camera/fisheye on ARI
  spec.enabled = false;
  spec.image_topic = name + "/image_raw";
  spec.info_topic = name + "/camera_info";
  return spec;
}

}  // namespace

std::vector<CameraSpec> ari_camera_specs() {
  std::vector<CameraSpec> specs;

  // Head camera: the Raspberry Pi camera on head_2_link at (0.0634, 0.182, 0); head_2_link's z
  // points to the robot's right, so the camera's own frame is head_2_link turned -90 deg about x.
  CameraSpec head;
  head.name = "head_front_camera";
  head.kind = CameraKind::kColour;
  head.mount_frame = "head_2_link";
  head.X_mount_optical.translation() = Eigen::Vector3d(0.0634, 0.182, 0.0);
  head.X_mount_optical.linear() =
      Eigen::AngleAxisd(-90.0 * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix() *
      R_body_optical();
  head.optical_frame = "head_front_camera_color_optical_frame";
  head.width = 1280;
  head.height = 960;
  head.hfov_rad = 62.2 * kDeg;  // the real robot's lens (Gazebo's model uses 80 deg)
  head.rate_hz = 10.0;
  head.image_topic = "head_front_camera/color/image_raw";
  head.info_topic = "head_front_camera/color/camera_info";
  specs.push_back(head);

  // Torso D435: colour optical frame 0.015 m left of the depth frame at (-0.104, 0.018, 1.105),
  // pitched 42.5 deg down; depth is rendered in the colour frame (aligned_depth_to_color).
  CameraSpec torso;
  torso.name = "torso_front_camera";
  torso.kind = CameraKind::kRgbd;
  torso.mount_frame = "base_footprint";
  torso.X_mount_optical = mount({-0.104, 0.033, 1.105}, 0.0, 42.5 * kDeg);
  torso.optical_frame = "torso_front_camera_color_optical_frame";
  torso.width = 848;
  torso.height = 480;
  torso.hfov_rad = 69.4 * kDeg;  // D435 colour sensor
  torso.rate_hz = 15.0;
  torso.min_range_m = 0.2;
  torso.max_range_m = 10.0;
  torso.image_topic = "torso_front_camera/color/image_raw";
  torso.info_topic = "torso_front_camera/color/camera_info";
  torso.depth_topic = "torso_front_camera/aligned_depth_to_color/image_raw";
  torso.depth_info_topic = "torso_front_camera/aligned_depth_to_color/camera_info";
  specs.push_back(torso);

  // Fisheyes: front pitched 19 deg up, rear turned 180 deg and pitched 25 deg up.
  specs.push_back(fisheye("front_fisheye_camera", mount({-0.142, 0.0, 1.321}, 0.0, -19.0 * kDeg)));
  specs.push_back(
      fisheye("rear_fisheye_camera", mount({-0.321, 0.0, 1.288}, 180.0 * kDeg, -25.0 * kDeg)));

  // T265 behind the torso, facing backwards and pitched 15 deg down; its two fisheyes sit 64 mm
  // apart (the T265 baseline) across the pose frame at (-0.328, 0.009, 1.159). Which one is on
  // which side is not in the sources; fisheye1 is taken on the camera's left.
  for (int i = 1; i <= 2; ++i) {
    const double left_offset = i == 1 ? 0.032 : -0.032;
    // Facing backwards, the camera's left is the robot's -y.
    CameraSpec t265 = fisheye("torso_back_camera/fisheye" + std::to_string(i),
                              mount({-0.328, 0.009 - left_offset, 1.159}, M_PI, 15.0 * kDeg));
    t265.optical_frame = "torso_back_camera_fisheye" + std::to_string(i) + "_optical_frame";
    t265.width = 848;
    t265.height = 800;
    t265.hfov_rad = 163.0 * kDeg;  // T265 lens
    t265.rate_hz = 30.0;
    specs.push_back(t265);
  }
  return specs;
}

Eigen::Isometry3d X_footprint_head_2(double head_1_rad, double head_2_rad) {
  // base_footprint -> base_link (z 0.125) -> head_1_link (-0.2255, 0, 1.1915), pan about z ->
  // head_2_link (0.0425, 0, 0.093) rpy (90 deg, 0, 0), tilt about the child's -z.
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translate(Eigen::Vector3d(-0.2255, 0.0, 0.125 + 1.1915));
  X.rotate(Eigen::AngleAxisd(head_1_rad, Eigen::Vector3d::UnitZ()));
  X.translate(Eigen::Vector3d(0.0425, 0.0, 0.093));
  X.rotate(Eigen::AngleAxisd(90.0 * kDeg, Eigen::Vector3d::UnitX()));
  X.rotate(Eigen::AngleAxisd(head_2_rad, -Eigen::Vector3d::UnitZ()));
  return X;
}

Eigen::Isometry3d X_footprint_optical(const CameraSpec& spec, double head_1_rad,
                                      double head_2_rad) {
  if (spec.mount_frame == "base_footprint") {
    return spec.X_mount_optical;
  }
  if (spec.mount_frame == "head_2_link") {
    return X_footprint_head_2(head_1_rad, head_2_rad) * spec.X_mount_optical;
  }
  throw core::ConfigError("camera " + spec.name + ": mount_frame: expected base_footprint or " +
                          "head_2_link, got '" + spec.mount_frame + "'");
}

Eigen::Isometry3d X_world_optical(const CameraSpec& spec, const core::Pose2& X_world_footprint,
                                  double head_1_rad, double head_2_rad) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() =
      Eigen::Vector3d(X_world_footprint.position.x(), X_world_footprint.position.y(), 0.0);
  X.rotate(Eigen::AngleAxisd(X_world_footprint.theta, Eigen::Vector3d::UnitZ()));
  return X * X_footprint_optical(spec, head_1_rad, head_2_rad);
}

}  // namespace ari_social_sim::physics
