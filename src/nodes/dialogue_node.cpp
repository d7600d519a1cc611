// dialogue_node: the Conversational Content Generator as a ROS node, in one of three modes
// (~mode): world (simulated humans answer a /tts-speaking ARI in the world), rl_env (reset/step
// services) or user_bot (simulated users heard through ROS4HRI speech). Reads parameters, builds
// the dialogue core, wires the mode's topics, services and action; no dialogue logic here.

#include <ros/package.h>
#include <ros/ros.h>
#include <ros/topic.h>

#include <memory>

#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/dialogue_run_config.hpp"
#include "ari_social_sim/dialogue/robot_nlu.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/scenario/world_speech_stage.hpp"
#include "conversions/world_state.hpp"
#include "dialogue/asr_stage.hpp"
#include "dialogue/live_dialogue_node.hpp"
#include "dialogue/rl_env_services.hpp"
#include "dialogue/sim_say_client.hpp"
#include "node_main.hpp"
#include "ros_params.hpp"
#include "single_publisher.hpp"

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

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  return nodes::run_node(argc, argv, "dialogue_node", [] {
    ros::NodeHandle nh;
    ros::NodeHandle private_handle("~");
    const std::string source = ros::this_node::getName() + " parameter";
    dialogue::DialogueRunConfig run =
        dialogue::DialogueRunConfig::from_yaml(nodes::read_private_params(private_handle));
    if (run.config.empty()) {
      run.config = ros::package::getPath("ari_social_sim") + "/config/dialogue/simulation.yaml";
    }
    // Read as YAML, a directory raises std::ios_failure, which no handler catches: refuse it here.
    core::check_input_file((source + ": config").c_str(), run.config);
    const std::unique_ptr<dialogue::DialogueSetup> setup =
        dialogue::DialogueSetup::create(dialogue::DialogueConfig::load(run.config));
    run.check_human_ids(setup->config.users.roles, source);
    const std::vector<std::string>& roles = setup->config.users.roles;
    ROS_INFO("dialogue_node: mode %s, settings %s, seed %lu", dialogue::to_string(run.mode),
             run.config.c_str(), static_cast<unsigned long>(run.seed));

    if (run.mode == dialogue::DialogueMode::kRlEnv) {
      nodes::RlEnvServices services(nh, *setup);
      ros::spin();
      return 0;
    }

    const dialogue::RobotNlu nlu(*setup->nlg, setup->domain, setup->corpus_or_null());
    if (run.mode == dialogue::DialogueMode::kWorld) {
      ROS_INFO("dialogue_node: waiting for /sim/world_state");
      const auto state = ros::topic::waitForMessage<WorldState>("/sim/world_state", nh);
      if (!state) {
        return 0;  // shut down while waiting
      }
      const nodes::WorldCast cast = nodes::cast_from_world(*state, run, roles, source);
      for (size_t r = 0; r < cast.human_ids.size(); ++r) {
        ROS_INFO("dialogue_node: the %s is human %u (%s)", roles[r].c_str(), cast.human_ids[r],
                 perception::person_id_of(cast.human_ids[r]).c_str());
      }
      if (!run.humans) {
        ROS_INFO("dialogue_node: no simulated humans (~humans false): /tts voices ARI only");
      }
      scenario::WorldSpeechStage stage(cast.robot_id, cast.human_ids, nodes::SimSayClient(nh));
      std::unique_ptr<nodes::LiveDialogueNode> node;
      // Subscribed before the node is built, so that no state is missed meanwhile. Every state
      // counts: a word lasts 8 steps at 150 wpm and 0.05 s, an act at least that.
      // world_node's alone: a second world_node's states are refused.
      nodes::SinglePublisher state_publisher("/sim/world_state");
      const ros::Subscriber states = nh.subscribe<WorldState>(
          "/sim/world_state", 100,
          [&stage, &node, &state_publisher](const ros::MessageEvent<const WorldState>& event) {
            if (!state_publisher.accept(event.getPublisherName())) {
              return;
            }
            stage.follow(nodes::from_msg(*event.getConstMessage()));
            if (node) {
              node->tick();
            }
          });
      node = std::make_unique<nodes::LiveDialogueNode>(nh, *setup, nlu, run, stage);
      ros::spin();
      return 0;
    }

    std::vector<uint32_t> ids(run.human_ids.begin(), run.human_ids.end());
    for (size_t r = ids.size(); r < roles.size(); ++r) {
      ids.push_back(static_cast<uint32_t>(r + 1));
    }
    nodes::AsrStage stage(nh, *setup->timing, roles, ids, run.language);
    nodes::LiveDialogueNode node(nh, *setup, nlu, run, stage);
    const ros::Timer tick = nh.createTimer(ros::Duration(1.0 / nodes::kAsrTickHz),
                                           [&node](const ros::TimerEvent&) { node.tick(); });
    const ros::Timer tracked =
        nh.createTimer(ros::Duration(1.0 / nodes::kTrackedHz),
                       [&stage](const ros::TimerEvent&) { stage.publish_tracked(); });
    ros::spin();
    return 0;
  });
}
