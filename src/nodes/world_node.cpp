// world_node: the 2D multi-party world as a ROS node that owns simulated time.
// Reads parameters, builds the world core, wires topics and services, converts at the edges.

#include <diagnostic_msgs/DiagnosticArray.h>
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
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "ari_social_sim/AddGroupMembers.h"
#include "ari_social_sim/CreateGroup.h"
#include "ari_social_sim/CreateWalkingGroup.h"
#include "ari_social_sim/JoinGroup.h"
#include "ari_social_sim/LeaveGroup.h"
#include "ari_social_sim/RemoveHuman.h"
#include "ari_social_sim/Say.h"
#include "ari_social_sim/SetGazeTargets.h"
#include "ari_social_sim/SetGoal.h"
#include "ari_social_sim/SetGroupArrangement.h"
#include "ari_social_sim/SetGroupCentre.h"
#include "ari_social_sim/SetGroupConversation.h"
#include "ari_social_sim/SetPose.h"
#include "ari_social_sim/SetPosture.h"
#include "ari_social_sim/SetReaction.h"
#include "ari_social_sim/SetVelocity.h"
#include "ari_social_sim/SpawnHuman.h"
#include "ari_social_sim/StepSimulation.h"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/group_report.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "ari_social_sim/world/service_requests.hpp"
#include "ari_social_sim/world/world_run_config.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"
#include "ari_social_sim/world_speech/small_talk_lines.hpp"
#include "node_support/frames.hpp"
#include "node_support/input_counters.hpp"
#include "node_support/node_main.hpp"
#include "node_support/ros_params.hpp"
#include "world_conversions/ari_base.hpp"
#include "world_conversions/world_markers.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr double kPausedClockPeriodS = 0.1;  // wall seconds between /clock messages while paused
// Longest wall-clock sleep (s) between looks at callbacks and ros::ok(): waiting for the next step
// at a slow real-time factor (1e-3: 50 s per step) still serves services and stops on SIGINT.
constexpr double kPacingSliceS = 0.05;
// Most steps one /sim/step request may take (at the default 0.05 s, 5000 s of sim time, about
// 10 s of wall time): the node serves nothing else meanwhile.
constexpr uint32_t kMaxStepsPerRequest = 100000;

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

constexpr char kCmdVelTopic[] = "/mobile_base_controller/cmd_vel";
constexpr char kHeadCommandTopic[] = "/head_controller/command";
constexpr char kGroundTruthTopic[] = "/ground_truth_odom";
constexpr char kJointStatesTopic[] = "/joint_states";
const std::string kHeadPosition = std::string("points[last].positions[") + kHeadPanJoint + "]";
const std::string kJointPosition = std::string("position[") + kHeadPanJoint + "]";

class WorldNode {
 public:
  WorldNode(const world::WorldRunConfig& config, world::Scene scene,
            std::shared_ptr<const world::ConversationLines> conversation_lines)
      : config_(config),
        scene_(std::move(scene)),
        conversation_lines_(std::move(conversation_lines)) {
    rebuild();
    map_ = world::rasterize_static_map(scene_.world, config_.simulation.map_resolution_m);
    paused_ = config_.start_paused;

    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    // Latched: a node that comes up while the world is paused (by /sim/pause, a debugger or a
    // test) gets the last state at once instead of waiting for the next step.
    state_pub_ = nh_.advertise<WorldState>("/sim/world_state", 10, /*latch=*/true);
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("/map", 1, /*latch=*/true);
    marker_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("/sim/markers", 1);
    diagnostics_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    if (config_.ari_source == world::AriSource::kInternal) {
      inputs_.declare_drop(kCmdVelTopic, "linear.x");
      inputs_.declare_drop(kCmdVelTopic, "angular.z");
      inputs_.declare_clamp(kCmdVelTopic);
      inputs_.declare_drop(kHeadCommandTopic, kHeadPosition);
      inputs_.declare_clamp(kHeadCommandTopic);
    } else {
      for (const char* field : {"pose.position.x", "pose.position.y", "pose.orientation",
                                "twist.linear.x", "twist.angular.z"}) {
        inputs_.declare_drop(kGroundTruthTopic, field);
      }
      inputs_.declare_drop(kJointStatesTopic, kJointPosition);
      inputs_.declare_clamp(kJointStatesTopic);
    }
    if (config_.ari_source == world::AriSource::kInternal) {
      odom_pub_ = nh_.advertise<nav_msgs::Odometry>("/mobile_base_controller/odom", 10);
      // The head's joint states come from here only in 2D mode; in 3D mode ari_physics_node
      // publishes /joint_states and this node reads them.
      joint_states_pub_ = nh_.advertise<sensor_msgs::JointState>("/joint_states", 10);
      cmd_vel_sub_ = nh_.subscribe(kCmdVelTopic, kCheckedInputQueue, &WorldNode::on_cmd_vel, this);
      head_sub_ =
          nh_.subscribe(kHeadCommandTopic, kCheckedInputQueue, &WorldNode::on_head_command, this);
    } else {
      // 3D mode: ari_physics_node drives ARI and publishes its odometry and tf; the 2D body
      // follows its ground truth and head pan.
      ground_truth_sub_ =
          nh_.subscribe(kGroundTruthTopic, kCheckedInputQueue, &WorldNode::on_ground_truth, this);
      joint_state_sub_ =
          nh_.subscribe(kJointStatesTopic, kCheckedInputQueue, &WorldNode::on_joint_states, this);
    }

    services_.push_back(nh_.advertiseService("/sim/spawn_human", &WorldNode::spawn_human, this));
    services_.push_back(nh_.advertiseService("/sim/remove_human", &WorldNode::remove_human, this));
    services_.push_back(nh_.advertiseService("/sim/set_goal", &WorldNode::set_goal, this));
    services_.push_back(nh_.advertiseService("/sim/set_velocity", &WorldNode::set_velocity, this));
    services_.push_back(nh_.advertiseService("/sim/set_pose", &WorldNode::set_pose, this));
    services_.push_back(nh_.advertiseService("/sim/create_group", &WorldNode::create_group, this));
    services_.push_back(
        nh_.advertiseService("/sim/create_walking_group", &WorldNode::create_walking_group, this));
    services_.push_back(
        nh_.advertiseService("/sim/add_group_members", &WorldNode::add_group_members, this));
    services_.push_back(
        nh_.advertiseService("/sim/set_group_centre", &WorldNode::set_group_centre, this));
    services_.push_back(nh_.advertiseService("/sim/set_group_conversation",
                                             &WorldNode::set_group_conversation, this));
    services_.push_back(nh_.advertiseService("/sim/set_group_arrangement",
                                             &WorldNode::set_group_arrangement, this));
    services_.push_back(nh_.advertiseService("/sim/join_group", &WorldNode::join_group, this));
    services_.push_back(nh_.advertiseService("/sim/leave_group", &WorldNode::leave_group, this));
    services_.push_back(nh_.advertiseService("/sim/say", &WorldNode::say, this));
    services_.push_back(
        nh_.advertiseService("/sim/set_gaze_targets", &WorldNode::set_gaze_targets, this));
    services_.push_back(nh_.advertiseService("/sim/set_reaction", &WorldNode::set_reaction, this));
    services_.push_back(nh_.advertiseService("/sim/set_posture", &WorldNode::set_posture, this));
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
    restart_pacing();
    while (ros::ok()) {
      ros::spinOnce();
      publish_diagnostics_when_due();
      if (paused_) {
        ros::WallDuration(0.01).sleep();
        // A paused world keeps publishing its clock (as Gazebo does), so that a node that comes
        // up meanwhile gets a valid sim time.
        if (ros::WallTime::now() - last_clock_wall_ > ros::WallDuration(kPausedClockPeriodS)) {
          publish_clock(ros::Time(simulation_->time_s()));
        }
        restart_pacing();
        continue;
      }
      // The next step is due once the wall clock has caught up with the sim time reached so far.
      // Seconds as doubles: at a tiny real-time factor the wait overflows a ros::WallDuration.
      // The wait goes in short slices so that callbacks are served and SIGINT is seen meanwhile.
      if (config_.real_time_factor > 0.0) {
        const double due_s = pacing_start_wall_s_ + (simulation_->time_s() - pacing_start_sim_s_) /
                                                        config_.real_time_factor;
        const double wait_s = due_s - ros::WallTime::now().toSec();
        if (wait_s > 0.0) {
          ros::WallDuration(std::min(wait_s, kPacingSliceS)).sleep();
          continue;
        }
      }
      step_once();
      if (config_.duration_s > 0.0 && simulation_->time_s() >= config_.duration_s - 1e-9) {
        report();
        return;
      }
    }
  }

 private:
  /// Sim time from now on is paced from the current sim time and wall time: after a pause, and
  /// after a reset took sim time back to 0 (pacing from the old start would then run as fast as
  /// possible until sim time caught up with it).
  void restart_pacing() {
    pacing_start_wall_s_ = ros::WallTime::now().toSec();
    pacing_start_sim_s_ = simulation_->time_s();
  }

  void publish_diagnostics_when_due() {
    inputs_.publish_when_due(diagnostics_pub_, ros::Time(simulation_->time_s()));
  }

  // The clamps StepDiagnostics counted during `command`, credited to `topic`.
  template <class Command>
  void count_clamps(const std::string& topic, Command command) {
    const uint64_t before = simulation_->diagnostics().clamped_commands;
    command();
    inputs_.add_clamps(topic, simulation_->diagnostics().clamped_commands - before);
  }

  void rebuild() {
    simulation_ = world::build_simulation(scene_, config_.simulation);
    simulation_->set_conversation_lines(conversation_lines_);
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

    joint_states_pub_.publish(joint_states_of(ari, stamp.toSec()));
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

  // Topic callbacks drop a message with any non-finite field they use (counted, warned, on
  // /diagnostics): the core would refuse it anyway, and a callback must not throw.
  void on_cmd_vel(const geometry_msgs::Twist& twist) {
    if (simulation_->ari() == nullptr) {
      ROS_WARN_THROTTLE(5.0, "cmd_vel received but the scene has no ARI");
      return;
    }
    const bool linear_ok = inputs_.finite(kCmdVelTopic, "linear.x", twist.linear.x);
    const bool angular_ok = inputs_.finite(kCmdVelTopic, "angular.z", twist.angular.z);
    if (linear_ok && angular_ok) {
      count_clamps(kCmdVelTopic,
                   [&] { simulation_->command_ari_twist(twist.linear.x, twist.angular.z); });
    }
  }

  void on_head_command(const trajectory_msgs::JointTrajectory& trajectory) {
    const std::optional<double> pan = head_pan_target(trajectory);
    if (simulation_->ari() == nullptr || !pan) {
      ROS_WARN_THROTTLE(5.0,
                        "head command ignored: needs ARI and a position for %s in its last point",
                        kHeadPanJoint);
      return;
    }
    if (inputs_.finite(kHeadCommandTopic, kHeadPosition, *pan)) {
      count_clamps(kHeadCommandTopic, [&] { simulation_->command_ari_head_pan(*pan); });
    }
  }

  void on_ground_truth(const nav_msgs::Odometry& truth) {
    if (simulation_->ari() == nullptr) {
      return;
    }
    const geometry_msgs::Point& p = truth.pose.pose.position;
    const geometry_msgs::Quaternion& q = truth.pose.pose.orientation;
    // Checked after the conversion: finite but huge components can still make a NaN yaw.
    const double yaw =
        std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
    const double linear = truth.twist.twist.linear.x;
    const double angular = truth.twist.twist.angular.z;
    bool ok = inputs_.finite(kGroundTruthTopic, "pose.position.x", p.x);
    ok = inputs_.finite(kGroundTruthTopic, "pose.position.y", p.y) && ok;
    ok = inputs_.finite(kGroundTruthTopic, "pose.orientation", yaw) && ok;
    ok = inputs_.finite(kGroundTruthTopic, "twist.linear.x", linear) && ok;
    ok = inputs_.finite(kGroundTruthTopic, "twist.angular.z", angular) && ok;
    if (ok) {
      simulation_->follow_ari({{p.x, p.y}, yaw}, linear, angular);
    }
  }

  void on_joint_states(const sensor_msgs::JointState& state) {
    const auto joint = std::find(state.name.begin(), state.name.end(), kHeadPanJoint);
    const size_t index = static_cast<size_t>(joint - state.name.begin());
    if (simulation_->ari() != nullptr && joint != state.name.end() &&
        index < state.position.size() &&
        inputs_.finite(kJointStatesTopic, kJointPosition, state.position[index])) {
      count_clamps(kJointStatesTopic,
                   [&] { simulation_->command_ari_head_pan(state.position[index]); });
    }
  }

  bool spawn_human(SpawnHuman::Request& req, SpawnHuman::Response& res) {
    return answer(res, [&] {
      const world::SpawnHumanRequest request{req.id,  req.name,   req.role,      from_msg(req.pose),
                                             req.age, req.gender, req.mask != 0, req.emotion};
      res.id = simulation_->add_human(request.spec()).id();
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
      simulation_->set_human_velocity(req.id, {req.vx, req.vy}, req.omega);
    });
  }

  bool set_pose(SetPose::Request& req, SetPose::Response& res) {
    return answer(res, [&] {
      simulation_->set_pose(req.id, from_msg(req.pose));
      publish_state();
    });
  }

  bool create_group(CreateGroup::Request& req, CreateGroup::Response& res) {
    return answer(res, [&] {
      world::GroupSpec spec;
      spec.id = req.id;
      spec.members = req.members;
      spec.centre = {req.centre.x, req.centre.y};
      spec.ospace_radius_m = req.ospace_radius;
      spec.arrangement =
          world::requested_arrangement("create_group", req.arrangement, spec.arrangement);
      res.id = simulation_->add_group(spec).id();
    });
  }

  bool create_walking_group(CreateWalkingGroup::Request& req, CreateWalkingGroup::Response& res) {
    return answer(res, [&] {
      world::WalkingGroupRequest request;
      request.id = req.id;
      request.members = req.members;
      request.formation = req.formation;
      request.goal = from_msg(req.goal);
      request.speed_mps = req.speed;
      request.spacing_m = req.spacing;
      request.on_arrival = req.on_arrival;
      request.arrangement = req.arrangement;
      res.id = simulation_->add_walking_group(request.spec()).id();
    });
  }

  bool add_group_members(AddGroupMembers::Request& req, AddGroupMembers::Response& res) {
    return answer(res, [&] { simulation_->add_group_members(req.group_id, req.members); });
  }

  bool set_group_centre(SetGroupCentre::Request& req, SetGroupCentre::Response& res) {
    return answer(res, [&] {
      simulation_->set_group_centre(req.group_id, {req.centre.x, req.centre.y});
    });
  }

  bool set_group_conversation(SetGroupConversation::Request& req,
                              SetGroupConversation::Response& res) {
    return answer(res, [&] { simulation_->set_group_conversation(req.group_id, req.enabled); });
  }

  bool set_group_arrangement(SetGroupArrangement::Request& req,
                             SetGroupArrangement::Response& res) {
    return answer(res, [&] {
      const model::Arrangement arrangement = world::requested_arrangement(
          "set_group_arrangement", req.arrangement, model::Arrangement::kCircle);
      simulation_->set_group_arrangement(
          req.group_id, arrangement, req.has_heading ? std::optional(req.heading) : std::nullopt);
    });
  }

  bool join_group(JoinGroup::Request& req, JoinGroup::Response& res) {
    return answer(res, [&] { simulation_->join_group(req.group_id, req.agent_id); });
  }

  bool leave_group(LeaveGroup::Request& req, LeaveGroup::Response& res) {
    return answer(res, [&] { simulation_->leave_group(req.agent_id); });
  }

  bool say(Say::Request& req, Say::Response& res) {
    return answer(res,
                  [&] { res.duration = simulation_->say(req.speaker_id, req.act, req.content); });
  }

  bool set_gaze_targets(SetGazeTargets::Request& req, SetGazeTargets::Response& res) {
    return answer(res, [&] {
      const world::GazeTargetsRequest request{req.targets, req.probabilities, req.mean_duration};
      simulation_->set_human_gaze(req.id, request.model());
    });
  }

  bool set_reaction(SetReaction::Request& req, SetReaction::Response& res) {
    return answer(res, [&] { simulation_->set_human_reaction(req.id, req.profile); });
  }

  bool set_posture(SetPosture::Request& req, SetPosture::Response& res) {
    return answer(res, [&] {
      simulation_->set_human_posture(req.id, world::requested_posture(req.posture));
    });
  }

  bool reset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    return answer(res, [&] {
      rebuild();
      restart_pacing();
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
      if (req.steps == 0 || req.steps > kMaxStepsPerRequest) {
        throw core::RequestError(
            "step: steps: expected an integer in [1, " + std::to_string(kMaxStepsPerRequest) +
            "] per request (call again for more), got " + std::to_string(req.steps));
      }
      // Nothing else is served while this runs; SIGINT still ends it between two steps.
      for (uint32_t i = 0; i < req.steps && ros::ok(); ++i) {
        step_once();
      }
      res.sim_time = simulation_->time_s();
    });
  }

  world::WorldRunConfig config_;
  world::Scene scene_;
  std::shared_ptr<const world::ConversationLines> conversation_lines_;
  std::unique_ptr<world::Simulation> simulation_;
  model::OccupancyGrid map_;
  bool paused_{false};
  ros::WallTime last_clock_wall_;
  uint64_t reported_clamps_{0};
  ros::WallTime last_markers_;
  double pacing_start_wall_s_{0.0};
  double pacing_start_sim_s_{0.0};
  InputCounters inputs_{"world_node"};

  ros::NodeHandle nh_;
  ros::Publisher clock_pub_, state_pub_, map_pub_, marker_pub_, odom_pub_, joint_states_pub_,
      diagnostics_pub_;
  ros::Subscriber cmd_vel_sub_, head_sub_, ground_truth_sub_, joint_state_sub_;
  std::vector<ros::ServiceServer> services_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  return nodes::run_node(argc, argv, "world_node", [] {
    ros::NodeHandle private_handle("~");
    world::WorldRunConfig config =
        world::WorldRunConfig::from_yaml(nodes::read_private_params(private_handle));
    if (config.scene.empty()) {
      config.scene = ros::package::getPath("ari_social_sim") + "/scenes/waiting_room.yaml";
    }
    world::Scene scene = world::load_scene_file(config.scene);
    scene.seed = config.seed.value_or(scene.seed);
    // Build once here so a scene that cannot be placed stops the node before it advertises.
    world::build_simulation(scene, config.simulation);
    ROS_INFO("world_node: %s (world %s), seed %lu, step %.3f s, real-time factor %s, ARI %s",
             scene.path.c_str(), scene.world.name.c_str(), static_cast<unsigned long>(scene.seed),
             config.simulation.step_s,
             config.real_time_factor > 0 ? std::to_string(config.real_time_factor).c_str()
                                         : "as fast as possible",
             config.ari_source == world::AriSource::kInternal ? "driven here (2D mode)"
                                                              : "from ari_physics_node (3D mode)");
    // What the conversation groups say: the package's small talk and dialogue domain.
    nodes::WorldNode node(
        config, std::move(scene),
        world_speech::SmallTalkLines::load(ros::package::getPath("ari_social_sim") + "/config"));
    node.run();
    return 0;
  });
}
