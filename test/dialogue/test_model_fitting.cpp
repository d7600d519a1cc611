#include <gtest/gtest.h>

#include "../common/data_sets.hpp"
#include "ari_social_sim/dialogue/model_fitting.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(ModelFitting, CountsContextsOfATinyCorpus) {
  MpgtCorpus corpus;
  corpus.dialogues.push_back(
      parse_mpgt_dialogue("ARI: Hello. # greet()\n"
                          "LP: Where is the cafe? # request(location(cafe)) @ G(LP, go-to(cafe))\n"
                          "ARI: Ground floor. # inform(location(cafe)) @ AG(LP, go-to(cafe))\n"
                          "LP: Shall we go? # suggest(going-to(cafe))\n"
                          "RC: Yes. # affirm()\n"
                          "RC: Thank you. # thank()\n",
                          "tiny"));
  FitOptions options;
  options.min_row_count = 1;
  options.prior_weight = 0.0;
  const UserModel model = fit_user_model(corpus, options);
  EXPECT_DOUBLE_EQ(model.robot_opens, 1.0);
  const RoleModel& patient = model.roles.at("patient");
  EXPECT_DOUBLE_EQ(patient.after_robot.row("greet").probability_of("request"), 1.0);
  EXPECT_DOUBLE_EQ(patient.after_robot.row("inform").probability_of("suggest"), 1.0);
  // LP's suggest is followed by RC and does not name ARI: human-to-human (1 of 1).
  EXPECT_DOUBLE_EQ(patient.to_other_probability("suggest"), 1.0);
  EXPECT_DOUBLE_EQ(patient.to_other_probability("request"), 0.0);
  const RoleModel& companion = model.roles.at("companion");
  EXPECT_DOUBLE_EQ(companion.after_other.row("suggest").probability_of("affirm"), 1.0);
  EXPECT_DOUBLE_EQ(companion.after_self.row("affirm").probability_of("thank"), 1.0);
  // One distinct goal target, not joint.
  ASSERT_EQ(model.goals.counts.size(), 1u);
  EXPECT_EQ(model.goals.counts[0], 1u);
  EXPECT_DOUBLE_EQ(model.goals.joint_share, 0.0);
}

TEST(ModelFitting, MpgtFitMatchesSpecsSection22) {
  ARI_SKIP_WITHOUT_DATA_SET(kMpgtDataSet);
  const MpgtCorpus corpus = load_mpgt_corpus(core::data_set_dir(kMpgtDataSet));
  FitOptions options;
  options.min_row_count = 1;
  const UserModel model = fit_user_model(corpus, options);
  // In MPGT: after ARI's greet (n 25), the next human intent is request 60 %; the two roles'
  // rows pooled give it back.
  const auto& c = model.roles.at("companion").after_robot.row("greet");
  const auto& p = model.roles.at("patient").after_robot.row("greet");
  EXPECT_EQ(c.count + p.count, 25);
  EXPECT_NEAR(
      (c.probability_of("request") * c.count + p.probability_of("request") * p.count) / 25.0, 0.60,
      1e-9);
  // 21 of 29 conversations open with ARI.
  EXPECT_NEAR(model.robot_opens, 21.0 / 29.0, 1e-9);
}

TEST(ModelFitting, RejectsBadOptions) {
  FitOptions options;
  options.min_row_count = 0;
  testing::expect_config_error([&] { options.validate(); },
                               {"FitOptions: min_row_count", "> 0", "got 0"});
}

}  // namespace
}  // namespace ari_social_sim::dialogue
