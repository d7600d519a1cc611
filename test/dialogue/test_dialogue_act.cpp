#include <gtest/gtest.h>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/dialogue_act.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(DialogueAct, ParsesNestedSlotsAndValue) {
  const DialogueAct act = parse_act("request(cafe(opening_times(opening_time)))", "t");
  EXPECT_EQ(act.intent, "request");
  // Three nested names: the innermost is the value, the other two the slot path.
  ASSERT_EQ(act.slots.size(), 2u);
  EXPECT_EQ(act.slots[0], "cafe");
  EXPECT_EQ(act.slots[1], "opening_times");
  EXPECT_EQ(act.value, "opening_time");
  EXPECT_EQ(act.to_string(), "request(cafe(opening_times(opening_time)))");
}

TEST(DialogueAct, OneSlotHasNoValueAndEmptyActHasNeither) {
  const DialogueAct food = parse_act("request(food)", "t");
  EXPECT_EQ(food.slots, std::vector<std::string>{"food"});
  EXPECT_EQ(food.value, "");
  const DialogueAct thank = parse_act(" thank() ", "t");
  EXPECT_TRUE(thank.slots.empty());
  EXPECT_EQ(thank.to_string(), "thank()");
}

TEST(DialogueAct, RoundTripsEveryShape) {
  for (const std::string text :
       {"thank()", "request(food)", "request(location(toilet))", "inform(ari(name))",
        "suggest(requesting(beverage(herbal_tea)))"}) {
    EXPECT_EQ(parse_act(text, "t").to_string(), text);
  }
}

TEST(DialogueAct, SplitsOnSemicolonAndTopLevelComma) {
  // convo5: "inform(location(cafe)), inform(beverage(hot_drink))" -> 2 acts; plus greet() -> 3.
  const auto acts = parse_acts("greet(); inform(location(cafe)), inform(beverage(hot_drink))", "t");
  ASSERT_EQ(acts.size(), 3u);
  EXPECT_EQ(acts[2].value, "hot_drink");
  EXPECT_EQ(acts_to_string(acts), "greet(); inform(location(cafe)); inform(beverage(hot_drink))");
}

TEST(DialogueAct, RepairModeFixesBracketsAndCountsThem) {
  int repairs = 0;
  // One surplus `)` (convo6) and one missing `)` (convo12): 2 repairs.
  const auto a = parse_acts("r-repet(directions(cafe)))", "t", true, &repairs);
  const auto b = parse_acts("request(cafe(opening_times())", "t", true, &repairs);
  EXPECT_EQ(repairs, 2);
  EXPECT_EQ(a[0].to_string(), "r-repet(directions(cafe))");
  EXPECT_EQ(b[0].to_string(), "request(cafe(opening_times))");
  EXPECT_THROW(parse_act("r-repet(directions(cafe)))", "t"), core::ConfigError);
}

TEST(DialogueAct, UnknownIntentIsNamedInTheError) {
  try {
    parse_act("requets(location(toilet))", "dom.yaml: goals[0].ask");
    FAIL() << "no error";
  } catch (const core::ConfigError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("dom.yaml: goals[0].ask"), std::string::npos) << message;
    EXPECT_NE(message.find("unknown intent 'requets'"), std::string::npos) << message;
  }
  EXPECT_THROW(parse_act("request", "t"), core::ConfigError);
  EXPECT_THROW(parse_act("request(Location)", "t"), core::ConfigError);
}

TEST(DialogueAct, KnowsTheTwentyFourMpgtIntents) {
  EXPECT_EQ(mpgt_intents().size(), 24u);
  EXPECT_TRUE(is_known_intent("youre-welcome"));
  EXPECT_FALSE(is_known_intent("none"));
}

}  // namespace
}  // namespace ari_social_sim::dialogue
