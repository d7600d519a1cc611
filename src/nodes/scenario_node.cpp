// scenario_node: plays a scenario's script (D6.4 §3.7) against a running suite through its public
// interfaces only: /sim/world_state and the /sim/... services of world_node, /tts (dialogue_node),
// move_base and /social_mpc/approach (social_mpc_node), /humans/persons/..., tf and
// /humans/interactions/groups (perception, whose persons are matched with the script's humans by
// where their bodies stand). Prints the transcript and the outcome at the end and exits 0 on
// success, 1 on failure, 130 when interrupted (SIGINT, SIGTERM, a ROS shutdown), after printing
// the report so far. Never waits for ever: a wall-time limit covers the whole run, and a world
// that stops sending states (world_node gone, or the world left paused) ends the run.

#include <actionlib/client/simple_action_client.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <signal.h>
#include <std_srvs/SetBool.h>

#include <csignal>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "ari_social_sim/AddGroupMembers.h"
#include "ari_social_sim/ApproachAction.h"
#include "ari_social_sim/CreateGroup.h"
#include "ari_social_sim/CreateWalkingGroup.h"
#include "ari_social_sim/DialogueOutcome.h"
#include "ari_social_sim/DialogueUtterance.h"
#include "ari_social_sim/Group.h"
#include "ari_social_sim/LeaveGroup.h"
#include "ari_social_sim/RemoveHuman.h"
#include "ari_social_sim/Say.h"
#include "ari_social_sim/ScenarioStatus.h"
#include "ari_social_sim/SetGazeTargets.h"
#include "ari_social_sim/SetGoal.h"
#include "ari_social_sim/SetGroupArrangement.h"
#include "ari_social_sim/SetGroupCentre.h"
#include "ari_social_sim/SetGroupConversation.h"
#include "ari_social_sim/SetPosture.h"
#include "ari_social_sim/SetReaction.h"
#include "ari_social_sim/SpawnHuman.h"
#include "ari_social_sim/StepSimulation.h"
#include "ari_social_sim/TtsAction.h"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/scenario/episode_metrics.hpp"
#include "ari_social_sim/scenario/episode_report.hpp"
#include "ari_social_sim/scenario/group_memory.hpp"
#include "ari_social_sim/scenario/person_identities.hpp"
#include "ari_social_sim/scenario/run_watchdog.hpp"
#include "ari_social_sim/scenario/scenario_run_config.hpp"
#include "ari_social_sim/scenario/script_runner.hpp"
#include "dialogue_conversions/dialogue.hpp"
#include "navigation_conversions/navigation_msgs.hpp"
#include "node_support/node_main.hpp"
#include "node_support/renewing_tf_buffer.hpp"
#include "node_support/ros_params.hpp"
#include "node_support/single_publisher.hpp"
#include "perception_conversions/heard_speech.hpp"
#include "perception_conversions/perceived_persons.hpp"
#include "scenario_conversions/scenario_status.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

using TtsClient = actionlib::SimpleActionClient<TtsAction>;
using MoveBaseClient = actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction>;
using ApproachClient = actionlib::SimpleActionClient<ApproachAction>;

constexpr char kLanguage[] = "en_GB";

// Exit code of an interrupted run: 128 + SIGINT, as a shell reports a process it interrupted.
constexpr int kInterruptedExit = 130;

// The signal that asked the node to stop (0: none). Set by the handler, read by every wait.
volatile std::sig_atomic_t g_stop_signal = 0;

void on_stop_signal(int signal) {
  g_stop_signal = signal;
}

// Why a run ends before its script does: the watchdog's reason, or an interruption.
struct RunStopped {
  std::string reason;
  bool interrupted{false};
};

// Called in every wait with what the node is doing; throws RunStopped when the run must end.
using StopCheck = std::function<void(const std::string& activity)>;

// Calls a /sim/... service; a refusal or an unreachable server becomes a core::RequestError.
template <class Service>
void call(const std::string& name, Service& service) {
  if (!ros::service::call(name, service)) {
    throw core::RequestError("service " + name + " is not available");
  }
  if (!service.response.success) {
    throw core::RequestError(service.response.message);
  }
}

// Maps an action client's state to the script's view of ARI's navigation.
scenario::NavigationStatus status_of(const actionlib::SimpleClientGoalState& state,
                                     const std::string& reason) {
  using State = actionlib::SimpleClientGoalState;
  switch (state.state_) {
    case State::PENDING:
    case State::ACTIVE:
      return {scenario::NavigationState::kActive, ""};
    case State::SUCCEEDED:
      return {scenario::NavigationState::kSucceeded, ""};
    case State::ABORTED:
    case State::REJECTED:
    case State::LOST:
      return {scenario::NavigationState::kFailed, reason.empty() ? state.toString() : reason};
    default:  // PREEMPTED, RECALLED: we cancelled it
      return {scenario::NavigationState::kIdle, ""};
  }
}

// The script's commands as requests to the suite's public services and actions.
class RosCommands : public scenario::Commands {
 public:
  // Creates the action clients the script uses and waits (wall time, as sim time may stand
  // still) for them and the world's services. Sim time must be valid (> 0): actionlib waits for it.
  // `while_waiting` runs about once a wall second while a server is missing; `check` on every
  // look.
  void connect(const scenario::ScriptInterfaces& uses, double timeout_s,
               const std::function<void()>& while_waiting, const StopCheck& check) {
    std::vector<std::pair<std::string, std::function<bool()>>> needed = {
        {"/sim/say", [] { return ros::service::exists("/sim/say", false); }}};
    if (uses.text_to_speech) {
      tts_ = std::make_unique<TtsClient>("/tts", true);
      needed.emplace_back("/tts action server", [this] { return tts_->isServerConnected(); });
    }
    if (uses.move_base) {
      move_base_ = std::make_unique<MoveBaseClient>("move_base", true);
      needed.emplace_back("move_base action server",
                          [this] { return move_base_->isServerConnected(); });
    }
    if (uses.approach) {
      approach_ = std::make_unique<ApproachClient>("/social_mpc/approach", true);
      needed.emplace_back("/social_mpc/approach action server",
                          [this] { return approach_->isServerConnected(); });
    }
    const ros::WallTime limit = ros::WallTime::now() + ros::WallDuration(timeout_s);
    ros::WallTime last_waited = ros::WallTime::now();
    for (const auto& [name, ready] : needed) {
      while (!ready()) {
        check("waiting for the " + name);
        if (ros::WallTime::now() > limit) {
          throw core::RequestError(name + " did not appear within " + std::to_string(timeout_s) +
                                   " s (server_timeout)");
        }
        if (ros::WallTime::now() - last_waited > ros::WallDuration(1.0)) {
          while_waiting();
          last_waited = ros::WallTime::now();
        }
        ros::spinOnce();
        ros::WallDuration(0.05).sleep();
      }
    }
  }

  scenario::NavigationStatus navigation() const {
    if (active_ == Navigation::kFailedUnsent) {
      return {scenario::NavigationState::kFailed, unsent_reason_};
    }
    if (active_ == Navigation::kMoveBase) {
      return status_of(move_base_->getState(), "");
    }
    if (active_ == Navigation::kApproach) {
      const auto result = approach_->getResult();
      return status_of(approach_->getState(), result ? result->reason : "");
    }
    return {};
  }

  void say(const scenario::AgentRef& speaker, const std::string& act,
           const std::string& text) override {
    if (speaker.is_ari()) {
      TtsGoal goal;
      goal.rawtext.text = text;
      goal.rawtext.lang_id = kLanguage;
      tts_->sendGoal(goal);
      return;
    }
    Say service;
    service.request.speaker_id = speaker.human_id;
    service.request.act = act;
    service.request.content = text;
    call("/sim/say", service);
  }

  void set_human_goal(model::ObjectId human, const core::Pose2& goal) override {
    SetGoal service;
    service.request.id = human;
    service.request.goal = to_msg(goal);
    call("/sim/set_goal", service);
  }

  void navigate(const core::Pose2& goal) override {
    cancel_navigation();
    move_base_msgs::MoveBaseGoal target;
    target.target_pose = map_goal_msg(goal, ros::Time::now());
    move_base_->sendGoal(target);
    active_ = Navigation::kMoveBase;
  }

  void approach(const std::string& person_id, bool join_group) override {
    cancel_navigation();
    ApproachGoal goal;
    goal.target_type =
        join_group ? ApproachGoal::TARGET_GROUP_OF_PERSON : ApproachGoal::TARGET_PERSON;
    goal.target_id = person_id;
    approach_->sendGoal(goal);
    active_ = Navigation::kApproach;
  }

  void fail_navigation(const std::string& reason) override {
    cancel_navigation();
    ROS_WARN("scenario_node: navigation goal not sent: %s", reason.c_str());
    unsent_reason_ = reason;
    active_ = Navigation::kFailedUnsent;
  }

  void cancel_navigation() override {
    if (active_ == Navigation::kMoveBase) {
      move_base_->cancelGoal();
    } else if (active_ == Navigation::kApproach) {
      approach_->cancelGoal();
    }
    active_ = Navigation::kNone;
  }

  void add_human(const world::HumanSpec& spec) override {
    SpawnHuman spawn;
    spawn.request.id = spec.id;
    spawn.request.name = spec.name;
    spawn.request.role = spec.role;
    spawn.request.pose = to_msg(spec.pose);
    spawn.request.age = static_cast<float>(spec.age_years);
    spawn.request.gender = model::to_string(spec.gender);
    spawn.request.mask = spec.mask;
    spawn.request.emotion = model::to_string(spec.emotion);
    call("/sim/spawn_human", spawn);
    if (spec.goal) {
      set_human_goal(spec.id, *spec.goal);
    }
    if (spec.gaze) {
      SetGazeTargets gaze;
      gaze.request.id = spec.id;
      for (const world::GazeTarget& target : spec.gaze->targets) {
        gaze.request.targets.push_back(target.id);
        gaze.request.probabilities.push_back(target.probability);
      }
      gaze.request.mean_duration = spec.gaze->mean_duration_s;
      call("/sim/set_gaze_targets", gaze);
    }
    if (spec.reaction != world::ReactionProfile::kIgnore) {
      SetReaction reaction;
      reaction.request.id = spec.id;
      reaction.request.profile = world::reaction_name(spec.reaction);
      call("/sim/set_reaction", reaction);
    }
  }

  void remove_human(model::ObjectId human) override {
    RemoveHuman service;
    service.request.id = human;
    call("/sim/remove_human", service);
  }

  void create_group(const world::GroupSpec& spec) override {
    CreateGroup service;
    service.request.id = spec.id;
    service.request.members = spec.members;
    service.request.centre.x = spec.centre.x();
    service.request.centre.y = spec.centre.y();
    service.request.ospace_radius = spec.ospace_radius_m;
    service.request.arrangement = model::to_string(spec.arrangement);
    call("/sim/create_group", service);
    if (spec.heading_rad) {
      // The heading is not among create_group's fields: it follows as its own request.
      set_group_arrangement(service.response.id, spec.arrangement, spec.heading_rad);
    }
    if (!spec.conversation.enabled) {
      // Nor is the conversation's switch (the script refuses its other fields).
      SetGroupConversation quiet;
      quiet.request.group_id = service.response.id;
      quiet.request.enabled = false;
      call("/sim/set_group_conversation", quiet);
    }
  }

  // The script refuses the spec's fields the service does not carry (line_spacing,
  // wait_distance), so the request is the whole spec.
  void create_walking_group(const world::WalkingGroupSpec& spec) override {
    CreateWalkingGroup service;
    service.request.id = spec.id;
    service.request.members = spec.members;
    service.request.formation = world::to_string(spec.formation);
    service.request.goal = to_msg(spec.goal);
    service.request.speed = spec.speed_mps;
    service.request.spacing = spec.spacing_m;
    service.request.on_arrival = world::to_string(spec.on_arrival);
    service.request.arrangement = model::to_string(spec.arrangement);
    call("/sim/create_walking_group", service);
  }

  void add_group_members(model::ObjectId group,
                         const std::vector<model::ObjectId>& members) override {
    AddGroupMembers service;
    service.request.group_id = group;
    service.request.members = members;
    call("/sim/add_group_members", service);
  }

  void set_group_centre(model::ObjectId group, const Eigen::Vector2d& centre) override {
    SetGroupCentre service;
    service.request.group_id = group;
    service.request.centre.x = centre.x();
    service.request.centre.y = centre.y();
    call("/sim/set_group_centre", service);
  }

  void set_group_arrangement(model::ObjectId group, model::Arrangement arrangement,
                             std::optional<double> heading_rad) override {
    SetGroupArrangement service;
    service.request.group_id = group;
    service.request.arrangement = model::to_string(arrangement);
    service.request.has_heading = heading_rad.has_value();
    service.request.heading = heading_rad.value_or(0.0);
    call("/sim/set_group_arrangement", service);
  }

  void leave_group(model::ObjectId agent) override {
    LeaveGroup service;
    service.request.agent_id = agent;
    call("/sim/leave_group", service);
  }

  void set_posture(model::ObjectId human, world::Posture posture) override {
    SetPosture service;
    service.request.id = human;
    service.request.posture = world::posture_name(posture);
    call("/sim/set_posture", service);
  }

 private:
  // The client of ARI's current goal; kFailedUnsent: a goal that could not be named.
  enum class Navigation { kNone, kMoveBase, kApproach, kFailedUnsent };

  std::unique_ptr<TtsClient> tts_;
  std::unique_ptr<MoveBaseClient> move_base_;
  std::unique_ptr<ApproachClient> approach_;
  Navigation active_{Navigation::kNone};
  std::string unsent_reason_;
};

class ScenarioNode {
 public:
  /// `dialogue` is needed by scripts that converse.
  ScenarioNode(const scenario::ScenarioRunConfig& config, scenario::Scenario scenario,
               std::unique_ptr<dialogue::DialogueSetup> dialogue)
      : config_(config),
        scenario_(std::move(scenario)),
        dialogue_(std::move(dialogue)),
        runner_(scenario_, config.seed.value_or(scenario_.scene.seed), dialogue_.get(),
                config.hearing),
        watchdog_(config.wall_time_limit_for(scenario_.script.time_limit_s), config.world_timeout_s,
                  ros::WallTime::now().toSec()),
        groups_(config.group_timeout_s) {
    status_pub_ = nh_.advertise<ScenarioStatus>("/scenario/status", 1, /*latch=*/true);
  }

  /// Waits for the suite, starts the world and plays the script, then prints the report;
  /// returns the exit code. Throws core::Error when a server the script needs does not appear
  /// within server_timeout.
  int run() {
    try {
      play();
    } catch (const RunStopped& stop) {
      if (stop.interrupted) {
        runner_.interrupt(stop.reason);
      } else {
        runner_.abort(stop.reason);
        ROS_ERROR("scenario_node: %s", stop.reason.c_str());
      }
      // The script's own end was published with its last world state; this one was not.
      status_pub_.publish(to_msg(scenario_.name, runner_, ros::Time::now().toSec()));
    }
    const scenario::Outcome& outcome = *runner_.outcome();
    // The recording ends with the script; a world gone or interrupted is left alone.
    if (!outcome.interrupted && world_reachable()) {
      set_paused(true);
    }
    std::cout << scenario::format_report(scenario_.name, runner_, metrics_.metrics()) << std::flush;
    if (outcome.interrupted) {
      return kInterruptedExit;
    }
    return outcome.success ? 0 : 1;
  }

 private:
  // Plays until the script ends; throws RunStopped when the run must end before it.
  void play() {
    step_paused_world();
    // A node that waits for a first world state before it serves (dialogue_node's /tts) may have
    // missed the one step: the paused world steps once a second until everything is up.
    commands_.connect(
        scenario_.script.interfaces(), config_.server_timeout_s, [this] { step_paused_world(); },
        [this](const std::string& activity) { check(activity); });
    state_sub_ = nh_.subscribe("/sim/world_state", 100, &ScenarioNode::on_world_state, this);
    const scenario::ScriptInterfaces uses = scenario_.script.interfaces();
    if (uses.approach || uses.perceived_groups) {
      tf_ = std::make_unique<RenewingTfBuffer>();
      persons_ = std::make_unique<PerceivedPersons>(nh_);
    }
    if (uses.perceived_groups) {
      groups_sub_ =
          nh_.subscribe("/humans/interactions/groups", 100, &ScenarioNode::on_group, this);
    }
    if (uses.speech_recognition ||
        (uses.dialogue && config_.hearing == scenario::Hearing::kRecognised)) {
      heard_speech_ = std::make_unique<HeardSpeech>(nh_);
    }
    if (uses.dialogue) {
      // What ARI perceived of the humans' utterances, and how the dialogue ended (latched).
      utterances_sub_ =
          nh_.subscribe("/sim/dialogue/utterances", 100, &ScenarioNode::on_utterance, this);
      outcome_sub_ = nh_.subscribe("/sim/dialogue/outcome", 10, &ScenarioNode::on_outcome, this);
    }
    // Connected before the world runs, so that the script sees every step from the first.
    const ros::WallTime limit = ros::WallTime::now() + ros::WallDuration(config_.server_timeout_s);
    while (state_sub_.getNumPublishers() == 0) {
      check("waiting for a publisher of /sim/world_state");
      if (ros::WallTime::now() > limit) {
        throw core::RequestError("/sim/world_state has no publisher after " +
                                 std::to_string(config_.server_timeout_s) + " s (server_timeout)");
      }
      ros::WallDuration(0.01).sleep();
    }
    if (config_.start_world) {
      set_paused(false);  // world_node may wait paused for the suite to come up
      watchdog_.expect_world(ros::WallTime::now().toSec());
    }
    while (!runner_.finished()) {
      ros::spinOnce();
      check(runner_.state().empty() ? "waiting for the first /sim/world_state"
                                    : "in state " + runner_.state());
      ros::WallDuration(0.001).sleep();
    }
  }

  // Ends the run (throws RunStopped) on a stop signal, a ROS shutdown, or the watchdog's limits.
  void check(const std::string& activity) {
    if (g_stop_signal != 0) {
      throw RunStopped{g_stop_signal == SIGINT ? "SIGINT" : "SIGTERM", true};
    }
    if (!ros::ok()) {
      throw RunStopped{"ROS shut down (rosnode kill or the master)", true};
    }
    if (const std::optional<std::string> reason = watchdog_.expired(
            ros::WallTime::now().toSec(), activity, [this] { return world_reachable(); })) {
      throw RunStopped{*reason, false};
    }
  }

  // Whether world_node answers: its /sim/pause service is registered and takes a connection (a
  // killed node stays registered with the master, but nothing listens on its port).
  bool world_reachable() const { return ros::service::exists("/sim/pause", false); }

 private:
  void on_world_state(const ros::MessageEvent<const WorldState>& event) {
    if (!state_publisher_.accept(event.getPublisherName())) {
      return;
    }
    const WorldState& msg = *event.getConstMessage();
    watchdog_.world_state(ros::WallTime::now().toSec());
    if (runner_.finished()) {
      return;
    }
    scenario::Observations observations;
    observations.world = from_msg(msg);
    observations.navigation = commands_.navigation();
    log_navigation_failure(observations.navigation);
    if (persons_) {
      tf_->renew_if_stale();
      identities_.update(observations.world, sightings());
      observations.person_ids = identities_.person_ids();
      log_new_matches(observations.person_ids);
    }
    observations.perceived_groups = groups_.believed_at(observations.world.time_s, identities_);
    observations.heard = std::move(heard_);
    heard_.clear();
    if (heard_speech_) {
      observations.transcripts = heard_speech_->take();
    }
    observations.dialogue_end = dialogue_end_;
    const size_t visits = runner_.visits().size();
    runner_.update(observations, commands_);
    metrics_.observe(observations);
    if (runner_.visits().size() != visits || runner_.finished()) {
      status_pub_.publish(to_msg(scenario_.name, runner_, msg.header.stamp.toSec()));
      ROS_INFO("scenario %s: %s at %.2f s", scenario_.name.c_str(),
               runner_.finished() ? "finished" : ("state " + runner_.state()).c_str(),
               observations.world.time_s);
    }
  }

  void on_group(const Group& msg) {
    groups_.report(msg.group_id, msg.header.stamp.toSec(), msg.members);
  }

  // Where perception's tracked persons are now: at their body, else at their person frame.
  std::vector<scenario::PersonSighting> sightings() const {
    std::vector<scenario::PersonSighting> sightings;
    for (const PerceivedPersons::Placed& person : persons_->place(tf_->buffer())) {
      sightings.push_back({person.person_id, person.X_map_frame.position, person.from_body});
    }
    return sightings;
  }

  // Who is who is the first thing to check when a script never sees its people.
  void log_new_matches(const std::map<model::ObjectId, std::string>& person_ids) {
    for (const auto& [human, person] : person_ids) {
      const auto logged = logged_person_ids_.find(human);
      if (logged == logged_person_ids_.end() || logged->second != person) {
        ROS_INFO("scenario_node: human %u is perceived as person %s", human, person.c_str());
      }
    }
    logged_person_ids_ = person_ids;
  }

  // The script sees only that navigation failed; the log says why.
  void log_navigation_failure(const scenario::NavigationStatus& navigation) {
    const bool failed = navigation.state == scenario::NavigationState::kFailed;
    if (failed && !navigation_failure_logged_) {
      ROS_WARN("scenario_node: ARI's navigation failed: %s", navigation.reason.c_str());
    }
    navigation_failure_logged_ = failed;
  }

  // A world started paused stands at sim time 0, which ROS takes for "no time yet"; one step
  // makes it valid for the action clients. A running world refuses the step, which is fine.
  void step_paused_world() {
    const ros::WallTime limit = ros::WallTime::now() + ros::WallDuration(config_.server_timeout_s);
    while (!ros::service::exists("/sim/step", false)) {
      check("waiting for world_node's /sim/step");
      if (ros::WallTime::now() > limit) {
        throw core::RequestError("world_node's /sim/step did not appear within " +
                                 std::to_string(config_.server_timeout_s) + " s (server_timeout)");
      }
      ros::WallDuration(0.05).sleep();
    }
    StepSimulation step;
    step.request.steps = 1;
    ros::service::call("/sim/step", step);
  }

  // What ARI perceived of a human utterance (the dialogue's error layer applied).
  void on_utterance(const DialogueUtterance& msg) {
    if (msg.speaker == dialogue::kRobot) {
      return;
    }
    try {
      heard_.push_back(from_msg(msg.heard));
    } catch (const core::Error& e) {
      ROS_WARN("/sim/dialogue/utterances: %s", e.what());
    }
  }

  void on_outcome(const DialogueOutcome& msg) { dialogue_end_ = from_msg(msg); }

  void set_paused(bool paused) {
    std_srvs::SetBool pause;
    pause.request.data = paused;
    if (!ros::service::call("/sim/pause", pause)) {
      ROS_WARN("scenario_node: /sim/pause is not available");
    }
  }

  scenario::ScenarioRunConfig config_;
  scenario::Scenario scenario_;
  std::unique_ptr<dialogue::DialogueSetup> dialogue_;
  scenario::ScriptRunner runner_;
  scenario::RunWatchdog watchdog_;
  SinglePublisher state_publisher_{"/sim/world_state"};  // world_node's alone
  std::vector<dialogue::Perception> heard_;              // since the last world state
  std::unique_ptr<HeardSpeech> heard_speech_;            // scripts waiting on what ARI heard
  std::optional<scenario::DialogueEnd> dialogue_end_;
  scenario::MetricsRecorder metrics_;
  scenario::GroupMemory groups_;
  scenario::PersonIdentities identities_;
  std::map<model::ObjectId, std::string> logged_person_ids_;  // the matches last logged
  bool navigation_failure_logged_{false};
  ros::NodeHandle nh_;
  std::unique_ptr<RenewingTfBuffer> tf_;       // when the script approaches or sees groups
  std::unique_ptr<PerceivedPersons> persons_;  // when the script approaches or sees groups
  RosCommands commands_;
  ros::Publisher status_pub_;
  ros::Subscriber state_sub_, groups_sub_, utterances_sub_, outcome_sub_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  // Our own SIGINT handling, so that an interrupted run prints its report before ROS shuts
  // down; SA_RESETHAND: a second Ctrl-C kills at once.
  return nodes::run_node(argc, argv, "scenario_node", ros::init_options::NoSigintHandler, [] {
    struct sigaction action {};
    action.sa_handler = nodes::on_stop_signal;
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    ros::NodeHandle private_handle("~");
    scenario::ScenarioRunConfig config =
        scenario::ScenarioRunConfig::from_yaml(nodes::read_private_params(private_handle));
    scenario::Scenario scenario = scenario::load_scenario_file(config.scenario);
    scenario.script.time_limit_s = config.script_time_limit_for(scenario.script.time_limit_s);
    std::unique_ptr<dialogue::DialogueSetup> dialogue;
    if (scenario.script.interfaces().dialogue) {
      if (config.dialogue_config.empty()) {
        config.dialogue_config =
            ros::package::getPath("ari_social_sim") + "/config/dialogue/simulation.yaml";
      }
      dialogue =
          dialogue::DialogueSetup::create(dialogue::DialogueConfig::load(config.dialogue_config));
    }
    // A run that fails still ends with ros::shutdown, after the node has reported.
    int code = nodes::kNodeErrorExit;
    {
      nodes::ScenarioNode node(config, std::move(scenario), std::move(dialogue));
      try {
        code = node.run();
      } catch (const core::Error& e) {
        ROS_FATAL("scenario_node: %s", e.what());
      }
    }
    ros::shutdown();
    return code;
  });
}
