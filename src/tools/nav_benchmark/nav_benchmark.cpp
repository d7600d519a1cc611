// nav_benchmark: randomised, seeded social-navigation episodes run in one process on the world
// core, with SocialMPC and with a non-social baseline (the same MPC without personal and group
// spaces); writes one CSV row per episode and prints a summary table per episode type.
// Perception is ground truth (every person and group known exactly, no errors, no occlusion).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/learning/ground_truth.hpp"
#include "ari_social_sim/learning/navigation_episodes.hpp"
#include "ari_social_sim/navigation/episode_scorer.hpp"
#include "ari_social_sim/navigation/navigation_errors.hpp"
#include "ari_social_sim/navigation/navigator.hpp"
#include "ari_social_sim/scenario/ari_observation.hpp"
#include "ari_social_sim/world/map_sensor.hpp"

namespace {

using namespace ari_social_sim;
using learning::EpisodeType;
using learning::NavigationEpisode;

constexpr int kUsageError = 2;

// The documented ranges (README): 10 000 episodes of all 8 types with both controllers are
// 160 000 runs, some four hours at the 0.08 s each of docs/PERFORMANCE.md, with every record held
// until the CSV is written; any seed that fits a signed 64-bit integer.
constexpr core::IntegerOption kEpisodes{"--episodes", 1, 10000};
constexpr core::IntegerOption kSeed{"--seed", 0, INT64_MAX};

std::string usage() {
  return R"(Usage:
  nav_benchmark [--episodes N] [--seed S] [--types T1,T2,...] [--controllers social,baseline]
                [--solver lbfgs|slsqp|mppi] [--config FILE] [--csv FILE [--overwrite]]
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
                    episode, refused if it exists unless --overwrite, written when all have run
  --worlds DIR      folder of the shipped worlds (default: the package's worlds/)
  --profile NAME    how every person of every episode reacts to ARI: ignore (default, the
                    episodes as they always were), yield, curious, avoid or block
                    (docs/world.md, section 10)
  --trace           print every replanning cycle (pose, goal, command, cost by term) to stderr
  --help            print this text

Exit status: 0 after a complete run, 2 on bad arguments or configuration, 1 when the CSV cannot
be written.
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
};

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
  for (size_t i = 0; i < names.size(); ++i) {
    if (std::find(names.begin(), names.begin() + i, names[i]) != names.begin() + i) {
      throw core::ConfigError(option + ": expected each name once, got '" + names[i] + "' twice");
    }
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
    if (arg == "--overwrite") {
      options.overwrite = true;
      continue;
    }
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
    } else if (arg == "--profile") {
      options.profile = core::parse_choice(value, world::kReactionProfiles, arg);
    } else {
      throw core::ConfigError(arg + ": unknown option (see --help)");
    }
  }
  // Paths before any episode: a typo must not cost the run.
  core::check_input_file("--config", options.config);
  core::check_input_directory("--worlds", options.worlds);
  if (!options.csv.empty()) {
    core::check_output_file("--csv", options.csv, options.overwrite);
  } else if (options.overwrite) {
    throw core::ConfigError("--overwrite: expected --csv too");
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

struct EpisodeRecord {
  std::string type, controller, profile, outcome, reason;
  int index{0};
  uint64_t seed{0};
  bool success{false};
  double time_to_goal_s{0.0};
  double shortest_path_m{0.0};
  navigation::EpisodeScore score;
  double final_position_error_m{-1.0};
  double final_heading_error_rad{-1.0};
  int gcff_includes_ari{-1};               // -1 = not a joining episode
  std::vector<double> solve_times_s;       // CPU time of each solve on its thread
  std::vector<double> solve_wall_times_s;  // wall time of each solve (grows with machine load)
};

double percentile(std::vector<double> values, double q) {
  if (values.empty()) {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const size_t index = std::min(
      values.size() - 1, static_cast<size_t>(std::ceil(q * values.size())) - (q > 0 ? 1 : 0));
  return values[index];
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

EpisodeRecord run_episode(NavigationEpisode episode, const navigation::NavigationConfig& config,
                          const std::string& controller, world::ReactionProfile profile,
                          bool trace) {
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
  const double stride = config.scene.group_stride_m;
  navigation::Navigator navigator(config, world::rasterize_static_map(sim.world(), 0.05));
  navigation::EpisodeScorer scorer(navigator.footprint(), config.mpc.personal_space,
                                   episode.exempt_people, episode.exempt_group);
  try {
    navigator.start(episode.target, learning::true_scene(sim, stride),
                    scenario::observe_ari(*sim.ari()), sim.time_s());
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

  const double control_period = 1.0 / config.navigator.rate_hz;
  double next_control_s = 0.0;
  size_t next_walk = 0;
  std::sort(episode.walks.begin(), episode.walks.end(),
            [](const auto& a, const auto& b) { return a.start_s < b.start_s; });
  record.outcome = "timeout";
  while (sim.time_s() < episode.time_limit_s) {
    while (next_walk < episode.walks.size() && episode.walks[next_walk].start_s <= sim.time_s()) {
      sim.set_human_goal(episode.walks[next_walk].human, episode.walks[next_walk].goal);
      ++next_walk;
    }
    const navigation::PerceivedScene scene = learning::true_scene(sim, stride);
    if (sim.time_s() >= next_control_s - 1e-9) {
      next_control_s += control_period;
      const navigation::NavigatorStep step =
          navigator.update(sim.time_s(), scenario::observe_ari(*sim.ari()), scene);
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
    navigation::ScoredTick tick;
    tick.time_s = sim.time_s();
    tick.ari = sim.ari()->pose();
    tick.linear_mps = sim.ari()->drive().linear_mps();
    const navigation::PerceivedScene truth = learning::true_scene(sim, stride);
    tick.people = truth.people;
    tick.groups = truth.groups;
    tick.static_penetration_m = sim.static_penetration_m(*sim.ari());
    scorer.add(tick);
  }
  record.score = scorer.score();

  // Final placement against the person or group (approach and join episodes).
  const core::Pose2 ari = sim.ari()->pose();
  const navigation::PerceivedScene final_scene = learning::true_scene(sim, stride);
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
  return record;
}

// Throws core::Error naming the path when writing fails; the file then keeps what it held.
void write_csv(const std::string& path, const std::vector<EpisodeRecord>& records) {
  core::OutputFile file("--csv", path);
  std::ostream& out = file.stream();
  out << "type,episode,seed,controller,profile,success,outcome,time_to_goal_s,path_length_m,"
         "path_length_ratio,person_collisions,static_collisions,min_person_distance_m,"
         "personal_space_share,ospace_intrusions,final_position_error_m,"
         "final_heading_error_rad,gcff_includes_ari,mean_abs_jerk,solve_cpu_median_ms,solve_cpu_"
         "max_ms,"
         "solves,reason\n";
  for (const EpisodeRecord& r : records) {
    const double ratio = r.shortest_path_m > 0.0 ? r.score.path_length_m / r.shortest_path_m : 0.0;
    std::string reason = r.reason;
    std::replace(reason.begin(), reason.end(), '"', '\'');
    char line[1024];
    std::snprintf(line, sizeof(line),
                  "%s,%d,%llu,%s,%s,%d,%s,%.2f,%.3f,%.3f,%d,%d,%.3f,%.4f,%d,%.3f,%.3f,%d,%.3f,%.3f,"
                  "%.3f,%zu,\"%s\"\n",
                  r.type.c_str(), r.index, static_cast<unsigned long long>(r.seed),
                  r.controller.c_str(), r.profile.c_str(), r.success ? 1 : 0, r.outcome.c_str(),
                  r.time_to_goal_s, r.score.path_length_m, ratio, r.score.person_collisions,
                  r.score.static_collisions, r.score.min_person_distance_m,
                  r.score.personal_space_share, r.score.ospace_intrusions, r.final_position_error_m,
                  r.final_heading_error_rad, r.gcff_includes_ari, r.score.mean_abs_jerk,
                  1e3 * percentile(r.solve_times_s, 0.5), 1e3 * percentile(r.solve_times_s, 1.0),
                  r.solve_times_s.size(), reason.c_str());
    out << line;
  }
  file.commit();
}

double mean_of(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) {
    sum += v;
  }
  return values.empty() ? 0.0 : sum / values.size();
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
      std::vector<const EpisodeRecord*> rows;
      for (const EpisodeRecord& r : records) {
        if (r.type == learning::type_name(type) && r.controller == controller) {
          rows.push_back(&r);
        }
      }
      int successes = 0, person_hits = 0, static_hits = 0, intruding = 0, gcff_yes = 0,
          gcff_count = 0;
      std::vector<double> times, ratios, shares, minima, jerks, position_errors, heading_errors,
          solves;
      for (const EpisodeRecord* r : rows) {
        successes += r->success ? 1 : 0;
        person_hits += r->score.person_collisions;
        static_hits += r->score.static_collisions;
        intruding += r->score.ospace_intrusions > 0 ? 1 : 0;
        shares.push_back(r->score.personal_space_share);
        minima.push_back(r->score.min_person_distance_m);
        jerks.push_back(r->score.mean_abs_jerk);
        solves.insert(solves.end(), r->solve_times_s.begin(), r->solve_times_s.end());
        if (r->success) {
          times.push_back(r->time_to_goal_s);
          if (r->shortest_path_m > 0.0) {
            ratios.push_back(r->score.path_length_m / r->shortest_path_m);
          }
          if (r->final_position_error_m >= 0.0) {
            position_errors.push_back(r->final_position_error_m);
            heading_errors.push_back(core::rad_to_deg(r->final_heading_error_rad));
          }
        }
        if (r->gcff_includes_ari >= 0) {
          ++gcff_count;
          gcff_yes += r->gcff_includes_ari;
        }
      }
      if (controller == "social") {
        all_solves.insert(all_solves.end(), solves.begin(), solves.end());
        for (const EpisodeRecord* r : rows) {
          all_wall.insert(all_wall.end(), r->solve_wall_times_s.begin(),
                          r->solve_wall_times_s.end());
        }
      }
      const double n = static_cast<double>(std::max<size_t>(rows.size(), 1));
      char placement[64] = "-";
      if (!position_errors.empty()) {
        std::snprintf(placement, sizeof(placement), "%.2f m / %.1f deg", mean_of(position_errors),
                      mean_of(heading_errors));
      }
      char gcff[32] = "-";
      if (gcff_count > 0) {
        std::snprintf(gcff, sizeof(gcff), "%.0f %%", 100.0 * gcff_yes / gcff_count);
      }
      std::printf(
          "| %s | %s | %s | %zu | %.0f %% | %d / %d | %d | %.2f %% | %.2f / %.2f m | %.1f s | %.2f "
          "| %s | %s | %.2f m/s^3 | %.1f / %.1f ms |\n",
          learning::type_name(type), controller.c_str(), world::reaction_name(options.profile),
          rows.size(), 100.0 * successes / n, person_hits, static_hits, intruding,
          100.0 * mean_of(shares),
          minima.empty() ? 0.0 : *std::min_element(minima.begin(), minima.end()), mean_of(minima),
          mean_of(times), mean_of(ratios), placement, gcff, mean_of(jerks),
          1e3 * percentile(solves, 0.5), 1e3 * percentile(solves, 0.99));
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

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::map<std::string, navigation::NavigationConfig> configs;
  learning::EpisodeWorlds worlds;
  try {
    options = parse(argc, argv);
    for (const std::string& controller : options.controllers) {
      configs.emplace(controller, controller_config(options, controller));
    }
    worlds = learning::EpisodeWorlds::load(options.worlds);
  } catch (const core::Error& e) {
    std::cerr << "nav_benchmark: " << e.what() << "\n";
    return kUsageError;
  }
  std::vector<EpisodeRecord> records;
  const auto started = std::chrono::steady_clock::now();
  for (EpisodeType type : options.types) {
    for (int i = 0; i < options.episodes; ++i) {
      for (const std::string& controller : options.controllers) {
        try {
          records.push_back(run_episode(learning::make_episode(type, i, options.seed, worlds),
                                        configs.at(controller), controller, options.profile,
                                        options.trace));
        } catch (const core::Error& e) {
          std::cerr << "nav_benchmark: " << learning::type_name(type) << " episode " << i << ": "
                    << e.what() << "\n";
          return kUsageError;
        }
        const EpisodeRecord& r = records.back();
        std::fprintf(stderr, "%s %d %s: %s %s\n", r.type.c_str(), r.index, r.controller.c_str(),
                     r.outcome.c_str(), r.reason.c_str());
      }
    }
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!options.csv.empty()) {
    try {
      write_csv(options.csv, records);
    } catch (const core::Error& e) {
      std::cerr << "nav_benchmark: " << e.what() << "\n";
      return 1;
    }
  }
  print_summary(records, options);
  std::printf("%zu episodes in %.0f s of wall time\n", records.size(), wall_s);
  return 0;
}
