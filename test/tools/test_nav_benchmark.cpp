// Runs the nav_benchmark program as a user would: options checked before the first episode, the
// CSV never silently replaced, a run interrupted with SIGINT and with SIGKILL then resumed.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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
           {"--resume", "--resume: expected --csv too"},
           {"--csv " + dir + "x.csv --overwrite --resume", "expected one of them, got both"},
           {"--profile shy",
            "--profile: expected ignore, yield, curious, avoid or block, got 'shy'"},
           {"--episodes", "--episodes: expected an integer in [1, 10000], got '--types'"}}) {
    const ProgramRun result = run(arguments + " --types pose --controllers social");
    expect_refused(result, fragment);
    EXPECT_EQ(result.err.find("pose 0 social"), std::string::npos) << arguments;
  }
  // An unknown option given last is unknown, not an option missing its value.
  expect_refused(run("--types pose --frobnicate"),
                 "--frobnicate: unknown option, expected one of --episodes");
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

// Two pose episodes with each controller: four short runs.
const std::string kSmallRun = "--episodes 2 --types pose --controllers social,baseline --csv ";

// The CSV without its two solve-time columns (solve_cpu_median_ms, solve_cpu_max_ms): CPU times,
// never the same in two runs; every other byte must be.
std::string without_solve_times(const std::string& csv) {
  std::istringstream lines(csv);
  std::string out;
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, ',');) {
      fields.push_back(field);
    }
    for (size_t i = 0; i < fields.size(); ++i) {
      out += (i == 19 || i == 20) ? std::string("-") : fields[i];
      out += i + 1 < fields.size() ? "," : "\n";
    }
  }
  return out;
}

// Starts the small run in the background (SIGINT ignored, as from a script), sends `signal` once
// its first episode is in the progress file, and returns the exit code.
int interrupted_run(const std::string& csv, int signal, std::string& message) {
  const std::string err = csv + "_stderr.txt";
  const pid_t pid = start_in_background(ARI_NAV_BENCHMARK_BIN, kSmallRun + csv, "/dev/null", err);
  EXPECT_GT(pid, 0);
  EXPECT_TRUE(wait_until([&] {
    return read_all(csv + ".active").find("\ndone pose/0/social\n") != std::string::npos;
  }));
  const int status = signal_and_wait(pid, signal);
  message = read_all(err);
  return status;
}

TEST(NavBenchmark, AnInterruptedRunResumesToTheSameCsv) {
  const std::string dir = ::testing::TempDir() + "nav_benchmark_resume/";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const ProgramRun whole = run(kSmallRun + dir + "whole.csv");
  ASSERT_EQ(whole.status, 0) << whole.err;
  const std::string reference = without_solve_times(read_all(dir + "whole.csv"));
  EXPECT_EQ(std::count(reference.begin(), reference.end(), '\n'), 5);  // header and 4 rows

  const std::string csv = dir + "sigint.csv";
  std::string message;
  EXPECT_EQ(interrupted_run(csv, SIGINT, message), 130) << message;
  EXPECT_NE(message.find("nav_benchmark: interrupted by SIGINT after "), std::string::npos)
      << message;
  EXPECT_NE(message.find("their records are in " + csv + ".active"), std::string::npos);
  EXPECT_NE(message.find("rerun the same command with --resume to finish"), std::string::npos);
  EXPECT_FALSE(fs::exists(csv));
  expect_refused(run(kSmallRun + csv), "holds the episodes of an interrupted run: pass --resume");
  expect_refused(
      run("--episodes 3 --types pose --controllers social,baseline --resume --csv " + csv),
      "was made with other settings");
  const ProgramRun resumed = run(kSmallRun + csv + " --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("episodes are in " + csv + ".active; running the other"),
            std::string::npos)
      << resumed.err;
  EXPECT_EQ(without_solve_times(read_all(csv)), reference);
  EXPECT_FALSE(fs::exists(csv + ".active"));
  const ProgramRun again = run(kSmallRun + csv + " --resume");
  EXPECT_EQ(again.status, 0);
  EXPECT_NE(again.out.find("nothing to do"), std::string::npos) << again.out;

  const std::string killed = dir + "sigkill.csv";
  EXPECT_EQ(interrupted_run(killed, SIGKILL, message), 128 + SIGKILL);
  const ProgramRun after_kill = run(kSmallRun + killed + " --resume");
  ASSERT_EQ(after_kill.status, 0) << after_kill.err;
  EXPECT_EQ(without_solve_times(read_all(killed)), reference);
  std::printf(
      "CSV after SIGINT + --resume and after SIGKILL + --resume: %s the uninterrupted "
      "run's but for the solve times\n",
      without_solve_times(read_all(killed)) == reference ? "the same bytes as" : "NOT");
}

// The summary table without its last column (solve p50 / p99, CPU times).
std::string table_without_solve_times(const std::string& out) {
  std::istringstream lines(out);
  std::string table;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| ", 0) == 0) {
      table += line.substr(0, line.rfind(" | ", line.size() - 3)) + "\n";
    }
  }
  return table;
}

TEST(NavBenchmark, ShardsMergeIntoWhatOneProcessWrites) {
  const std::string dir = ::testing::TempDir() + "nav_benchmark_shards/";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string plan = "--episodes 3 --types pose,approach --controllers social,baseline ";
  const ProgramRun whole = run(plan + "--csv " + dir + "whole.csv");
  ASSERT_EQ(whole.status, 0) << whole.err;
  for (int k = 1; k <= 3; ++k) {
    const ProgramRun shard =
        run(plan + "--csv " + dir + "nav.csv --shard " + std::to_string(k) + "/3");
    ASSERT_EQ(shard.status, 0) << shard.err;
    EXPECT_EQ(shard.err.find("pose " + std::to_string(k % 3) + " social"), std::string::npos)
        << "shard " << k << " ran another shard's episode";
  }
  EXPECT_FALSE(fs::exists(dir + "nav.csv"));  // the shards write their exact records only
  expect_refused(run(plan + "--csv " + dir + "other.csv --merge-shards 3"),
                 "other_shard1-of-3.records not found: shard 1 has not run");
  expect_refused(run("--episodes 3 --types pose --controllers social,baseline --csv " + dir +
                     "nav.csv --merge-shards 3"),
                 "nav_shard1-of-3.records was made with other settings");
  const ProgramRun merged = run(plan + "--csv " + dir + "nav.csv --merge-shards 3");
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_NE(merged.out.find("merged 3 shards: 12 records into " + dir + "nav.csv"),
            std::string::npos)
      << merged.out;
  // 12 rows in one process's order, every byte but the solve times the same; the table too.
  EXPECT_EQ(without_solve_times(read_all(dir + "nav.csv")),
            without_solve_times(read_all(dir + "whole.csv")));
  EXPECT_EQ(table_without_solve_times(merged.out), table_without_solve_times(whole.out));
  EXPECT_FALSE(fs::exists(dir + "nav_shard2-of-3.records"));  // merged, then removed
}

TEST(NavBenchmark, BadShardOptionsAreRefused) {
  for (const auto& [arguments, fragment] : std::vector<std::pair<std::string, std::string>>{
           {"--episodes 2 --shard 1/2", "--shard: expected --csv too"},
           {"--episodes 2 --shard 3/2 --csv x.csv", "--shard: expected K/N with 1 <= K <= N"},
           {"--episodes 2 --shard 1/3 --csv x.csv",
            "--shard: N = 3 is more than --episodes 2: expected at most one shard per episode"},
           {"--episodes 2 --merge-shards 0 --csv x.csv", "--merge-shards: expected an integer"},
           {"--episodes 2 --shard 1/2 --merge-shards 2 --csv x.csv",
            "--shard and --merge-shards: expected one of them, got both"},
           {"--episodes 2 --merge-shards 2 --resume --csv x.csv",
            "--merge-shards and --resume: expected one of them, got both"}}) {
    expect_refused(run(arguments + " --types pose --controllers social"), fragment);
  }
}

}  // namespace
}  // namespace ari_social_sim::tools::test
