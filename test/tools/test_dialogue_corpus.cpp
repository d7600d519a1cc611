// Runs the dialogue_corpus program as a user would: counts, seeds and paths checked before the
// first dialogue, outputs never half-written nor silently replaced.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "../common/data_sets.hpp"
#include "../common/file_size_limit.hpp"
#include "ari_social_sim/core/data_sets.hpp"
#include "program_run.hpp"

namespace ari_social_sim::tools::test {
namespace {

namespace fs = std::filesystem;

ProgramRun run(const std::string& arguments) {
  return run_program(ARI_DIALOGUE_CORPUS_BIN, arguments);
}

// A fresh empty folder for one test.
std::string scratch(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "dialogue_corpus_" + name + "/";
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

size_t count_lines(const std::string& text) {
  return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(DialogueCorpus, BadOptionsExitWithTwoBeforeWritingAnything) {
  const std::string dir = scratch("bad");
  const std::string out = " --out " + dir + "c.jsonl";
  // -1 once wrapped to 2^64 - 1 dialogues and filled the disk.
  expect_refused(run("--dialogues -1 --seed 1" + out),
                 "--dialogues: expected an integer in [1, 100000], got '-1'");
  expect_refused(run("--dialogues 0 --seed 1" + out), "got '0'");
  expect_refused(run("--dialogues 100001 --seed 1" + out), "got '100001'");
  expect_refused(run("--dialogues 1e3 --seed 1" + out), "got '1e3'");
  expect_refused(run("--dialogues 2 --seed -1" + out),
                 "--seed: expected an integer in [0, 9223372036854775807], got '-1'");
  expect_refused(run("--dialogues 2 --seed 9223372036854775808" + out), "--seed");
  expect_refused(run("--dialogues 2 --seed 1 --out " + dir),
                 "--out: " + dir + ": expected a file name, got a directory");
  expect_refused(run("--dialogues 2 --seed 1 --out " + dir + "no/c.jsonl"), "does not exist");
  expect_refused(run("--dialogues 2 --seed 1 --compare --report /proc/report.md"),
                 "--report: /proc/report.md: cannot write in /proc");
  expect_refused(run("--dialogues 2 --seed 1 --report " + dir + "r.md" + out),
                 "--report: the report holds the tables of --compare and --variety: expected one "
                 "of them too");
  expect_refused(run("--dialogues 2 --seed 1 --compare --report " + dir + "c.jsonl" + out),
                 "expected two files");
  expect_refused(run("--dialogues 2 --seed 1 --config " + dir + out),
                 "--config: " + dir + ": expected a readable file, got a directory");
  expect_refused(run("--dialogues 2 --seed 1 --corpus " + dir + "none" + out),
                 "--corpus: " + dir + "none: expected a directory");
  expect_refused(run("--dialogues 2 --seed 1 --nlg fancy" + out), "--nlg");
  expect_refused(run("--dialogues 2 --seed 1 --frobnicate" + out), "--frobnicate");
  expect_refused(run("--dialogues 2" + out), "are required");
  expect_refused(run("--dialogues 2 --seed 1 --compare --out ''"),
                 "--out: expected a value, got ''");
  EXPECT_EQ(fs::directory_iterator(dir), fs::directory_iterator());  // nothing written
}

// --help says where the MPGT corpus comes from and what needs it, naming no folder outside the
// repository.
// A job array's shards merged (--merge-shards) are the corpus one process writes, byte for byte
// (docs/cluster.md); a shard missing or from another run is refused.
TEST(DialogueCorpus, ShardsMergeIntoWhatOneProcessWrites) {
  const std::string dir = scratch("shards");
  const std::string plan = "--dialogues 6 --seed 3 --out ";
  ASSERT_EQ(run(plan + dir + "whole.jsonl").status, 0);
  for (int k = 1; k <= 3; ++k) {
    ASSERT_EQ(run(plan + dir + "c.jsonl --shard " + std::to_string(k) + "/3").status, 0);
  }
  EXPECT_TRUE(fs::exists(dir + "c_shard2-of-3.jsonl"));
  const ProgramRun merged = run(plan + dir + "c.jsonl --merge-shards 3");
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_EQ(read_all(dir + "c.jsonl"), read_all(dir + "whole.jsonl"));
  EXPECT_FALSE(fs::exists(dir + "c_shard2-of-3.jsonl"));

  ASSERT_EQ(run(plan + dir + "d.jsonl --shard 1/3").status, 0);
  expect_refused(run(plan + dir + "d.jsonl --merge-shards 3"), "d_shard2-of-3.jsonl: not found");
  // Shard 1 of a run of 9 holds dialogue 6, which a run of 6 has not.
  ASSERT_EQ(run("--dialogues 9 --seed 3 --out " + dir + "e.jsonl --shard 1/3").status, 0);
  for (int k = 2; k <= 3; ++k) {
    ASSERT_EQ(run(plan + dir + "e.jsonl --shard " + std::to_string(k) + "/3").status, 0);
  }
  expect_refused(run(plan + dir + "e.jsonl --merge-shards 3"), "dialogue 6 is not one of");
  expect_refused(run(plan + dir + "f.jsonl --shard 1/3 --variety"), "neither --compare nor");
}

TEST(DialogueCorpus, HelpSaysWhereTheCorpusComesFrom) {
  const ProgramRun help = run("--help");
  EXPECT_EQ(help.status, 0);
  for (const std::string fragment :
       {"https://github.com/AddleseeHQ/mpgt-eval", "corpus_dir in --config",
        "needed only by --compare and retrieval", "scripts/fetch_data.sh", "$ARI_MPGT_DIR",
        "--variety"}) {
    EXPECT_NE(help.err.find(fragment), std::string::npos) << help.err;
  }
  EXPECT_EQ(help.err.find("../"), std::string::npos) << help.err;
}

// What needs the corpus refuses before the first dialogue when it is nowhere; the rest runs.
TEST(DialogueCorpus, WithoutTheCorpusOnlyCompareAndRetrievalAreRefused) {
  const std::string dir = scratch("no_corpus");
  const std::string no_corpus =
      "env -u ARI_MPGT_DIR ARI_DATA_DIR=" + dir + "data " + std::string(ARI_DIALOGUE_CORPUS_BIN);
  const std::string args = "--dialogues 2 --seed 1 --out " + dir + "c.jsonl";
  expect_refused(run_program(no_corpus, args + " --compare"),
                 "--compare needs the MPGT corpus, and none was given (no --corpus DIR, "
                 "ARI_MPGT_DIR not set): data set 'dialogue/mpgt' is not in " +
                     dir + "data/dialogue/mpgt: fetch it with scripts/fetch_data.sh");
  expect_refused(run_program(no_corpus, args + " --nlg retrieval"),
                 "retrieval NLG (--nlg or nlg in --config) needs the MPGT corpus");
  EXPECT_FALSE(fs::exists(dir + "c.jsonl"));
  const ProgramRun templates = run_program(no_corpus, args + " --variety");
  ASSERT_EQ(templates.status, 0) << templates.err;
  EXPECT_GE(count_lines(read_all(dir + "c.jsonl")), 10u);
}

TEST(DialogueCorpus, CompareReadsTheDataSet) {
  ARI_SKIP_WITHOUT_DATA_SET("dialogue/mpgt");
  const ProgramRun compared =
      run_program("env -u ARI_MPGT_DIR " + std::string(ARI_DIALOGUE_CORPUS_BIN),
                  "--dialogues 3 --seed 2 --compare --nlg retrieval");
  ASSERT_EQ(compared.status, 0) << compared.err;
  EXPECT_NE(compared.out.find("corpus: MPGT, 29 conversations"), std::string::npos) << compared.out;
}

// The pooled row of one side of the --variety table: utterances, distinct texts, ratio.
struct PooledVariety {
  size_t utterances{0};
  size_t distinct{0};
  double ratio{0.0};
};

PooledVariety pooled_variety(const std::string& table, const std::string& side) {
  const std::string row = "| " + side + " | all ";
  const size_t at = table.find(row);
  EXPECT_NE(at, std::string::npos) << table;
  PooledVariety pooled;
  if (at != std::string::npos) {
    std::sscanf(table.c_str() + table.find("| ", at + row.size()), "| %zu | %zu | %lf",
                &pooled.utterances, &pooled.distinct, &pooled.ratio);
  }
  return pooled;
}

TEST(DialogueCorpus, VarietyCountsDistinctTextsPerAct) {
  const ProgramRun variety = run("--dialogues 100 --seed 1 --variety");
  ASSERT_EQ(variety.status, 0) << variety.err;
  EXPECT_NE(variety.out.find("Variety: 100 dialogues, seed 1, template NLG"), std::string::npos)
      << variety.out;
  EXPECT_NE(variety.out.find("| humans | thank() | "), std::string::npos) << variety.out;
  EXPECT_NE(variety.out.find("| ARI | "), std::string::npos) << variety.out;
  const PooledVariety humans = pooled_variety(variety.out, "humans");
  EXPECT_GT(humans.utterances, 1000u);  // about 20 human utterances a dialogue
  EXPECT_NEAR(humans.ratio, static_cast<double>(humans.distinct) / humans.utterances, 0.005);
  // The grammar's forms: most human utterances are worded afresh (0.89 measured).
  EXPECT_GT(humans.ratio, 0.8);
  // The same seed, the same table.
  EXPECT_EQ(run("--dialogues 100 --seed 1 --variety").out, variety.out);
}

TEST(DialogueCorpus, AnExistingOutputIsReplacedOnlyWithOverwrite) {
  const std::string dir = scratch("existing");
  const std::string args = "--seed 1 --out " + dir + "c.jsonl";
  ASSERT_EQ(run("--dialogues 2 " + args).status, 0);
  const std::string two = read_all(dir + "c.jsonl");
  EXPECT_GE(count_lines(two), 10u);  // two dialogues of several utterances
  expect_refused(run("--dialogues 3 " + args), "c.jsonl: exists (pass --overwrite to replace it)");
  EXPECT_EQ(read_all(dir + "c.jsonl"), two);
  ASSERT_EQ(run("--dialogues 3 --overwrite " + args).status, 0);
  const std::string three = read_all(dir + "c.jsonl");
  EXPECT_EQ(three.substr(0, two.size()), two);  // dialogue d has the same seed whatever N
  EXPECT_GT(count_lines(three), count_lines(two));
  EXPECT_FALSE(fs::exists(dir + "c.jsonl.part"));
}

TEST(DialogueCorpus, TheReportIsWhatStandardOutputShows) {
  const std::string dir = scratch("report");
  const ProgramRun run_1 = run("--dialogues 3 --seed 2 --variety --report " + dir + "r.md");
  ASSERT_EQ(run_1.status, 0) << run_1.err;
  EXPECT_EQ(read_all(dir + "r.md"), run_1.out);
  EXPECT_NE(run_1.out.find("Variety: 3 dialogues, seed 2"), std::string::npos);
}

TEST(DialogueCorpus, AFailedWriteExitsWithOneAndLeavesNoFile) {
  const std::string dir = scratch("full");
  const ari_social_sim::test::FileSizeLimit full_disk(4096);  // 20 dialogues take more
  const ProgramRun full = run("--dialogues 20 --seed 1 --out " + dir + "c.jsonl");
  EXPECT_EQ(full.status, 1);
  EXPECT_NE(full.err.find(dir + "c.jsonl: writing failed"), std::string::npos) << full.err;
  EXPECT_FALSE(fs::exists(dir + "c.jsonl"));
}

}  // namespace
}  // namespace ari_social_sim::tools::test
