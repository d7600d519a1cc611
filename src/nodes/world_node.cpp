// world_node: the 2D multi-party world as a ROS node that owns simulated time.
// Reads parameters, builds the world core, wires topics and services, converts at the edges.

#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/JointState.h>
#include <std_srvs/SetBool.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "ari_social_sim/AddGroupMembers.h"
#include "ari_social_sim/CreateGroup.h"
#include "ari_social_sim/RemoveHuman.h"
#include "ari_social_sim/Say.h"
#include "ari_social_sim/SetGazeTargets.h"
#include "ari_social_sim/SetGoal.h"
#include "ari_social_sim/SetGroupCentre.h"
#include "ari_social_sim/SetPose.h"
#include "ari_social_sim/SetVelocity.h"
#include "ari_social_sim/SpawnHuman.h"
#include "ari_social_sim/StepSimulation.h"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/group_report.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "ari_social_sim/world/world_run_config.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"
#include "conversions/ari_base.hpp"
#include "conversions/world_markers.hpp"
#include "conversions/world_state.hpp"
#include "frames.hpp"
#include "ros_params.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr double kPausedClockPeriodS = 0.1;  // wall seconds between /clock messages while paused

core::Pose2 from_msg(const geometry_msgs::Pose2D& pose) {
  return {{pose.x, pose.y}, pose.theta};
}

// Runs a service body; a core::Error becomes success = false with its text, as ROS users expect
// from a request the server understood but could not honour.
template <class Response, class Body>
bool answer(Response& response, Body body) {
  try {
    body();
    response.success = true;
  } catch (const core::Error& e) {
    response.success = false;
    response.message = e.what();
    ROS_WARN("%s", e.what());
  }
  return true;
}

class WorldNode {
 public:
  WorldNode(const world::WorldRunConfig& config, world::Scene scene)
      : config_(config), scene_(std::move(scene)) {
    rebuild();
    map_ = world::rasterize_static_map(scene_.world, config_.map_resolution_m);
    paused_ = config_.start_paused;

    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    state_pub_ = nh_.advertise<WorldState>("/sim/world_state", 10);
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("/map", 1, /*latch=*/true);
    marker_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("/sim/markers", 1);
    if (config_.ari_source == world::AriSource::kInternal) {
      odom_pub_ = nh_.advertise<nav_msgs::Odometry>("/mobile_base_controller/odom", 10);
      // The head's joint states come from here only in 2D mode; in 3D mode ari_physics_node
      // publishes /joint_states and this node reads them.
      joint_states_pub_ = nh_.advertise<sensor_msgs::JointState>("/joint_states", 10);
      cmd_vel_sub_ =
          nh_.subscribe("/mobile_base_controller/cmd_vel", 1, &WorldNode::on_cmd_vel, this);
      head_sub_ = nh_.subscribe("/head_controller/command", 1, &WorldNode::on_head_command, this);
    } else {
      // 3D mode: ari_physics_node drives ARI and publishes its odometry and tf; the 2D body
      // follows its ground truth and head pan.
      ground_truth_sub_ = nh_.subscribe("/ground_truth_odom", 1, &WorldNode::on_ground_truth, this);
      joint_state_sub_ = nh_.subscribe("/joint_states", 1, &WorldNode::on_joint_states, this);
    }

    services_.push_back(nh_.advertiseService("/sim/spawn_human", &WorldNode::spawn_human, this));
    services_.push_back(nh_.advertiseService("/sim/remove_human", &WorldNode::remove_human, this));
    services_.push_back(nh_.advertiseService("/sim/set_goal", &WorldNode::set_goal, this));
    services_.push_back(nh_.advertiseService("/sim/set_velocity", &WorldNode::set_velocity, this));
    services_.push_back(nh_.advertiseService("/sim/set_pose", &WorldNode::set_pose, this));
    services_.push_back(nh_.advertiseService("/sim/create_group", &WorldNode::create_group, this));
    services_.push_back(
        nh_.advertiseService("/sim/add_group_members", &WorldNode::add_group_members, this));
    services_.push_back(
        nh_.advertiseService("/sim/set_group_centre", &WorldNode::set_group_centre, this));
    services_.push_back(nh_.advertiseService("/sim/say", &WorldNode::say, this));
    services_.push_back(
        nh_.advertiseService("/sim/set_gaze_targets", &WorldNode::set_gaze_targets, this));
    services_.push_back(nh_.advertiseService("/sim/reset", &WorldNode::reset, this));
    services_.push_back(nh_.advertiseService("/sim/pause", &WorldNode::pause, this));
    services_.push_back(nh_.advertiseService("/sim/step", &WorldNode::step_service, this));

    // In 2D mode the base pose is exact, so map and odom coincide; in 3D mode ari_physics_node
    // publishes map -> odom, correcting its wheel odometry's drift.
    if (config_.ari_source == world::AriSource::kInternal) {
      static_tf_.sendTransform(map_to_odom(0.0));
    }
    publish_map();
    publish_state();
  }

  /// Steps until shutdown or the configured duration, pacing sim time at the real-time factor.
  void run() {
    ros::WallTime start = ros::WallTime::now();
    double start_sim_s = simulation_->time_s();
    while (ros::ok()) {
      ros::spinOnce();
      if (paused_) {
        ros::WallDuration(0.01).sleep();
        // A paused world keeps publishing its clock (as Gazebo does), so that a node that comes
        // up meanwhile gets a valid sim time.
        if (ros::WallTime::now() - last_clock_wall_ > ros::WallDuration(kPausedClockPeriodS)) {
          publish_clock(ros::Time(simulation_->time_s()));
        }
        start = ros::WallTime::now();
        start_sim_s = simulation_->time_s();
        continue;
      }
      step_once();
      if (config_.duration_s > 0.0 && simulation_->time_s() >= config_.duration_s - 1e-9) {
        report();
        return;
      }
      if (config_.real_time_factor > 0.0) {
        const double wall_due = (simulation_->time_s() - start_sim_s) / config_.real_time_factor;
        const ros::WallTime due = start + ros::WallDuration(wall_due);
        const ros::WallTime now = ros::WallTime::now();
        if (due > now) {
          (due - now).sleep();
        }
      }
    }
  }

 private:
  void rebuild() {
    world::SimulationConfig sim_config;
    sim_config.step_s = config_.step_s;
    sim_config.map_resolution_m = config_.map_resolution_m;
    simulation_ = world::build_simulation(scene_, sim_config);
    reported_clamps_ = 0;
  }

  void step_once() {
    simulation_->step();
    publish_state();
  }

  void publish_clock(const ros::Time& stamp) {
    rosgraph_msgs::Clock clock;
    clock.clock = stamp;
    clock_pub_.publish(clock);
    last_clock_wall_ = ros::WallTime::now();
  }

  void publish_state() {
    const world::WorldSnapshot snapshot = world::WorldSnapshot::of(*simulation_);
    const ros::Time stamp(snapshot.time_s);
    publish_clock(stamp);
    state_pub_.publish(to_msg(snapshot, kMapFrame));
    if (snapshot.ari && config_.ari_source == world::AriSource::kInternal) {
      publish_base(*snapshot.ari, stamp);
    }
    const ros::WallTime now = ros::WallTime::now();
    if (marker_pub_.getNumSubscribers() > 0 &&
        (now - last_markers_).toSec() >= 1.0 / config_.marker_rate_hz) {
      last_markers_ = now;
      marker_pub_.publish(world_markers(snapshot, scene_.world, kMapFrame));
    }
    const uint64_t clamps = simulation_->diagnostics().clamped_commands;
    if (clamps > reported_clamps_) {
      ROS_WARN_THROTTLE(5.0, "ARI commands beyond its limits were clamped (%lu so far)",
                        static_cast<unsigned long>(clamps));
      reported_clamps_ = clamps;
    }
  }

  void publish_base(const world::AriSnapshot& ari, const ros::Time& stamp) {
    tf_.sendTransform(odom_to_base(ari.pose, stamp.toSec()));
    odom_pub_.publish(to_odometry(ari, stamp.toSec()));

    // Every joint, as ARI's joint_state_controller reports them: the head pans (its tilt stays
    // level in 2D), the rest stays at rest.
    sensor_msgs::JointState joints;
    joints.header.stamp = stamp;
    joints.name = {kHeadPanJoint, kHeadTiltJoint};
    joints.position = {ari.head_pan_rad, 0.0};
    joints.velocity = {ari.head_pan_velocity_rps, 0.0};
    for (const char* joint : kJointsAtRest) {
      joints.name.push_back(joint);
      joints.position.push_back(0.0);
      joints.velocity.push_back(0.0);
    }
    joint_states_pub_.publish(joints);
  }

  void publish_map() { map_pub_.publish(to_msg(map_, kMapFrame, simulation_->time_s())); }

  void report() {
    std::cout << "\nworld_node: finished " << scene_.path << " at t = " << simulation_->time_s()
              << " s\n";
    for (const auto& human : simulation_->humans()) {
      std::printf("  human %u %-8s at (%.2f, %.2f), heading %.1f deg\n", human->id(),
                  human->spec().name.c_str(), human->pose().position.x(),
                  human->pose().position.y(), human->pose().theta * 180.0 / M_PI);
    }
    for (const auto& group : simulation_->groups()) {
      std::cout << world::GroupReport::of(*simulation_, *group).to_text();
    }
    std::cout << std::flush;
  }

  void on_cmd_vel(const geometry_msgs::Twist& twist) {
    if (simulation_->ari() == nullptr) {
      ROS_WARN_THROTTLE(5.0, "cmd_vel received but the scene has no ARI");
      return;
    }
    simulation_->command_ari_twist(twist.linear.x, twist.angular.z);
  }

  void on_head_command(const trajectory_msgs::JointTrajectory& trajectory) {
    const auto joint =
        std::find(trajectory.joint_names.begin(), trajectory.joint_names.end(), kHeadPanJoint);
    if (simulation_->ari() == nullptr || joint == trajectory.joint_names.end() ||
        trajectory.points.empty()) {
      ROS_WARN_THROTTLE(5.0, "head command ignored: needs ARI and a point for %s", kHeadPanJoint);
      return;
    }
    const size_t index = static_cast<size_t>(joint - trajectory.joint_names.begin());
    const trajectory_msgs::JointTrajectoryPoint& last = trajectory.points.back();
    if (index >= last.positions.size()) {
      ROS_WARN_THROTTLE(5.0, "head command ignored: no position for %s", kHeadPanJoint);
      return;
    }
    simulation_->command_ari_head_pan(last.positions[index]);
  }

  void on_ground_truth(const nav_msgs::Odometry& truth) {
    if (simulation_->ari() == nullptr) {
      return;
    }
    const geometry_msgs::Quaternion& q = truth.pose.pose.orientation;
    const double yaw =
        std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
    simulation_->follow_ari({{truth.pose.pose.position.x, truth.pose.pose.position.y}, yaw},
                            truth.twist.twist.linear.x, truth.twist.twist.angular.z);
  }

  void on_joint_states(const sensor_msgs::JointState& state) {
    const auto joint = std::find(state.name.begin(), state.name.end(), kHeadPanJoint);
    const size_t index = static_cast<size_t>(joint - state.name.begin());
    if (simulation_->ari() != nullptr && joint != state.name.end() &&
        index < state.position.size()) {
      simulation_->command_ari_head_pan(state.position[index]);
    }
  }

  world::Human& human(uint32_t id) {
    world::Human* found = simulation_->find_human(id);
    if (found == nullptr) {
      throw core::RequestError("no human with id " + std::to_string(id));
    }
    return *found;
  }

  bool spawn_human(SpawnHuman::Request& req, SpawnHuman::Response& res) {
    return answer(res, [&] {
      world::HumanSpec spec;
      spec.id = req.id == 0 ? simulation_->next_free_id(10) : req.id;
      spec.name = req.name;
      spec.role = req.role;
      spec.pose = from_msg(req.pose);
      if (req.age != 0.0f) {
        spec.age_years = req.age;
      }
      if (!req.gender.empty()) {
        const auto gender = world::parse_gender(req.gender);
        if (!gender) {
          throw core::RequestError("gender: expected female, male or non-identified, got '" +
                                   req.gender + "'");
        }
        spec.gender = *gender;
      }
      spec.mask = req.mask;
      if (!req.emotion.empty()) {
        const auto emotion = world::parse_emotion(req.emotion);
        if (!emotion) {
          throw core::RequestError("emotion: expected neutral, happy, angry or disturbed, got '" +
                                   req.emotion + "'");
        }
        spec.emotion = *emotion;
      }
      res.id = simulation_->add_human(spec).id();
    });
  }

  bool remove_human(RemoveHuman::Request& req, RemoveHuman::Response& res) {
    return answer(res, [&] { simulation_->remove_human(req.id); });
  }

  bool set_goal(SetGoal::Request& req, SetGoal::Response& res) {
    return answer(res, [&] { simulation_->set_human_goal(req.id, from_msg(req.goal)); });
  }

  bool set_velocity(SetVelocity::Request& req, SetVelocity::Response& res) {
    return answer(res, [&] {
      world::Human& h = human(req.id);
      if (!std::isfinite(req.vx) || !std::isfinite(req.vy) || !std::isfinite(req.omega)) {
        throw core::RequestError("velocity must be finite");
      }
      simulation_->release_from_group(req.id);
      h.set_velocity({req.vx, req.vy}, req.omega);
    });
  }

  bool set_pose(SetPose::Request& req, SetPose::Response& res) {
    return answer(res, [&] {
      if (simulation_->find_human(req.id) != nullptr) {
        simulation_->release_from_group(req.id);
      }
      simulation_->set_pose(req.id, from_msg(req.pose));
      publish_state();
    });
  }

  bool create_group(CreateGroup::Request& req, CreateGroup::Response& res) {
    return answer(res, [&] {
      world::GroupSpec spec;
      spec.id = req.id;
      if (spec.id == 0) {
        spec.id = simulation_->groups().empty() ? 1 : simulation_->groups().back()->id() + 1;
      }
      spec.members = req.members;
      spec.centre = {req.centre.x, req.centre.y};
      spec.ospace_radius_m = req.ospace_radius;
      res.id = simulation_->add_group(spec).id();
    });
  }

  bool add_group_members(AddGroupMembers::Request& req, AddGroupMembers::Response& res) {
    return answer(res, [&] { simulation_->add_group_members(req.group_id, req.members); });
  }

  bool set_group_centre(SetGroupCentre::Request& req, SetGroupCentre::Response& res) {
    return answer(res, [&] {
      world::GroupNavigation* group = simulation_->find_group(req.group_id);
      if (group == nullptr) {
        throw core::RequestError("no group with id " + std::to_string(req.group_id));
      }
      group->set_centre({req.centre.x, req.centre.y});
    });
  }

  bool say(Say::Request& req, Say::Response& res) {
    return answer(res, [&] {
      world::SpeechGenerator& speech = simulation_->speech_of(req.speaker_id);
      speech.say(req.act, req.content, simulation_->time_s());
      res.duration = speech.duration_s(req.content);
    });
  }

  bool set_gaze_targets(SetGazeTargets::Request& req, SetGazeTargets::Response& res) {
    return answer(res, [&] {
      world::Human& h = human(req.id);
      if (req.targets.size() != req.probabilities.size()) {
        throw core::RequestError("targets and probabilities must have the same length");
      }
      world::GazeModel model;
      for (size_t i = 0; i < req.targets.size(); ++i) {
        if (simulation_->find_object(req.targets[i]) == nullptr || req.targets[i] == req.id) {
          throw core::RequestError("gaze target " + std::to_string(req.targets[i]) +
                                   " is not another object of the world");
        }
        model.targets.push_back({req.targets[i], req.probabilities[i]});
      }
      model.mean_duration_s = req.mean_duration;
      model.validate();
      h.set_gaze_model(model);
    });
  }

  bool reset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    return answer(res, [&] {
      rebuild();
      publish_state();
      res.message = "reset to " + scene_.path;
    });
  }

  bool pause(std_srvs::SetBool::Request& req, std_srvs::SetBool::Response& res) {
    paused_ = req.data;
    res.success = true;
    res.message = paused_ ? "paused" : "running";
    return true;
  }

  bool step_service(StepSimulation::Request& req, StepSimulation::Response& res) {
    return answer(res, [&] {
      if (!paused_) {
        throw core::RequestError("step needs a paused simulation (call /sim/pause true first)");
      }
      if (req.steps == 0) {
        throw core::RequestError("steps must be >= 1");
      }
      for (uint32_t i = 0; i < req.steps; ++i) {
        step_once();
      }
      res.sim_time = simulation_->time_s();
    });
  }

  world::WorldRunConfig config_;
  world::Scene scene_;
  std::unique_ptr<world::Simulation> simulation_;
  world::OccupancyGrid map_;
  bool paused_{false};
  ros::WallTime last_clock_wall_;
  uint64_t reported_clamps_{0};
  ros::WallTime last_markers_;

  ros::NodeHandle nh_;
  ros::Publisher clock_pub_, state_pub_, map_pub_, marker_pub_, odom_pub_, joint_states_pub_;
  ros::Subscriber cmd_vel_sub_, head_sub_, ground_truth_sub_, joint_state_sub_;
  std::vector<ros::ServiceServer> services_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  ros::init(argc, argv, "world_node");
  ros::NodeHandle private_handle("~");
  world::WorldRunConfig config;
  world::Scene scene;
  try {
    config = world::WorldRunConfig::from_yaml(nodes::read_private_params(private_handle));
    if (config.scene.empty()) {
      config.scene = ros::package::getPath("ari_social_sim") + "/scenes/waiting_room.yaml";
    }
    scene = world::load_scene_file(config.scene);
    if (config.seed >= 0) {
      scene.seed = static_cast<uint64_t>(config.seed);
    }
    // Build once here so a scene that cannot be placed stops the node before it advertises.
    world::SimulationConfig check;
    check.step_s = config.step_s;
    check.map_resolution_m = config.map_resolution_m;
    world::build_simulation(scene, check);
  } catch (const core::Error& e) {
    ROS_FATAL("%s", e.what());
    return 2;
  }
  ROS_INFO("world_node: %s (world %s), seed %lu, step %.3f s, real-time factor %s, ARI %s",
           scene.path.c_str(), scene.world.name.c_str(), static_cast<unsigned long>(scene.seed),
           config.step_s,
           config.real_time_factor > 0 ? std::to_string(config.real_time_factor).c_str()
                                       : "as fast as possible",
           config.ari_source == world::AriSource::kInternal ? "driven here (2D mode)"
                                                            : "from ari_physics_node (3D mode)");
  nodes::WorldNode node(config, std::move(scene));
  node.run();
  return 0;
}
