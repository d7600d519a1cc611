#include <gtest/gtest.h>

#include <set>

#include "../common/data_sets.hpp"
#include "ari_social_sim/dialogue/nlg.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::config_path;
using testing::expect_config_error;

const char* kTemplates = R"yaml(
words:
  - {name: cafe, text: cafeteria}
templates:
  - {act: "request(location(*))", speaker: human, texts: ["Where is the {object}?"]}
  - {act: "thank()", speaker: any, texts: ["Thanks."]}
  - {act: "none", speaker: human, texts: ["Hmm."]}
)yaml";

TEST(Nlg, TemplatesFillTheObject) {
  const Nlg nlg(NlgTemplates::parse(core::YamlMap::parse(kTemplates, "t.yaml")), nullptr,
                NlgMode::kTemplate);
  core::Rng rng(1);
  EXPECT_EQ(nlg.realise(false, {parse_act("request(location(cafe))", "t")}, rng),
            "Where is the cafeteria?");
  EXPECT_EQ(nlg.realise(false, {parse_act("request(location(room_17))", "t")}, rng),
            "Where is the room 17?");
  EXPECT_EQ(nlg.realise(true, {parse_act("thank()", "t")}, rng), "Thanks.");
  EXPECT_EQ(nlg.realise(false, {}, rng), "Hmm.");
  // Two acts: two texts joined.
  EXPECT_EQ(nlg.realise(false, parse_acts("thank(); request(location(cafe))", "t"), rng),
            "Thanks. Where is the cafeteria?");
}

TEST(Nlg, TemplateTextsListEveryForm) {
  const Nlg nlg(NlgTemplates::load(config_path("nlg_templates.yaml")), nullptr, NlgMode::kTemplate);
  // nlg_templates.yaml: five human texts for request(location(*)) with 6x4x2, 3x2x2x2x2, 2x3x4,
  // 3x2x5 and 3x3 forms; toilet -> toilets.
  const std::vector<std::string> texts =
      nlg.template_texts(false, parse_act("request(location(toilet))", "t"));
  ASSERT_EQ(texts.size(), 48u + 48u + 24u + 30u + 9u);
  EXPECT_EQ(texts[0], "Excuse me, where is the toilets, please?");
  EXPECT_EQ(std::set<std::string>(texts.begin(), texts.end()).size(), texts.size());
  // 4x2 + 2x3x2 + 1 ways to offer help.
  EXPECT_EQ(nlg.template_texts(true, parse_act("offer-help()", "t")).size(), 21u);
  EXPECT_TRUE(nlg.template_texts(true, parse_act("call-nurse()", "t")).empty());
}

TEST(Nlg, RetrievalReturnsRealUtterances) {
  ARI_SKIP_WITHOUT_DATA_SET(kMpgtDataSet);
  const MpgtCorpus corpus = load_mpgt_corpus(core::data_set_dir(kMpgtDataSet));
  const Nlg nlg(NlgTemplates::load(config_path("nlg_templates.yaml")), &corpus,
                NlgMode::kRetrieval);
  // Every text ARI says for an act the corpus's ARI said is one of its utterances with that act.
  const DialogueAct act = parse_act("inform(location(toilet))", "t");
  std::set<std::string> said_in_corpus;
  for (const CorpusDialogue& dialogue : corpus.dialogues) {
    for (const CorpusUtterance& u : dialogue.utterances) {
      if (u.is_robot() && u.acts == std::vector<DialogueAct>{act}) {
        said_in_corpus.insert(u.text);
      }
    }
  }
  ASSERT_FALSE(said_in_corpus.empty());
  core::Rng rng(4);
  for (int draw = 0; draw < 20; ++draw) {
    const std::string text = nlg.realise(true, {act}, rng);
    EXPECT_EQ(said_in_corpus.count(text), 1u) << text;
  }
}

TEST(Nlg, RetrievalWithoutTheCorpusIsRefused) {
  EXPECT_THROW(Nlg(NlgTemplates::parse(core::YamlMap::parse(kTemplates, "t.yaml")), nullptr,
                   NlgMode::kRetrieval),
               core::ConfigError);
}

TEST(Nlg, BadTemplatesNameFileAndEntry) {
  expect_config_error(
      [] {
        NlgTemplates::parse(core::YamlMap::parse(
            "templates:\n  - {act: \"thnak()\", speaker: human, texts: [x]}\n", "n.yaml"));
      },
      {"n.yaml: templates[0].act", "unknown intent 'thnak'"});
  expect_config_error(
      [] {
        NlgTemplates::parse(core::YamlMap::parse(
            "templates:\n  - {act: \"thank()\", speaker: robto, texts: [x]}\n", "n.yaml"));
      },
      {"n.yaml: templates[0].speaker", "robto"});
  EXPECT_THROW(parse_nlg_mode("neural", "nlg"), core::ConfigError);
}

}  // namespace
}  // namespace ari_social_sim::dialogue
