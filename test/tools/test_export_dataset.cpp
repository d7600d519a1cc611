// Runs the export_dataset program as a user would: bad input refused before any work, and
// join_group (the shortest scenario) exported, checked as a COCO file, exported again byte for
// byte, and in three shards that together hold the same images and merge (--merge-shards) into
// the same annotations.json; an export interrupted with SIGINT and with SIGKILL, then resumed to
// the bytes of an uninterrupted one.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../common/file_size_limit.hpp"
#include "program_run.hpp"

namespace ari_social_sim::tools::test {
namespace {

namespace fs = std::filesystem;

ProgramRun run(const std::string& arguments) {
  return run_program(ARI_EXPORT_DATASET_BIN, arguments);
}

// Two short episodes, a frame a second of each camera: a few seconds on one core.
const std::string kExport = "--scenario join_group --episodes 2 --cameras head,torso --every 1";

// Checks a COCO file written by export_dataset with Python's json module (a real parser, not a
// pattern) and prints what it found: `images I persons P faces F files_checked C`, or the first
// problem on standard error with exit status 1. Each PNG's size is read from its IHDR chunk.
constexpr const char* kCheckScript = R"PY(
import json, struct, sys, os
folder, name = sys.argv[1], sys.argv[2]
with open(os.path.join(folder, name)) as f:
    data = json.load(f)
def fail(message):
    sys.stderr.write(message + "\n")
    sys.exit(1)
for key in ("info", "images", "annotations", "categories"):
    if key not in data:
        fail("no " + key)
if [(c["id"], c["name"]) for c in data["categories"]] != [(1, "person"), (2, "face")]:
    fail("categories: " + repr(data["categories"]))
images = {}
for image in data["images"]:
    if image["id"] in images:
        fail("image id twice: %d" % image["id"])
    images[image["id"]] = image
    path = os.path.join(folder, image["file_name"])
    with open(path, "rb") as png:
        head = png.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        fail(path + ": not a PNG")
    width, height = struct.unpack(">II", head[16:24])
    if (width, height) != (image["width"], image["height"]):
        fail("%s: %dx%d, the file says %dx%d" % (path, width, height, image["width"], image["height"]))
    for key in ("camera", "episode_seed", "time_s"):
        if key not in image:
            fail("image %d: no %s" % (image["id"], key))
ids = set()
counts = {1: 0, 2: 0}
for a in data["annotations"]:
    if a["id"] in ids:
        fail("annotation id twice: %d" % a["id"])
    ids.add(a["id"])
    if a["image_id"] not in images:
        fail("annotation %d: no image %d" % (a["id"], a["image_id"]))
    if a["category_id"] not in counts:
        fail("annotation %d: category %d" % (a["id"], a["category_id"]))
    counts[a["category_id"]] += 1
    image = images[a["image_id"]]
    x, y, w, h = a["bbox"]
    if not (x >= 0 and y >= 0 and w > 0 and h > 0 and x + w <= image["width"] and y + h <= image["height"]):
        fail("annotation %d: bbox %r outside %dx%d" % (a["id"], a["bbox"], image["width"], image["height"]))
    if a["iscrowd"] != 0 or a["area"] != w * h or not 0 <= a["occlusion"] <= 1:
        fail("annotation %d: %r" % (a["id"], a))
    for key in ("person_id", "truncated", "distance_m", "mask", "skin_tone", "seated"):
        if key not in a:
            fail("annotation %d: no %s" % (a["id"], key))
    if a["skin_tone"] not in range(1, 7):
        fail("annotation %d: skin_tone %r" % (a["id"], a["skin_tone"]))
    if (a["category_id"] == 2) != ("face_yaw_deg" in a):
        fail("annotation %d: face_yaw_deg on faces only" % a["id"])
print("images %d persons %d faces %d" % (len(images), counts[1], counts[2]))
)PY";

struct Check {
  bool passed{false};
  int images{0};
  int persons{0};
  int faces{0};
  std::string problem;
};

Check check_coco(const std::string& dir, const std::string& annotations) {
  const std::string script = ::testing::TempDir() + "check_coco.py";
  std::ofstream(script) << kCheckScript;
  const ProgramRun result = run_program("/usr/bin/python3", script + " " + dir + " " + annotations);
  Check check;
  check.problem = result.err;
  check.passed =
      result.status == 0 && std::sscanf(result.out.c_str(), "images %d persons %d faces %d",
                                        &check.images, &check.persons, &check.faces) == 3;
  return check;
}

// Every file under `dir`, by path relative to it, with its bytes.
std::map<std::string, std::string> files_under(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) {
      files[fs::relative(entry.path(), dir).string()] = read_all(entry.path().string());
    }
  }
  return files;
}

// Every file under `dir` equals the reference export's (made in one go), byte for byte, and no
// other file is there.
void expect_same_files(const std::string& dir,
                       const std::map<std::string, std::string>& reference) {
  const std::map<std::string, std::string> files = files_under(dir);
  int differing = 0;
  for (const auto& [path, bytes] : reference) {
    differing += files.count(path) == 0 || files.at(path) != bytes ? 1 : 0;
  }
  EXPECT_EQ(files.size(), reference.size());
  EXPECT_EQ(differing, 0);
  std::printf("%s: %zu files (annotations.json and PNGs), %d differing from the run in one go\n",
              dir.c_str(), files.size(), differing);
}

// The file_name of every image a COCO file lists (one image per line, as export_dataset writes).
std::set<std::string> image_names(const std::string& path) {
  std::set<std::string> names;
  std::istringstream lines(read_all(path));
  const std::string key = "\"file_name\": \"";
  for (std::string line; std::getline(lines, line);) {
    const size_t at = line.find(key);
    if (line.rfind("{\"id\"", 0) == 0 && at != std::string::npos) {
      const size_t start = at + key.size();
      names.insert(line.substr(start, line.find('"', start) - start));
    }
  }
  return names;
}

// Checks an episode's audio files written with --audio, with sox (soxi) for the WAV's format and
// numpy for its samples, and prints `channels C rate R seconds D segments S words W
// worst_onset_ms O clipped K`: for each RTTM segment, the first 10 ms of its speaker's channel
// (ARI's playback, 5; a person's processed channel, 0) whose RMS reaches a tenth of the segment's
// loudest, against the segment's (and its first CTM word's) start; K samples at full scale.
constexpr const char* kAudioCheckScript = R"PY(
import subprocess, sys, wave
import numpy as np
stem = sys.argv[1]
def soxi(flag):
    return subprocess.run(["soxi", flag, stem + ".wav"], check=True, capture_output=True,
                          text=True).stdout.strip()
channels, rate, seconds = int(soxi("-c")), int(soxi("-r")), float(soxi("-D"))
with wave.open(stem + ".wav") as w:
    samples = np.frombuffer(w.readframes(w.getnframes()), dtype="<i2").reshape(-1, channels)
segments = [line.split() for line in open(stem + ".rttm")]
words = [line.split() for line in open(stem + ".ctm")]
worst = 0.0
checked = 0
spans = [(float(s[3]), float(s[3]) + float(s[4])) for s in segments]
for segment in segments:
    start, duration, speaker = float(segment[3]), float(segment[4]), segment[7]
    # An onset is audible only after a silence: skip turns that start over another voice.
    if any(a < start <= b + 0.2 for a, b in spans if a != start):
        continue
    checked += 1
    first_word = min(float(w[2]) for w in words if abs(float(w[2]) - start) < 1e-6)
    channel = samples[:, 5 if speaker == "ARI" else 0].astype(float)
    a, b = int((start - 0.2) * rate), int((start + duration) * rate)
    windows = channel[a:b][: (b - a) // 160 * 160].reshape(-1, 160)
    energy = (windows ** 2).mean(axis=1)
    onset = a / rate + np.argmax(energy >= 0.01 * energy.max()) * 0.01  # RMS a tenth: -20 dB
    worst = max(worst, abs(onset - first_word))
clipped = int((np.abs(samples.astype(int)) >= 32767).sum())
ari = sum(1 for s in segments if s[7] == "ARI")
print("channels %d rate %d seconds %.2f segments %d ari %d words %d checked %d worst_onset_ms %.1f "
      "clipped %d" % (channels, rate, seconds, len(segments), ari, len(words), checked,
                      1000 * worst, clipped))
)PY";

TEST(ExportDataset, BadOptionsExitWithTwoNamingTheOption) {
  const std::string dir = ::testing::TempDir() + "export_dataset_bad";
  fs::remove_all(dir);
  const std::string base = "--scenario join_group --episodes 2 --out " + dir;
  for (const auto& [arguments, fragment] : std::vector<std::pair<std::string, std::string>>{
           {base + " --cameras head,fisheye",
            "--cameras: expected a comma-separated list of head and torso, got 'fisheye'"},
           {base + " --cameras head,head",
            "--cameras: expected each camera once, got 'head' twice"},
           {base + " --cameras ''", "--cameras: expected a value, got ''"},
           {base + " --cameras head --every 0",
            "--every: expected a finite number in [0.01, 86400], got '0'"},
           {base + " --cameras head --every -2",
            "--every: expected a finite number in [0.01, 86400], got '-2'"},
           {base + " --cameras head --every soon",
            "--every: expected a finite number in [0.01, 86400], got 'soon'"},
           {base + " --cameras head --shard 3/2",
            "--shard: expected K/N with 1 <= K <= N, got '3/2'"},
           {base + " --cameras head --shard 1", "--shard: expected K/N"},
           {base + " --cameras head --merge-shards 0",
            "--merge-shards: expected an integer in [1, 1000000], got '0'"},
           {base + " --cameras head --shard 1/1 --merge-shards 2",
            "--merge-shards and --shard: expected one of them"},
           {base + " --cameras head --resume --merge-shards 2",
            "--merge-shards and --resume: expected one of them"},
           {"--scenario join_group --episodes 0 --cameras head --out " + dir,
            "--episodes: expected an integer in [1, 1000000], got '0'"},
           {"--scenario join_group --episodes 2 --seed -1 --cameras head --out " + dir, "--seed"},
           {"--scenario /nonexistent.yaml --episodes 2 --cameras head --out " + dir,
            "/nonexistent.yaml"},
           {"--scenario join_group --episodes 2 --cameras head --out /etc/hostname",
            "--out: /etc/hostname: expected a directory, got a file"},
           {"--scenario join_group --episodes 2 --out " + dir,
            "expected --scenario, --episodes, --cameras or --audio (or both), and --out"},
           {base + " --cameras head --zoom 2",
            "--zoom: unknown option, expected one of --scenario"},
           // Last, it is still unknown, not an option missing its value.
           {base + " --cameras head --zoom",
            "--zoom: unknown option, expected one of --scenario"}}) {
    const ProgramRun result = run(arguments);
    expect_refused(result, fragment);
    EXPECT_EQ(result.out, "") << arguments;
  }
  EXPECT_FALSE(fs::exists(dir));
}

TEST(ExportDataset, AnEarlierExportIsKeptWithoutOverwrite) {
  const std::string dir = ::testing::TempDir() + "export_dataset_existing";
  fs::remove_all(dir);
  fs::create_directories(dir + "/images/head_front_camera");
  std::ofstream(dir + "/annotations.json") << "last week's labels";
  expect_refused(run(kExport + " --out " + dir),
                 "holds this run's output already (" + dir + "/annotations.json)");
  fs::remove(dir + "/annotations.json");
  std::ofstream(dir + "/images/head_front_camera/join_group_2_000003.png") << "last week's image";
  // Another scenario's or seed's images are not this run's.
  std::ofstream(dir + "/images/head_front_camera/join_group_3_000000.png") << "another seed's";
  expect_refused(run(kExport + " --out " + dir), "(1 images of its seeds): pass --overwrite");
  EXPECT_EQ(read_all(dir + "/images/head_front_camera/join_group_2_000003.png"),
            "last week's image");
}

TEST(ExportDataset, AFailedWriteExitsWithOne) {
  const std::string dir = ::testing::TempDir() + "export_dataset_unwritable";
  fs::remove_all(dir);
  ProgramRun result;
  {
    const ari_social_sim::test::FileSizeLimit full_disk(16384);  // a torso picture takes more
    result = run("--scenario join_group --episodes 1 --cameras torso --every 5 --out " + dir);
  }
  EXPECT_EQ(result.status, 1) << result.err;
  EXPECT_NE(result.err.find(dir + "/images/torso_front_camera/join_group_1_000000.png: writing "
                                  "failed"),
            std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(dir + "/annotations.json"));
  EXPECT_TRUE(fs::is_empty(dir + "/images/torso_front_camera"));  // no half picture
}

TEST(ExportDataset, WritesAValidCocoFileTheSameEachRunAndTheSameInMergedShards) {
  const std::string dir = ::testing::TempDir() + "export_dataset_whole";
  fs::remove_all(dir);
  const ProgramRun first = run(kExport + " --out " + dir);
  ASSERT_EQ(first.status, 0) << first.err;
  std::printf("%s", first.out.c_str());
  const Check check = check_coco(dir, "annotations.json");
  ASSERT_TRUE(check.passed) << check.problem;
  std::printf("annotations.json: %d images, %d person and %d face annotations\n", check.images,
              check.persons, check.faces);
  EXPECT_GE(check.persons, 1);
  const std::map<std::string, std::string> files = files_under(dir);
  // Every image listed is there, and nothing else but the annotations.
  const std::set<std::string> names = image_names(dir + "/annotations.json");
  EXPECT_EQ(names.size(), static_cast<size_t>(check.images));
  EXPECT_EQ(files.size(), names.size() + 1);
  // Both episodes start at frame 0 of each camera: the rig's schedule restarts with each.
  for (const char* seed : {"1", "2"}) {
    for (const char* camera : {"head_front_camera", "torso_front_camera"}) {
      EXPECT_EQ(
          names.count(std::string("images/") + camera + "/join_group_" + seed + "_000000.png"), 1u)
          << camera << " seed " << seed;
    }
  }

  // Again, over the first run's output: the same bytes, file for file.
  const ProgramRun again = run(kExport + " --out " + dir + " --overwrite");
  ASSERT_EQ(again.status, 0) << again.err;
  const std::map<std::string, std::string> again_files = files_under(dir);
  ASSERT_EQ(again_files.size(), files.size());
  int differing = 0;
  for (const auto& [path, bytes] : files) {
    differing += again_files.count(path) == 0 || again_files.at(path) != bytes ? 1 : 0;
  }
  EXPECT_EQ(differing, 0) << "files differing between two runs with the same seeds";
  std::printf("second run: %zu files, %d differing\n", again_files.size(), differing);

  // Shards 1/3 to 3/3: one episode each for the first two, none for the third; together the
  // unsharded run's images, byte for byte.
  const std::string shards = ::testing::TempDir() + "export_dataset_shards";
  fs::remove_all(shards);
  std::set<std::string> sharded_names;
  for (const std::string shard : {"1-of-3", "2-of-3", "3-of-3"}) {
    const std::string k_of_n = shard.substr(0, 1) + "/3";
    const ProgramRun part = run(kExport + " --shard " + k_of_n + " --out " + shards);
    ASSERT_EQ(part.status, 0) << part.err;
    const std::string file = "annotations_shard" + shard + ".json";
    const Check part_check = check_coco(shards, file);
    ASSERT_TRUE(part_check.passed) << part_check.problem;
    for (const std::string& name : image_names(shards + "/" + file)) {
      EXPECT_TRUE(sharded_names.insert(name).second) << name << " in both shards";
      EXPECT_EQ(read_all(shards + "/" + name), files.at(name)) << name;
    }
  }
  EXPECT_EQ(sharded_names, names);
  EXPECT_FALSE(fs::exists(shards + "/annotations.json"));

  // Merged: refused, writing nothing, with another plan than the shards' or a shard missing.
  const std::string merge = " --out " + shards + " --merge-shards 3";
  expect_refused(run("--scenario join_group --episodes 2 --cameras head,torso --every 2" + merge),
                 shards +
                     "/annotations_shard1-of-3.json: info: every_s: expected 2.0000, got "
                     "1.0000; frame_rate_hz: expected");
  fs::rename(shards + "/annotations_shard2-of-3.json", shards + "/set_aside.json");
  expect_refused(run(kExport + merge),
                 "1 of 3 shard files missing: " + shards + "/annotations_shard2-of-3.json");
  fs::rename(shards + "/set_aside.json", shards + "/annotations_shard2-of-3.json");
  EXPECT_FALSE(fs::exists(shards + "/annotations.json"));
  // With the shards' options: the unsharded run's folder, file for file, the shard files gone.
  const ProgramRun merged = run(kExport + merge);
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_EQ(merged.out, "export_dataset: merged 3 shards: " + std::to_string(check.images) +
                            " images, " + std::to_string(check.persons + check.faces) +
                            " annotations into " + shards + "/annotations.json\n");
  expect_same_files(shards, files);
  expect_refused(run(kExport + merge), "annotations.json: exists (pass --overwrite to replace it)");
  expect_refused(run(kExport + merge + " --overwrite"), "3 of 3 shard files missing");
}

// Three short episodes, one camera, a frame every 2 s: the cheapest export that can be stopped
// after its first episode and before its last.
const std::string kSmallExport =
    "--scenario join_group --episodes 3 --cameras torso --every 2 --out ";

// The image files the progress file lists (those of the finished episodes).
std::set<std::string> progress_images(const std::string& progress) {
  std::set<std::string> names;
  std::istringstream lines(read_all(progress));
  const std::string key = "\"file_name\": \"";
  for (std::string line; std::getline(lines, line);) {
    const size_t at = line.find(key);
    if (line.rfind("image ", 0) == 0 && at != std::string::npos) {
      const size_t start = at + key.size();
      names.insert(line.substr(start, line.find('"', start) - start));
    }
  }
  return names;
}

// Starts the small export into `dir` in the background (SIGINT ignored, as from a script), sends
// `signal` once its first episode is in the progress file, and returns the exit code.
int interrupted_export(const std::string& dir, int signal, std::string& message) {
  const std::string err = dir + "_stderr.txt";
  const pid_t pid =
      start_in_background(ARI_EXPORT_DATASET_BIN, kSmallExport + dir, "/dev/null", err);
  EXPECT_GT(pid, 0);
  const std::string progress = dir + "/annotations.json.active";
  EXPECT_TRUE(
      wait_until([&] { return read_all(progress).find("\ndone 0\n") != std::string::npos; }));
  const int status = signal_and_wait(pid, signal);
  message = read_all(err);
  return status;
}

TEST(ExportDataset, AnInterruptedExportKeepsFinishedEpisodesAndResumesToTheSameBytes) {
  const std::string reference_dir = ::testing::TempDir() + "export_dataset_reference";
  fs::remove_all(reference_dir);
  const ProgramRun whole = run(kSmallExport + reference_dir);
  ASSERT_EQ(whole.status, 0) << whole.err;
  const std::map<std::string, std::string> reference = files_under(reference_dir);
  ASSERT_GT(reference.size(), 3u);

  // SIGINT, to a process started with SIGINT ignored: it stops, keeping complete episodes only.
  const std::string dir = ::testing::TempDir() + "export_dataset_sigint";
  fs::remove_all(dir);
  std::string message;
  EXPECT_EQ(interrupted_export(dir, SIGINT, message), 130) << message;
  EXPECT_NE(message.find("export_dataset: interrupted by SIGINT after "), std::string::npos)
      << message;
  EXPECT_NE(message.find("rerun the same command with --resume to finish"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/annotations.json"));
  const std::set<std::string> kept = progress_images(dir + "/annotations.json.active");
  std::set<std::string> on_disk;
  for (const auto& [path, bytes] : files_under(dir)) {
    if (path != "annotations.json.active") {
      on_disk.insert(path);
      EXPECT_EQ(bytes, reference.at(path)) << path;  // no .part, no image of a dropped episode
    }
  }
  EXPECT_EQ(on_disk, kept);
  std::printf("after SIGINT: %zu images of finished episodes kept, exit 130\n", kept.size());
  // Other options are refused; the same ones finish the export.
  expect_refused(
      run("--scenario join_group --episodes 3 --cameras torso --every 1 --resume --out " + dir),
      "was made with other settings");
  const ProgramRun resumed = run(kSmallExport + dir + " --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(
      resumed.err.find("episodes are in " + dir + "/annotations.json.active; running the other"),
      std::string::npos)
      << resumed.err;
  expect_same_files(dir, reference);
  const ProgramRun again = run(kSmallExport + dir + " --resume");
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find("nothing to do, all 3 episodes are in"), std::string::npos) << again.out;

  // SIGKILL: no handler runs; --resume still ends with the same bytes.
  const std::string killed = ::testing::TempDir() + "export_dataset_sigkill";
  fs::remove_all(killed);
  EXPECT_EQ(interrupted_export(killed, SIGKILL, message), 128 + SIGKILL);
  expect_refused(run(kSmallExport + killed), "pass --overwrite to replace it, or --resume");
  const ProgramRun after_kill = run(kSmallExport + killed + " --resume");
  ASSERT_EQ(after_kill.status, 0) << after_kill.err;
  expect_same_files(killed, reference);
}

TEST(ExportDataset, AudioIsAWavSoxReadsWithLabelsOnTheWorldsTimesTheSameEachRun) {
  const std::string dir = ::testing::TempDir() + "export_dataset_audio";
  fs::remove_all(dir);
  const std::string audio = "--scenario group_discussion --episodes 1 --audio --out " + dir;
  const ProgramRun first = run(audio);
  ASSERT_EQ(first.status, 0) << first.err;
  const std::string stem = dir + "/audio/group_discussion_1";
  const std::string script = ::testing::TempDir() + "check_audio.py";
  std::ofstream(script) << kAudioCheckScript;
  const ProgramRun check = run_program("/usr/bin/python3", script + " " + stem);
  ASSERT_EQ(check.status, 0) << check.err;
  std::printf("%s", check.out.c_str());
  int channels = 0, rate = 0, segments = 0, ari = 0, words = 0, checked = 0, clipped = -1;
  double seconds = 0.0, worst_onset_ms = 1e9;
  ASSERT_EQ(std::sscanf(check.out.c_str(),
                        "channels %d rate %d seconds %lf segments %d ari %d words %d checked %d "
                        "worst_onset_ms %lf clipped %d",
                        &channels, &rate, &seconds, &segments, &ari, &words, &checked,
                        &worst_onset_ms, &clipped),
            9);
  EXPECT_EQ(clipped, 0);  // not even ARI's own voice, 0.4 m from the array
  EXPECT_EQ(channels, 6);
  EXPECT_EQ(rate, 16000);
  EXPECT_GT(seconds, 20.0);  // ARI walks back after the goodbyes
  // ARI's three lines, Irene's two scripted ones and Paul's and Irene's small talk (section 12
  // of docs/world.md): a word per CTM line, one line per RTTM turn.
  EXPECT_EQ(ari, 3);
  EXPECT_GE(segments, 8);
  EXPECT_GE(words, 23 + 3 * (segments - 5));
  // Every turn that starts after a silence is heard within 50 ms of its label.
  EXPECT_GE(checked, 2);
  EXPECT_LE(worst_onset_ms, 50.0);
  const std::string directions = read_all(stem + "_directions.csv");
  EXPECT_EQ(directions.rfind("time_s,human_id,azimuth_deg,distance_m\n", 0), 0u);
  EXPECT_NE(directions.find(",11,"), std::string::npos);  // Irene, while she speaks

  // Again: the same bytes.
  const std::map<std::string, std::string> files = files_under(dir + "/audio");
  ASSERT_EQ(run(audio + " --overwrite").status, 0);
  EXPECT_EQ(files_under(dir + "/audio"), files);
}

}  // namespace
}  // namespace ari_social_sim::tools::test
