// Benchmarks of the dialogue simulation in standalone mode (no ROS): whole dialogues of the rule
// policy, with and without writing JSON lines, the error layer alone, and the understanding of
// ARI's words that modes 1 and 3 run on every /tts goal.
#include <benchmark/benchmark.h>

#include "ari_social_sim/dialogue/dialogue_runner.hpp"
#include "ari_social_sim/dialogue/human_nlu.hpp"
#include "ari_social_sim/dialogue/json_lines.hpp"
#include "ari_social_sim/dialogue/robot_nlu.hpp"

namespace {

using namespace ari_social_sim::dialogue;

const DialogueSetup& template_setup() {
  static const auto setup =
      DialogueSetup::create(DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR));
  return *setup;
}

// Retrieval NLG reads the MPGT corpus where the tools look for it (--corpus aside); null, with
// the reason in `missing`, when it is not there.
const DialogueSetup* retrieval_setup(std::string* missing) {
  static std::string why_missing;
  static const auto setup = []() -> std::unique_ptr<DialogueSetup> {
    DialogueConfig config = DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR);
    config.nlg = NlgMode::kRetrieval;
    try {
      config.corpus_dir = required_mpgt_dir("", "retrieval NLG");
    } catch (const ari_social_sim::core::ConfigError& e) {
      why_missing = e.what();
      return nullptr;
    }
    return DialogueSetup::create(config);
  }();
  *missing = why_missing;
  return setup.get();
}

// One rule-policy dialogue per iteration, seeds 0, 1, 2, ... as dialogue_corpus --seed 0 uses.
void BM_RuleDialogue(benchmark::State& state) {
  std::string missing;
  const DialogueSetup* chosen = static_cast<NlgMode>(state.range(0)) == NlgMode::kRetrieval
                                    ? retrieval_setup(&missing)
                                    : &template_setup();
  if (chosen == nullptr) {
    state.SkipWithError(missing.c_str());
    return;
  }
  const DialogueSetup& setup = *chosen;
  DialogueEnv env(setup);
  RulePolicy policy(setup.domain);
  uint64_t index = 0;
  int64_t utterances = 0;
  for (auto _ : state) {
    const EpisodeRecord record = run_episode(env, policy, episode_seed(0, index++));
    utterances += static_cast<int64_t>(record.utterances.size());
    benchmark::DoNotOptimize(record.total_reward);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["utterances/s"] =
      benchmark::Counter(static_cast<double>(utterances), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RuleDialogue)
    ->ArgName("template0_retrieval1")
    ->Arg(static_cast<int>(NlgMode::kTemplate))
    ->Arg(static_cast<int>(NlgMode::kRetrieval));

// As dialogue_corpus: the dialogue plus its JSON lines.
void BM_RuleDialogueJsonl(benchmark::State& state) {
  const DialogueSetup& setup = template_setup();
  DialogueEnv env(setup);
  RulePolicy policy(setup.domain);
  uint64_t index = 0;
  size_t bytes = 0;
  for (auto _ : state) {
    const EpisodeRecord record = run_episode(env, policy, episode_seed(0, index));
    for (const Utterance& u : record.utterances) {
      bytes += utterance_json(static_cast<int>(index), u).size() + 1;
    }
    ++index;
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(static_cast<int64_t>(bytes));
}
BENCHMARK(BM_RuleDialogueJsonl);

void BM_ErrorModelApply(benchmark::State& state) {
  const DialogueSetup& setup = template_setup();
  Utterance u;
  u.speaker = "patient";
  u.addressees = {kRobot};
  u.text = "Can you tell me where the toilets are please";
  u.acts = {parse_act("request(location(toilet))", "bench")};
  const std::vector<std::string> humans{"patient", "companion"};
  ari_social_sim::core::Rng rng(1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(setup.errors->apply(u, humans, rng));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ErrorModelApply);

// One /tts text of two sentences understood against every exemplar (templates, and MPGT's ARI
// when the corpus is there).
void BM_RobotNluUnderstand(benchmark::State& state) {
  std::string missing;
  const DialogueSetup* with_corpus = retrieval_setup(&missing);
  const DialogueSetup& setup = with_corpus != nullptr ? *with_corpus : template_setup();
  const RobotNlu nlu(*setup.nlg, setup.domain, setup.corpus_or_null());
  const std::string text = "Hello. The toilets are down the corridor, second door on the left.";
  for (auto _ : state) {
    benchmark::DoNotOptimize(nlu.understand(text));
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["exemplars"] = static_cast<double>(nlu.exemplar_count());
}
BENCHMARK(BM_RobotNluUnderstand);

// One recogniser transcript (lower case, no punctuation: one sentence) understood against every
// exemplar of the people's side, as ARI's `converse` does for each final transcript.
void BM_HumanNluUnderstand(benchmark::State& state) {
  std::string missing;
  const DialogueSetup* with_corpus = retrieval_setup(&missing);
  const DialogueSetup& setup = with_corpus != nullptr ? *with_corpus : template_setup();
  const HumanNlu nlu(*setup.nlg, setup.domain, setup.corpus_or_null());
  const std::string text = "excuse me where can we find the cafeteria please";
  for (auto _ : state) {
    benchmark::DoNotOptimize(nlu.understand(text));
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["exemplars"] = static_cast<double>(nlu.exemplar_count());
}
BENCHMARK(BM_HumanNluUnderstand);

}  // namespace

BENCHMARK_MAIN();
