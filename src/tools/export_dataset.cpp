// export_dataset: labelled images of ARI's cameras from a scenario's episodes, as a COCO dataset.
//
//   export_dataset --scenario NAME|FILE --episodes N [--seed S] [--shard K/N]
//                  [--cameras head,torso] [--audio] --out DIR [--every SECONDS] [--motion-blur]
//                  [--overwrite | --resume]
//   export_dataset ...the same plan... --merge-shards N [--overwrite]
//
// The episodes are run_episodes' (episode i with seed S + i, S defaulting to the scenario's seed;
// --shard K/N takes the episodes with i % N == K - 1). At each frame due (each camera's rate, or
// every --every seconds of sim time) the chosen cameras render the people from ARI's pose, and
// each image is written as DIR/images/CAMERA/NAME_SEED_FRAME.png with its labels in
// DIR/annotations.json (DIR/annotations_shardK-of-N.json with --shard), which is written when every
// episode is done: until then the labels of the finished episodes are in annotations.json.active
// (core::ProgressJournal), from which --resume goes on. SIGINT or SIGTERM stops between two steps,
// drops the episode under way (its images deleted) and exits with 128 + the signal's number. Exit
// code 2 on bad input, 1 when rendering or writing fails (docs/cameras.md, "Labelled datasets").
// --audio also writes each episode's microphone-array audio with its labels (dataset::EpisodeAudio,
// docs/audio.md, "Audio data sets"). --merge-shards N runs nothing: it merges the files of shards
// 1/N..N/N in DIR into the DIR/annotations.json an unsharded run writes
// (dataset::merge_shard_files).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "ari_social_sim/batch/batch_plan.hpp"
#include "ari_social_sim/batch/progress_bar.hpp"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/core/progress_journal.hpp"
#include "ari_social_sim/core/stop_signal.hpp"
#include "ari_social_sim/dataset/coco_dataset.hpp"
#include "ari_social_sim/dataset/episode_audio.hpp"
#include "ari_social_sim/dataset/shard_merge.hpp"
#include "ari_social_sim/engine/episode.hpp"
#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/rendering/snapshot_cameras.hpp"

namespace {

using namespace ari_social_sim;
namespace fs = std::filesystem;

// A camera renders at most 100 frames per second of sim time (CameraSettings' rate_hz), hence
// 0.01 s; a day of sim time is longer than any scenario.
const core::NumberOption kEvery{"--every", core::between(0.01, 86400.0)};
// As many shards as --episodes allows episodes: a shard beyond the last episode writes an empty
// file, which merges as such.
constexpr core::IntegerOption kMergeShards{"--merge-shards", 1, 1000000};

// The cameras --cameras names: ARI's two pinholes, the ones labels can be made for.
struct CameraChoice {
  const char* option_name;
  const char* rig_name;
};
constexpr CameraChoice kCameraChoices[] = {{"head", "head_front_camera"},
                                           {"torso", "torso_front_camera"}};

// Fixed PNG settings: the same image always encodes to the same bytes, whatever OpenCV's default.
const std::vector<int> kPngParameters{cv::IMWRITE_PNG_COMPRESSION, 3, cv::IMWRITE_PNG_STRATEGY,
                                      cv::IMWRITE_PNG_STRATEGY_DEFAULT};

constexpr const char* kUsage =
    "usage: export_dataset --scenario NAME|FILE --episodes N [--seed S] [--shard K/N]\n"
    "                      [--cameras head,torso] [--audio] --out DIR [--every SECONDS]\n"
    "                      [--motion-blur] [--overwrite | --resume]\n"
    "       export_dataset ...the shards' options, without --shard... --merge-shards N\n"
    "                      [--overwrite]\n";

constexpr const char* kHelp = R"(
Runs a scenario's episodes as run_episodes does (episode i with seed S + i, S defaulting to the
scenario file's seed; --shard K/N runs the episodes with i % N == K - 1) and renders ARI's head
and/or torso camera with labels at each frame due: each camera's own rate, or every SECONDS of sim
time with --every. Writes DIR/images/CAMERA/NAME_SEED_FRAME.png and the labels as one COCO file,
DIR/annotations.json (DIR/annotations_shardK-of-N.json with --shard). NAME is one of the
package's scenarios or a scenario file; N in [1, 1000000]; seeds in [0, 2147483647]; SECONDS in
[0.01, 86400]. Output of these seeds already in DIR is replaced only with --overwrite.

--motion-blur smears people and the background as they move while the shutter is open
(docs/cameras.md, "Camera effects"). It needs frames at the cameras' own rate: frames sampled
--every more than 0.25 s apart have none.

--audio (with or without --cameras) writes each episode's audio as ARI's microphone array hears
it: DIR/audio/NAME_SEED.wav (six channels, 16 kHz, 16 bits), NAME_SEED.rttm (who speaks when),
NAME_SEED.ctm (every word's time) and NAME_SEED_directions.csv (each speaker's true direction
from the array every 64 ms).

Until every episode is done, the labels of the finished ones are kept in
DIR/annotations.json.active; DIR/annotations.json appears, complete, at the end. SIGINT (Ctrl-C)
or SIGTERM stops the export between two steps: the episode under way is dropped (its images
deleted), the finished ones are kept, and the same command with --resume finishes the export,
running only the missing episodes (refused unless the options and the scenario and configuration
files are those of the earlier run). The result is byte for byte that of an uninterrupted run,
after a SIGKILL or a crash too. A second Ctrl-C kills at once.

--merge-shards N runs no episode: with the options the shards were exported with, --shard left
out, it checks DIR/annotations_shardK-of-N.json for K = 1..N against them and merges them into
DIR/annotations.json, byte for byte the file one process would have written (an existing one is
replaced only with --overwrite), then removes the shard files. A missing shard, or one made with
other options, is refused naming the file and the field, and nothing is written. With --audio it
checks that every episode's audio files are in DIR/audio. N in [1, 1000000]; for N = 1 the one
file is DIR/annotations.json, which is checked and kept.

Exit status: 0 on success, 2 on bad input (checked before any episode runs), 1 when rendering or
writing fails, 130 after SIGINT and 143 after SIGTERM.
)";

struct Options {
  std::string scenario;
  batch::BatchPlan plan;
  batch::PlanOptionsGiven given;
  std::vector<std::string> cameras;  // rig names, in --cameras' order
  std::string out;
  std::optional<double> every_s;
  bool motion_blur{false};  // the cameras' motion blur (rendering::CameraEffects)
  bool audio{false};        // each episode's array audio with its labels (docs/audio.md)
  bool overwrite{false};
  bool resume{false};
  bool shard_given{false};               // --shard, even 1/1, which --merge-shards refuses
  std::optional<unsigned> merge_shards;  // --merge-shards N
};

// `head,torso` as rig names; each name once.
std::vector<std::string> parse_cameras(const std::string& list) {
  std::vector<std::string> cameras;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, comma - start);
    start = comma + 1;
    const CameraChoice* found = nullptr;
    for (const CameraChoice& choice : kCameraChoices) {
      found = name == choice.option_name ? &choice : found;
    }
    if (found == nullptr) {
      throw core::ConfigError(
          "--cameras: expected a comma-separated list of head and torso, got '" + name + "' in '" +
          list + "'");
    }
    if (std::find(cameras.begin(), cameras.end(), found->rig_name) != cameras.end()) {
      throw core::ConfigError("--cameras: expected each camera once, got '" + name +
                              "' twice in '" + list + "'");
    }
    cameras.emplace_back(found->rig_name);
  }
  return cameras;
}

Options parse_options(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--overwrite" || arg == "--resume" || arg == "--audio" || arg == "--motion-blur") {
      (arg == "--overwrite" ? options.overwrite
       : arg == "--resume"  ? options.resume
       : arg == "--audio"   ? options.audio
                            : options.motion_blur) = true;
      continue;
    }
    core::check_known_option(
        arg, {"--scenario", "--episodes", "--seed", "--shard", "--cameras", "--audio", "--out",
              "--every", "--motion-blur", "--overwrite", "--resume", "--merge-shards"});
    const std::string value = core::option_value(argc, argv, i);
    options.shard_given = options.shard_given || arg == "--shard";
    if (arg == "--scenario") {
      options.scenario = value;
    } else if (arg == "--cameras") {
      options.cameras = parse_cameras(value);
    } else if (arg == "--out") {
      options.out = value;
    } else if (arg == "--every") {
      options.every_s = kEvery.parse(value);
    } else if (arg == "--merge-shards") {
      options.merge_shards = static_cast<unsigned>(kMergeShards.parse(value));
    } else {
      batch::read_plan_option(arg, value, options.plan, options.given);
    }
  }
  if (options.scenario.empty() || !options.given.episodes ||
      (options.cameras.empty() && !options.audio) || options.out.empty()) {
    throw core::ConfigError(
        "expected --scenario, --episodes, --cameras or --audio (or both), and --out");
  }
  if (options.overwrite && options.resume) {
    throw core::ConfigError("--overwrite and --resume: expected one of them, got both");
  }
  if (options.merge_shards && options.shard_given) {
    throw core::ConfigError(
        "--merge-shards and --shard: expected one of them (the merge takes the options of the "
        "whole plan, the shards' without --shard), got both");
  }
  if (options.merge_shards && options.resume) {
    throw core::ConfigError(
        "--merge-shards and --resume: expected one of them (a merge is not resumed: it writes "
        "nothing until it is done), got both");
  }
  return options;
}

// Where one run (one shard) writes.
struct OutputPaths {
  std::string dir;
  std::string scenario;
  std::string annotations;

  // The labels of the finished episodes until `annotations` is written.
  std::string progress() const { return annotations + ".active"; }
  std::string image_dir(const std::string& camera) const { return "images/" + camera; }
  // Relative to dir, as the COCO file names it.
  std::string image(const std::string& camera, uint64_t seed, uint64_t frame) const {
    return image_dir(camera) + "/" + scenario + "_" + std::to_string(seed) + "_" +
           core::format_text("%06llu", static_cast<unsigned long long>(frame)) + ".png";
  }
};

// The pictures an earlier run of these seeds left in DIR/images/CAMERA (finished or .part).
std::vector<fs::path> earlier_images(const OutputPaths& paths, const Options& options) {
  std::set<std::string> seeds;
  for (uint64_t episode : options.plan.episode_indices()) {
    seeds.insert(std::to_string(options.plan.seed_of(episode)));
  }
  // NAME_SEED_ and six digits exactly: a prefix alone would take scenario NAME_SEED's pictures too.
  const std::string name =
      std::regex_replace(paths.scenario, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
  const std::regex pattern(name + R"(_(\d+)_\d{6}\.png(\.part)?)");
  std::vector<fs::path> found;
  for (const std::string& camera : options.cameras) {
    const fs::path dir = fs::path(paths.dir) / paths.image_dir(camera);
    if (!fs::is_directory(dir)) {
      continue;
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
      std::smatch match;
      const std::string file = entry.path().filename().string();
      if (std::regex_match(file, match, pattern) && seeds.count(match[1].str()) > 0) {
        found.push_back(entry.path());
      }
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

// A checked run, ready to go.
struct Export {
  Options options;
  scenario::Scenario scenario;
  std::string scenario_file;
  engine::EpisodeConfig config;
  OutputPaths paths;
  rendering::CameraRigConfig rig;
  std::optional<core::ProgressJournal> journal;  // unset when the export is complete already
  // With --audio: every episode's voices synthesised once per (voice, text) for the whole export.
  std::shared_ptr<audio::SpeechSynthesizer> synthesizer =
      std::make_shared<audio::SpeechSynthesizer>();
};

// What the COCO file's "info" says of the export, from the cameras the rig will render.
dataset::DatasetSettings dataset_settings(const Export& run) {
  dataset::DatasetSettings settings;
  settings.scenario = run.scenario.name;
  settings.plan = run.options.plan;
  settings.every_s = run.options.every_s;
  settings.motion_blur = run.options.motion_blur;
  for (const rendering::CameraSpec& spec : run.rig.cameras) {
    if (spec.enabled) {
      settings.cameras.push_back(spec.name);
      settings.frame_rate_hz.push_back(spec.rate_hz);
    }
  }
  return settings;
}

// The first line of the progress file: the COCO "info" and the digests of the scenario and
// configuration files, so that --resume adds only episodes made the same way.
std::string progress_settings(const Export& run) {
  return "export_dataset " + dataset::CocoDataset(dataset_settings(run)).info_json() +
         (run.options.audio ? " audio" : "") + " scenario_digest " +
         batch::digest_files({run.scenario_file, run.scenario.scene.world_path}) +
         " config_digest " + batch::digest_files(batch::files_under(ARI_CONFIG_DIR, ".yaml"));
}

// --resume of an export whose annotations are written: nothing to run if they were made with these
// options. Throws core::ConfigError otherwise.
void check_complete_export(const Export& run) {
  const std::string info =
      "\n\"info\": " + dataset::CocoDataset(dataset_settings(run)).info_json() + ",\n";
  std::ifstream in(run.paths.annotations, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (text.str().find(info) == std::string::npos) {
    throw core::ConfigError("--resume: " + run.paths.annotations +
                            " is complete and was made with other options: pass the same "
                            "options, --overwrite to replace it, or another --out");
  }
}

// The earlier output of these seeds: resumed, replaced, or a reason to stop. Sets run.journal when
// resuming from it.
void deal_with_earlier_output(Export& run) {
  const Options& options = run.options;
  const OutputPaths& paths = run.paths;
  const std::vector<fs::path> images = earlier_images(paths, options);
  const bool annotations_there = fs::exists(paths.annotations);
  const bool progress_there = fs::exists(paths.progress());
  if (options.resume && progress_there) {
    run.journal =
        core::ProgressJournal::resume("--resume", paths.progress(), progress_settings(run));
    if (run.journal->was_cut_short()) {
      std::cerr << "--resume: " << paths.progress()
                << " ended in an episode cut short (a run killed while writing it): removed it\n";
    }
    for (const fs::path& image : images) {
      if (image.extension() == ".part") {
        fs::remove(image);  // left by a killed run; its episode runs again
      }
    }
    return;
  }
  if (options.resume && annotations_there) {
    check_complete_export(run);
    return;
  }
  const bool found = annotations_there || progress_there || !images.empty();
  if (found && !options.overwrite && !options.resume) {
    std::string what = annotations_there ? paths.annotations : "";
    what += progress_there ? (what.empty() ? "" : ", ") + paths.progress() : "";
    what += images.empty() ? ""
                           : (what.empty() ? "" : ", ") + std::to_string(images.size()) +
                                 " images of its seeds";
    throw core::ConfigError("--out: " + options.out + " holds this run's output already (" + what +
                            "): pass --overwrite to replace it, or --resume to finish it");
  }
  // --overwrite (or --resume with nothing to resume): the earlier annotations and the images of
  // these seeds go first, so that neither a finished run nor a failed one leaves images and
  // annotations that do not match.
  for (const fs::path& image : images) {
    fs::remove(image);
  }
  fs::remove(paths.annotations);
  fs::remove(paths.progress());
  if (options.resume) {
    std::cerr << "--resume: " << paths.progress() << " not found: starting the export\n";
  } else if (found) {
    std::cerr << "--overwrite: removed " << (annotations_there ? paths.annotations + " and " : "")
              << images.size() << " images of the earlier run\n";
  }
}

// Checks everything the user gave and deals with the earlier output before the first episode, so
// that a bad option or path costs no run. Throws core::ConfigError (or std::filesystem_error).
Export prepare(int argc, char** argv) {
  Export run;
  Options& options = run.options;
  options = parse_options(argc, argv);
  run.scenario_file = scenario::scenario_file_of(options.scenario, ARI_SCENARIO_DIR);
  core::check_input_file("--scenario", run.scenario_file);
  run.scenario = scenario::load_scenario_file(run.scenario_file);
  if (!run.scenario.scene.ari) {
    throw core::ConfigError("--scenario: " + run.scenario_file +
                            ": expected a scenario with ARI (the cameras are ARI's), got none");
  }
  if (!options.given.seed) {
    options.plan.first_seed = run.scenario.scene.seed;
  }
  options.plan.validate("");

  // Only the chosen cameras render; --every sets their rate, so that CameraRig::due keeps time.
  for (rendering::CameraSpec& spec : run.rig.cameras) {
    spec.enabled = std::find(options.cameras.begin(), options.cameras.end(), spec.name) !=
                   options.cameras.end();
    if (spec.enabled && options.every_s) {
      spec.rate_hz = 1.0 / *options.every_s;
    }
  }
  run.rig.effects.motion_blur = options.motion_blur;
  run.rig.validate();

  if (fs::exists(options.out) && !fs::is_directory(options.out)) {
    throw core::ConfigError("--out: " + options.out + ": expected a directory, got a file");
  }
  OutputPaths& paths = run.paths;
  paths.dir = options.out;
  paths.scenario = run.scenario.name;
  paths.annotations = options.out + "/" + dataset::annotations_file_name(options.plan);
  if (options.merge_shards) {
    return run;  // no episode runs: merge_shards checks DIR's files itself
  }
  run.config = engine::EpisodeConfig::load(ARI_CONFIG_DIR);
  const bool complete_already =
      options.resume && !fs::exists(paths.progress()) && fs::exists(paths.annotations);
  deal_with_earlier_output(run);
  if (complete_already) {
    return run;
  }
  core::prepare_output_directory("--out", options.out);
  for (const std::string& camera : options.cameras) {
    core::prepare_output_directory("--out", options.out + "/" + paths.image_dir(camera));
  }
  if (options.audio) {
    core::prepare_output_directory("--out", options.out + "/audio");
  }
  core::check_output_file("--out", paths.annotations, /*replace=*/true);
  if (!run.journal) {
    run.journal = core::ProgressJournal::start("--out", paths.progress(), progress_settings(run));
  }
  return run;
}

// Encodes the RGB image as PNG and writes it whole or not at all (core::OutputFile).
void write_png(const std::string& path, const cv::Mat& rgb) {
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  std::vector<uint8_t> bytes;
  try {
    if (!cv::imencode(".png", bgr, bytes, kPngParameters)) {
      throw core::Error(path + ": cannot encode the image as PNG");
    }
  } catch (const cv::Exception& e) {
    throw core::Error(path + ": cannot encode the image as PNG: " + e.what());
  }
  core::OutputFile file("--out", path);
  file.stream().write(reinterpret_cast<const char*>(bytes.data()),
                      static_cast<std::streamsize>(bytes.size()));
  file.commit();
}

// An episode whose scene cannot be built from its seed: bad input (exit code 2), unlike a
// core::ConfigError from a file that cannot be written (core::OutputFile), which is a failure (1).
class BadEpisode : public core::Error {
 public:
  using core::Error::Error;
};

std::unique_ptr<engine::Episode> start_episode(const Export& run, uint64_t index, uint64_t seed) {
  try {
    return std::make_unique<engine::Episode>(run.scenario, seed, run.config);
  } catch (const core::Error& e) {
    const bool bad_input = dynamic_cast<const core::ConfigError*>(&e) != nullptr ||
                           dynamic_cast<const core::RequestError*>(&e) != nullptr;
    if (bad_input) {
      throw BadEpisode("episode " + std::to_string(index) + " (seed " + std::to_string(seed) +
                       "): " + e.what());
    }
    throw;
  }
}

// Renders one episode's frames due, writing each image as it is made (its path added to
// `written`), until the episode ends (true) or a stop signal comes (false). Throws BadEpisode, or
// core::Error when rendering or writing fails.
bool export_episode(const Export& run, rendering::CameraRig& rig, dataset::CocoDataset& dataset,
                    uint64_t index, std::vector<std::string>& written) {
  const uint64_t seed = run.options.plan.seed_of(index);
  const std::unique_ptr<engine::Episode> episode = start_episode(run, index, seed);
  // The looks vary from episode to episode and come back with the seed.
  rendering::SnapshotCameras cameras(rig, seed);
  std::vector<uint64_t> frames(rig.cameras().size(), 0);  // per camera, for the file names
  uint64_t ordinal = 0;                                   // images of the episode, for the ids
  std::unique_ptr<dataset::EpisodeAudio> audio;
  if (run.options.audio) {
    const std::string stem =
        dataset::EpisodeAudio::stem_of(run.paths.dir, run.paths.scenario, seed);
    const std::vector<std::string> files = dataset::EpisodeAudio::files_of(stem);
    written.insert(written.end(), files.begin(), files.end());  // dropped with the episode
    audio = std::make_unique<dataset::EpisodeAudio>(stem, run.scenario.scene, seed,
                                                    audio::RoomSettings{}, run.synthesizer);
  }
  // The initial state first (frame 0 at time 0), then after every step.
  while (true) {
    if (audio) {
      audio->observe(episode->snapshot());
    }
    for (rendering::LabelledImage& image : cameras.render_due(episode->snapshot())) {
      const std::string& camera = rig.cameras()[image.camera].name;
      dataset::DatasetImage entry;
      entry.id = dataset::DatasetIds::image(index, ordinal++);
      entry.file_name = run.paths.image(camera, seed, frames[image.camera]++);
      entry.width = image.colour.cols;
      entry.height = image.colour.rows;
      entry.camera = camera;
      entry.episode_seed = seed;
      entry.time_s = image.time_s;
      written.push_back(run.paths.dir + "/" + entry.file_name);
      write_png(written.back(), image.colour);
      dataset.add(entry, image.labels);
    }
    if (episode->finished()) {
      if (audio) {
        audio->finish();
      }
      return true;
    }
    if (core::g_stop_signal != 0) {
      return false;
    }
    episode->step();
  }
}

// After a stop signal: what is kept, and how to go on. Returns the exit code.
int report_stop(const Export& run, size_t done, size_t planned, size_t images,
                std::optional<uint64_t> dropped_seed, size_t dropped_images) {
  const int signal = core::g_stop_signal;
  std::cerr << "export_dataset: interrupted by " << core::stop_signal_name(signal) << " after "
            << done << " of " << planned << " episodes: their " << images << " images are in "
            << run.paths.dir << "/images, their labels in " << run.paths.progress() << " ("
            << run.paths.annotations << " is written once every episode is done)";
  if (dropped_seed) {
    std::cerr << "; the episode under way (seed " << *dropped_seed << ") was dropped, its "
              << dropped_images << " images deleted";
  }
  std::cerr << "; rerun the same command with --resume to finish\n";
  return core::stopped_exit_code(signal);
}

// Runs the episodes of the plan that the progress file does not hold yet, each to its images and
// its entry in the progress file, then writes the annotations, until done or stopped by a signal;
// returns the exit code. Throws BadEpisode, or core::Error when rendering or writing fails.
int export_episodes(Export& run) {
  const std::vector<uint64_t> planned = run.options.plan.episode_indices();
  if (!run.journal) {
    std::printf("%s: nothing to do, all %zu episodes are in %s\n", run.scenario.name.c_str(),
                planned.size(), run.paths.annotations.c_str());
    return 0;
  }
  // Each episode restarts the sensors' noise from its seed (SnapshotCameras): shards give the
  // bytes of one process.
  rendering::CameraRig rig(run.rig, run.options.plan.first_seed);
  rig.set_world(run.scenario.scene.world, rendering::SceneStyle{});
  dataset::CocoDataset dataset(dataset_settings(run));
  std::set<std::string> done;
  for (const core::ProgressJournal::Entry& entry : run.journal->kept()) {
    dataset.add_entries(entry.lines, run.journal->path());
    done.insert(entry.key);
  }
  if (!done.empty()) {
    std::cerr << "--resume: " << done.size() << " of " << planned.size() << " episodes are in "
              << run.journal->path() << "; running the other " << planned.size() - done.size()
              << "\n";
  }
  const bool terminal = isatty(STDERR_FILENO) != 0;
  const auto start = std::chrono::steady_clock::now();
  for (uint64_t index : planned) {
    if (done.count(std::to_string(index)) > 0) {
      continue;
    }
    if (core::g_stop_signal != 0) {
      return report_stop(run, done.size(), planned.size(), dataset.image_count(), std::nullopt, 0);
    }
    const dataset::CocoDataset::Mark mark = dataset.mark();
    std::vector<std::string> written;
    if (!export_episode(run, rig, dataset, index, written)) {
      for (const std::string& path : written) {
        fs::remove(path);
      }
      return report_stop(run, done.size(), planned.size(), mark.images,
                         run.options.plan.seed_of(index), written.size());
    }
    run.journal->add(std::to_string(index), dataset.entries_since(mark));
    done.insert(std::to_string(index));
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << (terminal ? "\r" : "")
              << batch::progress_line(done.size(), planned.size(), elapsed_s)
              << (terminal ? "" : "\n") << std::flush;
  }
  std::cerr << (terminal ? "\n" : "");
  core::OutputFile annotations("--out", run.paths.annotations);
  annotations.stream() << dataset.to_json();
  annotations.commit();
  run.journal->remove();
  std::printf("%s: %zu episodes, %zu images, %zu person and %zu face annotations in %s\n",
              run.scenario.name.c_str(), planned.size(), dataset.image_count(),
              dataset.count(dataset::CocoDataset::kPersonCategory),
              dataset.count(dataset::CocoDataset::kFaceCategory), run.paths.annotations.c_str());
  return 0;
}

// --audio with --merge-shards: the shards' COCO files do not say whether they were exported with
// --audio, so every episode's audio files must be in DIR/audio. Throws core::ConfigError naming
// the first one missing.
void check_audio_files(const Export& run) {
  const batch::BatchPlan& plan = run.options.plan;
  for (uint64_t episode : plan.episode_indices()) {
    const std::string stem =
        dataset::EpisodeAudio::stem_of(run.paths.dir, run.paths.scenario, plan.seed_of(episode));
    for (const std::string& file : dataset::EpisodeAudio::files_of(stem)) {
      if (!fs::is_regular_file(file)) {
        throw core::ConfigError("--audio: " + file + ": expected the audio of episode " +
                                std::to_string(episode) +
                                ", which its shard writes with --audio, got no file");
      }
    }
  }
}

// --merge-shards N: the shards' files, every check done before anything is written. Throws
// core::ConfigError (or std::filesystem_error).
dataset::CocoDataset checked_merge(const Export& run) {
  const unsigned shards = *run.options.merge_shards;
  core::check_input_directory("--out", run.paths.dir);
  if (shards > 1) {
    core::check_output_file("--out", run.paths.annotations, run.options.overwrite);
  }
  dataset::CocoDataset merged =
      dataset::merge_shard_files(run.paths.dir, dataset_settings(run), shards);
  if (run.options.audio) {
    check_audio_files(run);
  }
  return merged;
}

// Writes the merged annotations whole (core::OutputFile), and only then removes the shards' files:
// until the merged file is complete, they are the only copy of the labels. Throws core::Error (or
// std::filesystem_error).
void write_merged(const Export& run, const dataset::CocoDataset& merged) {
  core::OutputFile annotations("--out", run.paths.annotations);
  annotations.stream() << merged.to_json();
  annotations.commit();
  batch::BatchPlan shard = run.options.plan;
  shard.shard_count = *run.options.merge_shards;
  for (unsigned k = 1; k <= shard.shard_count; ++k) {
    shard.shard_index = k;
    fs::remove(run.paths.dir + "/" + dataset::annotations_file_name(shard));
  }
}

// --merge-shards N: the shards' COCO files, checked against the options, merged into the file an
// unsharded run writes, then removed. Returns the exit code: 2 when a file or option is refused
// (nothing written), 1 when writing fails.
int merge_shards(const Export& run) {
  const unsigned shards = *run.options.merge_shards;
  std::optional<dataset::CocoDataset> merged;
  try {
    merged = checked_merge(run);
  } catch (const core::Error& e) {
    std::cerr << "export_dataset: " << e.what() << "\n";
    return 2;
  } catch (const fs::filesystem_error& e) {
    std::cerr << "export_dataset: --out: " << e.what() << "\n";
    return 2;
  }
  if (shards == 1) {
    // Shard 1/1 writes annotations.json itself: checked, it is the merged file already.
    std::printf(
        "export_dataset: 1 shard: %s is the whole plan's file already (%zu images, %zu "
        "annotations), nothing to merge\n",
        run.paths.annotations.c_str(), merged->image_count(), merged->annotation_count());
    return 0;
  }
  try {
    write_merged(run, *merged);
  } catch (const core::Error& e) {
    std::cerr << "export_dataset: " << e.what() << "\n";
    return 1;
  } catch (const fs::filesystem_error& e) {
    std::cerr << "export_dataset: " << e.what() << "\n";
    return 1;
  }
  std::printf("export_dataset: merged %u shards: %zu images, %zu annotations into %s\n", shards,
              merged->image_count(), merged->annotation_count(), run.paths.annotations.c_str());
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
    std::cerr << "export_dataset: " << e.what() << "\n" << kUsage;
    return 2;
  } catch (const fs::filesystem_error& e) {
    std::cerr << "export_dataset: --out: " << e.what() << "\n";
    return 2;
  }
  if (run.options.merge_shards) {
    return merge_shards(run);
  }
  core::install_stop_handler();
  try {
    return export_episodes(run);
  } catch (const BadEpisode& e) {
    std::cerr << "\nexport_dataset: " << e.what() << "\n";
    return 2;
  } catch (const core::Error& e) {
    std::cerr << "\nexport_dataset: " << e.what() << "\n";
    return 1;
  } catch (const fs::filesystem_error& e) {
    std::cerr << "\nexport_dataset: " << e.what() << "\n";
    return 1;
  }
}
