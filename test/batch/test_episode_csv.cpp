#include <gtest/gtest.h>

#include <sstream>

#include "ari_social_sim/batch/episode_csv.hpp"
#include "expect_config_error.hpp"

namespace ari_social_sim::batch {
namespace {

size_t columns(const std::string& line) {
  size_t count = 1;
  bool quoted = false;
  for (char c : line) {
    quoted = c == '"' ? !quoted : quoted;
    count += (!quoted && c == ',') ? 1 : 0;
  }
  return count;
}

TEST(EpisodeCsv, RowsMatchTheHeaderAndQuoteText) {
  EpisodeSummary s;
  s.scenario = "group_discussion";
  s.episode = 3;
  s.seed = 4;
  s.finished = true;
  s.outcome = {true, "ARI left, \"happily\"", "leave", 41.5};
  s.states = "grouping=14.20;leave=6.00";
  s.metrics.ari_path_length_m = 9.125;
  s.metrics.contacts = 1;
  s.utterances = 5;
  s.ari_utterances = 3;
  const std::string row = csv_row(s);
  EXPECT_EQ(columns(row), columns(csv_header()));
  EXPECT_EQ(row,
            "group_discussion,3,4,1,\"ARI left, \"\"happily\"\"\",leave,41.500,"
            "grouping=14.20;leave=6.00,9.125,,1,0.000,0.000,0,0,5,3,0,0.000,0.000,0.000,0,-1.000,"
            "-1");
  s.finished = false;  // cut off: never a success
  EXPECT_NE(csv_row(s).find(",0,did not finish,"), std::string::npos);
}

// A row of `scenario` for episode i with seed 100 + i and a reason that spans two lines.
std::string row_of(uint64_t episode) {
  EpisodeSummary s;
  s.scenario = "join_group";
  s.episode = episode;
  s.seed = 100 + episode;
  s.finished = true;
  s.outcome = {false, "no \"space\",\nanywhere", "approach", 12.0};
  return csv_row(s) + "\n";
}

TEST(EpisodeCsv, ReadsBackTheRowsItWrote) {
  const std::string text = csv_header() + "\n" + row_of(0) + row_of(2) + row_of(1);
  const EpisodeCsvContents contents = read_episode_csv(text, "out/join_group.csv");
  ASSERT_EQ(contents.rows.size(), 3u);
  EXPECT_EQ(contents.rows[1].scenario, "join_group");
  EXPECT_EQ(contents.rows[1].episode, 2u);
  EXPECT_EQ(contents.rows[1].seed, 102u);
  EXPECT_FALSE(contents.rows[1].success);
  EXPECT_EQ(contents.rows[1].reason, "no \"space\",\nanywhere");
  EXPECT_EQ(contents.rows[1].final_state, "approach");
  EXPECT_EQ(contents.rows[2].episode, 1u);
  EXPECT_EQ(contents.complete_bytes, text.size());
  EXPECT_FALSE(contents.partial_row);
}

TEST(EpisodeCsv, ARowCutShortIsLeftOut) {
  const std::string complete = csv_header() + "\n" + row_of(0);
  const std::string cut = row_of(1).substr(0, 30);
  const EpisodeCsvContents contents = read_episode_csv(complete + cut, "x.csv");
  EXPECT_EQ(contents.rows.size(), 1u);
  EXPECT_EQ(contents.complete_bytes, complete.size());
  EXPECT_TRUE(contents.partial_row);
  // The quoted reason's newline does not end the row: cut inside the quotes, still partial.
  const std::string in_quotes = row_of(1).substr(0, row_of(1).find('\n') + 1);
  EXPECT_EQ(read_episode_csv(complete + in_quotes, "x.csv").rows.size(), 1u);
  // Nothing, or half a header: the resumed run starts with the header.
  EXPECT_EQ(read_episode_csv("", "x.csv").complete_bytes, 0u);
  const EpisodeCsvContents half = read_episode_csv(csv_header().substr(0, 10), "x.csv");
  EXPECT_EQ(half.complete_bytes, 0u);
  EXPECT_TRUE(half.partial_row);
}

TEST(EpisodeCsv, ForeignOrDamagedRowsAreNamed) {
  const std::string header = csv_header() + "\n";
  world::test::expect_config_error([] { read_episode_csv("scenario,episode,seed\n", "old.csv"); },
                                   "old.csv:1", {"expected the header"});
  world::test::expect_config_error(
      [&] { read_episode_csv(header + row_of(0) + "join_group,1,101\n", "x.csv"); }, "x.csv:4",
      {"expected 24 columns, got 3"});  // row_of spans lines 2 and 3
  std::string bad_seed = row_of(1);
  bad_seed.replace(bad_seed.find(",101,"), 5, ",-1,");
  world::test::expect_config_error([&] { read_episode_csv(header + bad_seed, "x.csv"); }, "x.csv:2",
                                   {"'1' and '-1'"});
  std::string bad_success = row_of(1);
  bad_success.replace(bad_success.find(",101,0,"), 7, ",101,yes,");
  world::test::expect_config_error([&] { read_episode_csv(header + bad_success, "x.csv"); },
                                   "x.csv:2", {"success: expected 0 or 1, got 'yes'"});
  world::test::expect_config_error(
      [&] { read_episode_csv(header + row_of(3) + row_of(3), "x.csv"); }, "x.csv:4",
      {"episode 3 has a row already"});
}

}  // namespace
}  // namespace ari_social_sim::batch
