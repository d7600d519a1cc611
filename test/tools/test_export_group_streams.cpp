// Runs the export_group_streams program as a user would: bad input refused before any work; a
// few scenes exported, read back with the F-formation readers detect_groups uses, counted and
// exported again byte for byte; and GCFF, as detect_groups runs it, scored on the perceived
// streams with perception's default error models and without them (issue 17, must-show 2), and
// where it falls short without them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "ari_social_sim/perception/fformation_dataset.hpp"
#include "ari_social_sim/perception/group_evaluation.hpp"
#include "program_run.hpp"

namespace ari_social_sim::tools::test {
namespace {

namespace fs = std::filesystem;

ProgramRun run(const std::string& arguments) {
  return run_program(ARI_EXPORT_GROUP_STREAMS_BIN, arguments);
}

std::string out_dir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "group_streams_" + name;
  fs::remove_all(dir);
  return dir;
}

TEST(ExportGroupStreams, BadInputIsRefusedBeforeAnySceneRuns) {
  const std::string out = out_dir("refused");
  expect_refused(run("--scenes 0 --out " + out), "--scenes: expected an integer in [1, 100000]");
  expect_refused(run("--scenes 1"), "expected --scenes and --out");
  expect_refused(run("--scenes 2 --seed 2147483647 --out " + out),
                 "--seed: expected the scenes' seeds in [0, 2147483647], got seeds "
                 "2147483647..2147483648");
  expect_refused(run("--scenes 1 --errors none --out " + out),
                 "--errors: expected default or off, got 'none'");
  expect_refused(run("--scenes 1 --mix even --out " + out),
                 "--mix: expected recorded or uniform, got 'even'");
  expect_refused(run("--scenes 1 --arrangements circle,square --out " + out),
                 "--arrangements: expected a comma-separated list of circle, vis-a-vis, "
                 "l-shape or side-by-side, got 'square'");
  expect_refused(run("--scenes 1 --arrangements circle,circle --out " + out),
                 "expected each arrangement once, got 'circle' twice");
  expect_refused(run("--scenes 1 --every 0.01 --out " + out), "--every: expected");
  expect_refused(run("--scenes 1 --seconds 5 --every 10 --out " + out),
                 "--every: expected at most --seconds (5");
  expect_refused(run("--scenes 1 --stride 3 --out " + out),
                 "--stride: unknown option, expected one of");
  EXPECT_FALSE(fs::exists(out));  // nothing was written
  std::ofstream(out) << "a file";
  expect_refused(run("--scenes 1 --out " + out), "expected a directory, got a file");
  fs::remove(out);
}

// Two scenes of 20 s sampled every 0.5 s: 2 x 40 frames.
const std::string kShortExport = "--scenes 2 --seed 3 --seconds 20 --every 0.5";

TEST(ExportGroupStreams, FilesParseCountAndRepeatByteForByte) {
  const std::string out = out_dir("short");
  const ProgramRun first = run(kShortExport + " --out " + out);
  ASSERT_EQ(first.status, 0) << first.err;

  const auto features = perception::read_fformation_features(out + "/features.csv");
  const auto truth = perception::read_fformation_groups(out + "/groundtruth.csv");
  const auto frames = perception::read_fformation_frames(out + "/frames.csv");
  ASSERT_EQ(frames.size(), 80u);
  EXPECT_EQ(frames.front(), 0);
  EXPECT_EQ(frames.back(), 79);
  size_t people = 0;
  for (const auto& [frame, persons] : features) {
    EXPECT_LE(frame, 79);
    people += persons.size();
  }
  size_t groups = 0;
  for (const auto& [frame, grouping] : truth) {
    // Every member of a true group is among the frame's perceived people; at most 5 groups.
    std::set<std::string> seen;
    for (const auto& person : features.at(frame)) {
      seen.insert(person.id);
    }
    EXPECT_LE(grouping.size(), 5u);
    for (const auto& group : grouping) {
      EXPECT_GE(group.size(), 2u);
      for (const std::string& member : group) {
        EXPECT_EQ(seen.count(member), 1u) << "frame " << frame << ": " << member;
      }
    }
    groups += grouping.size();
  }
  // The summary counts the same: people perceived, true groups and the world's groups.
  EXPECT_NE(first.out.find("2 scenes, 80 frames, " + std::to_string(people) +
                           " perceived people, " + std::to_string(groups) + " true groups of "),
            std::string::npos)
      << first.out;
  EXPECT_GT(groups, 80u);  // at least one group seen in most frames
  // ARI moves among the groups: at 0.3 m/s or more for most of 2 x 20 s, a goal every 10 to 15 s
  // (261 goals in 50 scenes of 60 s: docs/perception_gcff.md).
  double path_m = 0.0;
  int goals = 0;
  ASSERT_EQ(std::sscanf(first.out.c_str() + first.out.find("ARI: "),
                        "ARI: %lf m driven per scene, %d navigation goals", &path_m, &goals),
            2)
      << first.out;
  EXPECT_GT(path_m, 6.0);
  EXPECT_GE(goals, 3);

  const std::string features_bytes = read_all(out + "/features.csv");
  const std::string truth_bytes = read_all(out + "/groundtruth.csv");
  expect_refused(run(kShortExport + " --out " + out), "pass --overwrite");
  const ProgramRun again = run(kShortExport + " --out " + out + " --overwrite");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(read_all(out + "/features.csv"), features_bytes);
  EXPECT_EQ(read_all(out + "/groundtruth.csv"), truth_bytes);
  EXPECT_EQ(again.out, first.out);
}

// The streams of 30 s scenes and what GCFF with group_detection_node's parameters
// (config/perception.yaml: stride 0.6 m, MDL 0.8 m^2) finds in them, as detect_groups runs it.
struct Detection {
  perception::GroupTable truth;
  perception::GroupTable detected;
  std::vector<perception::FrameId> frames;

  perception::EvaluationScore score() const {
    return perception::evaluate_groups(detected, truth, frames, perception::kMatchTwoThirds);
  }
};

Detection detect(const std::string& name, const std::string& options) {
  const std::string out = out_dir(name);
  const ProgramRun exported = run(options + " --seed 1 --seconds 30 --every 0.5 --out " + out);
  EXPECT_EQ(exported.status, 0) << exported.err;
  perception::GcffParams params;
  params.stride = 0.6;
  params.mdl = 0.8;
  Detection d;
  d.detected = perception::detect_fformation_groups(
      perception::read_fformation_features(out + "/features.csv"), params);
  d.truth = perception::read_fformation_groups(out + "/groundtruth.csv");
  d.frames = perception::read_fformation_frames(out + "/frames.csv");
  return d;
}

std::string describe(const perception::EvaluationScore& s) {
  return "precision " + std::to_string(s.precision) + " recall " + std::to_string(s.recall) +
         " f1 " + std::to_string(s.f1);
}

// Must-show 2 with perception's default error models, the recorded mix (seed 1: F1 0.973).
TEST(ExportGroupStreams, GcffFindsThePerceivedGroupsWithDefaultErrors) {
  const perception::EvaluationScore s = detect("default", "--scenes 8").score();
  EXPECT_EQ(s.frames, 480u);  // 8 scenes x 60 samples
  EXPECT_GE(s.f1, 0.85) << describe(s);
}

// Must-show 2 without errors, the recorded mix. 16 scenes: near F1 = 1 one scene of side-by-side
// pairs (F1 0.95 alone) moves the score of 8 by 0.03 (seed 1: 0.992 over 16 scenes of 30 s, 0.987
// over 50 of 60 s).
TEST(ExportGroupStreams, GcffFindsThePerceivedGroupsWithoutErrors) {
  const perception::EvaluationScore s = detect("off", "--scenes 16 --errors off").score();
  EXPECT_EQ(s.frames, 960u);
  EXPECT_GE(s.f1, 0.95) << describe(s);
}

}  // namespace
}  // namespace ari_social_sim::tools::test
