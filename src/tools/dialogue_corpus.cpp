// dialogue_corpus: runs N dialogues of the built-in rule-based robot policy against the simulated
// patient and companion and writes one JSON object per utterance (JSON lines).
//
//   dialogue_corpus --dialogues N --seed S --out FILE.jsonl [--config FILE] [--corpus DIR]
//                   [--nlg template|retrieval] [--compare] [--report FILE.md] [--overwrite]
//
// --config defaults to <source>/config/dialogue/simulation.yaml; --corpus (the MPGT corpus used by
// retrieval NLG and --compare) to the config's corpus_dir, else $ARI_MPGT_DIR, else the build-time
// folder (docs/dialogue.md). --compare prints the
// comparison with MPGT (intent JS divergence, human-to-human share, lengths, complete and success
// rates) as Markdown, also to --report when given. Outputs are checked before the first dialogue
// (an existing one needs --overwrite) and appear under their names only when complete. Exit code
// 2 on bad input, 1 when writing fails.
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/dialogue/dialogue_runner.hpp"
#include "ari_social_sim/dialogue/dialogue_stats.hpp"
#include "ari_social_sim/dialogue/json_lines.hpp"

namespace {

using namespace ari_social_sim;
using namespace ari_social_sim::dialogue;

// The documented ranges (README, docs/dialogue.md): 100 000 dialogues are about 3 million JSON
// lines, 1 GB; any seed that fits a signed 64-bit integer.
constexpr core::IntegerOption kDialogues{"--dialogues", 1, 100000};
constexpr core::IntegerOption kSeed{"--seed", 0, INT64_MAX};

struct Options {
  int64_t dialogues{0};
  int64_t seed{0};
  std::string out;
  std::string config = default_dialogue_config_dir() + "/simulation.yaml";
  std::string corpus;
  std::string nlg;
  std::string report;
  bool compare{false};
  bool overwrite{false};
};

void print_usage() {
  std::cerr << "usage: dialogue_corpus --dialogues N --seed S --out FILE.jsonl [--config FILE]\n"
               "                       [--corpus DIR] [--nlg template|retrieval] [--compare]\n"
               "                       [--report FILE.md] [--overwrite]\n"
            << "  N in " << kDialogues.range() << ", S in " << kSeed.range() << "\n"
            << "  --out and --report must not exist yet unless --overwrite\n"
            << "  --config defaults to " << default_dialogue_config_dir() << "/simulation.yaml\n"
            << "  --corpus DIR: the MPGT corpus (below); default: corpus_dir in --config if set\n"
            << mpgt_corpus_help();
}

Options parse_options(int argc, char** argv) {
  Options options;
  bool have_dialogues = false;
  bool have_seed = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--compare") {
      options.compare = true;
      continue;
    }
    if (arg == "--overwrite") {
      options.overwrite = true;
      continue;
    }
    core::check_known_option(arg, {"--dialogues", "--seed", "--out", "--config", "--corpus",
                                   "--compare", "--nlg", "--report", "--overwrite"});
    const std::string value = core::option_value(argc, argv, i);
    if (arg == "--dialogues") {
      options.dialogues = kDialogues.parse(value);
      have_dialogues = true;
    } else if (arg == "--seed") {
      options.seed = kSeed.parse(value);
      have_seed = true;
    } else if (arg == "--out") {
      options.out = value;
    } else if (arg == "--config") {
      options.config = value;
    } else if (arg == "--corpus") {
      options.corpus = value;
    } else if (arg == "--nlg") {
      options.nlg = value;
    } else {
      options.report = value;  // --report
    }
  }
  if (!have_dialogues || !have_seed || (options.out.empty() && !options.compare)) {
    throw core::ConfigError("--dialogues, --seed and --out (or --compare) are required");
  }
  if (!options.report.empty() && !options.compare) {
    throw core::ConfigError("--report: the report is the comparison's: expected --compare too");
  }
  // Paths before any work: a typo must not cost the run.
  core::check_input_file("--config", options.config);
  if (!options.corpus.empty()) {
    core::check_input_directory("--corpus", options.corpus);
  }
  if (!options.out.empty()) {
    core::check_output_file("--out", options.out, options.overwrite);
  }
  if (!options.report.empty()) {
    core::check_output_file("--report", options.report, options.overwrite);
  }
  if (!options.out.empty() && options.out == options.report) {
    throw core::ConfigError("--out and --report: expected two files, got " + options.out +
                            " twice");
  }
  return options;
}

std::string percent(double share) {
  return core::format_text("%.1f %%", 100.0 * share);
}

std::string number(double value, int decimals = 3) {
  return core::format_text("%.*f", decimals, value);
}

std::string lengths_text(const DialogueStats& s) {
  return number(s.mean_length(), 1) + " / " + std::to_string(s.length_quantile(0.0)) + " / " +
         std::to_string(s.length_quantile(0.25)) + " / " + std::to_string(s.length_quantile(0.5)) +
         " / " + std::to_string(s.length_quantile(0.75)) + " / " +
         std::to_string(s.length_quantile(1.0));
}

std::string comparison(const Options& options, const std::vector<EpisodeRecord>& episodes,
                       const MpgtCorpus& corpus) {
  std::vector<CorpusDialogue> generated;
  double complete = 0;
  double success = 0;
  double truncated = 0;
  double reward = 0;
  double robot_turns = 0;
  for (const EpisodeRecord& e : episodes) {
    generated.push_back(to_corpus_dialogue(e.utterances));
    complete += e.outcome.complete ? 1 : 0;
    success += e.outcome.success ? 1 : 0;
    truncated += e.truncated ? 1 : 0;
    reward += e.total_reward;
    robot_turns += e.robot_turns;
  }
  const double n = static_cast<double>(std::max<size_t>(episodes.size(), 1));
  const DialogueStats sim = compute_stats(generated);
  const DialogueStats real = compute_stats(corpus.dialogues);
  std::ostringstream out;
  out << "Generated: " << episodes.size() << " dialogues, seed " << options.seed
      << "; corpus: MPGT, " << real.dialogues << " conversations.\n\n";
  out << "| figure | generated | MPGT |\n|---|---|---|\n";
  out << "| JS divergence, first human intent (incl. none) | "
      << number(js_divergence(sim.first_intents, real.first_intents)) << " | 0 |\n";
  out << "| JS divergence, all human intents | "
      << number(js_divergence(sim.all_intents, real.all_intents)) << " | 0 |\n";
  out << "| human-to-human share of utterances (heuristic) | " << percent(sim.human_to_human_share)
      << " | " << percent(real.human_to_human_share) << " |\n";
  out << "| human-to-human share of utterances (ground truth) | "
      << percent(true_human_to_human_share(episodes)) << " | n/a |\n";
  out << "| human share of utterances | "
      << percent(static_cast<double>(sim.human_utterances) / std::max<size_t>(sim.utterances, 1))
      << " | "
      << percent(static_cast<double>(real.human_utterances) / std::max<size_t>(real.utterances, 1))
      << " |\n";
  out << "| length, mean / min / q25 / median / q75 / max | " << lengths_text(sim) << " | "
      << lengths_text(real) << " |\n";
  out << "| rule policy: complete | " << percent(complete / n) << " | |\n";
  out << "| rule policy: success | " << percent(success / n) << " | |\n";
  out << "| rule policy: truncated | " << percent(truncated / n) << " | |\n";
  out << "| rule policy: mean reward / robot turns | " << number(reward / n, 1) << " / "
      << number(robot_turns / n, 1) << " | |\n";
  out << "\nFirst human intent distribution:\n\n| intent | generated | MPGT |\n|---|---|---|\n";
  Distribution keys = real.first_intents;
  for (const auto& entry : sim.first_intents) {
    keys[entry.first] += 0.0;
  }
  for (const auto& entry : keys) {
    const auto s = sim.first_intents.find(entry.first);
    const auto r = real.first_intents.find(entry.first);
    out << "| " << entry.first << " | " << percent(s == sim.first_intents.end() ? 0.0 : s->second)
        << " | " << percent(r == real.first_intents.end() ? 0.0 : r->second) << " |\n";
  }
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      print_usage();
      return 0;
    }
  }
  Options options;
  std::unique_ptr<const DialogueSetup> setup;
  std::unique_ptr<core::OutputFile> out;
  try {
    options = parse_options(argc, argv);
    DialogueConfig config = DialogueConfig::load(options.config);
    if (!options.corpus.empty()) {
      config.corpus_dir = options.corpus;
    }
    if (!options.nlg.empty()) {
      config.nlg = parse_nlg_mode(options.nlg, "--nlg");
    }
    setup = DialogueSetup::create(config);
    if (!options.out.empty()) {
      out = std::make_unique<core::OutputFile>("--out", options.out);
    }
  } catch (const core::Error& e) {
    std::cerr << "dialogue_corpus: " << e.what() << "\n";
    print_usage();
    return 2;
  }
  try {
    DialogueEnv env(*setup);
    RulePolicy policy(setup->domain);
    std::vector<EpisodeRecord> episodes;
    for (int64_t d = 0; d < options.dialogues; ++d) {
      EpisodeRecord episode =
          run_episode(env, policy, episode_seed(static_cast<uint64_t>(options.seed), d));
      if (out) {
        for (const Utterance& u : episode.utterances) {
          out->stream() << utterance_json(static_cast<int>(d), u) << '\n';
        }
      }
      if (options.compare) {
        episodes.push_back(std::move(episode));
      }
    }
    if (out) {
      out->commit();
    }
    if (options.compare) {
      const std::string text = comparison(options, episodes, setup->corpus);
      std::cout << text << std::flush;
      if (!options.report.empty()) {
        core::OutputFile report("--report", options.report);
        report.stream() << text;
        report.commit();
      }
    }
  } catch (const core::Error& e) {
    std::cerr << "dialogue_corpus: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
