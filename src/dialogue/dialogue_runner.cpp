#include "ari_social_sim/dialogue/dialogue_runner.hpp"

#include <algorithm>

#include "ari_social_sim/core/rng_streams.hpp"

namespace ari_social_sim::dialogue {

uint64_t episode_seed(uint64_t seed, uint64_t index) {
  return core::rng_for(seed, core::rng_streams::kDialogueEpisodes, index).next_u64();
}

EpisodeRecord run_episode(DialogueEnv& env, RulePolicy& policy, uint64_t seed) {
  EpisodeRecord record;
  policy.reset();
  Observation observation = env.reset(seed);
  while (true) {
    const StepResult result = env.step(policy.act(observation));
    record.total_reward += result.reward;
    if (result.terminated || result.truncated) {
      record.outcome.complete = result.info.complete;
      record.outcome.success = result.info.success;
      record.truncated = result.truncated;
      record.robot_turns = result.info.robot_turns;
      break;
    }
    observation = result.observation;
  }
  record.utterances = env.transcript();
  return record;
}

CorpusDialogue to_corpus_dialogue(const std::vector<Utterance>& utterances) {
  CorpusDialogue dialogue;
  for (const Utterance& u : utterances) {
    CorpusUtterance c;
    c.speaker = u.speaker;
    c.role = u.speaker;
    c.text = u.text;
    c.acts = u.acts;
    c.goals = u.goals;
    dialogue.utterances.push_back(std::move(c));
  }
  return dialogue;
}

double true_human_to_human_share(const std::vector<EpisodeRecord>& episodes) {
  double human_to_human = 0;
  double total = 0;
  for (const EpisodeRecord& episode : episodes) {
    for (const Utterance& u : episode.utterances) {
      total += 1;
      const bool to_robot =
          std::find(u.addressees.begin(), u.addressees.end(), kRobot) != u.addressees.end();
      human_to_human += !u.is_robot() && !to_robot ? 1 : 0;
    }
  }
  return total > 0 ? human_to_human / total : 0.0;
}

}  // namespace ari_social_sim::dialogue
