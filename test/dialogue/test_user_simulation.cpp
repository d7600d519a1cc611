#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/user_simulation.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

class UserSimulationTest : public ::testing::Test {
 protected:
  UserSimulationTest()
      : setup_(DialogueSetup::create(DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR))),
        users_(setup_->config.users, setup_->domain, setup_->model, "model", *setup_->nlg,
               *setup_->errors, *setup_->timing) {}

  Utterance robot(const std::string& acts) {
    Utterance u;
    u.speaker = kRobot;
    u.acts = parse_acts(acts, "t");
    return u;
  }

  std::unique_ptr<DialogueSetup> setup_;
  UserSimulation users_;
};

TEST_F(UserSimulationTest, RightAnswerResolvesWrongOneCostsPatience) {
  core::Rng rng(1);
  users_.reset(rng);
  Agenda goals({TrackedGoal{Goal{{"patient"}, "go-to", {"toilet"}}},
                TrackedGoal{Goal{{"companion"}, "go-to", {"cafe"}}}});
  goals.mark_stated(0);
  users_.set_agenda(goals);
  const Agenda& agenda = users_.agenda();
  const int patience = users_.humans()[0].patience;
  // A wrong target: the patient's goal stays stated and the patient loses one patience.
  Utterance wrong = robot("inform(directions(cafe))");
  users_.hear_robot(wrong);
  EXPECT_EQ(agenda.goals()[0].status, GoalStatus::kStated);
  EXPECT_EQ(users_.humans()[0].patience, patience - 1);
  // The cafe goal was answered in passing (AG label), although never stated.
  EXPECT_EQ(agenda.goals()[1].status, GoalStatus::kResolved);
  Utterance right = robot("inform(directions(toilet))");
  users_.hear_robot(right);
  EXPECT_EQ(agenda.goals()[0].status, GoalStatus::kResolved);
  ASSERT_EQ(right.goals.size(), 1u);
  EXPECT_EQ(right.goals[0].to_string(), "AG(patient, go-to(toilet))");
  EXPECT_TRUE(users_.finished());
}

TEST_F(UserSimulationTest, CantHelpIsRightOnlyWhereAriCannotKnow) {
  core::Rng rng(1);
  users_.reset(rng);
  Agenda goals({TrackedGoal{Goal{{"patient"}, "get-info", {"appt", "time"}}},
                TrackedGoal{Goal{{"patient"}, "go-to", {"toilet"}}}});
  goals.mark_stated(0);
  goals.mark_stated(1);
  goals.goals()[1].stated_order = -1;  // the appointment question is the most recent
  users_.set_agenda(goals);
  const Agenda& agenda = users_.agenda();
  Utterance decline = robot("cant-help()");
  users_.hear_robot(decline);
  EXPECT_TRUE(agenda.goals()[0].satisfied);  // appt(time): ari_knows false
  users_.hear_robot(decline);                // now the toilets are the focus
  EXPECT_EQ(agenda.goals()[1].status, GoalStatus::kResolved);
  EXPECT_FALSE(agenda.goals()[1].satisfied);  // ARI knows the toilets
}

TEST_F(UserSimulationTest, HumansTakeTurnsWithGapsAndAddressees) {
  core::Rng rng(7);
  int human_to_human = 0;
  int utterances = 0;
  for (int d = 0; d < 200; ++d) {
    users_.reset(rng);
    std::vector<Utterance> transcript;
    users_.open(transcript, rng);
    ASSERT_FALSE(transcript.empty());
    for (size_t i = 0; i < transcript.size(); ++i) {
      const Utterance& u = transcript[i];
      ASSERT_EQ(u.addressees.size(), 1u);
      EXPECT_NE(u.addressees[0], u.speaker);
      if (i > 0) {
        EXPECT_GE(u.start_s, transcript[i - 1].end_s);  // gaps are clipped at 0
      }
      human_to_human += u.addressees[0] != kRobot ? 1 : 0;
      ++utterances;
    }
    // At most max_human_run (6) utterances before ARI gets the floor.
    EXPECT_LE(transcript.size(), 6u);
  }
  // Some opening utterances go to the other human, most to ARI.
  EXPECT_GT(human_to_human, 0);
  EXPECT_LT(human_to_human, utterances);
}

}  // namespace
}  // namespace ari_social_sim::dialogue
