// dialogue_corpus: runs N dialogues of the built-in rule-based robot policy against the simulated
// patient and companion and writes one JSON object per utterance (JSON lines).
//
//   dialogue_corpus --dialogues N --seed S --out FILE.jsonl [--config FILE] [--corpus DIR]
//                   [--nlg template|retrieval] [--compare] [--variety] [--report FILE.md]
//                   [--overwrite]
//
// --config defaults to <source>/config/dialogue/simulation.yaml. The MPGT corpus is needed only
// by --compare and retrieval NLG; they read --corpus, else the config's corpus_dir, else
// $ARI_MPGT_DIR, else the data set's folder, and refuse before the first dialogue when it is
// missing (docs/dialogue.md). --compare prints the comparison with MPGT (intent JS divergence,
// human-to-human share, lengths, complete and success rates) and --variety the distinct texts
// per act as Markdown, also to --report when given. Outputs are checked before the first
// dialogue (an existing one needs --overwrite) and appear under their names only when complete:
// SIGINT or SIGTERM stops between two dialogues, writes nothing and exits with 128 + the signal's
// number. Exit code 2 on bad input, 1 when writing fails.
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "ari_social_sim/batch/batch_plan.hpp"
#include "ari_social_sim/batch/corpus_shard_merge.hpp"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/core/stop_signal.hpp"
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
  bool variety{false};
  bool overwrite{false};
  batch::BatchPlan shard;    // --shard K/N: the dialogues with d % N == K - 1 (episodes unused)
  unsigned merge_shards{0};  // --merge-shards N: merge a job array's N shards of --out

  bool has_tables() const { return compare || variety; }
  bool sharded() const { return shard.shard_count > 1 || merge_shards > 0; }
};

void print_usage() {
  std::cerr
      << "usage: dialogue_corpus --dialogues N --seed S --out FILE.jsonl [--config FILE]\n"
         "                       [--shard K/N | --merge-shards N]\n"
         "                       [--corpus DIR] [--nlg template|retrieval] [--compare]\n"
         "                       [--variety] [--report FILE.md] [--overwrite]\n"
      << "  N in " << kDialogues.range() << ", S in " << kSeed.range() << "\n"
      << "  --out and --report must not exist yet unless --overwrite\n"
      << "  --config defaults to " << default_dialogue_config_dir() << "/simulation.yaml\n"
      << "  --compare: the generated dialogues against MPGT (needs the corpus)\n"
      << "  --variety: distinct texts / utterances per side and first act\n"
      << "  --report FILE.md: the tables of --compare and --variety, also in a file\n"
      << "  --shard K/N: only the dialogues with d % N == K - 1, into FILE_shardK-of-N.jsonl\n"
      << "  --merge-shards N: the N shards of FILE.jsonl (all finished) merged into it, as\n"
      << "    one process writes it; the shards' files removed (docs/cluster.md)\n"
      << "  --corpus DIR: the MPGT corpus (below), needed only by --compare and retrieval\n"
      << "    NLG; default: corpus_dir in --config if set, else as below\n"
      << "  outputs appear only when complete; SIGINT (Ctrl-C) or SIGTERM stops between two\n"
      << "    dialogues and writes nothing (a second Ctrl-C kills at once)\n"
      << "  exit status: 0 on success, 2 on bad input, 1 when writing fails, 130 after\n"
      << "    SIGINT and 143 after SIGTERM\n"
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
    if (arg == "--variety") {
      options.variety = true;
      continue;
    }
    if (arg == "--overwrite") {
      options.overwrite = true;
      continue;
    }
    core::check_known_option(
        arg, {"--dialogues", "--seed", "--out", "--config", "--corpus", "--compare", "--nlg",
              "--report", "--overwrite", "--shard", "--merge-shards"});
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
    } else if (arg == "--shard") {
      batch::parse_shard(value, "", options.shard);
    } else if (arg == "--merge-shards") {
      options.merge_shards = batch::shard_count_option(arg, value);
    } else {
      options.report = value;  // --report
    }
  }
  if (!have_dialogues || !have_seed || (options.out.empty() && !options.has_tables())) {
    throw core::ConfigError(
        "--dialogues, --seed and --out (or --compare or --variety) are required");
  }
  if (!options.report.empty() && !options.has_tables()) {
    throw core::ConfigError(
        "--report: the report holds the tables of --compare and --variety: expected one of them "
        "too");
  }
  if (options.sharded() && (options.has_tables() || options.out.empty() ||
                            (options.merge_shards > 0 && options.shard.shard_count > 1))) {
    throw core::ConfigError(
        "--shard and --merge-shards: expected --out, one of the two, and neither --compare nor "
        "--variety (their tables need every dialogue: run them on the merged corpus' plan)");
  }
  options.shard.episodes = static_cast<uint64_t>(options.dialogues);
  if (options.shard.shard_count > 1) {
    options.out = batch::corpus_shard_path(options.out, options.shard);
  }
  // Paths before any work: a typo must not cost the run.
  core::check_input_file("--config", options.config);
  if (!options.corpus.empty()) {
    core::check_input_directory("--corpus", options.corpus);
  }
  // A merge of one shard keeps the file shard 1/1 wrote, which is the whole corpus already.
  if (!options.out.empty() && options.merge_shards != 1) {
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

std::vector<CorpusDialogue> as_corpus(const std::vector<EpisodeRecord>& episodes) {
  std::vector<CorpusDialogue> generated;
  generated.reserve(episodes.size());
  for (const EpisodeRecord& e : episodes) {
    generated.push_back(to_corpus_dialogue(e.utterances));
  }
  return generated;
}

std::string comparison(const Options& options, const std::vector<EpisodeRecord>& episodes,
                       const MpgtCorpus& corpus) {
  double complete = 0;
  double success = 0;
  double truncated = 0;
  double reward = 0;
  double robot_turns = 0;
  for (const EpisodeRecord& e : episodes) {
    complete += e.outcome.complete ? 1 : 0;
    success += e.outcome.success ? 1 : 0;
    truncated += e.truncated ? 1 : 0;
    reward += e.total_reward;
    robot_turns += e.robot_turns;
  }
  const double n = static_cast<double>(std::max<size_t>(episodes.size(), 1));
  const DialogueStats sim = compute_stats(as_corpus(episodes));
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
  out << "| goals: distinct targets labelled per dialogue (G, AG, CG), mean | "
      << number(sim.mean_goal_targets, 2) << " | " << number(real.mean_goal_targets, 2) << " |\n";
  out << "| closing: bye() in the last " << kClosingUtterances << " utterances | "
      << percent(sim.bye_closing_share) << " | " << percent(real.bye_closing_share) << " |\n";
  out << "| closing: thank() in the last " << kClosingUtterances << " utterances | "
      << percent(sim.thank_closing_share) << " | " << percent(real.thank_closing_share) << " |\n";
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

// The most frequent first acts of each side in the variety table; the rest are in the pooled row.
constexpr size_t kVarietyRowsPerSide = 12;

std::string variety_rows(const std::vector<ActVariety>& variety, bool robot) {
  std::ostringstream rows;
  size_t shown = 0;
  size_t utterances = 0;
  size_t distinct = 0;
  for (const ActVariety& v : variety) {
    if (v.robot != robot) {
      continue;
    }
    utterances += v.utterances;
    distinct += v.distinct_texts;
    if (shown++ < kVarietyRowsPerSide) {
      rows << "| " << (robot ? "ARI" : "humans") << " | " << v.first_act << " | " << v.utterances
           << " | " << v.distinct_texts << " | " << number(v.ratio(), 2) << " |\n";
    }
  }
  rows << "| " << (robot ? "ARI" : "humans") << " | all " << shown << " first acts | " << utterances
       << " | " << distinct << " | "
       << number(utterances == 0 ? 0.0 : static_cast<double>(distinct) / utterances, 2) << " |\n";
  return rows.str();
}

std::string variety_table(const Options& options, const std::vector<EpisodeRecord>& episodes,
                          NlgMode nlg) {
  const std::vector<ActVariety> variety = act_variety(as_corpus(episodes));
  std::ostringstream out;
  out << "Variety: " << episodes.size() << " dialogues, seed " << options.seed << ", "
      << core::choice_name(nlg, kNlgModes)
      << " NLG; distinct texts / utterances per side and first act (texts as said, before the "
         "error layer; the "
      << kVarietyRowsPerSide << " most frequent first acts of each side, then all).\n\n";
  out << "| side | first act | utterances | distinct texts | ratio |\n|---|---|---|---|---|\n";
  out << variety_rows(variety, false) << variety_rows(variety, true);
  return out.str();
}

// What needs the MPGT corpus in this run, for the message when it is missing; "" when nothing.
std::string corpus_needed_by(const Options& options, NlgMode nlg) {
  if (options.compare) {
    return "--compare";
  }
  return nlg == NlgMode::kRetrieval ? "retrieval NLG (--nlg or nlg in --config)" : "";
}

// The settings of the run: --config, with --nlg and, where the run needs the corpus, its folder
// (checked here, before the first dialogue).
DialogueConfig run_config(const Options& options) {
  DialogueConfig config = DialogueConfig::load(options.config);
  if (!options.corpus.empty()) {
    config.corpus_dir = options.corpus;
  }
  if (!options.nlg.empty()) {
    config.nlg = parse_nlg_mode(options.nlg, "--nlg");
  }
  const std::string needed_by = corpus_needed_by(options, config.nlg);
  if (!needed_by.empty() && config.corpus_dir.empty()) {
    config.corpus_dir = required_mpgt_dir("", needed_by);
  }
  return config;
}

// After a stop signal: nothing was written. Returns the exit code.
int report_stop(const Options& options, int64_t done) {
  const int signal = core::g_stop_signal;
  std::cerr << "dialogue_corpus: interrupted by " << core::stop_signal_name(signal) << " after "
            << done << " of " << options.dialogues << " dialogues: nothing written (the outputs "
            << "appear only once every dialogue is done); rerun to make them\n";
  return core::stopped_exit_code(signal);
}

// Runs the dialogues into `out` (when --out) and the tables, until done (0) or a stop signal comes
// (the exit code of report_stop; `out` is then dropped). Throws core::Error when writing fails.
int make_corpus(const Options& options, const DialogueSetup& setup,
                std::unique_ptr<core::OutputFile> out) {
  DialogueEnv env(setup);
  RulePolicy policy(setup.domain);
  std::vector<EpisodeRecord> episodes;
  for (int64_t d = 0; d < options.dialogues; ++d) {
    if (core::g_stop_signal != 0) {
      return report_stop(options, d);
    }
    if (static_cast<uint64_t>(d) % options.shard.shard_count != options.shard.shard_index - 1) {
      continue;  // another shard's
    }
    EpisodeRecord episode =
        run_episode(env, policy, episode_seed(static_cast<uint64_t>(options.seed), d));
    if (out) {
      for (const Utterance& u : episode.utterances) {
        out->stream() << utterance_json(static_cast<int>(d), u) << '\n';
      }
    }
    if (options.has_tables()) {
      episodes.push_back(std::move(episode));
    }
  }
  if (out) {
    out->commit();
  }
  if (options.has_tables()) {
    std::string text;
    if (options.compare) {
      text += comparison(options, episodes, *setup.corpus);
    }
    if (options.variety) {
      text += (text.empty() ? "" : "\n") + variety_table(options, episodes, setup.config.nlg);
    }
    std::cout << text << std::flush;
    if (!options.report.empty()) {
      core::OutputFile report("--report", options.report);
      report.stream() << text;
      report.commit();
    }
  }
  return 0;
}

// --merge-shards: the shards of --out (each finished) merged into the corpus one process writes;
// the shards' files removed once it is in place.
int merge_corpus(const Options& options) {
  batch::BatchPlan plan = options.shard;
  const std::string merged = batch::merge_corpus_shards(options.out, plan, options.merge_shards);
  core::OutputFile out("--out", options.out);
  out.stream() << merged;
  out.commit();
  for (unsigned k = 1; k <= options.merge_shards && options.merge_shards > 1; ++k) {
    plan.shard_index = k;
    plan.shard_count = options.merge_shards;
    std::remove(batch::corpus_shard_path(options.out, plan).c_str());
  }
  std::printf("dialogue_corpus: merged %u shards: %lld dialogues into %s\n", options.merge_shards,
              static_cast<long long>(options.dialogues), options.out.c_str());
  return 0;
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
    if (options.merge_shards > 0) {
      return merge_corpus(options);
    }
    setup = DialogueSetup::create(run_config(options));
    if (!options.out.empty()) {
      out = std::make_unique<core::OutputFile>("--out", options.out);
    }
  } catch (const core::Error& e) {
    std::cerr << "dialogue_corpus: " << e.what() << "\n";
    print_usage();
    return 2;
  }
  core::install_stop_handler();
  try {
    return make_corpus(options, *setup, std::move(out));
  } catch (const core::Error& e) {
    std::cerr << "dialogue_corpus: " << e.what() << "\n";
    return 1;
  }
}
