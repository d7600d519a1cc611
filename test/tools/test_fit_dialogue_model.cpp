// Runs the fit_dialogue_model program as a user would: options within their ranges, the shipped
// model reproduced, an existing output replaced only with --overwrite.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "program_run.hpp"

namespace ari_social_sim::tools::test {
namespace {

namespace fs = std::filesystem;

ProgramRun run(const std::string& arguments) {
  return run_program(ARI_FIT_DIALOGUE_MODEL_BIN, arguments);
}

TEST(FitDialogueModel, BadOptionsExitWithTwo) {
  const std::string dir = ::testing::TempDir() + "fit_dialogue_model_bad/";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = " --out " + dir + "m.yaml";
  expect_refused(run("--min-row-count -1" + out),
                 "--min-row-count: expected an integer in [1, 100000], got '-1'");
  expect_refused(run("--min-row-count 0" + out), "got '0'");
  expect_refused(run("--min-row-count 5x" + out), "got '5x'");  // once read as 5
  expect_refused(run("--prior-weight nan" + out),
                 "--prior-weight: expected a finite number in [0, 1e+06], got 'nan'");
  expect_refused(run("--prior-weight 1e400" + out), "got '1e400'");
  expect_refused(run("--prior-weight -0.5" + out), "got '-0.5'");
  expect_refused(run("--corpus /etc/hostname" + out),
                 "--corpus: /etc/hostname: expected a directory");
  expect_refused(run("--out " + dir), "expected a file name, got a directory");
  expect_refused(run("--out /proc/m.yaml"), "--out: /proc/m.yaml: cannot write in /proc");
  expect_refused(run("--overwrite"), "--overwrite: expected --out too");
  expect_refused(run("--prior-weight"), "--prior-weight: expected a value after it");
  expect_refused(run("--out ''"), "--out: expected a value, got ''");  // not standard output
  EXPECT_EQ(fs::directory_iterator(dir), fs::directory_iterator());
}

// --help says where the corpus comes from and how to point at it, naming no folder outside the
// repository; ARI_MPGT_DIR in the environment replaces the build-time folder.
TEST(FitDialogueModel, HelpAndEnvironmentPointAtTheCorpus) {
  const ProgramRun help = run("--help");
  EXPECT_EQ(help.status, 0);
  for (const std::string fragment :
       {"https://github.com/AddleseeHQ/mpgt-eval", "$ARI_MPGT_DIR", "-DARI_MPGT_DIR=DIR"}) {
    EXPECT_NE(help.err.find(fragment), std::string::npos) << help.err;
  }
  EXPECT_EQ(help.err.find("../"), std::string::npos) << help.err;
  const std::string missing = ::testing::TempDir() + "fit_dialogue_model_no_corpus";
  fs::remove_all(missing);
  expect_refused(run_program("ARI_MPGT_DIR=" + missing + " " + ARI_FIT_DIALOGUE_MODEL_BIN, ""),
                 "--corpus: " + missing);
}

TEST(FitDialogueModel, ReproducesTheShippedModelAndKeepsAnExistingOne) {
  const std::string dir = ::testing::TempDir() + "fit_dialogue_model_out/";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string shipped =
      read_all(std::string(ARI_SOURCE_DIR) + "/config/dialogue/mpgt_user_model.yaml");
  const ProgramRun fitted = run("--out " + dir + "m.yaml");
  ASSERT_EQ(fitted.status, 0) << fitted.err;
  EXPECT_NE(fitted.err.find("fitted 2 roles on 29 conversations"), std::string::npos);
  EXPECT_EQ(read_all(dir + "m.yaml"), shipped);
  std::ofstream(dir + "m.yaml") << "# edited by hand\n";
  expect_refused(run("--out " + dir + "m.yaml --prior-weight 1"),
                 "m.yaml: exists (pass --overwrite to replace it)");
  EXPECT_EQ(read_all(dir + "m.yaml"), "# edited by hand\n");
  ASSERT_EQ(run("--out " + dir + "m.yaml --overwrite").status, 0);
  EXPECT_EQ(read_all(dir + "m.yaml"), shipped);
}

}  // namespace
}  // namespace ari_social_sim::tools::test
