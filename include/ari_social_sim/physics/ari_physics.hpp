#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/physics/diff_drive_controller.hpp"
#include "ari_social_sim/physics/imu_model.hpp"
#include "ari_social_sim/physics/person_shape.hpp"
#include "ari_social_sim/physics/physics_config.hpp"
#include "ari_social_sim/physics/robot_model.hpp"
#include "ari_social_sim/physics/static_scene.hpp"
#include "ari_social_sim/physics/trajectory_controller.hpp"
#include "ari_social_sim/physics/wheel_odometry.hpp"

namespace ari_social_sim::physics {

/// Numeric trouble and corrected input met while stepping, counted rather than thrown.
struct PhysicsDiagnostics {
  uint64_t clamped_base_commands{0};  // cmd_vel scaled to the base's limits
  uint64_t nan_resets{0};             // non-finite multibody state put back to the last good one
};

/// ARI on Bullet: the URDF as a floating-base Featherstone multibody (btMultiBody) on the floor of
/// a world file's walls and furniture, with people as kinematic bodies; the drive wheels under
/// ARI's diff-drive controller with wheel odometry, the head, arm and hand joints under
/// position-controlled joint trajectory controllers, the passive finger joints copying the
/// actuated one, and a torso IMU.
///
/// Frames: "map" is the world (Bullet's) frame, z up, the floor at z = 0; "odom" starts equal to
/// map and drifts only with wheel slip. Requests validate and throw core::RequestError; step()
/// never throws.
class AriPhysics {
 public:
  /// `start`: base_footprint in the map frame. Throws core::ConfigError for an invalid config and
  /// core::RequestError if the model lacks one of ARI's controlled joints.
  AriPhysics(const RobotModel& model, const model::WorldDescription& world,
             const core::Pose2& start, const PhysicsConfig& config);
  ~AriPhysics();
  AriPhysics(const AriPhysics&) = delete;
  AriPhysics& operator=(const AriPhysics&) = delete;

  /// One physics step of config().step_s: controllers, servos, Bullet, odometry, IMU.
  void step();
  double time_s() const;
  uint64_t step_count() const;
  const PhysicsConfig& config() const { return config_; }

  // ---- commands ----
  /// A base twist (cmd_vel) at the current time. Returns true if it had to be scaled to the
  /// base's limits.
  bool command_base(double linear_mps, double angular_rps);
  /// The joint trajectory controller of that name (head_controller, arm_left_controller, ...);
  /// throws core::RequestError for another name.
  TrajectoryController& controller(const std::string& name);
  const std::vector<std::unique_ptr<TrajectoryController>>& controllers() const;
  /// Replaces the people with these (the 2D world's humans, map frame). Between two calls each
  /// person keeps moving with its velocity.
  void set_people(const std::vector<PersonState>& people);

  // ---- state: what the node publishes and the cameras render ----
  const RobotModel& model() const;
  const StaticScene& scene() const;
  /// The people's shapes now (after their motion since the last set_people).
  std::vector<PersonShape> people() const;
  /// The people as set_people had them, at the positions their bodies have glided to, with the
  /// velocities and walked distances of their walk (not of the glide's catch-up).
  std::vector<PersonState> people_states() const;
  /// Pose in the map frame of any URDF link or frame (base_footprint, head_front_camera_color_
  /// optical_frame, ...). Throws core::RequestError for an unknown name.
  Eigen::Isometry3d frame_pose(const std::string& frame) const;
  /// Every URDF link's pose in the map frame, indexed like model().links().
  std::vector<Eigen::Isometry3d> link_poses() const;
  /// base_footprint's true pose projected on the floor (map frame), and its velocity: linear
  /// along its own x axis (m/s) and yaw rate (rad/s).
  core::Pose2 base_pose() const;
  double base_linear_mps() const;
  double base_angular_rps() const;
  /// Wheel odometry: base_footprint in the odom frame.
  const WheelOdometry& odometry() const;
  /// Every movable joint of the model, in URDF order, and its state (rad, rad/s, N m).
  const std::vector<std::string>& joint_names() const;
  std::vector<double> joint_positions() const;
  std::vector<double> joint_velocities() const;
  std::vector<double> joint_efforts() const;
  double joint_position(const std::string& joint) const;
  /// The latest IMU reading (a new one every 1 / imu_rate_hz), and its frame.
  const ImuReading& imu() const;
  uint64_t imu_reading_count() const;
  static constexpr const char* kImuFrame = "torso_front_camera_imu_optical_frame";
  const PhysicsDiagnostics& diagnostics() const;

 private:
  struct Engine;
  PhysicsConfig config_;
  std::unique_ptr<Engine> engine_;
};

}  // namespace ari_social_sim::physics
