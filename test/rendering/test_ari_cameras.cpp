#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/rendering/ari_cameras.hpp"
#include "ari_social_sim/rendering/camera_rig_config.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr double kDeg = M_PI / 180.0;

CameraSpec spec_named(const std::vector<CameraSpec>& specs, const std::string& name) {
  for (const CameraSpec& spec : specs) {
    if (spec.name == name) {
      return spec;
    }
  }
  throw std::runtime_error("no camera " + name);
}

// The optical axis (z) of a camera in base_footprint.
Eigen::Vector3d optical_axis(const CameraSpec& spec, double pan, double tilt) {
  return X_footprint_optical(spec, pan, tilt).linear().col(2);
}

TEST(AriCameras, HeadCameraAtZeroPoseMatchesTheSpec) {
  const CameraSpec head = spec_named(ari_camera_specs(), "head_front_camera");
  const Eigen::Isometry3d X = X_footprint_optical(head, 0.0, 0.0);
  // ari_robot's URDF: head_front_camera at (-0.120, 0, 1.591) facing +x; REP-103 axes.
  EXPECT_LT((X.translation() - Eigen::Vector3d(-0.1196, 0.0, 1.5915)).norm(), 1e-4);
  EXPECT_LT((X.linear().col(2) - Eigen::Vector3d::UnitX()).norm(), 1e-12);  // z forward
  EXPECT_LT((X.linear().col(0) + Eigen::Vector3d::UnitY()).norm(), 1e-12);  // x right
  EXPECT_LT((X.linear().col(1) + Eigen::Vector3d::UnitZ()).norm(), 1e-12);  // y down
  EXPECT_EQ(head.width, 1280);
  EXPECT_EQ(head.height, 960);
  EXPECT_NEAR(head.hfov_rad / kDeg, 62.2, 1e-9);
  EXPECT_EQ(head.optical_frame, "head_front_camera_color_optical_frame");
  EXPECT_EQ(head.info_topic, "head_front_camera/color/camera_info");
}

TEST(AriCameras, HeadCameraFollowsPanAndTilt) {
  const CameraSpec head = spec_named(ari_camera_specs(), "head_front_camera");
  // Pan turns the axis left (counter-clockwise from above).
  const Eigen::Vector3d panned = optical_axis(head, 0.5, 0.0);
  EXPECT_LT((panned - Eigen::Vector3d(std::cos(0.5), std::sin(0.5), 0.0)).norm(), 1e-12);
  // Positive tilt looks down.
  const Eigen::Vector3d tilted = optical_axis(head, 0.0, 0.3);
  EXPECT_LT((tilted - Eigen::Vector3d(std::cos(0.3), 0.0, -std::sin(0.3))).norm(), 1e-12);
  // The camera swings about the pan axis at x = -0.2255: 0.106 m in front of it.
  const Eigen::Vector3d p = X_footprint_optical(head, M_PI / 2, 0.0).translation();
  EXPECT_NEAR(p.x(), -0.2255, 1e-9);
  EXPECT_NEAR(p.y(), 0.1059, 1e-4);
}

TEST(AriCameras, FixedMountsLookWhereTheSpecSays) {
  const std::vector<CameraSpec> specs = ari_camera_specs();
  const CameraSpec torso = spec_named(specs, "torso_front_camera");
  EXPECT_EQ(torso.kind, CameraKind::kRgbd);
  EXPECT_LT((optical_axis(torso, 1.0, 0.2) -
             Eigen::Vector3d(std::cos(42.5 * kDeg), 0.0, -std::sin(42.5 * kDeg)))
                .norm(),
            1e-12);
  EXPECT_NEAR(X_footprint_optical(torso, 0, 0).translation().z(), 1.105, 1e-9);
  const CameraSpec front = spec_named(specs, "front_fisheye_camera");
  EXPECT_LT(
      (optical_axis(front, 0, 0) - Eigen::Vector3d(std::cos(19 * kDeg), 0.0, std::sin(19 * kDeg)))
          .norm(),
      1e-12);
  const CameraSpec rear = spec_named(specs, "rear_fisheye_camera");
  EXPECT_LT(
      (optical_axis(rear, 0, 0) - Eigen::Vector3d(-std::cos(25 * kDeg), 0.0, std::sin(25 * kDeg)))
          .norm(),
      1e-12);
  // The T265 fisheyes face backwards, 64 mm apart.
  const Eigen::Vector3d t1 =
      X_footprint_optical(spec_named(specs, "torso_back_camera/fisheye1"), 0, 0).translation();
  const Eigen::Vector3d t2 =
      X_footprint_optical(spec_named(specs, "torso_back_camera/fisheye2"), 0, 0).translation();
  EXPECT_NEAR((t1 - t2).norm(), 0.064, 1e-9);
}

TEST(CameraRigConfig, DefaultsEnableHeadAndTorso) {
  const CameraRigConfig config = CameraRigConfig::from_yaml(core::YamlMap::parse("{}", "test"));
  int enabled = 0;
  for (const CameraSpec& spec : config.cameras) {
    enabled += spec.enabled ? 1 : 0;
  }
  EXPECT_EQ(enabled, 2);
  EXPECT_EQ(config.depth_encoding, DepthEncoding::kMetres32F);
}

TEST(CameraRigConfig, OverridesAndRejectsBadFields) {
  const CameraRigConfig config = CameraRigConfig::from_yaml(core::YamlMap::parse(
      "{depth_encoding: 16UC1, cameras: {head_front_camera: {width: 640, height: 480, "
      "rate_hz: 5}, torso_back_camera_fisheye1: {enabled: true}}}",
      "test"));
  EXPECT_EQ(config.depth_encoding, DepthEncoding::kMillimetres16U);
  EXPECT_EQ(spec_named(config.cameras, "head_front_camera").width, 640);
  EXPECT_DOUBLE_EQ(spec_named(config.cameras, "head_front_camera").rate_hz, 5.0);
  EXPECT_TRUE(spec_named(config.cameras, "torso_back_camera/fisheye1").enabled);

  auto error_of = [](const std::string& yaml) {
    try {
      CameraRigConfig::from_yaml(core::YamlMap::parse(yaml, "cams.yaml"));
    } catch (const core::ConfigError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("{cameras: {head_front_camera: {rate_hz: 0}}}").find("rate_hz"),
            std::string::npos);
  EXPECT_NE(error_of("{cameras: {head_camera: {}}}").find("head_camera"), std::string::npos);
  EXPECT_NE(error_of("{cameras: {head_front_camera: {widht: 10}}}").find("widht"),
            std::string::npos);
  EXPECT_NE(error_of("{depth_encoding: mm}").find("16UC1"), std::string::npos);
  EXPECT_NE(error_of("{cameras: {head_front_camera: {hfov_deg: 180}}}").find("hfov_deg"),
            std::string::npos);
}

TEST(CameraRigConfig, ValidateRefusesABadValueBuiltInCode) {
  CameraRigConfig config;
  EXPECT_NO_THROW(config.validate());
  config.cameras.front().width = 8;
  try {
    config.validate();
    ADD_FAILURE() << "accepted a width of 8";
  } catch (const core::ConfigError& e) {
    EXPECT_STREQ(e.what(), ("CameraRigConfig: cameras." + config_key_of(config.cameras.front()) +
                            ".width: expected an integer [16, 8192], got 8")
                               .c_str());
  }
}

}  // namespace
}  // namespace ari_social_sim::rendering
