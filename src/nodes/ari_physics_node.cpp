// ari_physics_node: ARI on Bullet (physics core) behind ARI's own ROS interfaces.
// Reads parameters, builds the core, wires topics, actions, services and tf, converts at the
// edges. Controllers, limits, odometry and head pointing are the core's; this file only times
// and publishes them. The controllers' and point_head's action servers are in physics/.

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_broadcaster.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/model/tracked_person.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/physics/ari_physics.hpp"
#include "ari_social_sim/physics/people_reports.hpp"
#include "ari_social_sim/physics/physics_run_config.hpp"
#include "ari_social_sim/rendering/renderer.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "node_support/frames.hpp"
#include "node_support/input_counters.hpp"
#include "node_support/node_main.hpp"
#include "node_support/renewing_tf_buffer.hpp"
#include "node_support/ros_params.hpp"
#include "node_support/single_publisher.hpp"
#include "nodes/physics/camera_interface.hpp"
#include "nodes/physics/controller_interface.hpp"
#include "nodes/physics/odom_frame.hpp"
#include "nodes/physics/point_head_interface.hpp"
#include "nodes/physics/sim_clock.hpp"
#include "world_conversions/ari_base.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

// The torso RGB-D camera is a D435i; its IMU topic is realsense2_camera's unified one
// (docs/physics.md: ARI's own launch files name no IMU topic).
constexpr char kImuTopic[] = "/torso_front_camera/imu";
// Covariance diagonal of mobile_base_controller's pose and twist (ari_robot's controller
// configuration).
constexpr double kOdomCovariance[6] = {0.001, 0.001, 1e6, 1e6, 1e6, 1000.0};

geometry_msgs::Quaternion quaternion_msg(const Eigen::Quaterniond& q) {
  geometry_msgs::Quaternion out;
  out.x = q.x();
  out.y = q.y();
  out.z = q.z();
  out.w = q.w();
  return out;
}

geometry_msgs::Pose pose_msg(const Eigen::Isometry3d& X) {
  geometry_msgs::Pose pose;
  pose.position.x = X.translation().x();
  pose.position.y = X.translation().y();
  pose.position.z = X.translation().z();
  pose.orientation = quaternion_msg(Eigen::Quaterniond(X.linear()));
  return pose;
}

void set_covariance(boost::array<double, 36>& covariance) {
  for (size_t i = 0; i < 6; ++i) {
    covariance[7 * i] = kOdomCovariance[i];
  }
}

class PhysicsNode {
 public:
  /// Throws what CameraInterface throws (bad camera or mapping parameters; no OpenGL context, with
  /// how to run without cameras).
  PhysicsNode(const physics::PhysicsRunConfig& config, const model::WorldDescription& world,
              std::unique_ptr<physics::AriPhysics> physics)
      : config_(config), physics_(std::move(physics)) {
    clock_.physics = physics_.get();
    if (config_.cameras_enabled) {
      try {
        cameras_ = std::make_unique<CameraInterface>(nh_, config_, world, *physics_);
      } catch (const rendering::RenderError& e) {
        throw rendering::RenderError(std::string(e.what()) +
                                     " (run with _cameras_enabled:=false to simulate without "
                                     "cameras)");
      }
    }
    if (config_.clock == physics::ClockSource::kOwn) {
      clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    }
    joint_state_pub_ = nh_.advertise<sensor_msgs::JointState>("/joint_states", 10);
    odom_pub_ = nh_.advertise<nav_msgs::Odometry>("/mobile_base_controller/odom", 10);
    ground_truth_pub_ = nh_.advertise<nav_msgs::Odometry>("/ground_truth_odom", 10);
    imu_pub_ = nh_.advertise<sensor_msgs::Imu>(kImuTopic, 10);
    diagnostics_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    declare_inputs();
    cmd_vel_sub_ = nh_.subscribe(kCmdVelTopic, kCheckedInputQueue, &PhysicsNode::on_cmd_vel, this);
    // Every state: each is drawn over its own world step (PeopleReports).
    world_state_sub_ = nh_.subscribe(kWorldStateTopic, physics::PeopleReports::kCapacity,
                                     &PhysicsNode::on_world_state, this);
    for (const auto& controller : physics_->controllers()) {
      controllers_.push_back(
          std::make_unique<ControllerInterface>(nh_, *controller, *physics_, clock_));
    }
    point_head_ = std::make_unique<PointHeadInterface>(nh_, *physics_, clock_, tf_);
  }

  void run() {
    if (config_.clock == physics::ClockSource::kWorld) {
      run_on_world_clock();
    } else {
      run_on_own_clock();
    }
  }

 private:
  static constexpr const char* kCmdVelTopic = "/mobile_base_controller/cmd_vel";
  static constexpr const char* kWorldStateTopic = "/sim/world_state";
  // Faster than a sprinter and a pirouette: nobody in a world of people walking and standing.
  static constexpr double kMaxPersonSpeedMps = 10.0;
  static constexpr double kMaxPersonTurnRps = 20.0;

  void declare_inputs() {
    for (const char* field : {"linear.x", "angular.z"}) {
      inputs_.declare_drop(kCmdVelTopic, field);
    }
    for (const char* field : {"humans[].pose", "humans[].velocity", "humans[].gaze.direction"}) {
      inputs_.declare_drop(kWorldStateTopic, field);
    }
    inputs_.declare_clamp(kCmdVelTopic);
  }

  // Own clock: advance one /clock tick at a time, paced at the real-time factor.
  void run_on_own_clock() {
    const double tick_s = 1.0 / kClockRateHz;
    ros::WallTime start = ros::WallTime::now();
    const double start_sim_s = clock_.now_s();
    publish_clock();
    while (ros::ok()) {
      ros::spinOnce();
      tf_.renew_if_stale();
      advance_to(clock_.now_s() + tick_s);
      publish_clock();
      if (config_.real_time_factor > 0.0) {
        const ros::WallTime due =
            start + ros::WallDuration((clock_.now_s() - start_sim_s) / config_.real_time_factor);
        const ros::WallTime now = ros::WallTime::now();
        if (due > now) {
          (due - now).sleep();
        }
      }
    }
  }

  // World clock: step up to each /clock world_node publishes.
  void run_on_world_clock() {
    bool anchored = false;
    while (ros::ok()) {
      ros::spinOnce();
      tf_.renew_if_stale();
      const double now_s = ros::Time::now().toSec();
      if (now_s <= 0.0) {
        ros::WallDuration(0.001).sleep();
        continue;
      }
      if (!anchored || now_s < clock_.now_s() - 1.0) {
        // First tick, or the world was reset: line the physics' time up with the world's.
        clock_.origin_s = now_s - physics_->time_s();
        anchored = true;
      }
      if (clock_.now_s() + 0.5 * physics_->config().step_s < now_s && !awaiting_state(now_s)) {
        advance_to(now_s);
      } else {
        ros::WallDuration(0.0005).sleep();
      }
    }
  }

  // world_node publishes its clock's tick to s, then its state at s; roscpp takes the tick on its
  // own thread, so on a busy machine the clock can reach s before the state has been taken.
  // Stepping to s then would draw the people of the state before (PeopleReports), a world step
  // behind what a reader of the images (hri_perception_node's crops) takes them to show: wait for
  // the state, for at most kMaxStateWait_s of wall time (a world that stopped publishing its
  // state must not stop the robot).
  bool awaiting_state(double now_s) {
    if (people_reports_.has_report_for(now_s)) {
      state_wait_start_.reset();
      return false;
    }
    const ros::WallTime wall = ros::WallTime::now();
    if (!state_wait_start_) {
      state_wait_start_ = wall;
    }
    return (wall - *state_wait_start_).toSec() < kMaxStateWait_s;
  }

  void advance_to(double target_s) {
    while (clock_.now_s() + 0.5 * physics_->config().step_s < target_s && ros::ok()) {
      if (auto people = people_reports_.take_for(clock_.now_s() + physics_->config().step_s)) {
        physics_->set_people(*people);
      }
      physics_->step();
      publish_due();
    }
    for (auto& controller : controllers_) {
      controller->update_goal();
    }
    point_head_->update_goal();
  }

  void publish_clock() {
    rosgraph_msgs::Clock clock;
    clock.clock = clock_.now();
    clock_pub_.publish(clock);
  }

  // Everything whose period has come, stamped with the sim time of this step.
  void publish_due() {
    const double now_s = clock_.now_s();
    const ros::Time stamp = clock_.now();
    if (now_s + 1e-9 >= next_publish_s_) {
      next_publish_s_ = now_s + 1.0 / config_.publish_rate_hz;
      publish_joint_states(stamp);
      publish_odometry(stamp);
      for (auto& controller : controllers_) {
        controller->publish_state();
      }
    }
    if (cameras_) {
      cameras_->update(stamp);
    }
    if (now_s + 1e-9 >= next_ground_truth_s_) {
      next_ground_truth_s_ = now_s + 1.0 / config_.ground_truth_rate_hz;
      publish_ground_truth(stamp);
    }
    if (physics_->imu_reading_count() != published_imu_count_) {
      published_imu_count_ = physics_->imu_reading_count();
      publish_imu(stamp);
    }
    const uint64_t clamps = physics_->diagnostics().clamped_base_commands;
    if (clamps > reported_clamps_) {
      ROS_WARN_THROTTLE(5.0, "cmd_vel beyond ARI's limits was scaled down (%lu so far)",
                        static_cast<unsigned long>(clamps));
      inputs_.add_clamps(kCmdVelTopic, clamps - reported_clamps_);
      reported_clamps_ = clamps;
    }
    inputs_.publish_when_due(diagnostics_pub_, stamp);
    if (physics_->diagnostics().nan_resets > 0) {
      ROS_ERROR_THROTTLE(5.0, "physics blew up and was reset %lu times",
                         static_cast<unsigned long>(physics_->diagnostics().nan_resets));
    }
  }

  void publish_joint_states(const ros::Time& stamp) {
    sensor_msgs::JointState state;
    state.header.stamp = stamp;
    state.name = physics_->joint_names();
    state.position = physics_->joint_positions();
    state.velocity = physics_->joint_velocities();
    state.effort = physics_->joint_efforts();
    joint_state_pub_.publish(state);
  }

  void publish_odometry(const ros::Time& stamp) {
    const physics::WheelOdometry& odometry = physics_->odometry();
    nav_msgs::Odometry odom;
    odom.header.stamp = stamp;
    odom.header.frame_id = kOdomFrame;
    odom.child_frame_id = kBaseFrame;
    odom.pose.pose = pose_msg(planar(odometry.pose()));
    odom.twist.twist.linear.x = odometry.linear_mps();
    odom.twist.twist.angular.z = odometry.angular_rps();
    set_covariance(odom.pose.covariance);
    set_covariance(odom.twist.covariance);
    odom_pub_.publish(odom);

    tf_broadcaster_.sendTransform({odom_to_base(odometry.pose(), stamp.toSec()),
                                   map_to_odom(stamp.toSec(), odom_in_map(*physics_))});
  }

  void publish_ground_truth(const ros::Time& stamp) {
    nav_msgs::Odometry truth;
    truth.header.stamp = stamp;
    truth.header.frame_id = kMapFrame;
    truth.child_frame_id = kBaseFrame;
    truth.pose.pose = pose_msg(physics_->frame_pose(kBaseFrame));
    truth.twist.twist.linear.x = physics_->base_linear_mps();
    truth.twist.twist.angular.z = physics_->base_angular_rps();
    ground_truth_pub_.publish(truth);
  }

  void publish_imu(const ros::Time& stamp) {
    const physics::ImuReading& reading = physics_->imu();
    sensor_msgs::Imu imu;
    imu.header.stamp = stamp;
    imu.header.frame_id = physics::AriPhysics::kImuFrame;
    imu.orientation_covariance[0] = -1.0;  // no orientation estimate, as the D435i's
    imu.angular_velocity.x = reading.angular_velocity_rps.x();
    imu.angular_velocity.y = reading.angular_velocity_rps.y();
    imu.angular_velocity.z = reading.angular_velocity_rps.z();
    imu.linear_acceleration.x = reading.linear_acceleration_mps2.x();
    imu.linear_acceleration.y = reading.linear_acceleration_mps2.y();
    imu.linear_acceleration.z = reading.linear_acceleration_mps2.z();
    const physics::ImuNoise& noise = physics_->config().imu_noise;
    for (size_t i = 0; i < 3; ++i) {
      imu.angular_velocity_covariance[4 * i] = noise.gyro_std_rps * noise.gyro_std_rps;
      imu.linear_acceleration_covariance[4 * i] = noise.accel_std_mps2 * noise.accel_std_mps2;
    }
    imu_pub_.publish(imu);
  }

  void on_cmd_vel(const geometry_msgs::Twist& twist) {
    const bool linear_ok = inputs_.finite(kCmdVelTopic, "linear.x", twist.linear.x);
    const bool angular_ok = inputs_.finite(kCmdVelTopic, "angular.z", twist.angular.z);
    if (linear_ok && angular_ok) {
      physics_->command_base(twist.linear.x, twist.angular.z);
    }
  }

  // A person whose numbers are not finite, who stands far outside any map or who moves faster
  // than anyone runs is left out of this update: the physics moves people on at their reported
  // velocity, and one at 1e300 m/s would leave the world's numbers in a step. The world's own
  // checks never let one through; a bag replay or a second publisher might.
  bool plausible(const HumanState& human) {
    const std::string problem =
        model::pose_problem({{human.pose.x, human.pose.y}, human.pose.theta});
    if (!problem.empty()) {
      inputs_.drop(kWorldStateTopic, "humans[].pose", problem);
      return false;
    }
    const double speed = std::hypot(human.velocity.linear.x, human.velocity.linear.y);
    const double turn = std::abs(human.velocity.angular.z);
    if (!(speed <= kMaxPersonSpeedMps && turn <= kMaxPersonTurnRps)) {
      inputs_.drop(kWorldStateTopic, "humans[].velocity",
                   core::format_text("%g m/s, %g rad/s, expected at most %g m/s and %g rad/s",
                                     speed, turn, kMaxPersonSpeedMps, kMaxPersonTurnRps));
      return false;
    }
    return inputs_.finite(kWorldStateTopic, "humans[].gaze.direction", human.gaze.direction);
  }

  void on_world_state(const ros::MessageEvent<const WorldState>& event) {
    if (!state_publisher_.accept(event.getPublisherName())) {
      return;
    }
    const WorldState& state = *event.getConstMessage();
    std::vector<physics::PersonState> people;
    for (const HumanState& human : state.humans) {
      if (!plausible(human)) {
        continue;
      }
      physics::PersonState person;
      person.id = human.id;
      person.pose = {{human.pose.x, human.pose.y}, human.pose.theta};
      person.velocity_mps = {human.velocity.linear.x, human.velocity.linear.y};
      person.angular_velocity_rps = human.velocity.angular.z;
      person.face_yaw_rad = human.gaze.direction;
      person.head_pitch_rad = human.head_pitch;
      person.age_years = human.age;
      person.gender = static_cast<model::Gender>(human.gender);
      person.mask = human.mask;
      person.emotion = static_cast<model::Emotion>(human.emotion);
      person.speaking = human.speech.is_speaking;
      person.seated_fraction = posture_of(human).seated_fraction();
      person.walked_m = human.walked_distance;
      people.push_back(person);
    }
    people_reports_.add(state.header.stamp.toSec(), std::move(people));
  }

  // /clock period when this node owns time: fine enough for actionlib and tf, few enough
  // messages at 20x real time.
  static constexpr double kClockRateHz = 200.0;

  physics::PhysicsRunConfig config_;
  std::unique_ptr<physics::AriPhysics> physics_;
  SimClock clock_;
  static constexpr double kMaxStateWait_s = 0.25;
  physics::PeopleReports people_reports_;
  std::optional<ros::WallTime> state_wait_start_;
  double next_publish_s_{0.0};
  double next_ground_truth_s_{0.0};
  uint64_t published_imu_count_{0};
  uint64_t reported_clamps_{0};

  ros::NodeHandle nh_;
  ros::Publisher clock_pub_, joint_state_pub_, odom_pub_, ground_truth_pub_, imu_pub_,
      diagnostics_pub_;
  ros::Subscriber cmd_vel_sub_, world_state_sub_;
  InputCounters inputs_{"ari_physics_node"};
  // world_node's alone: a second world_node's people are refused.
  SinglePublisher state_publisher_{kWorldStateTopic, &inputs_};
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  // Point-head targets may be people's frames, which come and go with perception's ids.
  RenewingTfBuffer tf_;
  std::vector<std::unique_ptr<ControllerInterface>> controllers_;
  std::unique_ptr<PointHeadInterface> point_head_;
  std::unique_ptr<CameraInterface> cameras_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  return nodes::run_node(argc, argv, "ari_physics_node", [] {
    ros::NodeHandle private_handle("~");
    const physics::PhysicsRunConfig config =
        physics::PhysicsRunConfig::from_yaml(nodes::read_private_params(private_handle));
    const std::string package = ros::package::getPath("ari_social_sim");
    const physics::RobotModel model = physics::RobotModel::from_urdf_file(
        config.urdf.empty() ? package + "/urdf/ari.urdf" : config.urdf);
    model::WorldDescription world_description;
    core::Pose2 start;
    if (!config.scene.empty()) {
      const world::Scene scene = world::load_scene_file(config.scene);
      if (!scene.ari) {
        throw core::ConfigError(config.scene + ": ari: the scene has no ARI to simulate");
      }
      world_description = scene.world;
      start = scene.ari->pose;
    } else {
      world_description = model::load_world_file(
          config.world.empty() ? package + "/worlds/room_6x6.yaml" : config.world);
      start = config.start_pose().value_or(
          core::Pose2{world_description.origin + 0.5 * world_description.size, 0.0});
    }
    auto simulation =
        std::make_unique<physics::AriPhysics>(model, world_description, start, config.physics);
    ROS_INFO("ari_physics_node: world %s, ARI at (%.2f, %.2f, %.2f rad), step %.4f s, clock %s",
             world_description.name.c_str(), start.position.x(), start.position.y(), start.theta,
             config.physics.step_s,
             config.clock == physics::ClockSource::kOwn ? "own" : "world_node's");
    nodes::PhysicsNode node(config, world_description, std::move(simulation));
    node.run();
    return 0;
  });
}
