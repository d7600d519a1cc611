// run_episodes: runs a scenario for many seeds in one process, without roscore, as fast as the
// machine allows; writes one rosbag per episode (the topics a live run records) and one CSV row
// of metrics per episode, with a progress line on standard error.
//
//   run_episodes --scenario NAME|FILE --episodes N [--seed S] [--shard K/N] [--out DIR]
//                [--no-bags]
//
// Episode i runs with seed S + i (S defaults to the scenario file's seed), so that it can be
// replayed live with `roslaunch ari_social_sim NAME.launch seed:=S+i`. --shard K/N runs the
// episodes with i % N == K - 1 (K from 1), for job arrays. Files: DIR/NAME_SEED.bag and
// DIR/NAME.csv (DIR/NAME_shardK-of-N.csv with --shard). Exit code 2 on bad input.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/scenario/batch_plan.hpp"
#include "ari_social_sim/scenario/episode.hpp"
#include "ari_social_sim/scenario/episode_csv.hpp"
#include "ari_social_sim/scenario/progress_bar.hpp"
#include "episode_bag.hpp"

namespace {

using namespace ari_social_sim;
constexpr char kSource[] = "command line";

struct Options {
  std::string scenario;
  scenario::BatchPlan plan;
  bool seed_given{false};
  std::string out{"episodes"};
  bool bags{true};
};

void print_usage() {
  std::cerr << "usage: run_episodes --scenario NAME|FILE --episodes N [--seed S] [--shard K/N]\n"
               "                    [--out DIR] [--no-bags]\n"
            << "  NAME is one of the package's scenarios (" << ARI_SCENARIO_DIR << ")\n";
}

uint64_t parse_count(const std::string& flag, const std::string& text) {
  try {
    size_t used = 0;
    const unsigned long long value = std::stoull(text, &used);
    if (used == text.size() && text[0] != '-') {
      return value;
    }
  } catch (const std::exception&) {
  }
  throw core::ConfigError(std::string(kSource) + ": " + flag +
                          ": expected a non-negative integer, got '" + text + "'");
}

Options parse_options(int argc, char** argv) {
  Options options;
  bool have_episodes = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--no-bags") {
      options.bags = false;
      continue;
    }
    if (i + 1 >= argc) {
      throw core::ConfigError(std::string(kSource) + ": " + arg + ": expected a value after it");
    }
    const std::string value = argv[++i];
    if (arg == "--scenario") {
      options.scenario = value;
    } else if (arg == "--episodes") {
      options.plan.episodes = parse_count(arg, value);
      have_episodes = true;
    } else if (arg == "--seed") {
      options.plan.first_seed = parse_count(arg, value);
      options.seed_given = true;
    } else if (arg == "--shard") {
      scenario::parse_shard(value, kSource, options.plan);
    } else if (arg == "--out") {
      options.out = value;
    } else {
      throw core::ConfigError(std::string(kSource) + ": " + arg +
                              ": expected one of --scenario, --episodes, --seed, --shard, --out, "
                              "--no-bags");
    }
  }
  if (options.scenario.empty() || !have_episodes) {
    throw core::ConfigError(std::string(kSource) + ": expected --scenario and --episodes");
  }
  return options;
}

// A name without a slash or extension is one of the package's scenarios.
std::string scenario_path(const std::string& scenario) {
  if (scenario.find('/') == std::string::npos && scenario.find('.') == std::string::npos) {
    return std::string(ARI_SCENARIO_DIR) + "/" + scenario + ".yaml";
  }
  return scenario;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  scenario::Scenario loaded;
  scenario::EpisodeConfig config;
  std::ofstream csv;
  std::string csv_path;
  try {
    options = parse_options(argc, argv);
    loaded = scenario::load_scenario_file(scenario_path(options.scenario));
    config = scenario::EpisodeConfig::load(ARI_CONFIG_DIR);
    if (!options.seed_given) {
      options.plan.first_seed = loaded.scene.seed;
    }
    options.plan.validate(kSource);
    std::filesystem::create_directories(options.out);
    const bool sharded = options.plan.shard_count > 1;
    csv_path = options.out + "/" + loaded.name +
               (sharded ? "_shard" + std::to_string(options.plan.shard_index) + "-of-" +
                              std::to_string(options.plan.shard_count)
                        : "") +
               ".csv";
    csv.open(csv_path);
    if (!csv) {
      throw core::ConfigError(std::string(kSource) + ": --out: cannot write " + csv_path);
    }
  } catch (const core::Error& e) {
    std::cerr << e.what() << "\n";
    print_usage();
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << kSource << ": --out: " << e.what() << "\n";
    return 2;
  }

  csv << scenario::csv_header() << "\n";
  const std::vector<uint64_t> episodes = options.plan.episode_indices();
  const bool terminal = isatty(STDERR_FILENO) != 0;
  const auto start = std::chrono::steady_clock::now();
  const auto seconds_since = [](std::chrono::steady_clock::time_point from) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
  };
  int successes = 0;
  double sim_time_s = 0.0;
  for (size_t done = 0; done < episodes.size(); ++done) {
    const uint64_t index = episodes[done];
    const uint64_t seed = options.plan.seed_of(index);
    const auto episode_start = std::chrono::steady_clock::now();
    try {
      scenario::Episode episode(loaded, seed, config);
      std::unique_ptr<tools::EpisodeBag> bag;
      if (options.bags) {
        bag = std::make_unique<tools::EpisodeBag>(
            options.out + "/" + loaded.name + "_" + std::to_string(seed) + ".bag", loaded.name);
      }
      while (!episode.finished()) {
        episode.step();
        if (bag) {
          bag->record_step(episode);
        }
      }
      const auto summary =
          scenario::EpisodeSummary::of(loaded.name, index, seed, episode.runner(),
                                       episode.metrics(), seconds_since(episode_start));
      csv << scenario::csv_row(summary) << "\n" << std::flush;
      successes += summary.outcome.success ? 1 : 0;
      sim_time_s += summary.outcome.end_time_s;
    } catch (const core::Error& e) {
      std::cerr << "\nepisode " << index << " (seed " << seed << "): " << e.what() << "\n";
      return 2;
    }
    const std::string line =
        scenario::progress_line(done + 1, episodes.size(), seconds_since(start));
    std::cerr << (terminal ? "\r" : "") << line << (terminal ? "" : "\n") << std::flush;
  }
  const double wall_s = seconds_since(start);
  std::cerr << (terminal ? "\n" : "");
  std::printf(
      "%s: %zu episodes, %d succeeded; %.1f s of sim time in %.2f s of wall time (%.0fx "
      "real time, %.1f episodes per minute)\nmetrics: %s\n",
      loaded.name.c_str(), episodes.size(), successes, sim_time_s, wall_s,
      wall_s > 0 ? sim_time_s / wall_s : 0.0, wall_s > 0 ? 60.0 * episodes.size() / wall_s : 0.0,
      csv_path.c_str());
  return 0;
}
