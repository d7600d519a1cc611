// run_episodes: runs a scenario for many seeds in one process, without roscore, as fast as the
// machine allows; writes one rosbag per episode (the topics a live run records) and one CSV row
// of metrics per episode, with a progress line on standard error.
//
//   run_episodes --scenario NAME|FILE --episodes N [--seed S] [--shard K/N] [--out DIR]
//                [--no-bags] [--audio] [--overwrite | --resume]
//
// Episode i runs with seed S + i (S defaults to the scenario file's seed), so that it can be
// replayed live with `roslaunch ari_social_sim NAME.launch seed:=S+i`. --shard K/N runs the
// episodes with i % N == K - 1 (K from 1), for job arrays. Files: DIR/NAME_SEED.bag,
// DIR/NAME.csv and the settings they were made with, DIR/NAME.settings.yaml (DIR/NAME_shardK-of-N.*
// with --shard). An existing output is refused unless --overwrite (replaces it) or --resume
// (checks the settings, keeps the rows there and runs the missing episodes). Each bag gets its name
// only when complete (core::PendingFile); SIGINT or SIGTERM stops between two steps,
// drops the episode under way (its bag deleted, no row) and exits with 128 + the
// signal's number. --audio adds each episode's array audio and labels, DIR/audio/NAME_SEED.*
// (dataset::EpisodeAudio, as export_dataset --audio). Exit code 0 when every episode of the CSV
// succeeded, 1 when any failed (the first few named on standard error), 2 on bad input, 3 when
// writing fails (docs/scenario.md, section 6).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "ari_social_sim/batch/batch_plan.hpp"
#include "ari_social_sim/batch/episode_csv.hpp"
#include "ari_social_sim/batch/progress_bar.hpp"
#include "ari_social_sim/batch/shard_merge.hpp"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/core/stop_signal.hpp"
#include "ari_social_sim/dataset/episode_audio.hpp"
#include "ari_social_sim/engine/episode.hpp"
#include "episode_bag/episode_bag.hpp"

namespace {

using namespace ari_social_sim;
namespace fs = std::filesystem;

// SIGINT/SIGTERM, shared with the other batch tools (core/stop_signal.hpp).
using core::g_stop_signal;
using core::install_stop_handler;

// Exit codes (docs/scenario.md, section 6); a stop signal gives 128 + its number.
constexpr int kAllSucceededExit = 0;
constexpr int kEpisodeFailedExit = 1;
constexpr int kBadInputExit = 2;
constexpr int kWriteFailedExit = 3;

// How many failed episodes the end of a run names: enough to start looking, few enough to read.
constexpr size_t kFailuresNamed = 5;

struct Options {
  std::string scenario;
  batch::BatchPlan plan;
  batch::PlanOptionsGiven given;
  std::string out{"episodes"};
  bool bags{true};
  bool audio{false};  // each episode's microphone-array audio and its labels (docs/audio.md)
  bool overwrite{false};
  bool resume{false};
  unsigned merge_shards{0};  // --merge-shards N: merge a job array's N shards instead of running
};

void print_usage() {
  std::cerr
      << "usage: run_episodes --scenario NAME|FILE --episodes N [--seed S] [--shard K/N]\n"
         "                    [--out DIR] [--no-bags] [--audio] [--overwrite | --resume]\n"
         "       run_episodes --scenario NAME|FILE --episodes N [--seed S] [--no-bags]\n"
         "                    [--audio] --out DIR --merge-shards K [--overwrite]\n"
      << "  NAME is one of the package's scenarios (" << ARI_SCENARIO_DIR << ")\n"
      << "  N in " << batch::episodes_option_range() << ", S in " << batch::seed_option_range()
      << " (the last seed, S + N - 1, too)\n"
         "  --audio: DIR/audio/NAME_SEED.wav (the array's six channels), .rttm, .ctm and\n"
         "  _directions.csv per episode (docs/audio.md, \"Audio data sets\")\n"
         "  an existing output in DIR is refused unless --overwrite (replace it) or\n"
         "  --resume (finish it: same settings, --episodes and --seed default to its own)\n"
         "  SIGINT (Ctrl-C) or SIGTERM stops between two steps, keeping the finished\n"
         "  episodes only (a second Ctrl-C kills at once)\n"
         "  --merge-shards K: DIR holds the K shards of this plan (--shard k/K, all finished);\n"
         "  writes NAME.csv and NAME.settings.yaml as one process running the plan would,\n"
         "  then removes the shards' CSVs and settings (docs/cluster.md)\n"
         "  exit status: 0 when every episode succeeded, 1 when any failed, 2 on bad input,\n"
         "  3 when writing fails, 130 after SIGINT and 143 after SIGTERM\n";
}

Options parse_options(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--no-bags") {
      options.bags = false;
      continue;
    }
    if (arg == "--audio") {
      options.audio = true;
      continue;
    }
    if (arg == "--overwrite") {
      options.overwrite = true;
      continue;
    }
    if (arg == "--resume") {
      options.resume = true;
      continue;
    }
    core::check_known_option(
        arg, {"--scenario", "--episodes", "--seed", "--shard", "--out", "--no-bags", "--audio",
              "--overwrite", "--resume", "--merge-shards"});
    const std::string value = core::option_value(argc, argv, i);
    if (arg == "--scenario") {
      options.scenario = value;
    } else if (arg == "--out") {
      options.out = value;
    } else if (arg == "--merge-shards") {
      options.merge_shards = batch::shard_count_option(arg, value);
    } else {
      batch::read_plan_option(arg, value, options.plan, options.given);
    }
  }
  if (options.scenario.empty() || (!options.given.episodes && !options.resume)) {
    throw core::ConfigError(
        "expected --scenario and --episodes (--episodes may be left out with "
        "--resume)");
  }
  if (options.overwrite && options.resume) {
    throw core::ConfigError("--overwrite and --resume: expected one of them, got both");
  }
  if (options.merge_shards > 0 &&
      (options.resume || options.given.shard || !options.given.episodes)) {
    throw core::ConfigError(
        "--merge-shards: expected the whole plan (--episodes, --seed) without --shard or "
        "--resume");
  }
  return options;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The files of one run (one shard) in DIR.
struct OutputPaths {
  std::string dir;
  std::string stem;  // NAME or NAME_shardK-of-N
  std::string name;  // NAME: bags are NAME_SEED.bag whatever the shard

  std::string csv() const { return dir + "/" + stem + ".csv"; }
  std::string settings() const { return dir + "/" + stem + ".settings.yaml"; }
  std::string bag(uint64_t seed) const {
    return dir + "/" + name + "_" + std::to_string(seed) + ".bag";
  }
};

// What the run would write that is there already, in words: the CSV, its settings, bags of its
// seeds (finished or .active); empty when nothing is.
std::string existing_outputs(const OutputPaths& paths, const std::vector<uint64_t>& seeds) {
  std::string found;
  for (const std::string& path : {paths.csv(), paths.settings()}) {
    if (fs::exists(path)) {
      found += (found.empty() ? "" : ", ") + path;
    }
  }
  size_t bags = 0;
  for (uint64_t seed : seeds) {
    bags +=
        fs::exists(paths.bag(seed)) || fs::exists(tools::EpisodeBag::active_path(paths.bag(seed)))
            ? 1
            : 0;
  }
  if (bags > 0) {
    found += (found.empty() ? "" : ", ") + std::to_string(bags) + " bags of its seeds";
  }
  return found;
}

// --overwrite: removes the earlier run's CSV, settings and bags (those its rows name, and any of
// this run's seeds, finished or .active) and, when `say`, what went.
void remove_earlier_run(const OutputPaths& paths, const std::vector<uint64_t>& seeds, bool say) {
  std::set<uint64_t> bag_seeds(seeds.begin(), seeds.end());
  size_t rows = 0;
  if (fs::exists(paths.csv())) {
    try {
      const batch::EpisodeCsvContents earlier =
          batch::read_episode_csv(read_file(paths.csv()), paths.csv());
      rows = earlier.rows.size();
      for (const batch::EpisodeCsvRow& row : earlier.rows) {
        bag_seeds.insert(row.seed);
      }
    } catch (const core::ConfigError&) {
      // Not a CSV of ours: only the bags of this run's seeds are known to be its.
    }
  }
  size_t bags = 0;
  for (uint64_t seed : bag_seeds) {
    bags += fs::remove(paths.bag(seed)) ? 1 : 0;
    fs::remove(tools::EpisodeBag::active_path(paths.bag(seed)));
  }
  const bool had_csv = fs::remove(paths.csv());
  fs::remove(paths.settings());
  if (!say) {
    return;
  }
  std::cerr << "--overwrite: removed "
            << (had_csv ? paths.csv() + " (" + std::to_string(rows) + " rows), " : std::string())
            << "its settings and " << bags << " bags of the earlier run\n";
}

// --resume: checks the earlier run (its settings `there`, if any) against this one's and returns
// the rows to keep; cuts a row left half-written off the CSV and deletes the .active files of
// episodes to redo. Throws core::ConfigError naming every difference.
std::vector<batch::EpisodeCsvRow> resume_earlier_run(
    const OutputPaths& paths, const std::optional<batch::BatchSettings>& there,
    const batch::BatchSettings& now, bool& csv_has_header) {
  if (!there) {
    throw core::ConfigError("--resume: " + paths.csv() + " has no settings file " +
                            paths.settings() +
                            " to check it was made with these settings; pass --overwrite to "
                            "start again");
  }
  const std::vector<std::string> differences = there->differences(now);
  if (!differences.empty()) {
    std::string text;
    for (const std::string& line : differences) {
      text += "\n  " + line;
    }
    throw core::ConfigError(
        "--resume: " + paths.csv() + " was made with other settings (" + paths.settings() +
        "):" + text + "\npass the same options, --overwrite to start again, or another --out");
  }
  const batch::EpisodeCsvContents contents =
      batch::read_episode_csv(read_file(paths.csv()), paths.csv());
  const std::vector<uint64_t> planned = now.plan.episode_indices();
  const std::set<uint64_t> plan(planned.begin(), planned.end());
  for (const batch::EpisodeCsvRow& row : contents.rows) {
    if (row.scenario != now.scenario || plan.count(row.episode) == 0 ||
        row.seed != now.plan.seed_of(row.episode)) {
      throw core::ConfigError("--resume: " + paths.csv() + ": the row of episode " +
                              std::to_string(row.episode) + " (scenario " + row.scenario +
                              ", seed " + std::to_string(row.seed) + ") is not one of this run's " +
                              std::to_string(now.plan.episodes) +
                              " episodes; pass --episodes with at least as many as there");
    }
  }
  if (contents.partial_row) {
    fs::resize_file(paths.csv(), contents.complete_bytes);
    std::cerr << "--resume: " << paths.csv()
              << " ended in a row cut short (a run killed while writing it): removed it\n";
  }
  csv_has_header = contents.complete_bytes > 0;
  std::set<uint64_t> done;
  for (const batch::EpisodeCsvRow& row : contents.rows) {
    done.insert(row.episode);
    if (now.bags && !fs::exists(paths.bag(row.seed))) {
      std::cerr << "--resume: warning: " << paths.bag(row.seed)
                << " is missing (its row is kept; delete the row to run it again)\n";
    }
  }
  for (uint64_t episode : planned) {
    if (done.count(episode) == 0) {
      fs::remove(tools::EpisodeBag::active_path(paths.bag(now.plan.seed_of(episode))));
    }
  }
  return contents.rows;
}

// The settings a run of `options` writes beside its CSV.
batch::BatchSettings settings_of(const Options& options, const std::string& scenario_file,
                                 const scenario::Scenario& scenario) {
  batch::BatchSettings settings;
  settings.scenario = scenario.name;
  settings.scenario_file = scenario_file;
  settings.scenario_digest = batch::digest_files({scenario_file, scenario.scene.world_path});
  settings.config_digest = batch::digest_files(batch::files_under(ARI_CONFIG_DIR, ".yaml"));
  settings.plan = options.plan;
  settings.bags = options.bags;
  settings.audio = options.audio;
  return settings;
}

// A checked run, ready to go.
struct Batch {
  Options options;
  scenario::Scenario scenario;
  engine::EpisodeConfig config;
  OutputPaths paths;
  std::vector<batch::EpisodeCsvRow> kept;  // rows of an earlier run that --resume keeps
  std::ofstream csv;                       // open for appending, the header written
  // With --audio: the voices synthesised once per (voice, text) for the whole batch.
  std::shared_ptr<audio::SpeechSynthesizer> synthesizer =
      std::make_shared<audio::SpeechSynthesizer>();
};

// Checks everything the user gave and deals with the earlier output before the first episode, so
// that a bad option or path costs no run. Throws core::Error (or std::filesystem_error).
Batch prepare(int argc, char** argv) {
  Batch batch;
  Options& options = batch.options;
  options = parse_options(argc, argv);
  const std::string scenario_file = scenario::scenario_file_of(options.scenario, ARI_SCENARIO_DIR);
  core::check_input_file("--scenario", scenario_file);
  batch.scenario = scenario::load_scenario_file(scenario_file);
  batch.config = engine::EpisodeConfig::load(ARI_CONFIG_DIR);
  if (fs::exists(options.out) && !fs::is_directory(options.out)) {
    throw core::ConfigError("--out: " + options.out + ": expected a directory, got a file");
  }
  OutputPaths& paths = batch.paths;
  paths.dir = options.out;
  paths.name = batch.scenario.name;
  paths.stem = paths.name + options.plan.shard_suffix();

  // The plan: --resume goes on with the earlier run's count and seeds unless told otherwise.
  std::optional<batch::BatchSettings> earlier;
  if (options.resume && fs::exists(paths.settings())) {
    earlier = batch::BatchSettings::parse(read_file(paths.settings()), paths.settings());
  }
  if (!options.given.episodes && !earlier) {
    throw core::ConfigError("--resume: " + paths.settings() +
                            " not found: nothing to resume, give --episodes");
  }
  if (!options.given.episodes) {
    options.plan.episodes = earlier->plan.episodes;
  }
  if (!options.given.seed) {
    options.plan.first_seed = earlier ? earlier->plan.first_seed : batch.scenario.scene.seed;
  }
  options.plan.validate("");
  const batch::BatchSettings settings = settings_of(options, scenario_file, batch.scenario);

  // The earlier output: resumed, replaced, or a reason to stop.
  std::vector<uint64_t> seeds;
  for (uint64_t index : options.plan.episode_indices()) {
    seeds.push_back(options.plan.seed_of(index));
  }
  bool csv_has_header = false;
  const std::string found = existing_outputs(paths, seeds);
  if (options.resume && fs::exists(paths.csv())) {
    batch.kept = resume_earlier_run(paths, earlier, settings, csv_has_header);
  } else if (options.resume) {
    std::cerr << "--resume: " << paths.csv() << " not found: starting the run\n";
    remove_earlier_run(paths, seeds, /*say=*/false);
  } else if (options.overwrite && !found.empty()) {
    remove_earlier_run(paths, seeds, /*say=*/true);
  } else if (!options.overwrite && !found.empty()) {
    throw core::ConfigError("--out: " + options.out + " holds this run's output already (" + found +
                            "): pass --resume to finish it or --overwrite to replace it");
  }

  // Settings first, then the CSV: a CSV is never without the settings that made it.
  core::prepare_output_directory("--out", options.out);
  if (options.audio) {
    core::prepare_output_directory("--out", options.out + "/audio");
  }
  core::OutputFile settings_file("--out", paths.settings());
  settings_file.stream() << settings.to_yaml();
  settings_file.commit();
  batch.csv.open(paths.csv(), std::ios::app);
  if (!batch.csv) {
    throw core::ConfigError("--out: cannot write " + paths.csv());
  }
  if (!csv_has_header) {
    batch.csv << batch::csv_header() << "\n" << std::flush;
  }
  return batch;
}

// The exit code of a run that went to its end: 0 when every row of the CSV (kept by --resume or
// new) is a success, else 1 after saying how many failed and, for the first few, why; a user or a
// job array sees a failed episode without reading the CSV.
int verdict(const std::vector<batch::EpisodeCsvRow>& rows, const std::string& csv) {
  std::vector<const batch::EpisodeCsvRow*> failed;
  for (const batch::EpisodeCsvRow& row : rows) {
    if (!row.success) {
      failed.push_back(&row);
    }
  }
  if (failed.empty()) {
    return kAllSucceededExit;
  }
  std::cerr << "run_episodes: " << failed.size() << " of " << rows.size() << " episodes in " << csv
            << " failed:\n";
  for (size_t i = 0; i < std::min(failed.size(), kFailuresNamed); ++i) {
    const batch::EpisodeCsvRow& row = *failed[i];
    std::cerr << "  seed " << row.seed << ": failed "
              << (row.final_state.empty() ? "before the script started"
                                          : "in state " + row.final_state)
              << ": " << row.reason << "\n";
  }
  if (failed.size() > kFailuresNamed) {
    std::cerr << "  and " << failed.size() - kFailuresNamed
              << " more (the rows with success 0 in the CSV)\n";
  }
  return kEpisodeFailedExit;
}

double seconds_since(std::chrono::steady_clock::time_point from) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
}

// The planned episodes that have no row yet (--resume keeps the others'), and how many episodes
// the run has in all: those and the distinct episodes kept.
struct PendingEpisodes {
  std::vector<uint64_t> indices;
  size_t planned{0};
};

PendingEpisodes pending_episodes(const Batch& batch) {
  std::set<uint64_t> done;
  for (const batch::EpisodeCsvRow& row : batch.kept) {
    done.insert(row.episode);
  }
  PendingEpisodes pending;
  for (uint64_t index : batch.options.plan.episode_indices()) {
    if (done.count(index) == 0) {
      pending.indices.push_back(index);
    }
  }
  pending.planned = done.size() + pending.indices.size();
  return pending;
}

// What the finished episodes of this run add up to, for the closing line.
struct RunTotals {
  int successes{0};
  double sim_time_s{0.0};
};

// Runs episode `index` to its bag and then its row in the CSV and `rows`. False when a stop signal
// ended it first: its bag is dropped and it gets no row. Throws core::Error.
bool run_episode(Batch& batch, uint64_t index, std::vector<batch::EpisodeCsvRow>& rows,
                 RunTotals& totals) {
  const OutputPaths& paths = batch.paths;
  const uint64_t seed = batch.options.plan.seed_of(index);
  engine::Episode episode(batch.scenario, seed, batch.config);
  std::unique_ptr<tools::EpisodeBag> bag;
  if (batch.options.bags) {
    bag = std::make_unique<tools::EpisodeBag>(paths.bag(seed), paths.name);
  }
  std::unique_ptr<dataset::EpisodeAudio> audio;
  if (batch.options.audio) {
    audio = std::make_unique<dataset::EpisodeAudio>(
        dataset::EpisodeAudio::stem_of(paths.dir, paths.name, seed), batch.scenario.scene, seed,
        audio::RoomSettings{}, batch.synthesizer);
  }
  while (!episode.finished() && g_stop_signal == 0) {
    episode.step();
    if (bag) {
      bag->record_step(episode);
    }
    if (audio) {
      audio->observe(episode.snapshot());
    }
  }
  if (g_stop_signal != 0) {
    if (audio) {
      audio.reset();
      for (const std::string& file : dataset::EpisodeAudio::files_of(
               dataset::EpisodeAudio::stem_of(paths.dir, paths.name, seed))) {
        fs::remove(file);
      }
    }
    return false;
  }
  // The bag and the audio under their names first, then the row: a row always has its files.
  if (bag) {
    bag->finish();
  }
  if (audio) {
    audio->finish();
  }
  const auto summary =
      batch::EpisodeSummary::of(paths.name, index, seed, episode.runner(), episode.metrics());
  batch.csv << batch::csv_row(summary) << "\n" << std::flush;
  if (!batch.csv) {
    throw core::Error(paths.csv() + ": writing the row of episode " + std::to_string(index) +
                      " failed");
  }
  rows.push_back(batch::EpisodeCsvRow::of(summary));
  totals.successes += summary.outcome.success ? 1 : 0;
  totals.sim_time_s += summary.outcome.end_time_s;
  return true;
}

// Stopped by a signal: what is kept, and how to go on. Returns the exit code, 128 + the signal.
int report_stop(const Batch& batch, const std::vector<batch::EpisodeCsvRow>& rows, size_t planned,
                std::optional<uint64_t> dropped_seed) {
  const OutputPaths& paths = batch.paths;
  size_t bags = 0;
  for (const batch::EpisodeCsvRow& row : rows) {
    bags += fs::exists(paths.bag(row.seed)) ? 1 : 0;
  }
  std::cerr << "run_episodes: interrupted by " << core::stop_signal_name(g_stop_signal) << " after "
            << rows.size() << " of " << planned << " episodes: " << rows.size() << " rows in "
            << paths.csv();
  if (batch.options.bags) {
    std::cerr << ", " << bags << " bags";
  }
  if (dropped_seed) {
    std::cerr << "; the episode under way (seed " << *dropped_seed << ") was dropped"
              << (batch.options.bags ? ", its bag deleted" : "");
  }
  std::cerr << "; rerun with --resume to finish\n";
  return core::stopped_exit_code(g_stop_signal);
}

// Runs the planned episodes that have no row yet, each to its bag and then its row, until done or
// stopped by a signal; returns the exit code.
int run(Batch& batch) {
  const Options& options = batch.options;
  const OutputPaths& paths = batch.paths;
  std::vector<batch::EpisodeCsvRow> rows = batch.kept;  // every row in the CSV, kept or new
  const PendingEpisodes pending = pending_episodes(batch);
  const std::vector<uint64_t>& episodes = pending.indices;
  const size_t planned = pending.planned;
  if (!batch.kept.empty()) {
    std::cerr << "--resume: " << batch.kept.size() << " of " << planned << " episodes are in "
              << paths.csv() << "; running the other " << episodes.size() << "\n";
  }
  if (episodes.empty()) {
    std::printf("%s: nothing to do, all %zu episodes are in %s\n", paths.name.c_str(), planned,
                paths.csv().c_str());
    return verdict(rows, paths.csv());
  }

  const bool terminal = isatty(STDERR_FILENO) != 0;
  const auto start = std::chrono::steady_clock::now();
  RunTotals totals;
  std::optional<uint64_t> dropped_seed;
  for (size_t ran = 0; ran < episodes.size() && g_stop_signal == 0; ++ran) {
    const uint64_t index = episodes[ran];
    try {
      if (!run_episode(batch, index, rows, totals)) {
        dropped_seed = options.plan.seed_of(index);
        break;
      }
    } catch (const core::Error& e) {
      // A scene that cannot be built is bad input; a file that cannot be written is not.
      const bool bad_input = dynamic_cast<const core::ConfigError*>(&e) != nullptr ||
                             dynamic_cast<const core::RequestError*>(&e) != nullptr;
      std::cerr << "\nrun_episodes: episode " << index << " (seed " << options.plan.seed_of(index)
                << "): " << e.what() << "\n";
      return bad_input ? kBadInputExit : kWriteFailedExit;
    }
    const std::string line = batch::progress_line(ran + 1, episodes.size(), seconds_since(start));
    std::cerr << (terminal ? "\r" : "") << line << (terminal ? "" : "\n") << std::flush;
  }
  const double wall_s = seconds_since(start);
  std::cerr << (terminal ? "\n" : "");
  if (g_stop_signal != 0) {
    return report_stop(batch, rows, planned, dropped_seed);
  }
  const size_t ran = episodes.size();
  std::printf(
      "%s: %zu episodes, %d succeeded; %.1f s of sim time in %.2f s of wall time (%.0fx "
      "real time, %.1f episodes per minute)\nmetrics: %s\n",
      paths.name.c_str(), ran, totals.successes, totals.sim_time_s, wall_s,
      wall_s > 0 ? totals.sim_time_s / wall_s : 0.0, wall_s > 0 ? 60.0 * ran / wall_s : 0.0,
      paths.csv().c_str());
  return verdict(rows, paths.csv());
}

// --merge-shards: the job array's shards in DIR merged into the files one process running the
// whole plan writes, checked first (every shard finished, with the plan's settings, every bag
// there); the shards' CSVs and settings are removed only once the merged files are in place.
// Returns the exit code of a run of the whole plan. Throws core::Error for bad input.
int merge_shards(Options options) {
  const std::string scenario_file = scenario::scenario_file_of(options.scenario, ARI_SCENARIO_DIR);
  core::check_input_file("--scenario", scenario_file);
  const scenario::Scenario scenario = scenario::load_scenario_file(scenario_file);
  if (!options.given.seed) {
    options.plan.first_seed = scenario.scene.seed;
  }
  options.plan.validate("");
  const OutputPaths paths{options.out, scenario.name, scenario.name};
  // One shard (1/1) writes the whole run's files itself: they are checked and kept.
  const bool in_place = options.merge_shards == 1;
  for (const std::string& path : {paths.csv(), paths.settings()}) {
    if (fs::exists(path) && !options.overwrite && !in_place) {
      throw core::ConfigError("--out: " + path +
                              " is there already: pass --overwrite to replace it with the merge");
    }
  }
  const batch::MergedEpisodeRun merged = batch::merge_episode_shards(
      options.out, settings_of(options, scenario_file, scenario), options.merge_shards);
  for (const batch::EpisodeCsvRow& row : merged.rows) {
    if (options.bags && !fs::exists(paths.bag(row.seed))) {
      throw core::ConfigError(paths.bag(row.seed) + ": not found: expected the bag of every row");
    }
  }
  core::OutputFile settings_file("--out", paths.settings());
  settings_file.stream() << merged.settings;
  settings_file.commit();
  core::OutputFile csv_file("--out", paths.csv());
  csv_file.stream() << merged.csv;
  csv_file.commit();
  for (unsigned k = 1; k <= options.merge_shards && !in_place; ++k) {
    batch::BatchPlan shard = options.plan;
    shard.shard_index = k;
    shard.shard_count = options.merge_shards;
    const OutputPaths shard_paths{options.out, scenario.name + shard.shard_suffix(), scenario.name};
    fs::remove(shard_paths.csv());
    fs::remove(shard_paths.settings());
  }
  std::printf("run_episodes: merged %u shards: %zu episodes into %s\n", options.merge_shards,
              merged.rows.size(), paths.csv().c_str());
  return verdict(merged.rows, paths.csv());
}

}  // namespace

int main(int argc, char** argv) {
  Batch batch;
  try {
    if (const Options options = parse_options(argc, argv); options.merge_shards > 0) {
      return merge_shards(options);
    }
    batch = prepare(argc, argv);
  } catch (const core::Error& e) {
    std::cerr << "run_episodes: " << e.what() << "\n";
    print_usage();
    return kBadInputExit;
  } catch (const fs::filesystem_error& e) {
    std::cerr << "run_episodes: --out: " << e.what() << "\n";
    return kBadInputExit;
  }
  install_stop_handler();
  return run(batch);
}
