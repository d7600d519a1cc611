#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "ari_social_sim/batch/batch_plan.hpp"
#include "expect_config_error.hpp"
#include "refusal_text.hpp"

namespace ari_social_sim::batch {
namespace {

TEST(BatchPlan, ShardsCoverEveryEpisodeOnce) {
  std::multiset<uint64_t> seen;
  for (unsigned k = 1; k <= 3; ++k) {
    BatchPlan plan{10, 100, k, 3};
    for (uint64_t i : plan.episode_indices()) {
      seen.insert(i);
    }
  }
  EXPECT_EQ(seen, (std::multiset<uint64_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  const BatchPlan second{10, 100, 2, 3};
  EXPECT_EQ(second.episode_indices(), (std::vector<uint64_t>{1, 4, 7}));
  EXPECT_EQ(second.seed_of(7), 107u);
  // More shards than episodes: the last shards have nothing to do.
  EXPECT_TRUE((BatchPlan{2, 1, 3, 4}).episode_indices().empty());
}

TEST(BatchPlan, ParsesShardsAndNamesBadOnes) {
  BatchPlan plan;
  parse_shard("3/8", "command line", plan);
  EXPECT_EQ(plan.shard_index, 3u);
  EXPECT_EQ(plan.shard_count, 8u);
  for (const char* bad : {"0/4", "5/4", "3", "a/4", "3/", "/4", "-1/4", "1/4/2"}) {
    world::test::expect_config_error([&] { parse_shard(bad, "command line", plan); },
                                     "command line: --shard", {"1 <= K <= N", bad});
  }
}

TEST(BatchPlan, SeedsMustStayBelowTwoToThe31) {
  world::test::expect_config_error(
      [] {
        (BatchPlan{10, 2147483640u, 1, 1}).validate("command line");
      },
      "command line: --seed", {"2147483640..2147483649", "[0, 2147483647]"});
  world::test::expect_config_error(
      [] {
        (BatchPlan{0, 1, 1, 1}).validate("command line");
      },
      "command line: --episodes", {"[1, 1e+06]", "got 0"});
  EXPECT_NO_THROW((BatchPlan{8, 2147483640u, 1, 1}).validate("command line"));
}

// The message validate gives, without a field as run_episodes calls it, or "" when it accepts.
std::string refusal(const BatchPlan& plan) {
  try {
    plan.validate("");
  } catch (const core::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(BatchPlan, ValidateNamesTheOptionsAndStartsThereWithoutAField) {
  // run_episodes prints it after its own name.
  EXPECT_EQ(refusal(BatchPlan{4, 1, 5, 4}), "--shard: expected K/N with 1 <= K <= N, got '5/4'");
  // core::number_text shows six significant digits.
  EXPECT_EQ(refusal(BatchPlan{4, 2147483648u, 1, 1}),
            "--seed: expected a non-negative integer [0, 2.14748e+09], got 2.14748e+09");
  EXPECT_EQ(refusal(BatchPlan{2000000, 1, 1, 1}),
            "--episodes: expected a non-negative integer [1, 1e+06], got 2e+06");
  EXPECT_EQ(refusal(BatchPlan{4, 1, 4, 4}), "");
}

BatchSettings example_settings() {
  BatchSettings settings;
  settings.scenario = "join_group";
  settings.scenario_file = "/data/it's here/join_group.yaml";
  settings.scenario_digest = "00000000000000ab";
  settings.config_digest = "1234567890abcdef";
  settings.plan = BatchPlan{40, 7, 2, 4};
  settings.bags = false;
  return settings;
}

TEST(BatchSettings, RoundTripsThroughTheirYaml) {
  const BatchSettings settings = example_settings();
  const BatchSettings read = BatchSettings::parse(settings.to_yaml(), "x.settings.yaml");
  EXPECT_EQ(read.scenario, "join_group");
  EXPECT_EQ(read.scenario_file, "/data/it's here/join_group.yaml");
  EXPECT_EQ(read.scenario_digest, "00000000000000ab");  // digits stay text, zeros kept
  EXPECT_EQ(read.config_digest, "1234567890abcdef");
  EXPECT_EQ(read.plan.episodes, 40u);
  EXPECT_EQ(read.plan.first_seed, 7u);
  EXPECT_EQ(read.plan.shard_index, 2u);
  EXPECT_EQ(read.plan.shard_count, 4u);
  EXPECT_FALSE(read.bags);
  EXPECT_TRUE(settings.differences(read).empty());
}

TEST(BatchSettings, RoundTripAnyTextAndKeepTheComment) {
  BatchSettings settings = example_settings();
  for (const char* text : {"null", "~", "true", "0012", "1e3", "a: b # c", "'quoted'", "\"double\"",
                           " spaced ", "- item", "[x]", "{y}", "&anchor", "*alias", "!tag",
                           "%percent", "line\nbreak", "ünïcode", ""}) {
    settings.scenario_file = text;
    const std::string yaml = settings.to_yaml();
    EXPECT_EQ(BatchSettings::parse(yaml, "x.settings.yaml").scenario_file, text) << yaml;
  }
  const std::string yaml = example_settings().to_yaml();
  EXPECT_EQ(yaml.rfind("# run_episodes: the settings the rows of the CSV beside this file", 0), 0u)
      << yaml;
  EXPECT_NE(yaml.find("\nshard: 2/4\n"), std::string::npos) << yaml;
}

// What run_episodes wrote before BatchSettings had a visit: every string single-quoted, the shard
// as text.
TEST(BatchSettings, FilesOfEarlierVersionsStillRead) {
  const BatchSettings read = BatchSettings::parse(
      "# run_episodes: the settings the rows of the CSV beside this file were made with;\n"
      "# --resume adds rows only with the same ones (docs/scenario.md, section 6).\n"
      "scenario: 'join_group'\n"
      "scenario_file: '/data/it''s here/join_group.yaml'\n"
      "scenario_digest: '00000000000000ab'\n"
      "config_digest: '1234567890abcdef'\n"
      "first_seed: 7\n"
      "episodes: 40\n"
      "shard: '2/4'\n"
      "bags: false\n",
      "old.settings.yaml");
  const BatchSettings expected = example_settings();
  EXPECT_EQ(read.scenario_file, expected.scenario_file);
  EXPECT_EQ(read.plan.episodes, expected.plan.episodes);
  EXPECT_TRUE(expected.differences(read).empty());  // audio too: written before --audio was
}

std::string refusal(const BatchSettings& settings) {
  return world::test::refusal_text<core::ConfigError>([&] { settings.validate(); });
}

TEST(BatchSettings, ValuesBuiltInCodeAreCheckedByTheFileRules) {
  EXPECT_EQ(refusal(example_settings()), "");
  BatchSettings shard = example_settings();
  shard.plan.shard_index = 5;
  EXPECT_EQ(refusal(shard), "BatchSettings: shard: expected K/N with 1 <= K <= N, got '5/4'");
  BatchSettings seeds = example_settings();
  seeds.plan.first_seed = 2147483620u;
  EXPECT_EQ(refusal(seeds),
            "BatchSettings: first_seed: expected the episodes' seeds in [0, 2147483647] (scene "
            "seeds), got seeds 2147483620..2147483659");
  BatchSettings digest = example_settings();
  digest.config_digest.clear();
  EXPECT_EQ(refusal(digest),
            "BatchSettings: config_digest: expected a value (the field is required), got ''");
}

TEST(BatchSettings, NameEveryDifferenceButTheEpisodeCount) {
  const BatchSettings there = example_settings();
  BatchSettings now = there;
  now.plan.episodes = 80;  // a resumed run may ask for more
  now.scenario_file = "scenarios/join_group.yaml";
  EXPECT_TRUE(there.differences(now).empty());
  now.plan.first_seed = 5;
  now.plan.shard_index = 1;
  now.bags = true;
  now.audio = true;
  now.config_digest = "0";
  EXPECT_EQ(there.differences(now),
            (std::vector<std::string>{
                "config: the configuration files changed since (digest 1234567890abcdef there, "
                "0 now)",
                "--seed: first seed 7 there, 5 now", "--shard: 2/4 there, 1/4 now",
                "--no-bags: no bags there, bags now", "--audio: no audio there, audio now"}));
}

TEST(BatchSettings, BadFilesAreNamed) {
  world::test::expect_config_error(
      [] { BatchSettings::parse("scenario: x\n", "out/x.settings.yaml"); },
      "out/x.settings.yaml: scenario_file", {"required"});
  std::string text = example_settings().to_yaml();
  text.replace(text.find("first_seed: 7"), 13, "first_seed: -7");
  world::test::expect_config_error([&] { BatchSettings::parse(text, "s.yaml"); },
                                   "s.yaml: first_seed", {"-7"});
  for (const char* bad : {"'5/4'", "'0/4'", "3", "'3/'", "'1/4/2'", "[1, 4]"}) {
    std::string shard = example_settings().to_yaml();
    shard.replace(shard.find("shard: 2/4"), 10, std::string("shard: ") + bad);
    world::test::expect_config_error([&] { BatchSettings::parse(shard, "s.yaml"); },
                                     "s.yaml: shard", {});
  }
  std::string seeds = example_settings().to_yaml();
  seeds.replace(seeds.find("first_seed: 7"), 13, "first_seed: 2147483620");
  world::test::expect_config_error([&] { BatchSettings::parse(seeds, "s.yaml"); },
                                   "s.yaml: first_seed", {"2147483620..2147483659"});
}

TEST(DigestFiles, ChangesWithAnyByteAndTheFileBoundary) {
  const std::string dir = ::testing::TempDir() + "digest_files/";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "a") << "seed: 1\n";
  std::ofstream(dir + "b") << "x";
  const std::string digest = digest_files({dir + "a", dir + "b"});
  EXPECT_EQ(digest.size(), 16u);
  EXPECT_EQ(digest_files({dir + "a", dir + "b"}), digest);
  // FNV-1a 64 of nothing is its offset basis, cbf29ce484222325.
  std::ofstream(dir + "empty");
  EXPECT_EQ(digest_files({}), "cbf29ce484222325");
  EXPECT_NE(digest_files({dir + "empty"}), "cbf29ce484222325");  // one boundary
  EXPECT_NE(digest_files({dir + "b", dir + "a"}), digest);
  std::ofstream(dir + "a") << "seed: 2\n";
  EXPECT_NE(digest_files({dir + "a", dir + "b"}), digest);
  world::test::expect_config_error([&] { digest_files({dir + "none"}); }, dir + "none",
                                   {"cannot read"});
}

}  // namespace
}  // namespace ari_social_sim::batch
