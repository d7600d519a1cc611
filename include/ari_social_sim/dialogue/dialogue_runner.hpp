#pragma once

#include <cstdint>
#include <vector>

#include "ari_social_sim/dialogue/dialogue_env.hpp"
#include "ari_social_sim/dialogue/mpgt_corpus.hpp"
#include "ari_social_sim/dialogue/rule_policy.hpp"

namespace ari_social_sim::dialogue {

/// One finished episode: the transcript and how it went.
struct EpisodeRecord {
  std::vector<Utterance> utterances;
  DialogueOutcome outcome;
  bool truncated{false};
  int robot_turns{0};
  double total_reward{0.0};
};

/// Seed of dialogue `index` of a batch run with `seed`: an independent stream per dialogue, so that
/// dialogue 7 is the same whether 10 or 1000 are generated.
uint64_t episode_seed(uint64_t seed, uint64_t index);

/// Runs one episode of `policy` in `env` from reset(seed) to termination or truncation.
EpisodeRecord run_episode(DialogueEnv& env, RulePolicy& policy, uint64_t seed);

/// The transcript in the corpus's form (speaker = role), for compute_stats.
CorpusDialogue to_corpus_dialogue(const std::vector<Utterance>& utterances);

/// Share of all utterances that a human addressed to another human only (ground truth).
double true_human_to_human_share(const std::vector<EpisodeRecord>& episodes);

}  // namespace ari_social_sim::dialogue
