// PointHeadSolver: aiming the head camera's optical axis.

#include <gtest/gtest.h>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/physics/point_head.hpp"

namespace ari_social_sim::physics {
namespace {

const RobotModel& ari() {
  static const RobotModel model = RobotModel::from_urdf_file(ARI_URDF);
  return model;
}

constexpr char kOptical[] = "head_front_camera_color_optical_frame";

TEST(PointHeadSolver, AimsTheOpticalAxisExactly) {
  const PointHeadSolver solver(ari());
  // A face 1.5 m ahead, 0.6 m to the left, 1.2 m high (below the camera, so the head tilts down).
  const Eigen::Vector3d target(1.5, 0.6, 1.2);
  const HeadAim aim = solver.solve(target, Eigen::Vector3d::UnitZ(), kOptical, {});
  EXPECT_LT(aim.error_rad, 1e-6);
  EXPECT_FALSE(aim.limited);
  EXPECT_GT(aim.pan_rad, 0.0);   // left
  EXPECT_GT(aim.tilt_rad, 0.0);  // down
  // The optical axis passes through the pan axis, so pan is the bearing from that axis; the camera
  // sits 0.182 m above the tilt axis, so tilt is not the naive depression angle from it.
  EXPECT_NEAR(aim.pan_rad, std::atan2(0.6, 1.5 + 0.2255), 1e-6);
  const Eigen::Vector3d from_tilt_axis =
      target - ari().link_pose("head_2_link", {{"head_1_joint", aim.pan_rad}}).translation();
  const double naive_tilt = std::atan2(-from_tilt_axis.z(), from_tilt_axis.head<2>().norm());
  EXPECT_GT(std::abs(aim.tilt_rad - naive_tilt), 0.05);
}

TEST(PointHeadSolver, StopsAtTheJointLimits) {
  // Straight behind ARI: pan saturates at 75 degrees and the error stays large.
  const PointHeadSolver solver(ari());
  const HeadAim aim = solver.solve({-3.0, 0.1, 1.5}, Eigen::Vector3d::UnitZ(), kOptical, {});
  EXPECT_TRUE(aim.limited);
  EXPECT_NEAR(aim.pan_rad, 1.309, 1e-9);
  EXPECT_GT(aim.error_rad, 1.0);
}

TEST(PointHeadSolver, RejectsFramesTheHeadDoesNotMove) {
  const PointHeadSolver solver(ari());
  EXPECT_THROW(solver.solve({1, 0, 1}, Eigen::Vector3d::UnitZ(), "torso_front_camera_link", {}),
               core::RequestError);
  EXPECT_THROW(solver.solve({1, 0, 1}, Eigen::Vector3d::UnitZ(), "nose", {}), core::RequestError);
  EXPECT_THROW(solver.solve({1, 0, 1}, Eigen::Vector3d::Zero(), kOptical, {}), core::RequestError);
}

}  // namespace
}  // namespace ari_social_sim::physics
