// Runs the fit_dialogue_model program as a user would: options within their ranges, the corpus
// found or asked for, the shipped model reproduced, an existing output replaced only with
// --overwrite.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../common/data_sets.hpp"
#include "ari_social_sim/core/data_sets.hpp"
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
// repository.
TEST(FitDialogueModel, HelpSaysWhereTheCorpusComesFrom) {
  const ProgramRun help = run("--help");
  EXPECT_EQ(help.status, 0);
  for (const std::string fragment :
       {"https://github.com/AddleseeHQ/mpgt-eval", "--corpus DIR", "$ARI_MPGT_DIR",
        "scripts/fetch_data.sh", "$ARI_DATA_DIR/dialogue/mpgt"}) {
    EXPECT_NE(help.err.find(fragment), std::string::npos) << help.err;
  }
  EXPECT_EQ(help.err.find("../"), std::string::npos) << help.err;
  EXPECT_EQ(help.err.find("-DARI_MPGT_DIR"), std::string::npos) << help.err;
}

// Without --corpus the tool reads $ARI_MPGT_DIR, else the data set; with neither it says how to
// get the corpus, before writing anything.
TEST(FitDialogueModel, WithoutTheCorpusItSaysHowToGetIt) {
  const std::string data = ::testing::TempDir() + "fit_dialogue_model_no_data/";
  fs::remove_all(data);
  fs::create_directories(data);
  const std::string out = " --out " + data + "m.yaml";
  expect_refused(
      run_program("env -u ARI_MPGT_DIR ARI_DATA_DIR=" + data + " " + ARI_FIT_DIALOGUE_MODEL_BIN,
                  out),
      "the fit needs the MPGT corpus, and none was given (no --corpus DIR, "
      "ARI_MPGT_DIR not set): data set 'dialogue/mpgt' is not in " +
          data + "/dialogue/mpgt: fetch it with scripts/fetch_data.sh");
  const std::string missing = data + "no_corpus";
  expect_refused(run_program("ARI_MPGT_DIR=" + missing + " " + ARI_FIT_DIALOGUE_MODEL_BIN, out),
                 "$ARI_MPGT_DIR: " + missing + ": expected a directory");
  EXPECT_EQ(fs::directory_iterator(data), fs::directory_iterator());
}

TEST(FitDialogueModel, ReproducesTheShippedModelAndKeepsAnExistingOne) {
  ARI_SKIP_WITHOUT_DATA_SET("dialogue/mpgt");
  // The data set, found without --corpus as a user who fetched it would.
  const auto run = [](const std::string& arguments) {
    return run_program("env -u ARI_MPGT_DIR " + std::string(ARI_FIT_DIALOGUE_MODEL_BIN), arguments);
  };
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
