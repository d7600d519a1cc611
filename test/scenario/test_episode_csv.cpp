#include <gtest/gtest.h>

#include <sstream>

#include "ari_social_sim/scenario/episode_csv.hpp"

namespace ari_social_sim::scenario {
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
  s.wall_time_s = 0.25;
  const std::string row = csv_row(s);
  EXPECT_EQ(columns(row), columns(csv_header()));
  EXPECT_EQ(row,
            "group_discussion,3,4,1,\"ARI left, \"\"happily\"\"\",leave,41.500,"
            "grouping=14.20;leave=6.00,9.125,,1,0.000,0.000,0,0,5,3,0.2500");
  s.finished = false;  // cut off: never a success
  EXPECT_NE(csv_row(s).find(",0,did not finish,"), std::string::npos);
}

}  // namespace
}  // namespace ari_social_sim::scenario
