// ARI's `converse` hearing the people through speech recognition (scenario::Hearing::kRecognised,
// the live speech:=audio) rather than the dialogue's simulated perceptions: in process the
// transcripts are perception's simulated recogniser's, understood by ARI's HumanNlu. The waiting
// room's dialogue must still end, and its goals be met about as often.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "ari_social_sim/engine/episode.hpp"

namespace ari_social_sim::engine {
namespace {

const std::string kSource = ARI_SOURCE_DIR;

struct DialogueTally {
  int episodes{0};
  int ended{0};      // the dialogue ended (complete or not)
  int succeeded{0};  // every goal of the people met
  double reward{0.0};
};

DialogueTally waiting_room_dialogues(scenario::Hearing hearing, int seeds) {
  const scenario::Scenario scenario =
      scenario::load_scenario_file(kSource + "/scenarios/waiting_room.yaml");
  EpisodeConfig config = EpisodeConfig::load(kSource + "/config");
  config.hearing = hearing;
  DialogueTally tally;
  for (int seed = 1; seed <= seeds; ++seed) {
    Episode episode(scenario, seed, config);
    while (!episode.finished()) {
      episode.step();
    }
    ++tally.episodes;
    if (const auto& end = episode.runner().dialogue_end()) {
      ++tally.ended;
      tally.succeeded += end->success ? 1 : 0;
      tally.reward += end->total_reward;
    }
  }
  return tally;
}

TEST(RecognisedHearing, TheWaitingRoomsDialogueEndsAndMeetsItsGoalsAsWithSimulatedHearing) {
  constexpr int kSeeds = 6;
  const DialogueTally simulated = waiting_room_dialogues(scenario::Hearing::kSimulated, kSeeds);
  const DialogueTally recognised = waiting_room_dialogues(scenario::Hearing::kRecognised, kSeeds);
  for (const auto& [name, tally] :
       {std::pair{"simulated", simulated}, {"recognised", recognised}}) {
    std::printf(
        "[ measured ] %s hearing: %d of %d dialogues ended, %d met every goal, "
        "mean reward %.1f\n",
        name, tally.ended, tally.episodes, tally.succeeded, tally.reward / tally.episodes);
  }
  EXPECT_GE(recognised.ended, kSeeds - 1);
  EXPECT_GE(recognised.succeeded, simulated.succeeded - 1);
}

}  // namespace
}  // namespace ari_social_sim::engine
