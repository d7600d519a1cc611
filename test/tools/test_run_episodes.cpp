// Runs the run_episodes program as a user would: bad options, an existing output, --resume, failed
// episodes and a run interrupted with SIGINT (docs/scenario.md, section 6). join_group episodes
// take about 0.1 s.
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "program_run.hpp"

namespace ari_social_sim::tools::test {
namespace {

namespace fs = std::filesystem;

ProgramRun run(const std::string& arguments) {
  return run_program(ARI_RUN_EPISODES_BIN, arguments);
}

// A fresh, absent output folder for one test.
std::string out_dir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "run_episodes_" + name;
  fs::remove_all(dir);
  return dir;
}

size_t count_lines(const std::string& text) {
  return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

// The bags and .active files in `dir`.
std::vector<fs::path> files_ending(const std::string& dir, const std::string& ending) {
  std::vector<fs::path> found;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.size() >= ending.size() &&
        name.compare(name.size() - ending.size(), ending.size(), ending) == 0) {
      found.push_back(entry.path());
    }
  }
  return found;
}

// The rows of a join_group CSV whose success column (the fourth, no quoted field before it) is 0.
size_t failed_rows(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  size_t failed = 0;
  while (std::getline(in, line)) {
    size_t at = 0;
    for (int field = 0; field < 3; ++field) {
      at = line.find(',', at) + 1;
    }
    failed += line.compare(at, 2, "0,") == 0 ? 1 : 0;
  }
  return failed;
}

// The seed column of each row of a join_group CSV (no quoted field before it).
std::vector<std::string> row_seeds(const std::string& csv) {
  std::vector<std::string> seeds;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const size_t first = line.find(',');
    const size_t second = line.find(',', first + 1);
    seeds.push_back(line.substr(second + 1, line.find(',', second + 1) - second - 1));
  }
  return seeds;
}

// Opens every bag in `dir` and counts its /clock messages: a bag cut short would not open.
void expect_complete_bags(const std::string& dir, const std::vector<std::string>& seeds) {
  EXPECT_EQ(files_ending(dir, ".bag").size(), seeds.size());
  EXPECT_TRUE(files_ending(dir, ".active").empty());
  for (const std::string& seed : seeds) {
    const std::string path = dir + "/join_group_" + seed + ".bag";
    ASSERT_TRUE(fs::exists(path)) << path;
    rosbag::Bag bag(path, rosbag::bagmode::Read);
    EXPECT_GT(rosbag::View(bag, rosbag::TopicQuery("/clock")).size(), 100u) << path;
  }
}

TEST(RunEpisodes, BadOptionsExitWithTwoBeforeWritingAnything) {
  const std::string out = out_dir("bad");
  const std::string args = "--scenario join_group --out " + out;
  expect_refused(run(args + " --episodes -1"),
                 "--episodes: expected an integer in [1, 1000000], got '-1'");
  expect_refused(run(args + " --episodes 0"), "got '0'");
  expect_refused(run(args + " --episodes 1000001"), "got '1000001'");
  expect_refused(run(args + " --episodes 18446744073709551617"), "[1, 1000000]");
  expect_refused(run(args + " --episodes 2x"), "got '2x'");
  expect_refused(run(args + " --episodes 1 --seed -3"), "--seed: expected an integer in [0, ");
  // 2147483640 + 9 passes 2^31 - 1.
  expect_refused(run(args + " --episodes 10 --seed 2147483640"), "2147483640..2147483649");
  expect_refused(run(args + " --episodes 1 --shard 3/2"), "--shard");
  expect_refused(run(args + " --episodes"), "--episodes: expected a value");
  expect_refused(run(args + " --episodes 1 --frobnicate 2"), "--frobnicate");
  // An empty value is no default: '' as --out would have been the root folder.
  expect_refused(run("--scenario join_group --episodes 1 --resume --out ''"),
                 "--out: expected a value, got ''");
  expect_refused(run(args + " --episodes 1 --overwrite --resume"), "got both");
  expect_refused(run(args + " --resume"), "nothing to resume, give --episodes");
  expect_refused(run("--scenario " + ::testing::TempDir() + " --episodes 1 --out " + out),
                 "expected a readable file, got a directory");
  EXPECT_FALSE(fs::exists(out));
  // Output folders that cannot be: a file, a folder in /proc (not even for root), /proc itself.
  std::ofstream(out) << "a file";
  expect_refused(run("--scenario join_group --episodes 1 --out " + out),
                 out + ": expected a directory, got a file");
  fs::remove(out);
  expect_refused(run("--scenario join_group --episodes 1 --out /proc/ari_episodes"),
                 "--out: /proc/ari_episodes: cannot create the directory");
  expect_refused(run("--scenario join_group --episodes 1 --out /proc"),
                 "--out: /proc: cannot write in the directory");
}

TEST(RunEpisodes, AnExistingOutputIsRefusedUnlessOverwritten) {
  const std::string out = out_dir("existing");
  // From seed 2: seed 1's group is one ARI cannot join (exit 1), beside the point here.
  const std::string args = "--scenario join_group --episodes 2 --seed 2 --no-bags --out " + out;
  ASSERT_EQ(run(args).status, 0);
  const std::string csv = read_all(out + "/join_group.csv");
  EXPECT_EQ(count_lines(csv), 3u);  // header and 2 rows
  expect_refused(run(args), "holds this run's output already (" + out + "/join_group.csv, " + out +
                                "/join_group.settings.yaml): pass --resume");
  EXPECT_EQ(read_all(out + "/join_group.csv"), csv);  // untouched
  // Bags of its seeds count too, even with no CSV.
  fs::remove(out + "/join_group.csv");
  fs::remove(out + "/join_group.settings.yaml");
  std::ofstream(out + "/join_group_2.bag.active") << "half";
  expect_refused(run("--scenario join_group --episodes 2 --seed 2 --out " + out),
                 "1 bags of its seeds");
  const ProgramRun replaced =
      run("--scenario join_group --episodes 3 --seed 2 --out " + out + " --overwrite");
  EXPECT_EQ(replaced.status, 0) << replaced.err;
  EXPECT_NE(replaced.err.find("--overwrite: removed its settings and 0 bags"), std::string::npos)
      << replaced.err;
  expect_complete_bags(out, {"2", "3", "4"});
  const ProgramRun again =
      run("--scenario join_group --episodes 1 --seed 2 --out " + out + " --overwrite");
  EXPECT_NE(again.err.find("removed " + out + "/join_group.csv (3 rows), its settings and 3 bags"),
            std::string::npos)
      << again.err;
  expect_complete_bags(out, {"2"});
}

TEST(RunEpisodes, ResumeAddsTheMissingEpisodesAndKeepsTheRest) {
  const std::string out = out_dir("resume");
  // From seed 2: seed 1's group is one ARI cannot join (exit 1), beside the point here.
  ASSERT_EQ(run("--scenario join_group --episodes 3 --seed 2 --out " + out).status, 0);
  const std::string first = read_all(out + "/join_group.csv");
  const std::string bag_2 = read_all(out + "/join_group_2.bag");
  // Other settings are refused, each difference named.
  const ProgramRun other =
      run("--scenario join_group --episodes 5 --seed 4 --no-bags --resume --out " + out);
  expect_refused(other, "was made with other settings");
  EXPECT_NE(other.err.find("--seed: first seed 2 there, 4 now"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("--no-bags: bags there, no bags now"), std::string::npos) << other.err;
  expect_refused(run("--scenario join_group --episodes 2 --resume --out " + out),
                 "the row of episode 2 (scenario join_group, seed 4) is not one of this run's 2");

  const ProgramRun resumed = run("--scenario join_group --episodes 5 --resume --out " + out);
  EXPECT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("3 of 5 episodes are in"), std::string::npos) << resumed.err;
  const std::string csv = read_all(out + "/join_group.csv");
  EXPECT_EQ(count_lines(csv), 6u);
  EXPECT_EQ(csv.substr(0, first.size()), first);  // the first 3 rows, byte for byte
  EXPECT_EQ(row_seeds(csv), (std::vector<std::string>{"2", "3", "4", "5", "6"}));
  EXPECT_EQ(read_all(out + "/join_group_2.bag"), bag_2);
  expect_complete_bags(out, {"2", "3", "4", "5", "6"});
  EXPECT_NE(read_all(out + "/join_group.settings.yaml").find("episodes: 5\n"), std::string::npos);

  // Without --episodes it goes on to the count of the settings: nothing left.
  const ProgramRun done = run("--scenario join_group --resume --out " + out);
  EXPECT_EQ(done.status, 0);
  EXPECT_NE(done.out.find("nothing to do, all 5 episodes are in"), std::string::npos);
  // A row cut short (a run killed while writing it) is removed, and its episode run again.
  std::ofstream(out + "/join_group.csv", std::ios::app) << "join_group,5,7,1,\"cut";
  const ProgramRun repaired = run("--scenario join_group --episodes 6 --resume --out " + out);
  EXPECT_EQ(repaired.status, 0) << repaired.err;
  EXPECT_NE(repaired.err.find("ended in a row cut short"), std::string::npos) << repaired.err;
  EXPECT_EQ(row_seeds(read_all(out + "/join_group.csv")),
            (std::vector<std::string>{"2", "3", "4", "5", "6", "7"}));
}

// A job array's shards merged (--merge-shards) are the files one process running the whole plan
// writes, byte for byte: the CSV, its settings and every bag (docs/cluster.md).
TEST(RunEpisodes, ShardsMergeIntoWhatOneProcessWrites) {
  const std::string plan = "--scenario join_group --episodes 6 --seed 2";
  const std::string whole = out_dir("merge_whole");
  ASSERT_EQ(run(plan + " --out " + whole).status, 0);
  const std::string sharded = out_dir("merge_sharded");
  for (int k = 1; k <= 3; ++k) {
    ASSERT_EQ(run(plan + " --shard " + std::to_string(k) + "/3 --out " + sharded).status, 0);
  }
  const ProgramRun merged = run(plan + " --merge-shards 3 --out " + sharded);
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_NE(merged.out.find("merged 3 shards: 6 episodes"), std::string::npos) << merged.out;
  for (const std::string file : {"join_group.csv", "join_group.settings.yaml", "join_group_2.bag",
                                 "join_group_5.bag", "join_group_7.bag"}) {
    EXPECT_EQ(read_all(sharded + "/" + file), read_all(whole + "/" + file)) << file;
  }
  EXPECT_TRUE(files_ending(sharded, "-of-3.csv").empty());
  EXPECT_TRUE(files_ending(sharded, "-of-3.settings.yaml").empty());
  // Merged again: the output is there; the shards are gone.
  expect_refused(run(plan + " --merge-shards 3 --out " + sharded), "pass --overwrite");

  const std::string missing = out_dir("merge_missing");
  for (int k = 1; k <= 2; ++k) {
    ASSERT_EQ(run(plan + " --shard " + std::to_string(k) + "/3 --out " + missing).status, 0);
  }
  expect_refused(run(plan + " --merge-shards 3 --out " + missing),
                 "join_group_shard3-of-3.settings.yaml: not found");
  ASSERT_EQ(run("--scenario join_group --episodes 6 --seed 20 --shard 3/3 --out " + missing).status,
            0);
  expect_refused(run(plan + " --merge-shards 3 --out " + missing),
                 "--seed: first seed 20 there, 2");
  expect_refused(run(plan + " --merge-shards 3 --shard 1/3 --out " + missing),
                 "--merge-shards: expected the whole plan");
  expect_refused(run(plan + " --merge-shards 0 --out " + missing), "--merge-shards: expected");

  // One shard writes the whole run's files: the merge checks them and keeps them.
  const std::string single = out_dir("merge_single");
  ASSERT_EQ(run(plan + " --shard 1/1 --out " + single).status, 0);
  const ProgramRun in_place = run(plan + " --merge-shards 1 --out " + single);
  EXPECT_EQ(in_place.status, 0) << in_place.err;
  EXPECT_EQ(read_all(single + "/join_group.csv"), read_all(whole + "/join_group.csv"));
}

// join_group with a script time limit too short to join anyone: every episode fails.
std::string hopeless_join_group(const std::string& dir) {
  std::string text = read_all(std::string(ARI_SOURCE_DIR) + "/scenarios/join_group.yaml");
  text.replace(text.find("../worlds/"), 3, std::string(ARI_SOURCE_DIR) + "/");
  text.replace(text.find("time_limit: 60"), 14, "time_limit: 1");
  fs::create_directories(dir);
  const std::string path = dir + "/join_group_hopeless.yaml";
  std::ofstream(path) << text;
  return path;
}

TEST(RunEpisodes, FailedEpisodesExitWithOneNamingTheFirstFive) {
  const std::string out = out_dir("failed");
  const std::string args =
      "--scenario " + hopeless_join_group(out) + " --episodes 7 --no-bags --out " + out;
  const ProgramRun failed = run(args);
  EXPECT_EQ(failed.status, 1) << failed.err;
  const std::string csv = out + "/join_group_hopeless.csv";
  EXPECT_NE(failed.err.find("run_episodes: 7 of 7 episodes in " + csv +
                            " failed:\n"
                            "  seed 1: failed in state join: time limit of 1.000000 s reached in "
                            "state join\n"),
            std::string::npos)
      << failed.err;
  EXPECT_NE(failed.err.find("  seed 5: "), std::string::npos) << failed.err;
  EXPECT_EQ(failed.err.find("  seed 6: "), std::string::npos) << failed.err;
  EXPECT_NE(failed.err.find("  and 2 more (the rows with success 0 in the CSV)\n"),
            std::string::npos)
      << failed.err;
  EXPECT_EQ(count_lines(read_all(csv)), 8u);  // the output is complete all the same
  // A resumed run answers for the rows it kept: a job array's rerun does not turn them green.
  const ProgramRun resumed = run(args + " --resume");
  EXPECT_EQ(resumed.status, 1) << resumed.err;
  EXPECT_NE(resumed.out.find("nothing to do"), std::string::npos) << resumed.out;
  EXPECT_NE(resumed.err.find("7 of 7 episodes in " + csv + " failed"), std::string::npos)
      << resumed.err;
}

TEST(RunEpisodes, AnInterruptedRunKeepsCompleteEpisodesOnlyAndResumes) {
  const std::string out = out_dir("interrupted");
  const std::string err = ::testing::TempDir() + "run_episodes_interrupted_stderr.txt";
  // `exec` so that the signal reaches run_episodes, not the shell.
  const std::string command = std::string("exec ") + ARI_RUN_EPISODES_BIN +
                              " --scenario join_group --episodes 50 --out " + out +
                              " >/dev/null 2>" + err;
  pid_t pid = 0;
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  ASSERT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ), 0);
  // SIGINT once the first bag has its final name, as a user pressing Ctrl-C mid-run.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!(fs::exists(out) && !files_ending(out, ".bag").empty()) &&
         std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(kill(pid, SIGINT), 0);
  int raw = 0;
  ASSERT_EQ(waitpid(pid, &raw, 0), pid);
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 130);  // 128 + SIGINT

  const std::vector<std::string> seeds = row_seeds(read_all(out + "/join_group.csv"));
  ASSERT_GE(seeds.size(), 1u);
  ASSERT_LT(seeds.size(), 50u);
  expect_complete_bags(out, seeds);  // the rows equal the complete bags, no .active left
  const std::string message = read_all(err);
  const std::string n = std::to_string(seeds.size());
  EXPECT_NE(message.find("interrupted by SIGINT after " + n + " of 50 episodes: " + n +
                         " rows in " + out + "/join_group.csv, " + n + " bags"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("rerun with --resume to finish"), std::string::npos);

  const ProgramRun resumed = run("--scenario join_group --resume --out " + out);
  // 0 when every episode of the 50 succeeded, else 1 (a few of ARI's joins fail: docs/scenario.md,
  // "Known limits").
  const size_t failed = failed_rows(read_all(out + "/join_group.csv"));
  EXPECT_EQ(resumed.status, failed > 0 ? 1 : 0) << resumed.err;
  EXPECT_LT(failed, 10u);
  std::vector<std::string> all;
  for (int seed = 1; seed <= 50; ++seed) {
    all.push_back(std::to_string(seed));
  }
  EXPECT_EQ(row_seeds(read_all(out + "/join_group.csv")), all);
  expect_complete_bags(out, all);
}

}  // namespace
}  // namespace ari_social_sim::tools::test
