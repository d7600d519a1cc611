// Runs the nav_benchmark program as a user would: options checked before the first episode, the
// CSV never silently replaced.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "program_run.hpp"

namespace ari_social_sim::tools::test {
namespace {

namespace fs = std::filesystem;

ProgramRun run(const std::string& arguments) {
  return run_program(ARI_NAV_BENCHMARK_BIN, arguments);
}

TEST(NavBenchmark, BadOptionsExitWithTwoBeforeAnyEpisode) {
  const std::string dir = ::testing::TempDir() + "nav_benchmark_bad/";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // 99999999999 was cast to int; 2^64 + 1 wrapped to seed 1.
  for (const auto& [arguments, fragment] : std::vector<std::pair<std::string, std::string>>{
           {"--episodes 99999999999", "--episodes: expected an integer in [1, 10000]"},
           {"--episodes 0", "got '0'"},
           {"--episodes -5", "got '-5'"},
           {"--seed 18446744073709551617", "--seed: expected an integer in [0, "},
           {"--seed -1", "got '-1'"},
           {"--types pose,pose", "--types: expected each name once, got 'pose' twice"},
           {"--types ''", "--types: expected a value, got ''"},
           {"--types walk", "--types: expected pose, doorway"},
           {"--controllers social,social", "'social' twice"},
           {"--solver newton", "--solver"},
           {"--config " + dir, "--config: " + dir + ": expected a readable file, got a directory"},
           {"--worlds /etc/hostname", "--worlds: /etc/hostname: expected a directory"},
           {"--csv " + dir, "--csv: " + dir + ": expected a file name, got a directory"},
           {"--csv /proc/nav.csv", "--csv: /proc/nav.csv: cannot write in /proc"},
           {"--overwrite", "--overwrite: expected --csv too"},
           {"--profile shy",
            "--profile: expected ignore, yield, curious, avoid or block, got 'shy'"},
           {"--episodes", "--episodes: expected an integer in [1, 10000], got '--types'"}}) {
    const ProgramRun result = run(arguments + " --types pose --controllers social");
    expect_refused(result, fragment);
    EXPECT_EQ(result.err.find("pose 0 social"), std::string::npos) << arguments;
  }
}

TEST(NavBenchmark, AnExistingCsvIsReplacedOnlyWithOverwrite) {
  const std::string dir = ::testing::TempDir() + "nav_benchmark_csv/";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string csv = dir + "nav.csv";
  std::ofstream(csv) << "a day of episodes\n";
  const std::string args = "--episodes 1 --types pose --controllers social --csv " + csv;
  const ProgramRun refused = run(args);
  expect_refused(refused, "nav.csv: exists (pass --overwrite to replace it)");
  EXPECT_EQ(refused.err.find("pose 0 social"), std::string::npos);  // refused before running
  EXPECT_EQ(read_all(csv), "a day of episodes\n");
  const ProgramRun replaced = run(args + " --overwrite");
  ASSERT_EQ(replaced.status, 0) << replaced.err;
  const std::string rows = read_all(csv);
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 2);  // header and one episode
  EXPECT_EQ(rows.find("pose,0,"), rows.find('\n') + 1);
  EXPECT_EQ(rows.find("type,episode,seed,controller,profile,success,"), 0u);
  EXPECT_NE(rows.find(",social,ignore,"), std::string::npos);  // the default profile
  EXPECT_FALSE(fs::exists(csv + ".part"));
}

}  // namespace
}  // namespace ari_social_sim::tools::test
