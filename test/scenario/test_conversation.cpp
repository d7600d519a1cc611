#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/scenario/conversation.hpp"

namespace ari_social_sim::scenario {
namespace {

// Keeps the acts of what ARI says.
struct SaidByAri {
  std::vector<std::string> acts;
  void take(const std::optional<SayAction>& said) {
    if (said) {
      EXPECT_TRUE(said->speaker.is_ari());
      EXPECT_FALSE(said->text.empty());
      acts.push_back(said->act);
    }
  }
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
  Conversation conversation(*setup, 3, Hearing::kSimulated);
  conversation.start();
  commands.take(conversation.update(obs));
  ASSERT_EQ(commands.acts.size(), 1u);
  EXPECT_EQ(commands.acts[0], "greet(); inform(ari(name)); offer-help()");

  // ARI's greeting plays; meanwhile the patient talks to the companion, then asks ARI.
  set_speaking(true, false);
  commands.take(conversation.update(obs));
  set_speaking(false, true);
  obs.heard = {request("request(location(toilet))", false)};
  commands.take(conversation.update(obs));
  obs.heard = {request("request(location(toilet))")};
  commands.take(conversation.update(obs));
  EXPECT_EQ(commands.acts.size(), 1u) << "ARI spoke while the patient was speaking";
  obs.heard.clear();
  set_speaking(false, false);
  commands.take(conversation.update(obs));
  ASSERT_EQ(commands.acts.size(), 2u);
  EXPECT_EQ(commands.acts[1], "inform(directions(toilet))");  // the domain's answer
  EXPECT_EQ(conversation.robot_turns(), 2);

  // Said to the companion only: ARI stays silent.
  set_speaking(true, false);
  commands.take(conversation.update(obs));
  set_speaking(false, false);
  obs.heard = {request("request(location(cafe))", false)};
  commands.take(conversation.update(obs));
  EXPECT_EQ(commands.acts.size(), 2u);

  // The dialogue ends: ARI stops taking turns.
  obs.heard = {request("request(location(cafe))")};
  DialogueEnd end;
  end.complete = end.success = true;
  end.robot_turns = 2;
  end.utterances = 6;
  obs.dialogue_end = end;
  commands.take(conversation.update(obs));
  EXPECT_FALSE(conversation.active());
  EXPECT_EQ(commands.acts.size(), 2u);
}

TEST_F(ConversationTest, WaitsForItsOwnUtteranceToPlay) {
  Conversation conversation(*setup, 3, Hearing::kSimulated);
  conversation.start();
  commands.take(
      conversation.update(obs));  // greeting sent, not yet playing (/tts waits for the floor)
  obs.heard = {request("request(location(toilet))")};
  commands.take(conversation.update(obs));
  EXPECT_EQ(commands.acts.size(), 1u);
  obs.heard.clear();
  set_speaking(true, false);
  commands.take(conversation.update(obs));
  set_speaking(false, false);
  commands.take(conversation.update(obs));  // played: now it answers the request it kept
  ASSERT_EQ(commands.acts.size(), 2u);
  EXPECT_EQ(commands.acts[1], "inform(directions(toilet))");  // the domain's answer
}

TEST_F(ConversationTest, HearsTheRecogniserWhenToldTo) {
  // speech:=audio: the dialogue's simulated perceptions are ignored, the transcripts understood.
  Conversation conversation(*setup, 3, Hearing::kRecognised);
  conversation.start();
  commands.take(conversation.update(obs));  // the greeting
  set_speaking(true, false);
  commands.take(conversation.update(obs));
  set_speaking(false, false);
  obs.heard = {request("request(location(toilet))")};
  commands.take(conversation.update(obs));
  EXPECT_EQ(commands.acts.size(), 1u) << "ARI answered a simulated perception";
  obs.heard.clear();
  obs.transcripts = {{"voice2", "excuse me where is the cafeteria please", 0.6}};
  commands.take(conversation.update(obs));
  ASSERT_EQ(commands.acts.size(), 2u);
  EXPECT_EQ(commands.acts[1], "inform(directions(cafe))");
}

}  // namespace
}  // namespace ari_social_sim::scenario
