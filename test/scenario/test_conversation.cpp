#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/scenario/conversation.hpp"

namespace ari_social_sim::scenario {
namespace {

// Keeps what ARI was asked to say.
class SaidByAri : public Commands {
 public:
  std::vector<std::string> acts;
  void say(const AgentRef& speaker, const std::string& act, const std::string& text) override {
    EXPECT_TRUE(speaker.is_ari());
    EXPECT_FALSE(text.empty());
    acts.push_back(act);
  }
  void set_human_goal(world::ObjectId, const core::Pose2&) override {}
  void navigate(const core::Pose2&) override {}
  void approach(world::ObjectId, bool) override {}
  void cancel_navigation() override {}
  void add_human(const world::HumanSpec&) override {}
  void remove_human(world::ObjectId) override {}
  void create_group(const world::GroupSpec&) override {}
  void add_group_members(world::ObjectId, const std::vector<world::ObjectId>&) override {}
  void set_group_centre(world::ObjectId, const Eigen::Vector2d&) override {}
};

class ConversationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    setup = dialogue::DialogueSetup::create(
        dialogue::DialogueConfig::defaults(dialogue::default_dialogue_config_dir()));
    obs.world.ari = world::AriSnapshot{};
    world::HumanSnapshot patient;
    patient.id = 10;
    obs.world.humans = {patient};
  }
  // The patient's request addressed to ARI, as ARI heard it.
  static dialogue::Perception request(const std::string& act, bool to_ari = true) {
    dialogue::Perception p;
    p.speaker = "patient";
    p.addressees = {to_ari ? "ARI" : "companion"};
    p.text = "where is it";
    p.acts = {dialogue::parse_act(act, "test")};
    return p;
  }
  void set_speaking(bool ari, bool patient) {
    obs.world.ari->speech.is_speaking = ari;
    obs.world.humans[0].speech.is_speaking = patient;
  }

  std::unique_ptr<dialogue::DialogueSetup> setup;
  Observations obs;
  SaidByAri commands;
};

TEST_F(ConversationTest, OpensWithTheGreetingThenAnswersWhatIsAddressedToAri) {
  Conversation conversation(*setup, 3);
  conversation.start();
  conversation.update(obs, commands);
  ASSERT_EQ(commands.acts.size(), 1u);
  EXPECT_EQ(commands.acts[0], "greet(); inform(ari(name)); offer-help()");

  // ARI's greeting plays; meanwhile the patient talks to the companion, then asks ARI.
  set_speaking(true, false);
  conversation.update(obs, commands);
  set_speaking(false, true);
  obs.heard = {request("request(location(toilet))", false)};
  conversation.update(obs, commands);
  obs.heard = {request("request(location(toilet))")};
  conversation.update(obs, commands);
  EXPECT_EQ(commands.acts.size(), 1u) << "ARI spoke while the patient was speaking";
  obs.heard.clear();
  set_speaking(false, false);
  conversation.update(obs, commands);
  ASSERT_EQ(commands.acts.size(), 2u);
  EXPECT_EQ(commands.acts[1], "inform(directions(toilet))");  // the domain's answer
  EXPECT_EQ(conversation.robot_turns(), 2);

  // Said to the companion only: ARI stays silent.
  set_speaking(true, false);
  conversation.update(obs, commands);
  set_speaking(false, false);
  obs.heard = {request("request(location(cafe))", false)};
  conversation.update(obs, commands);
  EXPECT_EQ(commands.acts.size(), 2u);

  // The dialogue ends: ARI stops taking turns.
  obs.heard = {request("request(location(cafe))")};
  obs.dialogue_end = DialogueEnd{true, true, false, 2, 6, 70.0};
  conversation.update(obs, commands);
  EXPECT_FALSE(conversation.active());
  EXPECT_EQ(commands.acts.size(), 2u);
}

TEST_F(ConversationTest, WaitsForItsOwnUtteranceToPlay) {
  Conversation conversation(*setup, 3);
  conversation.start();
  conversation.update(obs, commands);  // greeting sent, not yet playing (/tts waits for the floor)
  obs.heard = {request("request(location(toilet))")};
  conversation.update(obs, commands);
  EXPECT_EQ(commands.acts.size(), 1u);
  obs.heard.clear();
  set_speaking(true, false);
  conversation.update(obs, commands);
  set_speaking(false, false);
  conversation.update(obs, commands);  // played: now it answers the request it kept
  ASSERT_EQ(commands.acts.size(), 2u);
  EXPECT_EQ(commands.acts[1], "inform(directions(toilet))");  // the domain's answer
}

}  // namespace
}  // namespace ari_social_sim::scenario
