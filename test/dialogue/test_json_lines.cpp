#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/json_lines.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(JsonLines, EscapesAndLaysOutKeys) {
  Utterance u;
  u.turn = 3;
  u.speaker = "ARI";
  u.addressees = {"patient", "companion"};
  u.text = "Hello.";
  u.acts = {parse_act("greet()", "t")};
  u.goals = {GoalLabel{GoalLabelKind::kAnswered, Goal{{"patient"}, "go-to", {"toilet"}}}};
  u.end_s = 0.4;
  EXPECT_EQ(utterance_json(7, u),
            "{\"dialogue\":7,\"turn\":3,\"speaker\":\"ARI\",\"addressee\":[\"patient\","
            "\"companion\"],\"text\":\"Hello.\",\"acts\":[\"greet()\"],\"goals\":[\"AG(patient, "
            "go-to(toilet))\"],\"start_s\":0.000,\"end_s\":0.400}");
}

TEST(JsonLines, HumanUtterancesCarryWhatAriHeard) {
  Utterance u;
  u.speaker = "patient";
  u.addressees = {"ARI"};
  u.heard.dropped = true;
  const std::string line = utterance_json(0, u);
  EXPECT_NE(line.find("\"addressee\":\"ARI\""), std::string::npos) << line;
  EXPECT_NE(line.find("\"heard\":{\"dropped\":true}"), std::string::npos) << line;
}

}  // namespace
}  // namespace ari_social_sim::dialogue
