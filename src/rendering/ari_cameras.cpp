#include "ari_social_sim/rendering/ari_cameras.hpp"

#include <cmath>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/model/ari_sensor_geometry.hpp"

namespace ari_social_sim::rendering {
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

Eigen::Vector3d vector_of(const model::MountPoint& point) {
  return {point.x_m, point.y_m, point.z_m};
}

// A mount at `position`, turned by yaw then pitched (positive pitch looks down), in its parent.
Eigen::Isometry3d mount(const model::MountPoint& position, double yaw_rad, double pitch_rad) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = vector_of(position);
  X.linear() = (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()))
                   .toRotationMatrix() *
               R_body_optical();
  return X;
}

void set_image(CameraSpec& spec, const model::CameraGeometry& geometry) {
  spec.width = geometry.width_px;
  spec.height = geometry.height_px;
  spec.hfov_rad = geometry.hfov_deg * kDeg;
}

CameraSpec fisheye(const std::string& name, const Eigen::Isometry3d& X_footprint_optical) {
  CameraSpec spec;
  spec.name = name;
  spec.kind = CameraKind::kFisheye;
  spec.mount_frame = "base_footprint";
  spec.X_mount_optical = X_footprint_optical;
  spec.optical_frame = name + "_optical_frame";
  set_image(spec, model::kFisheyeCamera);
  spec.rate_hz = 5.0;  // the relay rate of /front_camera/fisheye on ARI
  spec.enabled = false;
  spec.image_topic = name + "/image_raw";
  spec.info_topic = name + "/camera_info";
  return spec;
}

}  // namespace

std::vector<CameraSpec> ari_camera_specs() {
  std::vector<CameraSpec> specs;

  // Head camera on head_2_link; head_2_link's z points to the robot's right, so the camera's own
  // frame is head_2_link turned -90 deg about x.
  CameraSpec head;
  head.name = "head_front_camera";
  head.kind = CameraKind::kColour;
  head.mount_frame = "head_2_link";
  head.X_mount_optical.translation() = vector_of(model::kHeadCameraInTiltLink);
  head.X_mount_optical.linear() =
      Eigen::AngleAxisd(-90.0 * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix() *
      R_body_optical();
  head.optical_frame = "head_front_camera_color_optical_frame";
  set_image(head, model::kHeadCamera);
  head.rate_hz = 10.0;
  head.image_topic = "head_front_camera/color/image_raw";
  head.info_topic = "head_front_camera/color/camera_info";
  specs.push_back(head);

  // Torso D435: depth is rendered in the colour frame (aligned_depth_to_color).
  CameraSpec torso;
  torso.name = "torso_front_camera";
  torso.kind = CameraKind::kRgbd;
  torso.mount_frame = "base_footprint";
  torso.X_mount_optical =
      mount(model::kTorsoCameraInFootprint, 0.0, model::kTorsoCameraPitchDownDeg * kDeg);
  torso.optical_frame = "torso_front_camera_color_optical_frame";
  set_image(torso, model::kTorsoCamera);
  torso.rate_hz = 15.0;
  torso.min_range_m = model::kTorsoCameraMinRangeM;
  torso.max_range_m = model::kTorsoCameraMaxRangeM;
  torso.image_topic = "torso_front_camera/color/image_raw";
  torso.info_topic = "torso_front_camera/color/camera_info";
  torso.depth_topic = "torso_front_camera/aligned_depth_to_color/image_raw";
  torso.depth_info_topic = "torso_front_camera/aligned_depth_to_color/camera_info";
  specs.push_back(torso);

  // Fisheyes: the rear one turned 180 deg.
  specs.push_back(fisheye("front_fisheye_camera", mount(model::kFrontFisheyeInFootprint, 0.0,
                                                        -model::kFrontFisheyePitchUpDeg * kDeg)));
  specs.push_back(fisheye("rear_fisheye_camera", mount(model::kRearFisheyeInFootprint, M_PI,
                                                       -model::kRearFisheyePitchUpDeg * kDeg)));

  // T265 behind the torso, facing backwards: its two fisheyes sit half the baseline either side of
  // the pose frame. Which one is on which side is not in the sources; fisheye1 is taken on the
  // camera's left.
  for (int i = 1; i <= 2; ++i) {
    const double half_baseline = 0.5 * model::kBackCameraBaselineM;
    const double left_offset = i == 1 ? half_baseline : -half_baseline;
    // Facing backwards, the camera's left is the robot's -y.
    model::MountPoint position = model::kBackCameraInFootprint;
    position.y_m -= left_offset;
    CameraSpec t265 = fisheye("torso_back_camera/fisheye" + std::to_string(i),
                              mount(position, M_PI, model::kBackCameraPitchDownDeg * kDeg));
    t265.optical_frame = "torso_back_camera_fisheye" + std::to_string(i) + "_optical_frame";
    set_image(t265, model::kBackFisheyeCamera);
    t265.rate_hz = 30.0;
    specs.push_back(t265);
  }
  return specs;
}

Eigen::Isometry3d X_footprint_head_2(double head_1_rad, double head_2_rad) {
  // base_footprint -> base_link -> head_1_link, pan about z -> head_2_link rpy (90 deg, 0, 0),
  // tilt about the child's -z.
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translate(Eigen::Vector3d(0.0, 0.0, model::kBaseLinkHeightM));
  X.translate(vector_of(model::kHeadPanJointInBaseLink));
  X.rotate(Eigen::AngleAxisd(head_1_rad, Eigen::Vector3d::UnitZ()));
  X.translate(vector_of(model::kHeadTiltJointInPanLink));
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

}  // namespace ari_social_sim::rendering
