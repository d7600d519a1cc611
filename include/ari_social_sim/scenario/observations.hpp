#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/dialogue/spoken_dialogue.hpp"
#include "ari_social_sim/dialogue/utterance.hpp"
#include "ari_social_sim/perception/voice_transcript.hpp"
#include "ari_social_sim/scenario/agent_ref.hpp"
#include "ari_social_sim/scenario/person_identities.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::scenario {

/// State of ARI's last navigation goal (set_goal, approach or join_group), as its action client
/// reports it.
enum class NavigationState { kIdle, kActive, kSucceeded, kFailed };

struct NavigationStatus {
  NavigationState state{NavigationState::kIdle};
  std::string reason;  // why it failed; empty otherwise
};

/// One group as perception reports it, its members mapped to the simulated humans they were
/// found to be (persons matched with no human are left out).
struct PerceivedGroup {
  std::string group_id;
  std::vector<AgentRef> members;
};

/// A perceived group from its ROS4HRI person ids, each mapped through `identities`.
PerceivedGroup perceived_group(const std::string& group_id,
                               const std::vector<std::string>& person_ids,
                               const PersonIdentities& identities);

/// How the dialogue with the simulated humans ended (dialogue_node: /sim/dialogue/outcome).
using DialogueEnd = dialogue::OutcomeEvent;

/// What a script sees at one tick: ground truth of the world (scenario_node: /sim/world_state),
/// ARI's navigation (the move_base and /social_mpc/approach clients), who perception's persons
/// are (PersonIdentities on /humans/persons/... and tf) and the groups they form
/// (/humans/interactions/groups) and the dialogue (/sim/dialogue/utterances and /outcome). The
/// batch tool fills the same from the cores in-process.
struct Observations {
  world::WorldSnapshot world;
  NavigationStatus navigation;
  /// The person id perception reports each simulated human as, for the humans matched so far
  /// (PersonIdentities::person_ids): how approach and join_group name them to navigation.
  std::map<model::ObjectId, std::string> person_ids;
  std::vector<PerceivedGroup> perceived_groups;
  /// Human utterances of the dialogue that started since the previous observation, as ARI
  /// perceived them (the dialogue's error layer applied).
  std::vector<dialogue::Perception> heard;
  /// Final transcripts of ARI's speech recognition since the previous observation, any voice
  /// (ROS4HRI's /humans/voices/<id>/speech; in process, the perception pipeline's voices).
  std::vector<perception::VoiceTranscript> transcripts;
  /// Set once the dialogue has ended.
  std::optional<DialogueEnd> dialogue_end;
};

}  // namespace ari_social_sim::scenario
