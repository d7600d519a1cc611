// Runs the detect_groups program as a user would, through the shell.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "../common/data_sets.hpp"
#include "program_run.hpp"

namespace {

using ari_social_sim::tools::test::ProgramRun;

std::string temp_path(const std::string& name) {
  return ::testing::TempDir() + "detect_groups_" + name;
}

// Runs detect_groups with `arguments` (shell syntax), capturing its output and exit status.
ProgramRun run(const std::string& arguments) {
  return ari_social_sim::tools::test::run_program(ARI_DETECT_GROUPS_BIN, arguments);
}

std::string data_file(const std::string& name) {
  return ari_social_sim::core::data_set_dir("fformation") + "/" + name;
}

// A features table and a ground-truth table of two frames, written here, for the tests that need
// well-formed input but not the recorded data set.
std::string small_table(const std::string& name, const std::string& text) {
  const std::string path = temp_path(name);
  std::ofstream(path) << text;
  return path;
}

std::string small_features() {
  return small_table("small_features.csv",
                     "frame,person_id,x,y,theta\n1,a,0,0,0\n1,b,120,0,3.141593\n2,c,0,0,0\n");
}

std::string small_groups() {
  return small_table("small_groups.csv", "frame,group,person_id\n1,0,a\n1,0,b\n");
}

TEST(DetectGroups, HelpDocumentsTheOptions) {
  const ProgramRun help = run("--help");
  EXPECT_EQ(help.status, 0);
  for (const char* option : {"--features", "--stride", "--mdl", "--evaluate", "--frames",
                             "--threshold", "frame,group,person_id"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  }
}

TEST(DetectGroups, WritesGroupsAsCsv) {
  // Frame 7: ann and bob face each other 1.2 m apart, cy stands alone facing away; frame 8: cy.
  const std::string features = temp_path("features.csv");
  std::ofstream(features) << "frame,person_id,x,y,theta\n"
                             "7,ann,0,0,0\n7,cy,5,5,0\n7,bob,1.2,0,3.141593\n8,cy,5,5,0\n";
  const ProgramRun result = run("--features " + features + " --stride 0.6 --mdl 0.8");
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(result.out, "frame,group,person_id\n7,0,ann\n7,0,bob\n");
}

TEST(DetectGroups, EvaluatesAgainstGroundTruth) {
  ARI_SKIP_WITHOUT_DATA_SET("fformation");
  const std::string arguments =
      "--features " + data_file("Synth_features.csv") + " --stride 30 --mdl 6000 --evaluate " +
      data_file("Synth_groups.csv") + " --frames " + data_file("Synth_frames.csv");
  const ProgramRun two_thirds = run(arguments);
  EXPECT_EQ(two_thirds.status, 0) << two_thirds.err;
  EXPECT_EQ(two_thirds.out, "precision 0.967 recall 0.980 f1 0.973\n");
  const ProgramRun all = run(arguments + " --threshold 1");
  EXPECT_EQ(all.out, "precision 0.908 recall 0.910 f1 0.909\n");
}

TEST(DetectGroups, BadArgumentsExitWithTwo) {
  const std::string features = small_features();
  const auto expect_usage_error = [](const ProgramRun& result, const std::string& fragment) {
    EXPECT_EQ(result.status, 2);
    EXPECT_TRUE(result.out.empty());
    EXPECT_NE(result.err.find(fragment), std::string::npos) << result.err;
  };
  expect_usage_error(run("--features " + features + " --stride 30"), "--mdl");
  expect_usage_error(run("--features " + features + " --stride x --mdl 1"), "--stride");
  expect_usage_error(run("--features " + features + " --stride 30 --mdl"),
                     "--mdl: expected a value");
  expect_usage_error(run("--features " + features + " --stride 30 --mdl -1"), "mdl");
  expect_usage_error(run("--features " + features + " --stride 30 --mdl 1 --frobnicate 3"),
                     "--frobnicate");
  expect_usage_error(run("--features " + features + " --stride 30 --mdl 1 --threshold 0.5"),
                     "--threshold");
  expect_usage_error(run("--features " + features + " --stride 30 --mdl 1 --evaluate " + features),
                     "--frames");
  expect_usage_error(run("--features /nonexistent.csv --stride 30 --mdl 1"),
                     "/nonexistent.csv: cannot open");
  expect_usage_error(run("--features " + features + " --stride nan --mdl 1"),
                     "--stride: expected a finite number > 0, got 'nan'");
  expect_usage_error(run("--features " + features + " --stride 1e400 --mdl 1"), "got '1e400'");
  expect_usage_error(run("--features " + ::testing::TempDir() + " --stride 30 --mdl 1"),
                     "--features: " + ::testing::TempDir() +
                         ": expected a readable file, got a "
                         "directory");
  expect_usage_error(run("--features " + features + " --stride 30 --mdl 1 --evaluate " + features +
                         " --frames /nonexistent_frames.csv"),
                     "--frames: /nonexistent_frames.csv: cannot open");
  // Ground truth given as features: the header is wrong, named with file, line and column.
  expect_usage_error(run("--features " + small_groups() + " --stride 30 --mdl 1"),
                     "small_groups.csv:1:1:");
}

TEST(DetectGroups, AFailedWriteExitsWithOne) {
  // /dev/full takes the open and refuses the bytes, as a full disk does.
  const ProgramRun full = ari_social_sim::tools::test::run_program(
      ARI_DETECT_GROUPS_BIN, "--features " + small_features() + " --stride 30 --mdl 6000",
      "/dev/full");
  EXPECT_EQ(full.status, 1);
  EXPECT_NE(full.err.find("standard output: writing the groups failed"), std::string::npos)
      << full.err;
}

}  // namespace
