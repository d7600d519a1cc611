// export_group_streams: what ARI perceives of seeded random group scenes, as the CSV files of an
// F-formation data set, for detect_groups (docs/perception_gcff.md, "GCFF on perceived streams").
//
//   export_group_streams --scenes N [--seed S] [--seconds T] [--every SECONDS]
//                        [--errors default|off] [--mix recorded|uniform] [--arrangements LIST]
//                        --out DIR [--overwrite]
//
// Scene i is scenario::make_random_group_scene with seed S + i in worlds/room_12x12.yaml, run for
// T seconds of sim time by the batch engine (scenario::Episode: the world, perception with
// config/perception.yaml's error models, social navigation driving ARI along its route). Every
// SECONDS of sim time the perception frame is sampled (scenario::GroupStreams) into
// DIR/features.csv, DIR/groundtruth.csv and DIR/frames.csv, written once every scene is done:
// SIGINT or SIGTERM stops between two world steps, writes nothing and exits with 128 + the
// signal's number. Exit code 2 on bad input, 1 when writing fails.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/batch/group_streams.hpp"
#include "ari_social_sim/batch/progress_bar.hpp"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/core/sim_timer.hpp"
#include "ari_social_sim/core/stop_signal.hpp"
#include "ari_social_sim/engine/episode.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/scenario/random_group_scene.hpp"

namespace {

using namespace ari_social_sim;
namespace fs = std::filesystem;

// Seeds are scene seeds (scenario::BatchPlan's range): the last, S + N - 1, too.
constexpr core::IntegerOption kScenes{"--scenes", 1, 100000};
constexpr core::IntegerOption kSeed{"--seed", 0, 2147483647};
// The world steps 0.05 s, hence the shortest sampling period; an hour of sim time per scene is
// far more than a scene's people do anything new in.
const core::NumberOption kSeconds{"--seconds", core::between(1.0, 3600.0)};
const core::NumberOption kEvery{"--every", core::between(0.05, 3600.0)};

constexpr const char* kWorld = ARI_WORLD_DIR "/room_12x12.yaml";
constexpr const char* kFiles[] = {"features.csv", "groundtruth.csv", "frames.csv"};

constexpr const char* kUsage =
    "usage: export_group_streams --scenes N [--seed S] [--seconds T] [--every SECONDS]\n"
    "                            [--errors default|off] [--mix recorded|uniform]\n"
    "                            [--arrangements LIST] --out DIR [--overwrite]\n";

constexpr const char* kHelp = R"(
Runs N seeded random group scenes (scene i with seed S + i, S 1 by default) in the batch engine
for T seconds of sim time each (60 by default): 3 to 5 groups in F-formations, 0 to 2 people
alone, standing or walking, and ARI driving from group to group, in worlds/room_12x12.yaml.
The groups' arrangements and sizes are drawn from a mix: `recorded` (the default) as recorded
gatherings have them, pairs and triads in each arrangement and circles of 4 to 6 more rarely;
`uniform` each arrangement equally often, a circle of 3 or 4, a vis-a-vis or L-shape of 2 to 4,
a side-by-side row of 2 or 3 (the mix before issue 31). Only the arrangements LIST names are
drawn (circle,vis-a-vis,l-shape,side-by-side: all four by default).
Every SECONDS of sim time (0.5 by default) it writes what ARI's perception reports, with
config/perception.yaml's error models (--errors default) or none (--errors off):

  DIR/features.csv     frame,person_id,x,y,theta: each person tracked with a body, at it (map
                       frame, metres, rad)
  DIR/groundtruth.csv  frame,group,person_id: the world's groups, by perceived person id;
                       members not perceived that frame are left out, and so are groups with
                       fewer than two members left
  DIR/frames.csv       frame: every frame written

detect_groups reads them (--features, --evaluate, --frames). N in [1, 100000], S in
[0, 2147483647] (S + N - 1 too), T in [1, 3600], SECONDS in [0.05, T]. Existing files are
replaced only with --overwrite; the same options give the same bytes.

The three files are written once every scene is done, each whole. SIGINT (Ctrl-C) or SIGTERM
stops the export between two world steps and writes nothing. A second Ctrl-C kills at once.

Exit status: 0 on success, 2 on bad input (checked before any scene runs), 1 when writing fails,
130 after SIGINT and 143 after SIGTERM.
)";

std::vector<model::Arrangement> all_arrangements() {
  std::vector<model::Arrangement> all;
  for (const auto& arrangement : model::kArrangements) {
    all.push_back(arrangement.value);
  }
  return all;
}

struct Options {
  uint64_t scenes{0};
  uint64_t first_seed{1};
  double seconds{60.0};
  double every_s{0.5};
  bool errors{true};
  bool recorded_mix{true};
  std::vector<model::Arrangement> arrangements{all_arrangements()};
  std::string out;
  bool overwrite{false};
};

// `circle,l-shape` as arrangements, each once.
std::vector<model::Arrangement> parse_arrangements(const std::string& list) {
  std::vector<model::Arrangement> arrangements;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, comma - start);
    start = comma + 1;
    std::optional<model::Arrangement> arrangement;
    for (const auto& choice : model::kArrangements) {
      arrangement = name == choice.name ? choice.value : arrangement;
    }
    if (!arrangement) {
      throw core::ConfigError("--arrangements: expected a comma-separated list of " +
                              core::choice_names(model::kArrangements) + ", got '" + name +
                              "' in '" + list + "'");
    }
    if (std::find(arrangements.begin(), arrangements.end(), *arrangement) != arrangements.end()) {
      throw core::ConfigError("--arrangements: expected each arrangement once, got '" + name +
                              "' twice in '" + list + "'");
    }
    arrangements.push_back(*arrangement);
  }
  return arrangements;
}

Options parse_options(int argc, char** argv) {
  Options options;
  bool scenes_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--overwrite") {
      options.overwrite = true;
      continue;
    }
    core::check_known_option(arg, {"--scenes", "--seed", "--seconds", "--every", "--errors",
                                   "--mix", "--arrangements", "--out", "--overwrite"});
    const std::string value = core::option_value(argc, argv, i);
    if (arg == "--scenes") {
      options.scenes = static_cast<uint64_t>(kScenes.parse(value));
      scenes_given = true;
    } else if (arg == "--seed") {
      options.first_seed = static_cast<uint64_t>(kSeed.parse(value));
    } else if (arg == "--seconds") {
      options.seconds = kSeconds.parse(value);
    } else if (arg == "--every") {
      options.every_s = kEvery.parse(value);
    } else if (arg == "--errors") {
      if (value != "default" && value != "off") {
        throw core::ConfigError("--errors: expected default or off, got '" + value + "'");
      }
      options.errors = value == "default";
    } else if (arg == "--mix") {
      if (value != "recorded" && value != "uniform") {
        throw core::ConfigError("--mix: expected recorded or uniform, got '" + value + "'");
      }
      options.recorded_mix = value == "recorded";
    } else if (arg == "--arrangements") {
      options.arrangements = parse_arrangements(value);
    } else {
      options.out = value;  // --out
    }
  }
  if (!scenes_given || options.out.empty()) {
    throw core::ConfigError("expected --scenes and --out");
  }
  const uint64_t last_seed = options.first_seed + options.scenes - 1;
  if (last_seed > static_cast<uint64_t>(kSeed.max)) {
    throw core::ConfigError("--seed: expected the scenes' seeds in " + kSeed.range() +
                            ", got seeds " + std::to_string(options.first_seed) + ".." +
                            std::to_string(last_seed));
  }
  if (options.every_s > options.seconds) {
    throw core::ConfigError("--every: expected at most --seconds (" +
                            std::to_string(options.seconds) + "), got " +
                            std::to_string(options.every_s));
  }
  return options;
}

// A checked run, ready to go.
struct Export {
  Options options;
  engine::EpisodeConfig config;
  scenario::RandomGroupSceneSpec scene;
};

// Checks everything the user gave and the output files before the first scene, so that a bad
// option or path costs no run. Throws core::ConfigError.
Export prepare(int argc, char** argv) {
  Export run;
  Options& options = run.options;
  options = parse_options(argc, argv);
  run.config = engine::EpisodeConfig::load(ARI_CONFIG_DIR);
  run.config.perception.errors_enabled = options.errors;
  run.scene.world = model::load_world_file(kWorld);
  run.scene.world_path = kWorld;
  run.scene.mix = scenario::kinds_of(
      options.recorded_mix ? scenario::recorded_group_mix() : scenario::uniform_group_mix(),
      options.arrangements);
  run.scene.duration_s = options.seconds;
  run.scene.validate();

  if (fs::exists(options.out) && !fs::is_directory(options.out)) {
    throw core::ConfigError("--out: " + options.out + ": expected a directory, got a file");
  }
  core::prepare_output_directory("--out", options.out);
  for (const char* file : kFiles) {
    core::check_output_file("--out", options.out + "/" + file, options.overwrite);
  }
  return run;
}

// A scene that cannot be built from its seed: bad input (exit code 2), unlike a core::ConfigError
// from a file that cannot be written (core::OutputFile), which is a failure (1).
class BadScene : public core::Error {
 public:
  using core::Error::Error;
};

// The result of `build`, a core::ConfigError from it (a scene its seed cannot build) becoming
// BadScene.
template <class Build>
auto building_scene(uint64_t index, uint64_t seed, Build build) {
  try {
    return build();
  } catch (const core::ConfigError& e) {
    throw BadScene("scene " + std::to_string(index) + " (seed " + std::to_string(seed) +
                   "): " + e.what());
  }
}

void write_file(const std::string& path, const std::string& text) {
  core::OutputFile file("--out", path);
  file.stream() << text;
  file.commit();
}

// After a stop signal: nothing was written. Returns the exit code.
int report_stop(const Options& options, uint64_t done) {
  const int signal = core::g_stop_signal;
  std::cerr << "export_group_streams: interrupted by " << core::stop_signal_name(signal)
            << " after " << done << " of " << options.scenes << " scenes: nothing written in "
            << options.out << " (its three files are written once every scene is done); rerun "
            << "to make them\n";
  return core::stopped_exit_code(signal);
}

// Runs every scene, sampling its perception frames, then writes the three files: 0, or the exit
// code of report_stop when a stop signal came first. Throws BadScene when a scene cannot be
// built, core::Error when writing fails.
int export_scenes(const Export& run) {
  const Options& options = run.options;
  batch::GroupStreams streams;
  // How much ARI moved among the groups, for the summary.
  double path_m = 0.0;
  int goals = 0;
  int failed_goals = 0;
  const bool terminal = isatty(STDERR_FILENO) != 0;
  const auto start = std::chrono::steady_clock::now();
  for (uint64_t i = 0; i < options.scenes; ++i) {
    const uint64_t seed = options.first_seed + i;
    const scenario::Scenario scene =
        building_scene(i, seed, [&] { return scenario::make_random_group_scene(run.scene, seed); });
    const std::unique_ptr<engine::Episode> episode = building_scene(
        i, seed, [&] { return std::make_unique<engine::Episode>(scene, seed, run.config); });
    core::SimTimer sampler(1.0 / options.every_s);
    // A sample falls due on a world step; it takes the first frame perception reports from then
    // on (at the default rates, that step's own).
    bool sample_due = false;
    while (!episode->finished() && core::g_stop_signal == 0) {
      episode->step();
      sample_due = sample_due || sampler.due(episode->snapshot().time_s);
      if (sample_due && episode->perception_frame() != nullptr) {
        streams.add(episode->snapshot(), *episode->perception_frame());
        sample_due = false;
      }
    }
    // A signal on the scene's last step stops nothing: the scene is done.
    if (!episode->finished()) {
      std::cerr << (terminal ? "\n" : "");  // after the progress line
      return report_stop(options, i);
    }
    path_m += episode->metrics().ari_path_length_m;
    goals += episode->metrics().navigation_goals;
    failed_goals += episode->metrics().navigation_failures;
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << (terminal ? "\r" : "") << batch::progress_line(i + 1, options.scenes, elapsed_s)
              << (terminal ? "" : "\n") << std::flush;
  }
  std::cerr << (terminal ? "\n" : "");
  write_file(options.out + "/features.csv", streams.features_csv());
  write_file(options.out + "/groundtruth.csv", streams.groundtruth_csv());
  write_file(options.out + "/frames.csv", streams.frames_csv());
  const batch::GroupStreamCounts& counts = streams.counts();
  std::printf(
      "export_group_streams: %llu scenes, %zu frames, %zu perceived people, %zu true groups of "
      "%zu (two or more members perceived), in %s\n",
      static_cast<unsigned long long>(options.scenes), counts.frames, counts.feature_rows,
      counts.truth_groups, counts.world_groups, options.out.c_str());
  std::printf("ARI: %.1f m driven per scene, %d navigation goals, %d of them failed\n",
              path_m / static_cast<double>(options.scenes), goals, failed_goals);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--help") {
      std::cout << kUsage << kHelp;
      return 0;
    }
  }
  Export run;
  try {
    run = prepare(argc, argv);
  } catch (const core::Error& e) {
    std::cerr << "export_group_streams: " << e.what() << "\n" << kUsage;
    return 2;
  } catch (const fs::filesystem_error& e) {
    std::cerr << "export_group_streams: --out: " << e.what() << "\n";
    return 2;
  }
  core::install_stop_handler();
  try {
    return export_scenes(run);
  } catch (const BadScene& e) {
    std::cerr << "\nexport_group_streams: " << e.what() << "\n";
    return 2;
  } catch (const core::Error& e) {
    std::cerr << "\nexport_group_streams: " << e.what() << "\n";
    return 1;
  }
}
