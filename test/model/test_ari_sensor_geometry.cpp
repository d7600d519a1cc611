#include <gtest/gtest.h>

#include "ari_social_sim/model/ari_sensor_geometry.hpp"

namespace ari_social_sim::model {
namespace {

// The planar head camera that perception uses is the URDF's head_front_camera at pan 0 and tilt 0:
// (-0.1196, 0, 1.5915) in base_footprint, as test_robot_model reads it from urdf/ari.urdf.
TEST(AriSensorGeometry, PlanarHeadCameraIsTheUrdfsHeadCameraWithTheHeadLevel) {
  EXPECT_NEAR(kHeadPanJointInBaseLink.x_m + head_camera_ahead_of_pan_axis_m(), -0.1196, 1e-12);
  EXPECT_NEAR(head_camera_height_m(), 1.5915, 1e-12);
}

// ARI's head camera is a Raspberry Pi Camera Module v2: 62.2 degrees across 4:3 images.
TEST(AriSensorGeometry, HeadCameraIsTheRaspberryPiCameraV2) {
  EXPECT_DOUBLE_EQ(kHeadCamera.hfov_deg, 62.2);
  EXPECT_EQ(kHeadCamera.width_px * 3, kHeadCamera.height_px * 4);
}

}  // namespace
}  // namespace ari_social_sim::model
