#include <gtest/gtest.h>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/ari_sensors.hpp"
#include "perception_scenes.hpp"

namespace ari_social_sim::perception {
namespace {

TEST(AriSensors, MountsFollowTheBase) {
  const PerceptionConfig config;
  world::AriSnapshot ari;
  ari.pose = {{2.0, 1.0}, core::kPi / 2};  // facing +y
  const AriSensors sensors = AriSensors::of(ari, config);
  // Fisheye 0.142 m behind base_footprint: (2, 1 - 0.142), facing +y, 90 deg either side.
  EXPECT_NEAR(sensors.body_camera.X_map_sensor.position.x(), 2.0, 1e-12);
  EXPECT_NEAR(sensors.body_camera.X_map_sensor.position.y(), 0.858, 1e-12);
  EXPECT_NEAR(sensors.body_camera.X_map_sensor.theta, core::kPi / 2, 1e-12);
  EXPECT_NEAR(sensors.body_camera.half_angle_rad, core::kPi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(sensors.body_camera.range_m, 10.0);
  // Head camera at pan 0: -0.2255 + 0.1059 = -0.1196 m along the heading (ari_robot's URDF, as
  // the rendered head camera); its lens is the Raspberry Pi camera v2's 62.2 degrees.
  EXPECT_NEAR(sensors.face_camera.X_map_sensor.position.y(), 0.8804, 1e-12);
  EXPECT_NEAR(sensors.face_camera.half_angle_rad, core::deg_to_rad(31.1), 1e-12);
  EXPECT_NEAR(sensors.microphone.y(), 0.878, 1e-12);
  EXPECT_DOUBLE_EQ(sensors.listening_range_m, 5.0);
}

TEST(AriSensors, HeadCameraTurnsWithThePan) {
  const PerceptionConfig config;
  world::AriSnapshot ari;
  ari.head_pan_rad = core::deg_to_rad(60.0);  // head turned left
  const AriSensors sensors = AriSensors::of(ari, config);
  // Pan axis at (-0.2255, 0); camera 0.1059 m ahead of it along 60 degrees.
  EXPECT_NEAR(sensors.face_camera.X_map_sensor.position.x(), -0.2255 + 0.1059 * 0.5, 1e-12);
  EXPECT_NEAR(sensors.face_camera.X_map_sensor.position.y(), 0.1059 * std::sqrt(3.0) / 2, 1e-12);
  EXPECT_NEAR(sensors.face_camera.X_map_sensor.theta, core::deg_to_rad(60.0), 1e-12);
  // The fisheye stays with the base.
  EXPECT_NEAR(sensors.body_camera.X_map_sensor.theta, 0.0, 1e-12);
}

}  // namespace
}  // namespace ari_social_sim::perception
