// DiffDriveController: ARI's mobile_base_controller limits and wheel speeds.

#include <gtest/gtest.h>

#include "ari_social_sim/physics/diff_drive_controller.hpp"

namespace ari_social_sim::physics {
namespace {

DiffDriveController ari_base() {
  return DiffDriveController(model::AriLimits{}, DriveGeometry{0.125, 0.44});
}

void run(DiffDriveController& drive, double from_s, double seconds) {
  for (int i = 1; i <= static_cast<int>(seconds * 1000.0 + 0.5); ++i) {
    drive.update(from_s + i * 0.001, 0.001);
  }
}

// Repeats a cmd_vel every 0.05 s (20 Hz, well inside the 0.25 s timeout) for `seconds`.
void drive_for(DiffDriveController& drive, double linear, double angular, double seconds) {
  for (int tick = 0; tick < static_cast<int>(seconds / 0.05 + 0.5); ++tick) {
    drive.command(linear, angular, tick * 0.05);
    run(drive, tick * 0.05, 0.05);
  }
}

TEST(DiffDriveController, KeepsTheTurningRadiusWhenLimiting) {
  // 2 m/s and 1 rad/s: 2x over the 1 m/s limit, so both halve (radius 2 m kept).
  DiffDriveController drive = ari_base();
  EXPECT_TRUE(drive.command(2.0, 1.0, 0.0));
  drive_for(drive, 2.0, 1.0, 2.0);
  EXPECT_NEAR(drive.linear_mps(), 1.0, 1e-9);
  EXPECT_NEAR(drive.angular_rps(), 0.5, 1e-9);
}

TEST(DiffDriveController, ReversesNoFasterThanPointTwo) {
  DiffDriveController drive = ari_base();
  EXPECT_TRUE(drive.command(-0.5, 0.0, 0.0));
  drive_for(drive, -0.5, 0.0, 1.0);
  EXPECT_NEAR(drive.linear_mps(), -0.2, 1e-9);
}

TEST(DiffDriveController, AcceleratesAtOneMetrePerSecondSquared) {
  DiffDriveController drive = ari_base();
  EXPECT_FALSE(drive.command(0.5, 0.0, 0.0));
  run(drive, 0.0, 0.1);
  EXPECT_NEAR(drive.linear_mps(), 0.1, 1e-9);
}

TEST(DiffDriveController, StopsAfterTheCommandTimeout) {
  // Commanded once at t = 0: held until 0.25 s, then braked at 1 m/s^2 (0.5 m/s in 0.5 s).
  DiffDriveController drive = ari_base();
  drive.command(0.2, 0.0, 0.0);
  run(drive, 0.0, 0.24);
  EXPECT_NEAR(drive.linear_mps(), 0.2, 1e-9);
  run(drive, 0.24, 0.5);
  EXPECT_NEAR(drive.linear_mps(), 0.0, 1e-9);
}

TEST(DiffDriveController, WheelSpeedsRealiseTheTwist) {
  // 0.5 m/s and 1 rad/s: wheels at (0.5 -+ 1 x 0.22) / 0.125 = 2.24 and 5.76 rad/s.
  DiffDriveController drive = ari_base();
  drive_for(drive, 0.5, 1.0, 2.0);
  EXPECT_NEAR(drive.left_wheel_rps(), 2.24, 1e-9);
  EXPECT_NEAR(drive.right_wheel_rps(), 5.76, 1e-9);
}

}  // namespace
}  // namespace ari_social_sim::physics
