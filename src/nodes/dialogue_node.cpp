// dialogue_node: the Conversational Content Generator as a ROS node, in one of three modes
// (~mode): world (simulated humans answer a /tts-speaking ARI in the world), rl_env (reset/step
// services) or user_bot (simulated users heard through ROS4HRI speech). Reads parameters, builds
// the dialogue core, wires the mode's topics, services and action; no dialogue logic here.

#include <ros/package.h>
#include <ros/ros.h>
#include <ros/topic.h>

#include <memory>
#include <optional>

#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/dialogue_run_config.hpp"
#include "ari_social_sim/dialogue/robot_nlu.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/world_speech/world_speech_stage.hpp"
#include "node_support/node_main.hpp"
#include "node_support/ros_params.hpp"
#include "node_support/single_publisher.hpp"
#include "nodes/dialogue/asr_stage.hpp"
#include "nodes/dialogue/live_dialogue_node.hpp"
#include "nodes/dialogue/rl_env_services.hpp"
#include "nodes/dialogue/sim_say_client.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr double kAsrTickHz = 50.0;
constexpr double kTrackedHz = 10.0;

/// World ids of ARI and of one human per role, from the first world state (DialogueRunConfig::
/// cast). Throws core::ConfigError when the world has no ARI or lacks a role.
struct WorldCast {
  uint32_t robot_id{0};
  std::vector<uint32_t> human_ids;
};

WorldCast cast_from_world(const WorldState& state, const dialogue::DialogueRunConfig& run,
                          const std::vector<std::string>& roles, const std::string& source) {
  if (!state.has_ari) {
    throw core::ConfigError("/sim/world_state: the world has no ARI to speak the /tts goals");
  }
  WorldCast cast;
  cast.robot_id = state.ari.id;
  if (!run.humans) {
    return cast;  // ARI's voice only
  }
  std::vector<std::pair<uint32_t, std::string>> humans;
  for (const HumanState& human : state.humans) {
    humans.emplace_back(human.id, human.role);
  }
  cast.human_ids = run.cast(humans, roles, "/sim/world_state", source);
  for (size_t r = 0; r < roles.size(); ++r) {
    const auto& human = *std::find_if(humans.begin(), humans.end(),
                                      [&](const auto& h) { return h.first == cast.human_ids[r]; });
    if (human.second != roles[r]) {
      ROS_WARN("human %u plays the %s but the world calls it a %s", human.first, roles[r].c_str(),
               human.second.c_str());
    }
  }
  return cast;
}

// The mode's settings and the dialogue core built from them. Throws core::Error on a bad setting.
struct DialogueNodeSetup {
  dialogue::DialogueRunConfig run;
  std::unique_ptr<dialogue::DialogueSetup> setup;
};

DialogueNodeSetup load_setup(ros::NodeHandle& private_handle, const std::string& source) {
  DialogueNodeSetup loaded;
  dialogue::DialogueRunConfig& run = loaded.run;
  run = dialogue::DialogueRunConfig::from_yaml(read_private_params(private_handle));
  if (run.config.empty()) {
    run.config = ros::package::getPath("ari_social_sim") + "/config/dialogue/simulation.yaml";
  }
  // Read as YAML, a directory raises std::ios_failure, which no handler catches: refuse it here.
  core::check_input_file((source + ": config").c_str(), run.config);
  loaded.setup = dialogue::DialogueSetup::create(dialogue::DialogueConfig::load(run.config));
  run.check_human_ids(loaded.setup->config.users.roles, source);
  return loaded;
}

// world mode: the humans of the world state answer ARI, whose /tts goals the world speaks.
int run_world_mode(ros::NodeHandle& nh, const DialogueNodeSetup& loaded,
                   const dialogue::RobotNlu& nlu, const std::string& source) {
  const dialogue::DialogueRunConfig& run = loaded.run;
  const std::vector<std::string>& roles = loaded.setup->config.users.roles;
  ROS_INFO("dialogue_node: waiting for /sim/world_state");
  const auto state = ros::topic::waitForMessage<WorldState>("/sim/world_state", nh);
  if (!state) {
    return 0;  // shut down while waiting
  }
  const WorldCast cast = cast_from_world(*state, run, roles, source);
  for (size_t r = 0; r < cast.human_ids.size(); ++r) {
    ROS_INFO("dialogue_node: the %s is human %u (%s)", roles[r].c_str(), cast.human_ids[r],
             perception::person_id_of(cast.human_ids[r]).c_str());
  }
  if (!run.humans) {
    ROS_INFO("dialogue_node: no simulated humans (~humans false): /tts voices ARI only");
  }
  world_speech::WorldSpeechStage stage(cast.robot_id, cast.human_ids, SimSayClient(nh));
  std::unique_ptr<LiveDialogueNode> node;
  // Subscribed before the node is built, so that no state is missed meanwhile. Every state
  // counts: a word lasts 8 steps at 150 wpm and 0.05 s, an act at least that.
  // world_node's alone: a second world_node's states are refused.
  SinglePublisher state_publisher("/sim/world_state");
  // Named as a boost::function of a MessageEvent: a bare lambda would be wrapped as a ConstPtr
  // callback, whose events name every publisher "unknown_publisher". A state that fails
  // input_problem is dropped: from_msg assumes a checked message.
  const boost::function<void(const ros::MessageEvent<const WorldState>&)> on_state =
      [&stage, &node, &state_publisher](const ros::MessageEvent<const WorldState>& event) {
        const WorldState& msg = *event.getConstMessage();
        if (!state_publisher.accept(event.getPublisherName())) {
          return;
        }
        if (const std::optional<InputProblem> problem = input_problem(msg)) {
          ROS_WARN_THROTTLE(5.0, "/sim/world_state: dropped a state: %s: %s",
                            problem->field.c_str(), problem->what.c_str());
          return;
        }
        stage.follow(from_msg(msg));
        if (node) {
          node->tick();
        }
      };
  const ros::Subscriber states = nh.subscribe<WorldState>("/sim/world_state", 100, on_state);
  node = std::make_unique<LiveDialogueNode>(nh, *loaded.setup, nlu, run, stage);
  ros::spin();
  return 0;
}

// user_bot mode: simulated users heard through ROS4HRI speech, with ids from ~human_ids or 1, 2...
int run_user_bot_mode(ros::NodeHandle& nh, const DialogueNodeSetup& loaded,
                      const dialogue::RobotNlu& nlu) {
  const dialogue::DialogueRunConfig& run = loaded.run;
  const std::vector<std::string>& roles = loaded.setup->config.users.roles;
  std::vector<uint32_t> ids(run.human_ids.begin(), run.human_ids.end());
  for (size_t r = ids.size(); r < roles.size(); ++r) {
    ids.push_back(static_cast<uint32_t>(r + 1));
  }
  AsrStage stage(nh, *loaded.setup->timing, roles, ids, run.language);
  LiveDialogueNode node(nh, *loaded.setup, nlu, run, stage);
  const ros::Timer tick = nh.createTimer(ros::Duration(1.0 / kAsrTickHz),
                                         [&node](const ros::TimerEvent&) { node.tick(); });
  const ros::Timer tracked =
      nh.createTimer(ros::Duration(1.0 / kTrackedHz),
                     [&stage](const ros::TimerEvent&) { stage.publish_tracked(); });
  ros::spin();
  return 0;
}

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  return nodes::run_node(argc, argv, "dialogue_node", [] {
    ros::NodeHandle nh;
    ros::NodeHandle private_handle("~");
    const std::string source = ros::this_node::getName() + " parameter";
    const nodes::DialogueNodeSetup loaded = nodes::load_setup(private_handle, source);
    const dialogue::DialogueRunConfig& run = loaded.run;
    ROS_INFO("dialogue_node: mode %s, settings %s, seed %lu", dialogue::to_string(run.mode),
             run.config.c_str(), static_cast<unsigned long>(run.seed));

    if (run.mode == dialogue::DialogueMode::kRlEnv) {
      nodes::RlEnvServices services(nh, *loaded.setup);
      ros::spin();
      return 0;
    }
    const dialogue::RobotNlu nlu(*loaded.setup->nlg, loaded.setup->domain,
                                 loaded.setup->corpus_or_null());
    if (run.mode == dialogue::DialogueMode::kWorld) {
      return nodes::run_world_mode(nh, loaded, nlu, source);
    }
    return nodes::run_user_bot_mode(nh, loaded, nlu);
  });
}
