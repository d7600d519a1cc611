// nav_benchmark: randomised, seeded social-navigation episodes run in one process on the world
// core, with SocialMPC and with a non-social baseline (the same MPC without personal and group
// spaces); writes one CSV row per episode and prints a summary table per episode type.
// Perception is ground truth (every person and group known exactly, no errors, no occlusion).
// With --csv, each finished episode's record goes to CSV.active (core::ProgressJournal) and the CSV
// is written when all are done; SIGINT or SIGTERM stops between two steps, drops the episode under
// way and exits with 128 + the signal's number; --resume goes on from CSV.active.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "ari_social_sim/batch/batch_plan.hpp"
#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/core/progress_journal.hpp"
#include "ari_social_sim/core/stop_signal.hpp"
#include "ari_social_sim/engine/ari_observation.hpp"
#include "ari_social_sim/learning/ground_truth.hpp"
#include "ari_social_sim/learning/navigation_episodes.hpp"
#include "ari_social_sim/navigation/episode_scorer.hpp"
#include "ari_social_sim/navigation/navigation_errors.hpp"
#include "ari_social_sim/navigation/navigator.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "episode_record.hpp"

namespace {

using namespace ari_social_sim;
using learning::EpisodeType;
using learning::NavigationEpisode;
using tools::nav::EpisodeRecord;
using tools::nav::percentile;

constexpr int kUsageError = 2;

// The documented ranges (README): 10 000 episodes of all 8 types with both controllers are
// 160 000 runs, some four hours at the 0.08 s each of docs/PERFORMANCE.md, with every record held
// until the CSV is written; any seed that fits a signed 64-bit integer.
constexpr core::IntegerOption kEpisodes{"--episodes", 1, 10000};
constexpr core::IntegerOption kSeed{"--seed", 0, INT64_MAX};

std::string usage() {
  return R"(Usage:
  nav_benchmark [--episodes N] [--seed S] [--types T1,T2,...] [--controllers social,baseline]
                [--solver lbfgs|slsqp|mppi] [--config FILE]
                [--csv FILE [--overwrite | --resume] [--shard K/N | --merge-shards N]]
                [--worlds DIR] [--profile ignore|yield|curious|avoid|block] [--trace]

Runs N seeded episodes of each type with each controller, on the world core in one process,
with ground-truth perception, and prints a summary table per type and controller. Solve times
are CPU time of the solving thread (one core); the wall-clock figures follow the table.

  --episodes N      episodes per type, in )" +
         kEpisodes.range() + R"( (default 50)
  --seed S          base seed (default 1), in )" +
         kSeed.range() + R"(; episode i of a type
                    always gets the same world
  --types LIST      comma-separated subset of pose, doorway, corridor, crossing, approach,
                    join2, join3, join4 (default all)
  --controllers L   social, baseline or both (default social,baseline); baseline = the same MPC
                    with the personal-space, personal-space-edge, o-space and o-space-edge
                    weights set to 0 and no
                    group areas in its geodesic field (people remain obstacles)
  --solver NAME     overrides the config's mpc.solver
  --config FILE     SocialMPC parameters (default: the package's config/social_mpc.yaml)
  --csv FILE        writes one row per episode (default: no CSV); checked before the first
                    episode, refused if it exists unless --overwrite, written when all have run;
                    until then the finished episodes are kept in FILE.active
  --resume          finishes a run stopped by a signal or a crash from FILE.active: refused
                    unless the options, the --config file and the worlds are those of that run;
                    the CSV is byte for byte that of an uninterrupted run but for the solve
                    times (CPU time, never the same twice)
  --shard K/N       runs episodes i with i % N == K - 1 (of every type and controller), for
                    job arrays (docs/cluster.md); writes their exact records to
                    FILE_shardK-of-N.records instead of the CSV (needs --csv, N <= --episodes)
  --merge-shards N  writes FILE, and prints the table, from the N shards' records of the same
                    options: what one process writes, but for the solve times
  --worlds DIR      folder of the shipped worlds (default: the package's worlds/)
  --profile NAME    how every person of every episode reacts to ARI: ignore (default, the
                    episodes as they always were), yield, curious, avoid or block
                    (docs/world.md, section 10)
  --trace           print every replanning cycle (pose, goal, command, cost by term) to stderr
  --help            print this text

SIGINT (Ctrl-C) or SIGTERM stops the run between two steps: the episode under way is dropped,
the finished ones stay in FILE.active (nothing is kept without --csv), and the same command with
--resume finishes it. A second Ctrl-C kills at once.

Exit status: 0 after a complete run, 2 on bad arguments or configuration, 1 when the CSV cannot
be written, 130 after SIGINT and 143 after SIGTERM.
)";
}

struct Options {
  int episodes{50};
  uint64_t seed{1};
  std::vector<EpisodeType> types{learning::all_episode_types()};
  std::vector<std::string> controllers{"social", "baseline"};
  std::string solver;
  std::string config{std::string(ARI_SOURCE_DIR) + "/config/social_mpc.yaml"};
  std::string csv;
  std::string worlds{std::string(ARI_SOURCE_DIR) + "/worlds"};
  world::ReactionProfile profile{world::ReactionProfile::kIgnore};
  bool trace{false};
  bool overwrite{false};
  bool resume{false};
  unsigned shard_index{1};  // --shard K/N
  unsigned shard_count{1};
  unsigned merge_shards{0};  // --merge-shards N; 0 when not merging
};

// Where a shard keeps its exact records: FILE_shardK-of-N.records, beside FILE.
std::string shard_records_path(const std::string& csv, unsigned index, unsigned count) {
  const std::filesystem::path path(csv);
  return (path.parent_path() / (path.stem().string() + "_shard" + std::to_string(index) + "-of-" +
                                std::to_string(count) + ".records"))
      .string();
}

// What this run writes at its end and keeps its progress beside: the CSV, or a shard's records.
std::string final_output(const Options& options) {
  return options.shard_count > 1
             ? shard_records_path(options.csv, options.shard_index, options.shard_count)
             : options.csv;
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    items.push_back(item);
  }
  return items;
}

// Throws core::ConfigError naming `option` for a name given twice: its table would count its
// episodes twice.
void check_list(const std::string& option, const std::vector<std::string>& names) {
  for (auto name = names.begin(); name != names.end(); ++name) {
    if (std::find(names.begin(), name, *name) != name) {
      throw core::ConfigError(option + ": expected each name once, got '" + *name + "' twice");
    }
  }
}

// Throws core::ConfigError for --shard or --merge-shards without what they need.
void check_shard_options(const Options& options) {
  const bool sharded = options.shard_count > 1;
  if ((sharded || options.merge_shards > 0) && options.csv.empty()) {
    throw core::ConfigError(std::string(sharded ? "--shard" : "--merge-shards") +
                            ": expected --csv too (the shards' records are kept beside it)");
  }
  if (sharded && options.merge_shards > 0) {
    throw core::ConfigError("--shard and --merge-shards: expected one of them, got both");
  }
  if (options.merge_shards > 0 && options.resume) {
    throw core::ConfigError("--merge-shards and --resume: expected one of them, got both");
  }
  const unsigned shards = std::max(options.shard_count, options.merge_shards);
  if (shards > static_cast<unsigned>(options.episodes)) {
    throw core::ConfigError((sharded ? "--shard: " : "--merge-shards: ") + std::string("N = ") +
                            std::to_string(shards) + " is more than --episodes " +
                            std::to_string(options.episodes) +
                            ": expected at most one shard per episode");
  }
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help") {
      std::cout << usage();
      std::exit(0);
    }
    if (arg == "--trace") {
      options.trace = true;
      continue;
    }
    if (arg == "--overwrite" || arg == "--resume") {
      (arg == "--overwrite" ? options.overwrite : options.resume) = true;
      continue;
    }
    core::check_known_option(
        arg, {"--episodes", "--seed", "--types", "--controllers", "--solver", "--config", "--csv",
              "--worlds", "--profile", "--trace", "--overwrite", "--resume", "--shard",
              "--merge-shards", "--help"});
    const std::string value = core::option_value(argc, argv, i);
    if (arg == "--episodes") {
      options.episodes = static_cast<int>(kEpisodes.parse(value));
    } else if (arg == "--seed") {
      options.seed = static_cast<uint64_t>(kSeed.parse(value));
    } else if (arg == "--types") {
      options.types.clear();
      const std::vector<std::string> names = split(value);
      check_list(arg, names);
      for (const std::string& name : names) {
        EpisodeType type;
        if (!learning::parse_type(name, type)) {
          throw core::ConfigError(
              "--types: expected pose, doorway, corridor, crossing, approach, join2, "
              "join3 or join4, got '" +
              name + "'");
        }
        options.types.push_back(type);
      }
    } else if (arg == "--controllers") {
      options.controllers = split(value);
      check_list(arg, options.controllers);
      for (const std::string& name : options.controllers) {
        if (name != "social" && name != "baseline") {
          throw core::ConfigError("--controllers: expected social and/or baseline, got '" + name +
                                  "'");
        }
      }
    } else if (arg == "--solver") {
      if (value != "lbfgs" && value != "slsqp" && value != "mppi") {
        throw core::ConfigError("--solver: expected lbfgs, slsqp or mppi, got '" + value + "'");
      }
      options.solver = value;
    } else if (arg == "--config") {
      options.config = value;
    } else if (arg == "--csv") {
      options.csv = value;
    } else if (arg == "--worlds") {
      options.worlds = value;
    } else if (arg == "--shard") {
      batch::BatchPlan plan;
      batch::parse_shard(value, "", plan);
      options.shard_index = plan.shard_index;
      options.shard_count = plan.shard_count;
    } else if (arg == "--merge-shards") {
      options.merge_shards = batch::shard_count_option(arg, value);
    } else {
      options.profile = core::parse_choice(value, world::kReactionProfiles, arg);
    }
  }
  // Paths before any episode: a typo must not cost the run.
  core::check_input_file("--config", options.config);
  core::check_input_directory("--worlds", options.worlds);
  if (options.overwrite && options.resume) {
    throw core::ConfigError("--overwrite and --resume: expected one of them, got both");
  }
  check_shard_options(options);
  // Merging one shard keeps the CSV that shard 1/1 wrote.
  if (!options.csv.empty() && options.merge_shards != 1) {
    core::check_output_file("--csv", final_output(options), options.overwrite || options.resume);
  } else if (options.overwrite || options.resume) {
    throw core::ConfigError(std::string(options.overwrite ? "--overwrite" : "--resume") +
                            ": expected --csv too");
  }
  return options;
}

navigation::NavigationConfig controller_config(const Options& options,
                                               const std::string& controller) {
  navigation::NavigationConfig config = navigation::NavigationConfig::load_file(options.config);
  if (!options.solver.empty()) {
    for (navigation::SolverKind kind :
         {navigation::SolverKind::kLbfgs, navigation::SolverKind::kSlsqp,
          navigation::SolverKind::kMppi}) {
      if (options.solver == navigation::solver_name(kind)) {
        config.mpc.solver = kind;
      }
    }
  }
  if (controller == "baseline") {
    config.mpc.weights.personal_space = 0.0;
    config.mpc.weights.personal_space_edge = 0.0;
    config.mpc.weights.group_space = 0.0;
    config.mpc.weights.ospace_edge = 0.0;
    config.navigator.geodesic.group_cost = 0.0;
  }
  return config;
}

const char* reaction_phase_name(world::RobotReaction::Phase phase) {
  switch (phase) {
    case world::RobotReaction::Phase::kIdle:
      return "";
    case world::RobotReaction::Phase::kSteppingAside:
      return ":aside";
    case world::RobotReaction::Phase::kWaiting:
      return ":waiting";
    case world::RobotReaction::Phase::kReturning:
      return ":returning";
    case world::RobotReaction::Phase::kEngaged:
      return ":engaged";
  }
  return "";
}

// One line per replanning cycle: time, ARI's pose and speeds, whether ARI is inside someone's
// personal space (as scored), the goal, the command, the plan's cost by term (--trace, for tuning).
void print_trace(const world::Simulation& sim, const navigation::Navigator& navigator,
                 const navigation::NavigatorStep& step, bool in_space) {
  const core::Pose2& ari = sim.ari()->pose();
  const core::Pose2& goal = navigator.goal()->pose;
  std::fprintf(stderr,
               "t=%.1f ari=(%.2f,%.2f,%.2f) v=%.2f w=%.2f %s goal=(%.2f,%.2f,%.2f) d=%.2f "
               "cmd=(%.2f,%.2f) %s J=%.3f:",
               sim.time_s(), ari.position.x(), ari.position.y(), ari.theta,
               sim.ari()->drive().linear_mps(), sim.ari()->drive().angular_rps(),
               in_space ? "IN-SPACE" : "clear", goal.position.x(), goal.position.y(), goal.theta,
               step.distance_to_goal_m, step.command.linear_mps, step.command.angular_rps,
               step.phase.c_str(), navigator.plan().cost);
  for (const navigation::TermCost& term : navigator.plan().terms) {
    std::fprintf(stderr, " %s=%.3f", term.name, term.cost);
  }
  for (const auto& human : sim.humans()) {
    const world::RobotReaction* reaction = human->reaction();
    std::fprintf(stderr, " human%u=(%.2f,%.2f,%.2f)%s", human->id(), human->pose().position.x(),
                 human->pose().position.y(), human->pose().theta,
                 reaction == nullptr ? "" : reaction_phase_name(reaction->phase_state()));
  }
  std::fprintf(stderr, "\n");
}

// What the scorer sees after a step: ARI and the true scene.
void score_step(const world::Simulation& sim, double group_stride_m,
                navigation::EpisodeScorer& scorer) {
  navigation::ScoredTick tick;
  tick.time_s = sim.time_s();
  tick.ari = sim.ari()->pose();
  tick.linear_mps = sim.ari()->drive().linear_mps();
  const navigation::PerceivedScene truth = learning::true_scene(sim, group_stride_m);
  tick.people = truth.people;
  tick.groups = truth.groups;
  tick.static_penetration_m = sim.static_penetration_m(*sim.ari());
  scorer.add(tick);
}

// Steps the episode until the navigator succeeds or aborts, or time runs out, scoring every step.
// False when a stop signal came first.
bool drive_episode(NavigationEpisode& episode, const navigation::NavigationConfig& config,
                   navigation::Navigator& navigator, navigation::EpisodeScorer& scorer, bool trace,
                   EpisodeRecord& record) {
  world::Simulation& sim = *episode.simulation;
  const double stride = config.scene.group_stride_m;
  const double control_period = 1.0 / config.navigator.rate_hz;
  double next_control_s = 0.0;
  size_t next_walk = 0;
  std::sort(episode.walks.begin(), episode.walks.end(),
            [](const auto& a, const auto& b) { return a.start_s < b.start_s; });
  record.outcome = "timeout";
  while (sim.time_s() < episode.time_limit_s) {
    if (core::g_stop_signal != 0) {
      return false;
    }
    while (next_walk < episode.walks.size() && episode.walks[next_walk].start_s <= sim.time_s()) {
      sim.set_human_goal(episode.walks[next_walk].human, episode.walks[next_walk].goal);
      ++next_walk;
    }
    const navigation::PerceivedScene scene = learning::true_scene(sim, stride);
    if (sim.time_s() >= next_control_s - 1e-9) {
      next_control_s += control_period;
      const navigation::NavigatorStep step =
          navigator.update(sim.time_s(), engine::observe_ari(*sim.ari()), scene);
      if (step.replanned) {
        record.solve_times_s.push_back(navigator.plan().solve_cpu_s);
        record.solve_wall_times_s.push_back(navigator.plan().solve_time_s);
        if (trace) {
          print_trace(sim, navigator, step, scorer.last_tick_in_space());
        }
      }
      if (step.state == navigation::NavigationState::kSucceeded) {
        record.outcome = "succeeded";
        record.success = true;
        record.time_to_goal_s = sim.time_s();
        break;
      }
      if (step.state == navigation::NavigationState::kAborted) {
        record.outcome = "aborted";
        record.reason = step.reason;
        break;
      }
      sim.command_ari_twist(step.command.linear_mps, step.command.angular_rps);
      sim.command_ari_head_pan(step.command.pan_rad);
    }
    sim.step();
    score_step(sim, stride, scorer);
  }
  return true;
}

// Final placement against the person or group (approach and join episodes).
void record_final_placement(const NavigationEpisode& episode,
                            const navigation::NavigationConfig& config,
                            const navigation::Navigator& navigator, EpisodeRecord& record) {
  const world::Simulation& sim = *episode.simulation;
  const core::Pose2 ari = sim.ari()->pose();
  const navigation::PerceivedScene final_scene =
      learning::true_scene(sim, config.scene.group_stride_m);
  std::optional<Eigen::Vector2d> facing;
  if (const auto* person = std::get_if<navigation::PersonTarget>(&episode.target)) {
    if (const auto* p = final_scene.find_person(person->person_id)) {
      facing = p->position;
      record.final_position_error_m =
          std::abs((p->position - ari.position).norm() - config.goal_finder.approach_distance_m);
    }
  } else if (const auto* group = std::get_if<navigation::GroupTarget>(&episode.target)) {
    if (const auto* g = final_scene.find_group(group->group_id)) {
      facing = g->centre;
      record.final_position_error_m = (navigator.goal()->pose.position - ari.position).norm();
      record.gcff_includes_ari =
          learning::gcff_includes_ari(sim, navigator.footprint(), episode.exempt_people) ? 1 : 0;
    }
  }
  if (facing) {
    const Eigen::Vector2d to = *facing - ari.position;
    record.final_heading_error_rad =
        std::abs(core::angle_difference(std::atan2(to.y(), to.x()), ari.theta));
  }
}

// Runs one episode to its record; nothing when a stop signal came first.
std::optional<EpisodeRecord> run_episode(NavigationEpisode episode,
                                         const navigation::NavigationConfig& config,
                                         const std::string& controller,
                                         world::ReactionProfile profile, bool trace) {
  world::Simulation& sim = *episode.simulation;
  // Every person reacts alike; with kIgnore nothing is set, so the episodes stay as they were.
  if (profile != world::ReactionProfile::kIgnore) {
    for (const auto& human : sim.humans()) {
      sim.set_human_reaction(human->id(), profile);
    }
  }
  EpisodeRecord record;
  record.type = learning::type_name(episode.type);
  record.controller = controller;
  record.profile = world::reaction_name(profile);
  record.index = episode.index;
  record.seed = episode.seed;
  navigation::Navigator navigator(config, world::rasterize_static_map(sim.world(), 0.05));
  navigation::EpisodeScorer scorer(navigator.footprint(), config.mpc.personal_space,
                                   episode.exempt_people, episode.exempt_group);
  try {
    navigator.start(episode.target, learning::true_scene(sim, config.scene.group_stride_m),
                    engine::observe_ari(*sim.ari()), sim.time_s());
  } catch (const core::Error& e) {
    record.outcome = "rejected";
    record.reason = e.what();
    return record;
  }
  // Shortest passable path from the start, for the path length ratio.
  navigation::GeodesicParams plain = config.navigator.geodesic;
  plain.clearance_penalty = 0.0;
  record.shortest_path_m =
      navigation::GeodesicField(navigator.sdf(), navigator.goal()->pose.position, plain)
          .cost(sim.ari()->pose().position);
  if (!drive_episode(episode, config, navigator, scorer, trace, record)) {
    return std::nullopt;
  }
  record.score = scorer.score();
  record_final_placement(episode, config, navigator, record);
  return record;
}

double mean_of(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) {
    sum += v;
  }
  return values.empty() ? 0.0 : sum / values.size();
}

// One row of the summary table: the episodes of one type with one controller.
struct SummaryRow {
  size_t episodes{0};
  int successes{0}, person_hits{0}, static_hits{0}, intruding{0}, gcff_yes{0}, gcff_count{0};
  std::vector<double> times, ratios, shares, minima, jerks, position_errors, heading_errors, solves,
      wall_solves;
};

SummaryRow summarise(const std::vector<EpisodeRecord>& records, const std::string& type,
                     const std::string& controller) {
  SummaryRow row;
  for (const EpisodeRecord& r : records) {
    if (r.type != type || r.controller != controller) {
      continue;
    }
    ++row.episodes;
    row.successes += r.success ? 1 : 0;
    row.person_hits += r.score.person_collisions;
    row.static_hits += r.score.static_collisions;
    row.intruding += r.score.ospace_intrusions > 0 ? 1 : 0;
    row.shares.push_back(r.score.personal_space_share);
    row.minima.push_back(r.score.min_person_distance_m);
    row.jerks.push_back(r.score.mean_abs_jerk);
    row.solves.insert(row.solves.end(), r.solve_times_s.begin(), r.solve_times_s.end());
    row.wall_solves.insert(row.wall_solves.end(), r.solve_wall_times_s.begin(),
                           r.solve_wall_times_s.end());
    if (r.success) {
      row.times.push_back(r.time_to_goal_s);
      if (r.shortest_path_m > 0.0) {
        row.ratios.push_back(r.score.path_length_m / r.shortest_path_m);
      }
      if (r.final_position_error_m >= 0.0) {
        row.position_errors.push_back(r.final_position_error_m);
        row.heading_errors.push_back(core::rad_to_deg(r.final_heading_error_rad));
      }
    }
    if (r.gcff_includes_ari >= 0) {
      ++row.gcff_count;
      row.gcff_yes += r.gcff_includes_ari;
    }
  }
  return row;
}

void print_summary_row(const SummaryRow& row, const char* type, const std::string& controller,
                       world::ReactionProfile profile) {
  const double n = static_cast<double>(std::max<size_t>(row.episodes, 1));
  char placement[64] = "-";
  if (!row.position_errors.empty()) {
    std::snprintf(placement, sizeof(placement), "%.2f m / %.1f deg", mean_of(row.position_errors),
                  mean_of(row.heading_errors));
  }
  char gcff[32] = "-";
  if (row.gcff_count > 0) {
    std::snprintf(gcff, sizeof(gcff), "%.0f %%", 100.0 * row.gcff_yes / row.gcff_count);
  }
  std::printf(
      "| %s | %s | %s | %zu | %.0f %% | %d / %d | %d | %.2f %% | %.2f / %.2f m | %.1f s | %.2f "
      "| %s | %s | %.2f m/s^3 | %.1f / %.1f ms |\n",
      type, controller.c_str(), world::reaction_name(profile), row.episodes,
      100.0 * row.successes / n, row.person_hits, row.static_hits, row.intruding,
      100.0 * mean_of(row.shares),
      row.minima.empty() ? 0.0 : *std::min_element(row.minima.begin(), row.minima.end()),
      mean_of(row.minima), mean_of(row.times), mean_of(row.ratios), placement, gcff,
      mean_of(row.jerks), 1e3 * percentile(row.solves, 0.5), 1e3 * percentile(row.solves, 0.99));
}

void print_summary(const std::vector<EpisodeRecord>& records, const Options& options) {
  std::printf(
      "| type | controller | profile | episodes | success | collisions (people/static) | episodes "
      "with o-space intrusion | personal-space time | min distance to people (min / mean) | time "
      "to goal | path ratio | final position / heading error | GCFF includes ARI | mean abs jerk "
      "| solve p50 / p99 (CPU) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<double> all_solves, all_wall;
  for (EpisodeType type : options.types) {
    for (const std::string& controller : options.controllers) {
      const SummaryRow row = summarise(records, learning::type_name(type), controller);
      if (controller == "social") {
        all_solves.insert(all_solves.end(), row.solves.begin(), row.solves.end());
        all_wall.insert(all_wall.end(), row.wall_solves.begin(), row.wall_solves.end());
      }
      print_summary_row(row, learning::type_name(type), controller, options.profile);
    }
  }
  if (!all_solves.empty()) {
    std::printf(
        "\nSocialMPC solve time (CPU, one core) over %zu solves: median %.2f ms, p99 %.2f ms, max "
        "%.2f ms\n",
        all_solves.size(), 1e3 * percentile(all_solves, 0.5), 1e3 * percentile(all_solves, 0.99),
        1e3 * percentile(all_solves, 1.0));
    std::printf("SocialMPC solve time (wall) over the same solves: median %.2f ms, p99 %.2f ms\n",
                1e3 * percentile(all_wall, 0.5), 1e3 * percentile(all_wall, 0.99));
  }
}

// One run of the plan: episode `index` of a type with a controller, in the CSV's order.
struct PlannedRun {
  EpisodeType type;
  int index;
  std::string controller;

  // The run's key in the progress file, e.g. `pose/3/social`.
  std::string key() const {
    return std::string(learning::type_name(type)) + "/" + std::to_string(index) + "/" + controller;
  }
};

// The runs of this process: every one, or a shard's (episodes i with i % N == K - 1).
std::vector<PlannedRun> plan_of(const Options& options) {
  std::vector<PlannedRun> plan;
  for (EpisodeType type : options.types) {
    for (int i = static_cast<int>(options.shard_index) - 1; i < options.episodes;
         i += static_cast<int>(options.shard_count)) {
      for (const std::string& controller : options.controllers) {
        plan.push_back({type, i, controller});
      }
    }
  }
  return plan;
}

// The progress file's first line: every option that changes a record, and the digests of the
// files the episodes read.
std::string progress_settings(const Options& options) {
  std::string types, controllers;
  for (EpisodeType type : options.types) {
    types += (types.empty() ? "" : ",") + std::string(learning::type_name(type));
  }
  for (const std::string& controller : options.controllers) {
    controllers += (controllers.empty() ? "" : ",") + controller;
  }
  return "nav_benchmark episodes=" + std::to_string(options.episodes) +
         " seed=" + std::to_string(options.seed) + " types=" + types +
         " controllers=" + controllers + " solver=" + options.solver +
         " profile=" + world::reaction_name(options.profile) +
         (options.shard_count > 1 ? " shard=" + std::to_string(options.shard_index) + "/" +
                                        std::to_string(options.shard_count)
                                  : std::string()) +
         " config_digest=" + batch::digest_files({options.config}) +
         " worlds_digest=" + batch::digest_files(batch::files_under(options.worlds, ".yaml"));
}

// A checked benchmark, ready to go.
struct Benchmark {
  Options options;
  std::map<std::string, navigation::NavigationConfig> configs;
  learning::EpisodeWorlds worlds;
  std::optional<core::ProgressJournal> journal;  // with --csv, unless the CSV is complete
  std::vector<EpisodeRecord> records;            // --resume: those of the earlier run
  bool complete_already{false};                  // --resume of a run that wrote its CSV
};

// The records of `journal`, which must be the first runs of `plan`, in its order. Throws
// core::ConfigError naming `option`, the file and the record.
std::vector<EpisodeRecord> records_of(const core::ProgressJournal& journal,
                                      const std::vector<PlannedRun>& plan,
                                      const std::string& option) {
  std::vector<EpisodeRecord> records;
  for (size_t k = 0; k < journal.kept().size(); ++k) {
    const core::ProgressJournal::Entry& entry = journal.kept()[k];
    if (k >= plan.size() || entry.key != plan[k].key()) {
      throw core::ConfigError(option + ": " + journal.path() + ": record " + std::to_string(k + 1) +
                              " is " + entry.key + ", expected " +
                              (k < plan.size() ? plan[k].key() : "none"));
    }
    records.push_back(tools::nav::parse_record(entry.lines.substr(0, entry.lines.size() - 1),
                                               journal.path() + ": " + entry.key));
  }
  return records;
}

// --resume: the records of the progress file, which must be the plan's first runs.
void keep_earlier_records(Benchmark& benchmark) {
  const core::ProgressJournal& journal = *benchmark.journal;
  if (journal.was_cut_short()) {
    std::cerr << "--resume: " << journal.path()
              << " ended in an episode cut short (a run killed while writing it): removed it\n";
  }
  benchmark.records = records_of(journal, plan_of(benchmark.options), "--resume");
}

// --merge-shards N: the records of shard K, checked to be all of that shard's with these options,
// added to `by_key` under their runs' keys. Throws core::ConfigError naming the file.
void add_shard_records(const Options& options, unsigned index,
                       std::map<std::string, EpisodeRecord>& by_key) {
  Options shard = options;
  shard.shard_index = index;
  shard.shard_count = options.merge_shards;
  const std::string option = "--merge-shards " + std::to_string(options.merge_shards);
  const std::string path = shard_records_path(options.csv, index, options.merge_shards);
  if (!std::filesystem::exists(path)) {
    throw core::ConfigError(option + ": " + path + " not found: shard " + std::to_string(index) +
                            (std::filesystem::exists(path + ".active")
                                 ? " has not finished (its records so far are in " + path +
                                       ".active: rerun it with "
                                       "--resume)"
                                 : " has not run"));
  }
  const core::ProgressJournal journal =
      core::ProgressJournal::resume(option, path, progress_settings(shard));
  const std::vector<PlannedRun> plan = plan_of(shard);
  std::vector<EpisodeRecord> records = records_of(journal, plan, option);
  if (records.size() != plan.size()) {
    throw core::ConfigError(option + ": " + path + ": expected the shard's " +
                            std::to_string(plan.size()) + " records, got " +
                            std::to_string(records.size()));
  }
  for (size_t k = 0; k < plan.size(); ++k) {
    by_key.emplace(plan[k].key(), std::move(records[k]));
  }
}

// --merge-shards N: every shard's records in the order one process runs them.
std::vector<EpisodeRecord> merged_records(const Options& options) {
  std::map<std::string, EpisodeRecord> by_key;
  for (unsigned k = 1; k <= options.merge_shards; ++k) {
    add_shard_records(options, k, by_key);
  }
  std::vector<EpisodeRecord> records;
  for (const PlannedRun& run : plan_of(options)) {
    records.push_back(by_key.at(run.key()));
  }
  return records;
}

// With --csv: the progress file of an earlier run resumed, or a new one. Throws core::ConfigError.
void open_progress(Benchmark& benchmark) {
  const Options& options = benchmark.options;
  const std::string progress = final_output(options) + ".active";
  const std::string settings = progress_settings(options);
  const bool progress_there = std::filesystem::exists(progress);
  if (options.resume && progress_there) {
    benchmark.journal = core::ProgressJournal::resume("--resume", progress, settings);
    keep_earlier_records(benchmark);
    return;
  }
  if (options.resume && std::filesystem::exists(final_output(options))) {
    benchmark.complete_already = true;
    return;
  }
  if (progress_there && !options.overwrite) {
    throw core::ConfigError("--csv: " + progress +
                            " holds the episodes of an interrupted run: pass --resume to finish "
                            "it or --overwrite to start again");
  }
  if (options.resume) {
    std::cerr << "--resume: " << progress << " not found: starting the run\n";
  }
  benchmark.journal = core::ProgressJournal::start("--csv", progress, settings);
}

// Checks the options and files before any episode. Throws core::Error.
Benchmark prepare(int argc, char** argv) {
  Benchmark benchmark;
  benchmark.options = parse(argc, argv);
  for (const std::string& controller : benchmark.options.controllers) {
    benchmark.configs.emplace(controller, controller_config(benchmark.options, controller));
  }
  benchmark.worlds = learning::EpisodeWorlds::load(benchmark.options.worlds);
  if (!benchmark.options.csv.empty() && benchmark.options.merge_shards == 0) {
    open_progress(benchmark);
  }
  return benchmark;
}

// After a stop signal: what is kept, and how to go on. Returns the exit code.
int report_stop(const Benchmark& benchmark, size_t planned, const PlannedRun& dropped) {
  const int signal = core::g_stop_signal;
  std::cerr << "nav_benchmark: interrupted by " << core::stop_signal_name(signal) << " after "
            << benchmark.records.size() << " of " << planned << " episodes";
  if (benchmark.journal) {
    std::cerr << ": their records are in " << benchmark.journal->path() << " ("
              << final_output(benchmark.options) << " is written once every episode is done)";
  }
  std::cerr << "; the episode under way (" << dropped.key() << ") was dropped";
  if (benchmark.journal) {
    std::cerr << "; rerun the same command with --resume to finish\n";
  } else {
    std::cerr << "; nothing was kept (no --csv)\n";
  }
  return core::stopped_exit_code(signal);
}

// Runs the planned episodes that have no record yet, keeping each in the progress file, until done
// or stopped by a signal; returns 0, or the exit code to end with. Throws core::Error when the
// progress file cannot be written.
int run_episodes(Benchmark& benchmark) {
  const Options& options = benchmark.options;
  const std::vector<PlannedRun> plan = plan_of(options);
  if (!benchmark.records.empty()) {
    std::cerr << "--resume: " << benchmark.records.size() << " of " << plan.size()
              << " episodes are in " << benchmark.journal->path() << "; running the other "
              << plan.size() - benchmark.records.size() << "\n";
  }
  for (size_t k = benchmark.records.size(); k < plan.size(); ++k) {
    const PlannedRun& run = plan[k];
    std::optional<EpisodeRecord> record;
    try {
      record = run_episode(
          learning::make_episode(run.type, run.index, options.seed, benchmark.worlds),
          benchmark.configs.at(run.controller), run.controller, options.profile, options.trace);
    } catch (const core::Error& e) {
      std::cerr << "nav_benchmark: " << learning::type_name(run.type) << " episode " << run.index
                << ": " << e.what() << "\n";
      return kUsageError;
    }
    if (!record) {
      return report_stop(benchmark, plan.size(), run);
    }
    if (benchmark.journal) {
      benchmark.journal->add(run.key(), tools::nav::record_line(*record) + "\n");
    }
    benchmark.records.push_back(*record);
    std::fprintf(stderr, "%s %d %s: %s %s\n", record->type.c_str(), record->index,
                 record->controller.c_str(), record->outcome.c_str(), record->reason.c_str());
  }
  return 0;
}

// --merge-shards N: writes the CSV and prints the table one process would, then removes the
// shards' records. Returns the exit code.
int merge_shards(Benchmark& benchmark) {
  const Options& options = benchmark.options;
  if (options.merge_shards == 1) {  // shard 1/1 is the whole run and wrote the CSV itself
    if (!std::filesystem::exists(options.csv)) {
      std::cerr << "nav_benchmark: --merge-shards 1: " << options.csv
                << " not found: the one shard has not finished\n";
      return kUsageError;
    }
    std::printf("nav_benchmark: one shard: %s is the whole run's\n", options.csv.c_str());
    return 0;
  }
  try {
    benchmark.records = merged_records(options);
  } catch (const core::Error& e) {
    std::cerr << "nav_benchmark: " << e.what() << "\n";
    return kUsageError;
  }
  try {
    tools::nav::write_csv(options.csv, benchmark.records);
  } catch (const core::Error& e) {
    std::cerr << "nav_benchmark: " << e.what() << "\n";
    return 1;
  }
  for (unsigned k = 1; k <= options.merge_shards; ++k) {
    std::filesystem::remove(shard_records_path(options.csv, k, options.merge_shards));
  }
  print_summary(benchmark.records, options);
  std::printf("nav_benchmark: merged %u shards: %zu records into %s\n", options.merge_shards,
              benchmark.records.size(), options.csv.c_str());
  return 0;
}

// What a finished run writes: the CSV, or a shard's records (its progress file, renamed).
void write_output(Benchmark& benchmark) {
  if (!benchmark.journal) {
    return;
  }
  if (benchmark.options.shard_count > 1) {
    benchmark.journal->complete_as(final_output(benchmark.options));
  } else {
    tools::nav::write_csv(benchmark.options.csv, benchmark.records);
    benchmark.journal->remove();
  }
}

}  // namespace

int main(int argc, char** argv) {
  Benchmark benchmark;
  try {
    benchmark = prepare(argc, argv);
  } catch (const core::Error& e) {
    std::cerr << "nav_benchmark: " << e.what() << "\n";
    return kUsageError;
  }
  if (benchmark.options.merge_shards > 0) {
    return merge_shards(benchmark);
  }
  const std::string output = final_output(benchmark.options);
  if (benchmark.complete_already) {
    std::printf("nothing to do: %s is complete (no %s.active to resume)\n", output.c_str(),
                output.c_str());
    return 0;
  }
  core::install_stop_handler();
  const auto started = std::chrono::steady_clock::now();
  try {
    const int stopped = run_episodes(benchmark);
    if (stopped != 0) {
      return stopped;
    }
    write_output(benchmark);
  } catch (const core::Error& e) {
    std::cerr << "nav_benchmark: " << e.what() << "\n";
    return 1;
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  print_summary(benchmark.records, benchmark.options);
  std::printf("%zu episodes in %.0f s of wall time\n", benchmark.records.size(), wall_s);
  return 0;
}
