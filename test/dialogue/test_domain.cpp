#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/domain.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::config_path;
using testing::expect_config_error;
using testing::replace_once;

const char* kSmallDomain = R"yaml(
predicates:
  - name: go-to
    weight: 3
    ask: ["request(location(*))", "request(directions(*))"]
    answer: "inform(directions(*))"
    objects:
      - {path: toilet, weight: 1, ari_knows: true}
      - {path: stairs, weight: 1, ari_knows: false}
  - name: eat
    weight: 1
    ask: ["request(food(*))"]
    answer: "inform(food(*))"
    objects:
      - {path: "", weight: 1, ari_knows: true}
)yaml";

TEST(Domain, HospitalDomainSamplesPredicatesByWeight) {
  const Domain domain = Domain::load(config_path("hospital_domain.yaml"));
  ASSERT_EQ(domain.predicates().size(), 5u);
  core::Rng rng(1);
  int go_to = 0;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    go_to += domain.sample_goal({"patient"}, rng).predicate == "go-to" ? 1 : 0;
  }
  // Weights 211 / (211 + 71 + 68 + 58 + 2) = 211 / 410 = 0.515; binomial sd 0.005.
  EXPECT_NEAR(go_to / static_cast<double>(n), 211.0 / 410.0, 0.02);
}

TEST(Domain, AsksAnswersAndRecognisesGoals) {
  const Domain domain = Domain::parse(core::YamlMap::parse(kSmallDomain, "small.yaml"));
  const Goal toilet{{"patient"}, "go-to", {"toilet"}};
  const auto asks = domain.ask_acts(toilet);
  ASSERT_EQ(asks.size(), 2u);
  EXPECT_EQ(asks[0].to_string(), "request(location(toilet))");
  EXPECT_EQ(domain.answer_act(toilet).to_string(), "inform(directions(toilet))");
  // An empty object drops the `*` level: eat() is asked as request(food).
  const Goal eat{{"companion"}, "eat", {}};
  EXPECT_EQ(domain.ask_acts(eat)[0].to_string(), "request(food)");
  EXPECT_EQ(domain.goal_of_request(parse_act("request(food)", "t"))->predicate_text(), "eat()");
  EXPECT_EQ(domain.goal_of_request(parse_act("request(directions(stairs))", "t"))->predicate_text(),
            "go-to(stairs)");
  EXPECT_FALSE(domain.goal_of_request(parse_act("request(location(moon))", "t")).has_value());
  EXPECT_EQ(domain.goal_of_answer(parse_act("inform(directions(toilet))", "t"))->predicate_text(),
            "go-to(toilet)");
  EXPECT_FALSE(domain.find_object(Goal{{}, "go-to", {"stairs"}})->ari_knows);
}

TEST(Domain, UnknownIntentNamesFileAndEntry) {
  const std::string text = replace_once(kSmallDomain, "request(food(*))", "requets(food(*))");
  expect_config_error([&] { Domain::parse(core::YamlMap::parse(text, "bad_domain.yaml")); },
                      {"bad_domain.yaml", "predicates[1].ask[0]", "'requets(food(*))'",
                       "unknown intent 'requets'"});
}

TEST(Domain, BadWeightPatternAndUnknownKeyAreErrors) {
  const std::string zero = replace_once(kSmallDomain, "weight: 3", "weight: 0");
  expect_config_error([&] { Domain::parse(core::YamlMap::parse(zero, "d.yaml")); },
                      {"d.yaml: predicates[0].weight", "> 0", "0"});
  const std::string no_star =
      replace_once(kSmallDomain, "inform(directions(*))", "inform(directions(x))");
  expect_config_error([&] { Domain::parse(core::YamlMap::parse(no_star, "d.yaml")); },
                      {"predicates[0].answer", "*"});
  const std::string typo = replace_once(kSmallDomain, "ari_knows: false", "ari_know: false");
  expect_config_error([&] { Domain::parse(core::YamlMap::parse(typo, "d.yaml")); },
                      {"d.yaml", "objects[1]"});
}

TEST(Domain, PatternsRoundTrip) {
  const DialogueAct pattern{"request", {"cafe", "*"}, ""};
  const DialogueAct act = instantiate_pattern(pattern, {"opening_times", "closing_time"});
  EXPECT_EQ(act.to_string(), "request(cafe(opening_times(closing_time)))");
  EXPECT_EQ(*match_pattern(pattern, act),
            (std::vector<std::string>{"opening_times", "closing_time"}));
}

}  // namespace
}  // namespace ari_social_sim::dialogue
