#include <gtest/gtest.h>

#include <map>
#include <set>

#include "ari_social_sim/dialogue/nlg.hpp"
#include "ari_social_sim/dialogue/template_text.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::expect_config_error;

TEST(TemplateText, TwoByThreeAlternativesGiveSixFormsDrawnEvenly) {
  const TemplateText text = TemplateText::parse("[Hello|Hi] [there|ARI|], friend.", "t");
  EXPECT_EQ(text.form_count(), 6u);
  EXPECT_EQ(text.expand(100), (std::vector<std::string>{
                                  "Hello there, friend.", "Hello ARI, friend.", "Hello , friend.",
                                  "Hi there, friend.", "Hi ARI, friend.", "Hi , friend."}));
  core::Rng rng(3);
  std::map<std::string, int> drawn;
  for (int i = 0; i < 6000; ++i) {
    ++drawn[text.draw(rng)];
  }
  ASSERT_EQ(drawn.size(), 6u);
  for (const auto& [form, count] : drawn) {
    // Uniform: 1000 each; 5 standard deviations (sqrt(6000 * 1/6 * 5/6) = 29) either side.
    EXPECT_NEAR(count, 1000, 145) << form;
  }
}

TEST(TemplateText, TheSameSeedGivesTheSameTexts) {
  const TemplateText text = TemplateText::parse("[a|b|c|d] [e|f|g] [h|i|]", "t");
  core::Rng first(42);
  core::Rng second(42);
  core::Rng other(43);
  std::vector<std::string> a;
  std::vector<std::string> b;
  std::vector<std::string> c;
  for (int i = 0; i < 50; ++i) {
    a.push_back(text.draw(first));
    b.push_back(text.draw(second));
    c.push_back(text.draw(other));
  }
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(TemplateText, AboveTheCapEveryAlternativeStillAppears) {
  const TemplateText text = TemplateText::parse("[a|b|c] [d|e] [f|g|h|i]", "t");
  EXPECT_EQ(text.form_count(), 24u);
  EXPECT_EQ(text.expand(24).size(), 24u);
  // Over the cap: as many texts as the widest group, alternative i mod n of each group.
  EXPECT_EQ(text.expand(23), (std::vector<std::string>{"a d f", "b e g", "c d h", "a e i"}));
}

TEST(TemplateText, PlainTextHasOneForm) {
  const TemplateText text = TemplateText::parse("Where is the {object}?", "t");
  EXPECT_EQ(text.form_count(), 1u);
  core::Rng rng(1);
  EXPECT_EQ(text.draw(rng), "Where is the {object}?");
}

TEST(TemplateText, TidyClosesTheGapsOfEmptyAlternatives) {
  EXPECT_EQ(tidy_sentence_text(" where is it ?  "), "Where is it?");
  EXPECT_EQ(tidy_sentence_text("ok , thanks. and  you?"), "Ok, thanks. And you?");
  EXPECT_EQ(tidy_sentence_text("It is 14:30."), "It is 14:30.");
  EXPECT_EQ(tidy_sentence_text("so um..."), "So um...");
  EXPECT_EQ(tidy_sentence_text(""), "");
}

TEST(TemplateText, BadSyntaxNamesTheFieldAndThePlace) {
  expect_config_error(
      [] { TemplateText::parse("[Hello|Hi there", "f.yaml: templates[2].texts[1]"); },
      {"f.yaml: templates[2].texts[1]: expected ']' to close the '[' at character 1",
       "got '[Hello|Hi there'"});
  expect_config_error([] { TemplateText::parse("Hello] there", "f"); },
                      {"f: expected ']' only to close a '[' (at character 6)"});
  expect_config_error([] { TemplateText::parse("[a|[b|c]]", "f"); }, {"groups do not nest"});
  expect_config_error([] { TemplateText::parse("yes|no", "f"); }, {"'|' only between"});
  expect_config_error([] { TemplateText::parse("[maybe] so", "f"); }, {"two or more alternatives"});
  expect_config_error([] { TemplateText::parse("the {place}", "f"); },
                      {"{object}, the only placeholder (at character 5)"});
  expect_config_error([] { TemplateText::parse("object}", "f"); }, {"'}' only as the end"});
}

TEST(TemplateText, TheTemplateFileRefusesBadSyntaxByEntryAndText) {
  expect_config_error(
      [] {
        NlgTemplates::parse(core::YamlMap::parse(
            "templates:\n  - {act: \"thank()\", speaker: human, texts: [\"Thanks.\", \"[Ta|\"]}\n",
            "n.yaml"));
      },
      {"n.yaml: templates[0].texts[1]: expected ']'", "got '[Ta|'"});
}

TEST(TemplateText, NlgListsAndDrawsEveryForm) {
  const Nlg nlg(NlgTemplates::parse(core::YamlMap::parse(
                    "words:\n  - {name: cafe, text: cafeteria}\n"
                    "templates:\n"
                    "  - {act: \"request(location(*))\", speaker: human,\n"
                    "     texts: [\"[Excuse me, |Sorry, |]where is the {object}[ please|]?\"]}\n",
                    "t.yaml")),
                nullptr, NlgMode::kTemplate);
  const DialogueAct act = parse_act("request(location(cafe))", "t");
  const std::vector<std::string> texts = nlg.template_texts(false, act);
  const std::set<std::string> forms(texts.begin(), texts.end());
  EXPECT_EQ(forms,
            (std::set<std::string>{
                "Excuse me, where is the cafeteria please?", "Excuse me, where is the cafeteria?",
                "Sorry, where is the cafeteria please?", "Sorry, where is the cafeteria?",
                "Where is the cafeteria please?", "Where is the cafeteria?"}));
  core::Rng rng(5);
  std::set<std::string> drawn;
  for (int i = 0; i < 200; ++i) {
    drawn.insert(nlg.realise(false, {act}, rng));
  }
  EXPECT_EQ(drawn, forms);
  const std::vector<std::string> vocabulary = nlg.vocabulary();
  for (const std::string word : {"Excuse", "Sorry,", "please?", "Where"}) {
    EXPECT_NE(std::find(vocabulary.begin(), vocabulary.end(), word), vocabulary.end()) << word;
  }
}

}  // namespace
}  // namespace ari_social_sim::dialogue
